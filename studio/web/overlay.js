// SPDX-License-Identifier: Apache-2.0
// The maps of an IFS drawn over a picture as the parallelograms they make of a frame, with their
// handles, and the handle under the pointer: for the IFS F on the canvas (the frame: the view
// rectangle the document was framed with) and for the colouring IFS G on the source (the frame:
// the source's unit square). A surface is {ctx, frame, toPixels(p), toPlane(px), scale} where
// scale is canvas pixels per CSS pixel.
import { apply, moved, rotatedScaled, sheared } from './geometry.js';

const kHandle = 4;  // half a handle's side, CSS pixels
const kGrab = 9;    // how near the pointer must be to grab a handle, CSS pixels

// The points of map i's handles in canvas pixels: its centre, its four corners, and the flip
// marker at the middle of its right edge.
function handlePoints(s, m) {
  const corners = s.frame.corners.map((c) => s.toPixels(apply(m, c)));
  const centre = s.toPixels(apply(m, s.frame.centre));
  const edge = s.toPixels(apply(m, [s.frame.corners[1][0], s.frame.centre[1]]));
  return { corners, centre, edge };
}

// Draws every map; the selected one solid and thicker, with its flip marker.
export function drawMaps(s, maps, colour, selected) {
  const { ctx } = s;
  const k = s.scale;
  maps.forEach((m, i) => {
    const h = handlePoints(s, m);
    ctx.strokeStyle = colour(i);
    ctx.lineWidth = (i === selected ? 2.5 : 1.2) * k;
    ctx.setLineDash(i === selected ? [] : [5 * k, 4 * k]);
    ctx.beginPath();
    h.corners.forEach((p, j) => (j ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
    ctx.closePath();
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = ctx.strokeStyle;
    h.corners.forEach((p, j) => {
      ctx.fillRect(p[0] - kHandle * k, p[1] - kHandle * k, 2 * kHandle * k, 2 * kHandle * k);
      // Corner 0, the image of the frame's lower left, is marked: it shows the map's orientation.
      if (j === 0) ctx.strokeRect(p[0] - 7 * k, p[1] - 7 * k, 14 * k, 14 * k);
    });
    ctx.beginPath();
    ctx.arc(h.centre[0], h.centre[1], 6 * k, 0, 2 * Math.PI);
    ctx.fill();
    if (i === selected) {  // the flip marker: a small diamond
      ctx.beginPath();
      ctx.moveTo(h.edge[0], h.edge[1] - 6 * k);
      ctx.lineTo(h.edge[0] + 6 * k, h.edge[1]);
      ctx.lineTo(h.edge[0], h.edge[1] + 6 * k);
      ctx.lineTo(h.edge[0] - 6 * k, h.edge[1]);
      ctx.closePath();
      ctx.fillStyle = '#fff';
      ctx.fill();
      ctx.stroke();
    }
    ctx.fillStyle = '#000';
    ctx.font = `bold ${Math.round(10 * k)}px sans-serif`;
    ctx.fillText(String(i + 1), h.centre[0] - 3 * k, h.centre[1] + 4 * k);
  });
}

// Outlines only (thin, dotted): the colouring as the server used it, where it differs.
export function drawOutlines(s, maps, style) {
  const { ctx } = s;
  ctx.save();
  ctx.strokeStyle = style;
  ctx.lineWidth = s.scale;
  ctx.setLineDash([2 * s.scale, 3 * s.scale]);
  for (const m of maps) {
    const pts = s.frame.corners.map((c) => s.toPixels(apply(m, c)));
    ctx.beginPath();
    pts.forEach((p, j) => (j ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
    ctx.closePath();
    ctx.stroke();
  }
  ctx.restore();
}

// The handle at canvas point px: {map, kind: 'centre' | 'corner' | 'flip', corner}, the
// selected map's first; null if none.
export function hitHandle(s, maps, selected, px) {
  const near = (p) => Math.hypot(p[0] - px[0], p[1] - px[1]) <= kGrab * s.scale;
  const order = [selected, ...maps.keys()].filter((i) => i >= 0 && i < maps.length);
  for (const i of order) {
    const h = handlePoints(s, maps[i]);
    if (i === selected && near(h.edge)) return { map: i, kind: 'flip' };
    if (near(h.centre)) return { map: i, kind: 'centre' };
    for (let k = 0; k < 4; k++) if (near(h.corners[k])) return { map: i, kind: 'corner', corner: k };
  }
  return null;
}

// Map h.map after dragging its handle from plane point `start` to `p` (Shift: shear a corner).
export function dragged(s, h, m0, start, p, shift) {
  if (h.kind === 'centre') return moved(m0, start, p);
  return shift ? sheared(m0, s.frame, h.corner, p) : rotatedScaled(m0, s.frame, h.corner, p);
}

// Where a handle is in the page (client coordinates): for tests and scripts.
export function handleClientPoint(s, canvas, m, kind = 'centre', corner = 0) {
  const h = handlePoints(s, m);
  const p = kind === 'centre' ? h.centre : kind === 'flip' ? h.edge : h.corners[corner];
  const r = canvas.getBoundingClientRect();
  return { x: r.left + p[0] * r.width / canvas.width, y: r.top + p[1] * r.height / canvas.height };
}

// A pointer event's position in canvas pixels.
export function canvasPoint(canvas, event) {
  const r = canvas.getBoundingClientRect();
  return [(event.clientX - r.left) * canvas.width / r.width,
          (event.clientY - r.top) * canvas.height / r.height];
}
