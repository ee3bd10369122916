// SPDX-License-Identifier: Apache-2.0
// The page's geometry (studio/web/geometry.js) under node's own test runner (`node --test`, no
// browser, no npm package): the handles' drags put the dragged corner under the pointer and keep
// what they promise to keep; the default probabilities are the server's (docs/design.md §1).
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

// Imported from its text: the page's .js files are ES modules that no package.json declares, and
// Debian 12's node (18) does not detect that by itself.
const source = readFileSync(new URL('../../studio/web/geometry.js', import.meta.url), 'utf8');
const g = await import(`data:text/javascript,${encodeURIComponent(source)}`);

const near = (a, b, what) => {
  assert.equal(a.length, b.length, what);
  a.forEach((x, i) => assert.ok(Math.abs(x - b[i]) < 1e-12, `${what}: ${a} != ${b}`));
};
const fern = [0.85, 0.04, -0.04, 0.85, 0, 1.6];
const square = g.frameOf([0, 0, 1, 1]);

test('apply is f(x, y) = (a x + b y + e, c x + d y + f)', () => {
  near(g.apply([1, 2, 3, 4, 5, 6], [1, 1]), [8, 13], 'apply');
});

test('factor is the largest singular value', () => {
  near([g.factor([0.5, 0, 0, 0.2, 3, 4])], [0.5], 'diagonal');
  const c = 0.3 * Math.cos(0.7), s = 0.3 * Math.sin(0.7);
  near([g.factor([c, -s, s, c, 0, 0])], [0.3], 'a rotation scaled by 0.3');
  near([g.factor([0, 0, 0, 0, 1, 1])], [0], 'a constant map');
});

test('frameOf lists the corners counter-clockwise from (x0, y0) and the centre', () => {
  const f = g.frameOf([-1, 0, 3, 2]);
  assert.deepEqual(f.corners, [[-1, 0], [3, 0], [3, 2], [-1, 2]]);
  assert.deepEqual(f.centre, [1, 1]);
});

test('moved translates the image by the pointer displacement', () => {
  near(g.moved(fern, [1, 1], [1.5, 0.25]), [0.85, 0.04, -0.04, 0.85, 0.5, 0.85], 'moved');
});

test('rotatedScaled puts the corner under the pointer and keeps the centre image', () => {
  for (let k = 0; k < 4; ++k) {
    const p = [0.3 + 0.1 * k, -0.2];
    const m = g.rotatedScaled(fern, square, k, p);
    near(g.apply(m, square.corners[k]), p, `corner ${k}`);
    near(g.apply(m, square.centre), g.apply(fern, square.centre), `centre, corner ${k}`);
    // A similarity times the old linear part: the shape's angles are kept (det ratio = |z|²).
    const ratio = (m[0] * m[3] - m[1] * m[2]) / (fern[0] * fern[3] - fern[1] * fern[2]);
    assert.ok(ratio > 0, 'no mirror');
  }
  // A quarter turn of the corner about the centre's image is a quarter turn of the map.
  const Q = g.apply(fern, square.centre);
  const c0 = g.apply(fern, square.corners[0]);
  const turned = [Q[0] - (c0[1] - Q[1]), Q[1] + (c0[0] - Q[0])];
  const m = g.rotatedScaled(fern, square, 0, turned);
  near([m[0], m[1], m[2], m[3]], [-fern[2], -fern[3], fern[0], fern[1]], 'quarter turn');
  assert.equal(g.rotatedScaled([0, 0, 0, 0, 1, 1], square, 0, [2, 2]), null);
});

test('sheared moves the corner and keeps its neighbour on the edge and the centre image', () => {
  for (let k = 0; k < 4; ++k) {
    const p = [0.9, 0.1 * k];
    const m = g.sheared(fern, square, k, p);
    near(g.apply(m, square.corners[k]), p, `corner ${k}`);
    near(g.apply(m, square.corners[k ^ 1]), g.apply(fern, square.corners[k ^ 1]), `neighbour of ${k}`);
    near(g.apply(m, square.centre), g.apply(fern, square.centre), `centre, corner ${k}`);
  }
  assert.equal(g.sheared(fern, g.frameOf([0, 0, 0, 1]), 0, [1, 1]), null);
});

test('defaultProbabilities is proportional to |det| with a 1 % floor', () => {
  near(g.defaultProbabilities([[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.25, 0, 0]]), [2 / 3, 1 / 3], 'dets');
  // A map of determinant 0 (the fern's stem) gets 1 % of the largest weight.
  near(g.defaultProbabilities([[0, 0, 0, 0.16, 0, 0], [0.5, 0, 0, 0.5, 0, 0]]), [0.0025 / 0.2525, 0.25 / 0.2525], 'floor');
  near(g.defaultProbabilities([[0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 1, 1]]), [0.5, 0.5], 'all singular');
});

test('flipped mirrors the map inside its frame', () => {
  const m = g.flipped(fern, square);
  for (let k = 0; k < 4; ++k) near(g.apply(m, square.corners[k]), g.apply(fern, square.corners[k ^ 1]), `corner ${k}`);
  near(g.flipped(m, square), fern, 'twice is the map');
});

test('shifted and middleMap', () => {
  near(g.shifted(fern, 1, -1), [0.85, 0.04, -0.04, 0.85, 1, 0.6], 'shifted');
  const f = g.frameOf([0, 0, 4, 2]);
  const m = g.middleMap(f);
  near(g.apply(m, f.centre), f.centre, 'fixes the centre');
  near([g.factor(m)], [0.5], 'half size');
});
