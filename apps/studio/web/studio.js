// SPDX-License-Identifier: Apache-2.0
// ifsfx studio, the page (docs/studio.md). It holds the preset being edited and sends all of it
// with every render: the server keeps no state but the render in flight, and a newer request
// cancels that one. Coordinates: "plane" is the IFS plane (y up), "pixels" the canvas's own
// pixels (y down), through the view rectangle of the last picture.

const token = new URLSearchParams(location.search).get('token') || '';
const $ = (id) => document.getElementById(id);
const canvas = $('canvas');
const ctx = canvas.getContext('2d');

let state = { name: 'studio', description: '', maps: [], probabilities: [], colours: [] };
let selected = 0;
let lockedView = null;  // "x0,y0,x1,y1" sent with each render once framed, so handles stay put
let picture = null;     // the last ImageBitmap drawn
let pictureView = null; // [x0, y0, x1, y1] of that picture
const undoStack = [];
const redoStack = [];
const stats = { seq: 0, drawnSeq: 0, latencies: [], renderMs: [], errors: 0 };
window.studio = stats;

async function api(path, options = {}) {
  const headers = Object.assign({ 'X-Ifsfx-Token': token }, options.headers || {});
  if (options.body) headers['Content-Type'] = 'application/json';
  return fetch(path, Object.assign({}, options, { headers }));
}

function status(text, error = false) {
  $('status').textContent = text;
  $('status').className = error ? 'error' : '';
}

// ---- the mathematics the page needs to draw and drag (the renders are the server's) ----

const apply = (m, p) => [m[0] * p[0] + m[1] * p[1] + m[4], m[2] * p[0] + m[3] * p[1] + m[5]];

// The largest singular value of [[a b][c d]]: the map's contraction factor.
function factor(m) {
  const t = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] + m[3] * m[3];
  const det = m[0] * m[3] - m[1] * m[2];
  return Math.sqrt((t + Math.sqrt(Math.max(t * t - 4 * det * det, 0))) / 2);
}

// The frame: the view rectangle, as plane points; corners 0..3 counter-clockwise from (x0, y0).
function frame() {
  const v = lockedView ? lockedView.split(',').map(Number) : pictureView || [0, 0, 1, 1];
  return {
    corners: [[v[0], v[1]], [v[2], v[1]], [v[2], v[3]], [v[0], v[3]]],
    centre: [(v[0] + v[2]) / 2, (v[1] + v[3]) / 2],
  };
}

function toPixels(p) {
  const v = pictureView || [0, 0, 1, 1];
  return [(p[0] - v[0]) * canvas.width / (v[2] - v[0]),
          (v[3] - p[1]) * canvas.height / (v[3] - v[1])];
}
function toPlane(px) {
  const v = pictureView || [0, 0, 1, 1];
  return [v[0] + px[0] * (v[2] - v[0]) / canvas.width,
          v[3] - px[1] * (v[3] - v[1]) / canvas.height];
}

function mapColour(i, n) {
  if (state.colours.length === n) return state.colours[i];
  return `hsl(${Math.round(360 * i / Math.max(n, 1))}, 90%, 60%)`;
}

// ---- drawing ----

function draw() {
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (picture) ctx.drawImage(picture, 0, 0, canvas.width, canvas.height);
  const f = frame();
  state.maps.forEach((m, i) => {
    const pts = f.corners.map((c) => toPixels(apply(m, c)));
    ctx.strokeStyle = mapColour(i, state.maps.length);
    ctx.lineWidth = i === selected ? 2.5 : 1.2;
    ctx.setLineDash(i === selected ? [] : [5, 4]);
    ctx.beginPath();
    pts.forEach((p, k) => (k ? ctx.lineTo(p[0], p[1]) : ctx.moveTo(p[0], p[1])));
    ctx.closePath();
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = ctx.strokeStyle;
    pts.forEach((p, k) => ctx.fillRect(p[0] - 4, p[1] - 4, 8, 8) || (k === 0 && ctx.strokeRect(p[0] - 7, p[1] - 7, 14, 14)));
    const c = toPixels(apply(m, f.centre));
    ctx.beginPath();
    ctx.arc(c[0], c[1], 6, 0, 2 * Math.PI);
    ctx.fill();
    ctx.fillStyle = '#000';
    ctx.font = 'bold 10px sans-serif';
    ctx.fillText(String(i + 1), c[0] - 3, c[1] + 4);
  });
}

function fmt(x) { return String(Number(x.toPrecision(6))); }

