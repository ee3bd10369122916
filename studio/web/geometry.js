// SPDX-License-Identifier: Apache-2.0
// The little mathematics the page needs to draw maps and drag their handles (the renders are the
// server's). A map is [a, b, c, d, e, f]: f(x, y) = (a x + b y + e, c x + d y + f), in the plane
// it lives in (the IFS plane, or the source's unit square for the colouring IFS).

export const apply = (m, p) => [m[0] * p[0] + m[1] * p[1] + m[4], m[2] * p[0] + m[3] * p[1] + m[5]];

// The largest singular value of [[a b][c d]]: the map's contraction factor.
export function factor(m) {
  const t = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3];
  const det = m[0] * m[3] - m[1] * m[2];
  return Math.sqrt((t + Math.sqrt(Math.max(t * t - 4 * det * det, 0))) / 2);
}

// A frame: a rectangle [x0, y0, x1, y1] as corners 0..3 counter-clockwise from (x0, y0).
export function frameOf(v) {
  return {
    corners: [[v[0], v[1]], [v[2], v[1]], [v[2], v[3]], [v[0], v[3]]],
    centre: [(v[0] + v[2]) / 2, (v[1] + v[3]) / 2],
  };
}

// Translate: the map's image moves by the pointer's displacement (start → p).
export function moved(m0, start, p) {
  return [m0[0], m0[1], m0[2], m0[3], m0[4] + p[0] - start[0], m0[5] + p[1] - start[1]];
}

// The map whose linear part is L and that sends q to Q.
function through(L, q, Q) {
  return [L[0], L[1], L[2], L[3], Q[0] - (L[0] * q[0] + L[1] * q[1]), Q[1] - (L[2] * q[0] + L[3] * q[1])];
}

// Rotate and scale about the image of the frame's centre: corner k of the frame goes where the
// pointer p is, by the complex ratio of the corner's new and old offsets. null if degenerate.
export function rotatedScaled(m0, f, k, p) {
  const q = f.centre;
  const Q = apply(m0, q);
  const dk = [f.corners[k][0] - q[0], f.corners[k][1] - q[1]];
  const target = [p[0] - Q[0], p[1] - Q[1]];
  const old = [m0[0] * dk[0] + m0[1] * dk[1], m0[2] * dk[0] + m0[3] * dk[1]];
  const n2 = old[0] * old[0] + old[1] * old[1];
  if (n2 < 1e-18) return null;
  const zr = (target[0] * old[0] + target[1] * old[1]) / n2;
  const zi = (target[1] * old[0] - target[0] * old[1]) / n2;
  return through([zr * m0[0] - zi * m0[2], zr * m0[1] - zi * m0[3],
                  zi * m0[0] + zr * m0[2], zi * m0[1] + zr * m0[3]], q, Q);
}

// Shear: corner k goes to the pointer p, the corner beside it on its horizontal edge (k ^ 1) and
// the image of the centre stay. null if degenerate.
export function sheared(m0, f, k, p) {
  const q = f.centre;
  const Q = apply(m0, q);
  const dk = [f.corners[k][0] - q[0], f.corners[k][1] - q[1]];
  const target = [p[0] - Q[0], p[1] - Q[1]];
  const d2 = [f.corners[k ^ 1][0] - q[0], f.corners[k ^ 1][1] - q[1]];
  const w2 = [m0[0] * d2[0] + m0[1] * d2[1], m0[2] * d2[0] + m0[3] * d2[1]];
  const det = dk[0] * d2[1] - d2[0] * dk[1];
  if (Math.abs(det) < 1e-12) return null;
  // L = W · D⁻¹ with D = [dk d2], W = [target w2]
  const inv = [d2[1] / det, -d2[0] / det, -dk[1] / det, dk[0] / det];
  return through([target[0] * inv[0] + w2[0] * inv[2], target[0] * inv[1] + w2[0] * inv[3],
                  target[1] * inv[0] + w2[1] * inv[2], target[1] * inv[1] + w2[1] * inv[3]], q, Q);
}

// The probabilities the server uses when none are given: ∝ |det| with a floor of 1 % of the
// largest (docs/design.md §1).
export function defaultProbabilities(maps) {
  const dets = maps.map((m) => Math.abs(m[0] * m[3] - m[1] * m[2]));
  const top = Math.max(...dets);
  const w = dets.map((d) => Math.max(d, 0.01 * top) || 1);
  const sum = w.reduce((a, b) => a + b, 0);
  return w.map((x) => x / sum);
}

// Mirror: the same parallelogram, its inside flipped left to right (f ∘ R, R the reflection of
// the frame about its vertical centre line x = cx).
export function flipped(m, f) {
  const cx = f.centre[0];
  return [-m[0], m[1], -m[2], m[3], m[4] + 2 * m[0] * cx, m[5] + 2 * m[2] * cx];
}

// The map moved by (dx, dy) in its plane.
export const shifted = (m, dx, dy) => [m[0], m[1], m[2], m[3], m[4] + dx, m[5] + dy];

// A half-size map of the frame onto its own middle: f(q) = q, q the frame's centre.
export function middleMap(f, scale = 0.5) {
  const q = f.centre;
  return [scale, 0, 0, scale, q[0] * (1 - scale), q[1] * (1 - scale)];
}
