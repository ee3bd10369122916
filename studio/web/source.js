// SPDX-License-Identifier: Apache-2.0
// Colour stealing's source beside the canvas: the image (as the server reads it, scaled down to
// fit) with the colouring IFS G drawn over it, each piece the parallelogram g_n makes of the
// source's unit square (y up: (0, 0) is the image's lower left corner), dragged as the IFS's maps
// are. Map n of the IFS takes its colours from piece n.
import { api } from './api.js';
import { frameOf } from './geometry.js';
import { canvasPoint, dragged, drawMaps, drawOutlines, handleClientPoint, hitHandle } from './overlay.js';

const kSide = 320;  // the panel's canvas, CSS pixels a side at most

export class SourcePanel {
  // on: {maps() (G as shown), used() (G as the server fitted it, or null), colour(i),
  // selected(), select(i), flip(i), begin() (a drag starts: returns G to edit),
  // drag(maps, eventTime, i) (piece i moved), end()}
  constructor(canvas, on) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.on = on;
    this.image = null;  // a canvas holding the source
    this.name = null;
    this.drag = null;
    const frame = frameOf([0, 0, 1, 1]);
    this.surface = {
      ctx: this.ctx, frame,
      toPixels: (p) => [p[0] * this.canvas.width, (1 - p[1]) * this.canvas.height],
      toPlane: (px) => [px[0] / this.canvas.width, 1 - px[1] / this.canvas.height],
      get scale() { return 1; },
    };
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    let raw = false;  // as on the canvas (studio.js): pointerrawupdate where the browser has it
    canvas.addEventListener('pointerrawupdate', (e) => { raw = true; this.move(e); });
    canvas.addEventListener('pointermove', (e) => { if (!raw) this.move(e); });
    canvas.addEventListener('pointerup', () => this.up());
    canvas.addEventListener('pointercancel', () => this.up());
  }

  // Shows source `name` ("sample" or a file of the folder); throws the server's message.
  async load(name) {
    if (name === this.name && this.image) return;
    const res = await api(`/api/source?name=${encodeURIComponent(name)}`);
    if (!res.ok) throw new Error((await res.json()).error);
    const [w, h] = res.headers.get('X-Ifsfx-Size').split('x').map(Number);
    const bytes = new Uint8ClampedArray(await res.arrayBuffer());
    const image = document.createElement('canvas');
    image.width = w;
    image.height = h;
    image.getContext('2d').putImageData(new ImageData(bytes, w, h), 0, 0);
    this.image = image;
    this.name = name;
    this.sourceSize = res.headers.get('X-Ifsfx-Source-Size');
    // The panel keeps the source's aspect: the unit square is stretched over the image.
    const fit = Math.min(kSide / w, kSide / h);
    this.canvas.width = Math.round(w * fit);
    this.canvas.height = Math.round(h * fit);
    this.draw();
  }

  draw() {
    const { ctx, canvas } = this;
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    if (this.image) ctx.drawImage(this.image, 0, 0, canvas.width, canvas.height);
    const maps = this.on.maps();
    if (!maps) return;
    const used = this.on.used();
    const differs = used && used.some((m, i) => !maps[i] || m.some((x, k) => Math.abs(x - maps[i][k]) > 1e-6));
    if (differs) drawOutlines(this.surface, used, 'rgba(255, 255, 255, 0.8)');
    drawMaps(this.surface, maps, this.on.colour, this.on.selected());
  }

  handle(i, kind = 'centre', corner = 0) {
    return handleClientPoint(this.surface, this.canvas, this.on.maps()[i], kind, corner);
  }

  down(event) {
    const maps = this.on.maps();
    if (!maps) return;
    const h = hitHandle(this.surface, maps, this.on.selected(), canvasPoint(this.canvas, event));
    if (!h) return;
    this.canvas.setPointerCapture(event.pointerId);
    this.on.select(h.map);
    if (h.kind === 'flip') {
      this.on.flip(h.map);
      return;
    }
    const g = this.on.begin();
    this.drag = Object.assign(h, { start: this.surface.toPlane(canvasPoint(this.canvas, event)),
                                   g, m0: g[h.map].slice() });
  }

  move(event) {
    if (!this.drag) return;
    const p = this.surface.toPlane(canvasPoint(this.canvas, event));
    const m = dragged(this.surface, this.drag, this.drag.m0, this.drag.start, p, event.shiftKey);
    if (!m) return;
    const g = this.drag.g.slice();
    g[this.drag.map] = m;
    this.on.drag(g, event.timeStamp, this.drag.map);
  }

  up() {
    if (!this.drag) return;
    this.drag = null;
    this.on.end();
  }
}