function defaultProbabilities() {
  const dets = state.maps.map((m) => Math.abs(m[0] * m[3] - m[1] * m[2]));
  const top = Math.max(...dets);
  const w = dets.map((d) => Math.max(d, 0.01 * top) || 1);
  const sum = w.reduce((a, b) => a + b, 0);
  return w.map((x) => x / sum);
}

function renderTable() {
  const body = document.querySelector('#maps tbody');
  body.textContent = '';
  const n = state.maps.length;
  state.maps.forEach((m, i) => {
    const tr = document.createElement('tr');
    tr.dataset.map = i;
    if (i === selected) tr.className = 'selected';
    const head = document.createElement('td');
    head.innerHTML = `<span class="swatch"></span> ${i + 1}`;
    head.firstChild.style.background = mapColour(i, n);
    head.onclick = () => { selected = i; renderTable(); draw(); };
    tr.appendChild(head);
    const fields = ['a', 'b', 'c', 'd', 'e', 'f', 'p'];
    fields.forEach((name, k) => {
      const td = document.createElement('td');
      const input = document.createElement('input');
      input.name = `${name}${i}`;
      input.inputMode = 'decimal';  // text: a number field's spinner would hide digits
      input.value = k < 6 ? fmt(m[k]) : (state.probabilities.length === n ? fmt(state.probabilities[i]) : '');
      if (k === 6 && state.probabilities.length !== n) input.placeholder = 'auto';
      input.onchange = () => {
        const value = Number(input.value);
        if (input.value === '' || !Number.isFinite(value)) { renderTable(); return; }
        edit(() => {
          if (k < 6) state.maps[i][k] = value;
          else {
            if (state.probabilities.length !== n) state.probabilities = defaultProbabilities();
            state.probabilities[i] = value;
          }
        });
      };
      td.appendChild(input);
      tr.appendChild(td);
    });
    const fac = factor(m);
    const ftd = document.createElement('td');
    ftd.className = fac >= 1 ? 'warn factor' : 'factor';
    ftd.textContent = fac >= 1 ? `${fac.toFixed(3)} ⚠ ≥ 1` : fac.toFixed(3);
    if (fac >= 1) ftd.title = 'This map does not contract: the IFS has no attractor unless it contracts on average';
    tr.appendChild(ftd);
    const actions = document.createElement('td');
    for (const [label, title, action] of [['↑', 'Move up', () => move(i, -1)],
                                          ['↓', 'Move down', () => move(i, 1)],
                                          ['✕', 'Delete', () => remove(i)]]) {
      const b = document.createElement('button');
      b.textContent = label;
      b.title = title;
      b.onclick = action;
      actions.appendChild(b);
    }
    tr.appendChild(actions);
    body.appendChild(tr);
  });
}

// ---- edits, undo and redo ----

const snapshot = () => JSON.stringify(state);

function edit(change) {
  undoStack.push(snapshot());
  redoStack.length = 0;
  change();
  changed();
}

function changed(eventTime) {
  renderTable();
  draw();
  render(eventTime);
}

function undo() {
  if (!undoStack.length) return;
  redoStack.push(snapshot());
  state = JSON.parse(undoStack.pop());
  selected = Math.min(selected, state.maps.length - 1);
  changed();
}
function redo() {
  if (!redoStack.length) return;
  undoStack.push(snapshot());
  state = JSON.parse(redoStack.pop());
  selected = Math.min(selected, state.maps.length - 1);
  changed();
}

function each(list, i, action) { if (list.length === state.maps.length) action(list); }

function move(i, by) {
  const j = i + by;
  if (j < 0 || j >= state.maps.length) return;
  edit(() => {
    for (const list of [state.probabilities, state.colours])
      each(list, i, (l) => ([l[i], l[j]] = [l[j], l[i]]));
    [state.maps[i], state.maps[j]] = [state.maps[j], state.maps[i]];
    selected = j;
  });
}

function remove(i) {
  if (state.maps.length <= 1) { status('an IFS needs at least one map', true); return; }
  edit(() => {
    for (const list of [state.probabilities, state.colours]) each(list, i, (l) => l.splice(i, 1));
    state.maps.splice(i, 1);
    selected = Math.min(selected, state.maps.length - 1);
  });
}

function add() {
  edit(() => {
    const q = frame().centre;
    const n = state.maps.length;
    if (state.probabilities.length === n) state.probabilities.push(1 / (n + 1));
    if (state.colours.length === n) state.colours.push('#ffffff');
    state.maps.push([0.5, 0, 0, 0.5, q[0] * 0.5, q[1] * 0.5]);  // f(q) = q: half size, centred
    selected = n;
  });
}

// ---- rendering: each edit sends the preset; a newer request cancels the one in flight ----

let controller = null;

