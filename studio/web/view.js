// SPDX-License-Identifier: Apache-2.0
// What the canvas shows: a rectangle of the IFS plane [x0, y0, x1, y1] (y up) on the canvas's
// pixels (y down). Pan and zoom change it; the frame the maps are drawn on does not.

export class View {
  constructor(canvas) {
    this.canvas = canvas;
    this.rect = null;  // null: not framed yet (the server frames the attractor)
  }

  get framed() { return this.rect !== null; }

  toPixels(p) {
    const v = this.rect || [0, 0, 1, 1];
    return [(p[0] - v[0]) * this.canvas.width / (v[2] - v[0]),
            (v[3] - p[1]) * this.canvas.height / (v[3] - v[1])];
  }

  toPlane(px) {
    const v = this.rect || [0, 0, 1, 1];
    return [v[0] + px[0] * (v[2] - v[0]) / this.canvas.width,
            v[3] - px[1] * (v[3] - v[1]) / this.canvas.height];
  }

  // Zoom by `factor` (> 1: closer) about the canvas point px, which keeps its plane point; not
  // below 1e-9 or above 1e9 plane units across (doubles would run out of digits first).
  zoomAt(px, factor) {
    const p = this.toPlane(px);
    const v = this.rect;
    const width = (v[2] - v[0]) / factor;
    if (!(width > 1e-9 && width < 1e9)) return;
    this.rect = [p[0] - (p[0] - v[0]) / factor, p[1] - (p[1] - v[1]) / factor,
                 p[0] + (v[2] - p[0]) / factor, p[1] + (v[3] - p[1]) / factor];
  }

  // Move the picture by (dx, dy) canvas pixels.
  panBy(dx, dy) {
    const v = this.rect;
    const sx = (v[2] - v[0]) / this.canvas.width;
    const sy = (v[3] - v[1]) / this.canvas.height;
    this.rect = [v[0] - dx * sx, v[1] + dy * sy, v[2] - dx * sx, v[3] + dy * sy];
  }

  // The rectangle as the server's "view" field.
  text() { return this.rect ? this.rect.join(',') : null; }
}