function requestBody() {
  const body = {
    name: state.name, description: state.description, maps: state.maps,
    mode: $('mode').value, size: $('size').value,
  };
  if (state.probabilities.length) body.probabilities = state.probabilities;
  if (state.colours.length) body.colours = state.colours;
  if (body.mode === 'steal') body.source = $('source').value || 'sample';
  if (lockedView) body.view = lockedView;
  return body;
}

async function render(eventTime = performance.now()) {
  const seq = ++stats.seq;
  if (controller) controller.abort();
  controller = new AbortController();
  try {
    const res = await api('/api/render', {
      method: 'POST', body: JSON.stringify(requestBody()), signal: controller.signal,
    });
    if (res.status === 409) return;  // a newer request took over
    if (!res.ok) {
      stats.errors++;
      status((await res.json()).error, true);
      return;
    }
    const view = res.headers.get('X-Ifsfx-View');
    const bitmap = await createImageBitmap(await res.blob());
    if (seq < stats.drawnSeq) return;
    const [w, h] = $('size').value.split('x').map(Number);
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    picture = bitmap;
    pictureView = view.split(',').map(Number);
    if (!lockedView) lockedView = view;
    stats.drawnSeq = seq;
    draw();
    stats.latencies.push(performance.now() - eventTime);
    stats.renderMs.push(Number(res.headers.get('X-Ifsfx-Render-Ms')));
    status(`${state.name}: ${state.maps.length} maps, rendered in ${res.headers.get('X-Ifsfx-Render-Ms')} ms`);
  } catch (e) {
    if (e.name !== 'AbortError') status(String(e), true);
  }
}

// ---- dragging handles ----

let drag = null;

function canvasPoint(event) {
  const r = canvas.getBoundingClientRect();
  return [(event.clientX - r.left) * canvas.width / r.width,
          (event.clientY - r.top) * canvas.height / r.height];
}

// The handle under a canvas point: {map, kind: 'centre' | 'corner', corner}.
function hit(px) {
  const f = frame();
  const near = (p) => Math.hypot(p[0] - px[0], p[1] - px[1]) <= 9 * canvas.width / canvas.getBoundingClientRect().width;
  const order = [selected, ...state.maps.keys()];
  for (const i of order) {
    const m = state.maps[i];
    if (near(toPixels(apply(m, f.centre)))) return { map: i, kind: 'centre' };
    for (let k = 0; k < 4; k++)
      if (near(toPixels(apply(m, f.corners[k])))) return { map: i, kind: 'corner', corner: k };
  }
  return null;
}

// Where a handle of map i is, in the page's (client) coordinates: for tests and scripts.
stats.handle = (i, kind = 'centre', corner = 0) => {
  const f = frame();
  const p = toPixels(apply(state.maps[i], kind === 'centre' ? f.centre : f.corners[corner]));
  const r = canvas.getBoundingClientRect();
  return { x: r.left + p[0] * r.width / canvas.width, y: r.top + p[1] * r.height / canvas.height };
};
stats.state = () => JSON.parse(snapshot());
// For the panels of jobs.js, fit.js, video.js and superifs.js: the preset with the render
// settings, and opening a preset (one undoable edit).
stats.requestBody = () => JSON.parse(JSON.stringify(requestBody()));
stats.openPreset = (preset) => {
  undoStack.push(snapshot());
  redoStack.length = 0;
  open(preset);
};

canvas.addEventListener('pointerdown', (event) => {
  const h = hit(canvasPoint(event));
  if (!h) return;
  canvas.setPointerCapture(event.pointerId);
  selected = h.map;
  drag = Object.assign(h, { before: snapshot(), start: toPlane(canvasPoint(event)),
                            map: h.map, m0: state.maps[h.map].slice(), moved: false });
  renderTable();
  draw();
});

canvas.addEventListener('pointermove', (event) => {
  if (!drag) return;
  const p = toPlane(canvasPoint(event));
  const m0 = drag.m0;
  const f = frame();
  const q = f.centre;
  let m;
  if (drag.kind === 'centre') {  // translate: e, f follow the pointer
    m = [m0[0], m0[1], m0[2], m0[3], m0[4] + p[0] - drag.start[0], m0[5] + p[1] - drag.start[1]];
  } else {
    const Q = apply(m0, q);  // the image of the frame's centre stays put
    const dk = [f.corners[drag.corner][0] - q[0], f.corners[drag.corner][1] - q[1]];
    const target = [p[0] - Q[0], p[1] - Q[1]];
    let L;
    if (event.shiftKey) {
      // Shear: the corner goes to the pointer, the corner beside it on its horizontal edge stays.
      const k2 = drag.corner ^ 1;
      const d2 = [f.corners[k2][0] - q[0], f.corners[k2][1] - q[1]];
      const w2 = [m0[0] * d2[0] + m0[1] * d2[1], m0[2] * d2[0] + m0[3] * d2[1]];
      const det = dk[0] * d2[1] - d2[0] * dk[1];
      if (Math.abs(det) < 1e-12) return;
      // L = W · D⁻¹ with D = [dk d2], W = [target w2]
      const inv = [d2[1] / det, -d2[0] / det, -dk[1] / det, dk[0] / det];
      L = [target[0] * inv[0] + w2[0] * inv[2], target[0] * inv[1] + w2[0] * inv[3],
           target[1] * inv[0] + w2[1] * inv[2], target[1] * inv[1] + w2[1] * inv[3]];
    } else {
      // Rotate and scale about the centre's image: multiply by the complex ratio of the corner's
      // new and old offsets.
      const old = [m0[0] * dk[0] + m0[1] * dk[1], m0[2] * dk[0] + m0[3] * dk[1]];
      const n2 = old[0] * old[0] + old[1] * old[1];
      if (n2 < 1e-18) return;
      const zr = (target[0] * old[0] + target[1] * old[1]) / n2;
      const zi = (target[1] * old[0] - target[0] * old[1]) / n2;
      L = [zr * m0[0] - zi * m0[2], zr * m0[1] - zi * m0[3], zi * m0[0] + zr * m0[2], zi * m0[1] + zr * m0[3]];
    }
    m = [L[0], L[1], L[2], L[3], Q[0] - (L[0] * q[0] + L[1] * q[1]), Q[1] - (L[2] * q[0] + L[3] * q[1])];
  }
  if (!drag.moved) { undoStack.push(drag.before); redoStack.length = 0; drag.moved = true; }
  state.maps[drag.map] = m;
  changed(event.timeStamp);
});

const endDrag = () => { drag = null; };
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);

// ---- the rest of the page ----

function open(preset) {
  state = { name: preset.name, description: preset.description || '', maps: preset.maps,
            probabilities: preset.probabilities || [], colours: preset.colours || [] };
  selected = 0;
  lockedView = null;
  $('file').value = `${preset.name}.toml`;
  changed();
}

async function json(path) {
  const res = await api(path);
  const body = await res.json();
  if (!res.ok) throw new Error(body.error);
  return body;
}

async function start() {
  if (!token) { status('open the URL that `ifsfx studio` printed: it carries the token', true); return; }
  const [presets, sources, initial] = await Promise.all([
    json('/api/presets'), json('/api/sources'), json('/api/preset')]);
  const select = $('preset');
  for (const p of [{ name: initial.name, description: 'opened' }, ...presets]) {
    const o = document.createElement('option');
    o.value = p.name === initial.name && p.description === 'opened' ? '' : p.name;
    o.textContent = `${p.name}${p.maps ? ` (${p.maps} maps)` : ''}`;
    select.appendChild(o);
  }
  for (const s of sources) {
    const o = document.createElement('option');
    o.value = o.textContent = s;
    $('source').appendChild(o);
  }
  select.onchange = async () => {
    try {
      const preset = await json(select.value ? `/api/preset?name=${encodeURIComponent(select.value)}` : '/api/preset');
      undoStack.push(snapshot());
      redoStack.length = 0;
      open(preset);
    } catch (e) { status(String(e.message), true); }
  };
  const modeChanged = () => {
    $('source-label').style.display = $('mode').value === 'steal' ? '' : 'none';
    render();
  };
  $('mode').onchange = modeChanged;
  $('source').onchange = () => render();
  $('size').onchange = () => { lockedView = null; render(); };
  $('reframe').onclick = () => { lockedView = null; render(); };
  $('undo').onclick = undo;
  $('redo').onclick = redo;
  $('add').onclick = add;
  $('save').onclick = save;
  $('source-label').style.display = 'none';
  open(initial);
}

async function save() {
  const res = await api('/api/save', {
    method: 'POST', body: JSON.stringify(Object.assign(requestBody(), { file: $('file').value })),
  });
  const body = await res.json();
  if (res.ok) status(`saved ${body.saved}`);
  else status(body.error, true);
}

document.addEventListener('keydown', (event) => {
  if (event.target.tagName === 'INPUT') return;
  const key = event.key.toLowerCase();
  if ((event.ctrlKey || event.metaKey) && key === 'z') {
    event.preventDefault();
    if (event.shiftKey) redo(); else undo();
  } else if ((event.ctrlKey || event.metaKey) && key === 'y') {
    event.preventDefault();
    redo();
  }
});

start().catch((e) => status(String(e.message || e), true));
