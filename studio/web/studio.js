// SPDX-License-Identifier: Apache-2.0
// ifsfx studio, the page (docs/studio.md). It holds the document being edited (the preset, and
// the colouring IFS of colour stealing) and sends all of it with every render: the server keeps
// no state but the renders in flight. Coordinates: "plane" is the IFS plane (y up), "pixels" the
// canvas's own pixels (y down), through the view (view.js); the maps are drawn as the
// parallelograms they make of the frame, the view rectangle the document was framed with (it
// stays put under pan and zoom, so that the handles do not jump). A fractal flame's document
// also has `flame` (flame.js): its maps are its xforms' pre-affine maps in the editor plane,
// drawn on the unit square, and the picture is framed by its camera.
import { $, getJson, postJson, status, token } from './api.js';
import { listPresets, listSources, uploadImage } from './folder.js';
import { chaosDuplicate, chaosRemove, chaosSwap, drawPalette, listFor, loadVariations, newXform,
         paletteColour, renderFlamePanel } from './flame.js';
import { defaultProbabilities, flipped, frameOf, middleMap, shifted } from './geometry.js';
import { LiveRenderer } from './live.js';
import { session } from './panels.js';
import { canvasPoint, dragged, drawMaps, handleClientPoint, hitHandle } from './overlay.js';
import { SourcePanel } from './source.js';
import { renderColouringTable, renderMapsTable, updateRow } from './table.js';
import { View } from './view.js';

const canvas = $('canvas');
const ctx = canvas.getContext('2d');
const view = new View(canvas);

// The document: what Save writes (the preset, and NAME.colouring.toml when colouring is set).
let doc = { name: 'studio', description: '', maps: [], probabilities: [], colours: [],
            colouring: null, allow_expansive: false, flame: null };
let selected = 0;
let frame = null;       // frameOf(frameRect): where the maps are drawn from
let frameRect = null;   // [x0, y0, x1, y1]: the view the document was framed with
let picture = null;     // {canvas, view, full}: the last picture, drawn where its view lies
let usedColouring = null;  // G as the server fitted it (X-Ifsfx-Colouring)
let flameView = null;   // the rectangle a flame's own camera shows: no "view" is sent for it
let openedFile = null;  // the folder file the document came from
const undoStack = [];
const redoStack = [];
const defaults = new Map();  // N → {colours, colouring}: the server's palette and tiling for N maps
const stats = { seq: 0, drawnSeq: 0, latencies: [], fullLatencies: [], renderMs: [],
                fullRenderMs: [], errors: 0 };
window.studio = stats;

// ---- the document's defaults for N maps (the server computes them) ----

function defaultsFor(n) {
  if (!defaults.has(n)) {
    defaults.set(n, null);
    getJson(`/api/defaults?maps=${n}`).then((d) => {
      defaults.set(n, d);
      refresh();
    }).catch((e) => status(e.message, true));
  }
  return defaults.get(n);
}

function colourOf(i) {
  if (doc.flame) return paletteColour(doc.flame, doc.flame.xforms[i].colour);
  const n = doc.maps.length;
  if (doc.colours.length === n) return doc.colours[i];
  const d = defaultsFor(n);
  return d ? d.colours[i] : '#888888';
}

// G as shown and edited: the document's, or the default tiling for N maps.
function colouringShown() {
  if (doc.colouring) return doc.colouring;
  const d = defaultsFor(doc.maps.length);
  return d ? d.colouring : null;
}

// ---- drawing ----

const surface = {
  ctx,
  get frame() { return frame; },
  toPixels: (p) => view.toPixels(p),
  toPlane: (px) => view.toPlane(px),
  get scale() { return canvas.width / canvas.getBoundingClientRect().width || 1; },
};

function draw() {
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (picture && view.framed) {
    const v = picture.view;
    const a = view.toPixels([v[0], v[3]]);
    const b = view.toPixels([v[2], v[1]]);
    ctx.imageSmoothingEnabled = true;
    ctx.drawImage(picture.canvas, a[0], a[1], b[0] - a[0], b[1] - a[1]);
  }
  if (frame) drawMaps(surface, doc.maps, colourOf, selected);
}

const steal = () => $('mode').value === 'steal';

function renderTables() {
  renderMapsTable(document.querySelector('#maps tbody'), doc, selected, colourOf, {
    select: (i) => { selected = i; refresh(); },
    set: (i, k, v) => edit(() => {
      if (k < 6) doc.maps[i][k] = v;
      else if (doc.flame) doc.flame.xforms[i][k === 6 ? 'weight' : 'colour'] = v;
      else {
        if (doc.probabilities.length !== doc.maps.length) doc.probabilities = defaultProbabilities(doc.maps);
        doc.probabilities[i] = v;
      }
    }),
    colour: (i, c) => edit(() => {
      const n = doc.maps.length;
      if (doc.colours.length !== n) doc.colours = Array.from({ length: n }, (_, j) => colourOf(j));
      doc.colours[i] = c;
    }),
    move, duplicate, remove,
    flip: (i) => edit(() => { doc.maps[i] = flipped(doc.maps[i], frame || frameOf([0, 0, 1, 1])); }),
    restore: refresh,
  });
  $('p-head').textContent = doc.flame ? 'w' : 'p';
  $('colour-head').textContent = doc.flame ? 'colour (0–1)' : 'colour';
  $('flame-panel').hidden = !doc.flame;
  if (doc.flame) renderFlame();
  $('colouring-panel').hidden = !steal();
  const g = colouringShown();
  if (steal() && g) {
    renderColouringTable(document.querySelector('#colouring tbody'), g, selected, colourOf, {
      select: (i) => { selected = i; refresh(); },
      set: (i, k, v) => edit(() => { ensureColouring()[i][k] = v; }),
      restore: refresh,
    });
  }
  $('colouring-state').textContent = doc.colouring
    ? 'edited: saved beside the preset as NAME.colouring.toml'
    : `the default tiling for ${doc.maps.length} maps`;
  $('reset-colouring').disabled = !doc.colouring;
}

// The flame's panel: the palette strip and the selected xform's variations.
function renderFlame() {
  drawPalette($('palette'), doc.flame, selected);
  const terms = (list, k) => doc.flame.xforms[selected][list][k];
  renderFlamePanel(doc, selected, {
    set: (list, k, param, v) => edit(() => {
      if (param) terms(list, k).params[param] = v;
      else terms(list, k).weight = v;
    }),
    remove: (list, k) => edit(() => { doc.flame.xforms[selected][list].splice(k, 1); }),
    add: (name) => edit(() => { doc.flame.xforms[selected][listFor(name)].push({ name, weight: 1, params: {} }); }),
    field: (key, v) => edit(() => { doc.flame.xforms[selected][key] = v; }),
    restore: refresh,
  });
}

function refresh() {
  renderTables();
  draw();
  if (steal()) source.draw();
}

// ---- edits, undo and redo ----

// An undo step: the document and the frame its maps were drawn on (opening a preset frames it
// anew; undoing that goes back to the old frame too).
const snapshot = () => JSON.stringify({ doc, frame: frameRect });

function pushUndo(before = snapshot()) {
  undoStack.push(before);
  redoStack.length = 0;
}

function edit(change, eventTime) {
  pushUndo();
  change();
  changed(eventTime);
}

function changed(eventTime, interactive = false) {
  selected = Math.max(0, Math.min(selected, doc.maps.length - 1));
  renderer.changed(eventTime, interactive);  // the request first, the page after
  refresh();
}

// One map moved during a drag (of the IFS, or of the colouring with `prefix` 'g'): the request
// first, then only that map's fields and the drawings.
function dragChanged(eventTime, prefix, i, m) {
  renderer.changed(eventTime, true);
  const table = prefix ? '#colouring tbody' : '#maps tbody';
  updateRow(document.querySelector(table), prefix, i, m, !doc.flame);
  draw();
  if (steal()) source.draw();
}

function restore(from, to) {
  if (!from.length) return;
  to.push(snapshot());
  const step = JSON.parse(from.pop());
  if (step.doc.name !== doc.name || Boolean(step.doc.flame) !== Boolean(doc.flame))
    $('file').value = saveName(step.doc.name, Boolean(step.doc.flame));
  // Another frame, or another camera (another flame, or one flame and one IFS): framed anew.
  const camera = (d) => JSON.stringify(d.flame && d.flame.camera);
  const reframed = JSON.stringify(step.frame) !== JSON.stringify(frameRect) || camera(step.doc) !== camera(doc);
  doc = step.doc;
  if (reframed) {
    frameRect = step.frame;
    frame = frameRect && frameOf(frameRect);
    // A flame's frame is the unit square, not a view: its camera frames it again.
    view.rect = frameRect && !doc.flame ? frameRect.slice() : null;
    picture = null;
  }
  changed();
}
const undo = () => restore(undoStack, redoStack);
const redo = () => restore(redoStack, undoStack);

function ensureColouring() {
  if (!doc.colouring) doc.colouring = JSON.parse(JSON.stringify(colouringShown()));
  return doc.colouring;
}

// The lists that follow the maps (probabilities, colours, the colouring's pieces, a flame's
// xforms), when set.
function lists() {
  const n = doc.maps.length;
  return [doc.probabilities, doc.colours, doc.colouring || [], doc.flame ? doc.flame.xforms : []]
    .filter((l) => l.length === n);
}

function move(i, by) {
  const j = i + by;
  if (j < 0 || j >= doc.maps.length) return;
  edit(() => {
    for (const l of [...lists(), doc.maps]) [l[i], l[j]] = [l[j], l[i]];
    if (doc.flame) chaosSwap(doc.flame.xforms, i, j);
    selected = j;
  });
}

function duplicate(i) {
  if (doc.maps.length >= 64) { status('at most 64 maps', true); return; }
  edit(() => {
    const w = frameRect ? frameRect[2] - frameRect[0] : 1;
    for (const l of lists()) l.splice(i + 1, 0, JSON.parse(JSON.stringify(l[i])));
    if (doc.flame) chaosDuplicate(doc.flame.xforms, i);
    if (doc.probabilities.length === doc.maps.length + 1) doc.probabilities[i + 1] = doc.probabilities[i];
    doc.maps.splice(i + 1, 0, shifted(doc.maps[i], 0.04 * w, -0.04 * w));  // beside it, visible
    selected = i + 1;
  });
}

function remove(i) {
  if (doc.maps.length <= 1) { status('an IFS needs at least one map', true); return; }
  edit(() => {
    for (const l of [...lists(), doc.maps]) l.splice(i, 1);
    if (doc.flame) chaosRemove(doc.flame.xforms, i);
    selected = Math.min(selected, doc.maps.length - 1);
  });
}

function add() {
  if (doc.maps.length >= 64) { status('at most 64 maps', true); return; }
  edit(() => {
    const n = doc.maps.length;
    if (doc.probabilities.length === n) doc.probabilities.push(1 / (n + 1));
    if (doc.colours.length === n) doc.colours.push('#ffffff');
    if (doc.colouring && doc.colouring.length === n) doc.colouring.push(middleMap(frameOf([0, 0, 1, 1]), 0.25));
    if (doc.flame) doc.flame.xforms.push(newXform());
    doc.maps.push(middleMap(frame || frameOf([0, 0, 1, 1])));
    selected = n;
  });
}

// ---- the live picture ----

// The quality of a flame's live picture: its own, up to this (a flame file may ask for
// thousands of samples a pixel; a Jobs still renders at the flame's own).
const kFlamePreviewQuality = 10;

function requestBody() {
  if (doc.flame) {
    // measure: the flame look; attractor, tops, steal: its xforms through the chaos game.
    const body = { name: doc.name, maps: doc.maps, flame: doc.flame, mode: $('mode').value };
    if (body.mode === 'steal') {
      body.source = $('source').value || 'sample';
      if (doc.colouring) body.colouring = doc.colouring;
    }
    // Framed by its camera until panned or zoomed: the picture `ifsfx render NAME.flame` makes.
    if (view.framed && view.text() !== (flameView && flameView.join(','))) body.view = view.text();
    return body;
  }
  const body = { name: doc.name, description: doc.description, maps: doc.maps, mode: $('mode').value };
  if (doc.probabilities.length) body.probabilities = doc.probabilities;
  if (doc.colours.length) body.colours = doc.colours;
  if (doc.allow_expansive) body.allow_expansive = true;
  if (body.mode === 'steal') {
    body.source = $('source').value || 'sample';
    if (doc.colouring) body.colouring = doc.colouring;
  }
  if (view.framed) body.view = view.text();
  return body;
}

const pictureCanvas = document.createElement('canvas');
const renderer = new LiveRenderer({
  body: () => {
    const body = requestBody();
    if (doc.flame) body.quality = Math.min(doc.flame.quality, kFlamePreviewQuality);
    return body;
  },
  size: () => $('size').value.split('x').map(Number),
  stats,
  fail: (message) => status(message, true),
  show: (p) => {
    if (pictureCanvas.width !== p.width || pictureCanvas.height !== p.height) {
      pictureCanvas.width = p.width;
      pictureCanvas.height = p.height;
    }
    pictureCanvas.getContext('2d').putImageData(p.image, 0, 0);
    picture = { canvas: pictureCanvas, view: p.view, full: p.full };
    if (!view.framed) {  // the server framed the attractor: the frame and the view from now on
      view.rect = p.view.slice();
      if (doc.flame) flameView = p.view.slice();
      else {  // an IFS's maps are drawn on this frame (a flame's on the unit square)
        frameRect = p.view.slice();
        frame = frameOf(frameRect);
      }
      renderTables();
    }
    usedColouring = p.colouring;
    draw();
    if (steal()) source.draw();
    if (p.full) {
      const what = doc.flame
        ? `flame, ${doc.maps.length} xforms, quality ${Math.min(doc.flame.quality, kFlamePreviewQuality)} of its ${doc.flame.quality}`
        : `${doc.maps.length} maps; ${$('mode').value}`;
      status(`${doc.name}: ${what} ${p.width}x${p.height} rendered in ${p.renderMs} ms`);
    }
  },
});
// The stats the tests and bench/studio_latency.mjs read.
Object.defineProperty(stats, 'seq', { get: () => renderer.version });
stats.settled = () => renderer.settled();
stats.picture = () => (picture ? picture.canvas.toDataURL('image/png') : null);
stats.state = () => JSON.parse(JSON.stringify(doc));
stats.view = () => view.rect && view.rect.slice();
stats.handle = (i, kind = 'centre', corner = 0) =>
  handleClientPoint(surface, canvas, doc.maps[i], kind, corner);
stats.sourceHandle = (i, kind = 'centre', corner = 0) => source.handle(i, kind, corner);
// For the panels below the editor (panels.js, jobs.js, fit.js, video.js, superifs.js): the preset
// with the picture's settings, and opening a preset as one undoable edit.
stats.requestBody = () => JSON.parse(JSON.stringify(requestBody()));
stats.openPreset = (preset) => {
  pushUndo();
  open(preset);
};

// ---- the canvas: drag a handle, or pan (empty space, the middle button) and zoom (the wheel) ----

let gesture = null;

canvas.addEventListener('pointerdown', (event) => {
  if (!frame) return;
  const px = canvasPoint(canvas, event);
  const h = event.button === 0 ? hitHandle(surface, doc.maps, selected, px) : null;
  canvas.setPointerCapture(event.pointerId);
  if (h && h.kind === 'flip') {
    edit(() => { doc.maps[h.map] = flipped(doc.maps[h.map], frame); }, event.timeStamp);
    return;
  }
  if (h) {
    selected = h.map;
    gesture = Object.assign(h, { type: 'map', before: snapshot(), start: view.toPlane(px),
                                 m0: doc.maps[h.map].slice(), moved: false });
    refresh();
  } else if (event.button === 0 || event.button === 1) {
    event.preventDefault();
    gesture = { type: 'pan', last: px };
    canvas.classList.add('panning');
  }
});

function pointerMoved(event) {
  if (!gesture) return;
  const px = canvasPoint(canvas, event);
  if (gesture.type === 'pan') {
    view.panBy(px[0] - gesture.last[0], px[1] - gesture.last[1]);
    gesture.last = px;
    draw();
    renderer.changed(event.timeStamp, true);
    return;
  }
  const m = dragged(surface, gesture, gesture.m0, gesture.start, view.toPlane(px), event.shiftKey);
  if (!m) return;
  if (!gesture.moved) { pushUndo(gesture.before); gesture.moved = true; }
  doc.maps[gesture.map] = m;
  dragChanged(event.timeStamp, '', gesture.map, m);
}

// Chrome delivers pointerrawupdate as the pointer moves, pointermove only at the next animation
// frame (up to 16 ms later): a drag follows the first where there is one.
let rawUpdates = false;
canvas.addEventListener('pointerrawupdate', (event) => { rawUpdates = true; pointerMoved(event); });
canvas.addEventListener('pointermove', (event) => { if (!rawUpdates) pointerMoved(event); });

function endGesture() {
  if (!gesture) return;
  gesture = null;
  canvas.classList.remove('panning');
  renderer.rest();
  refresh();
}
canvas.addEventListener('pointerup', endGesture);
canvas.addEventListener('pointercancel', endGesture);
canvas.addEventListener('auxclick', (event) => event.preventDefault());

canvas.addEventListener('wheel', (event) => {
  if (!view.framed) return;
  event.preventDefault();
  const delta = event.deltaMode === 1 ? event.deltaY * 40 : event.deltaY;  // lines to pixels
  view.zoomAt(canvasPoint(canvas, event), Math.exp(-delta * 0.0015));
  draw();
  renderer.changed(event.timeStamp, true);
}, { passive: false });

// ---- colour stealing: the source and the colouring IFS on it ----

let sourceBefore = null;
const source = new SourcePanel($('source-canvas'), {
  maps: colouringShown,
  used: () => usedColouring,
  colour: colourOf,
  selected: () => selected,
  select: (i) => { selected = i; refresh(); },
  begin: () => {
    sourceBefore = snapshot();
    return JSON.parse(JSON.stringify(colouringShown()));
  },
  drag: (g, eventTime, i) => {
    doc.colouring = g;
    if (sourceBefore) {  // the first move: an undo step, and the table of the edited colouring
      pushUndo(sourceBefore);
      sourceBefore = null;
      renderTables();
    }
    dragChanged(eventTime, 'g', i, g[i]);
  },
  end: () => { sourceBefore = null; renderer.rest(); refresh(); },
  flip: (i) => edit(() => { ensureColouring()[i] = flipped(ensureColouring()[i], frameOf([0, 0, 1, 1])); }),
});

async function showSource() {
  if (!steal()) return;
  try {
    await source.load($('source').value || 'sample');
    $('source-size').textContent = source.sourceSize ? `${source.sourceSize} pixels` : '';
  } catch (e) { status(e.message, true); }
}

async function upload(file) {
  status(`uploading ${file.name}…`);
  try {
    const saved = await uploadImage(file);
    await listSources(saved);
    $('mode').value = 'steal';
    status(`${saved}: saved in the folder; it is the source now`);
    modeChanged();
  } catch (e) { status(e.message, true); }
}

// Save's name for a document: NAME.toml, or NAME.flame, as a plain name of the folder.
function saveName(name, flame) {
  const plain = (name || 'studio').replace(/[^A-Za-z0-9_.+ -]/g, '-').replace(/\.\.+/g, '.')
    .replace(/^[^A-Za-z0-9_]+/, '') || 'studio';
  const file = `${plain}.${flame ? 'flame' : 'toml'}`;
  return file === openedFile ? `${plain}-2.${flame ? 'flame' : 'toml'}` : file;
}

// A flame opens in measure mode, its look as flam3 renders it; its attractor, tops and steal
// draw its xforms through the chaos game. An IFS keeps the mode chosen.
function kindChanged(opened) {
  if (opened && doc.flame && $('mode').value !== 'measure') {
    $('mode').value = 'measure';
    $('source-label').hidden = true;
  }
}

function open(preset) {
  doc = { name: preset.name, description: preset.description || '', maps: preset.maps,
          probabilities: preset.probabilities || [], colours: preset.colours || [],
          colouring: preset.colouring || null, allow_expansive: Boolean(preset.allow_expansive),
          flame: preset.flame || null };
  selected = 0;
  view.rect = null;
  frameRect = doc.flame ? [0, 0, 1, 1] : null;
  frame = frameRect && frameOf(frameRect);
  picture = null;
  openedFile = preset.origin_file || null;
  $('file').value = saveName(preset.name, Boolean(doc.flame));
  if (preset.warnings && preset.warnings.length) status(preset.warnings.join('; '));
  kindChanged(true);
  changed();
}

async function openSelected() {
  const which = JSON.parse($('preset').value || '{}');
  $('preset').selectedIndex = 0;
  if (!which.initial && !which.name && !which.file) return;
  const query = which.initial ? '' : which.name ? `?name=${encodeURIComponent(which.name)}`
    : `?file=${encodeURIComponent(which.file)}` + (which.entry !== undefined ? `&entry=${encodeURIComponent(which.entry)}` : '');
  try {
    const preset = await getJson(`/api/preset${query}`);
    pushUndo();
    open(preset);
  } catch (e) { status(e.message, true); }
}

async function save() {
  const body = Object.assign(requestBody(), { file: $('file').value });
  if (doc.colouring) body.colouring = doc.colouring;
  try {
    const answer = await postJson('/api/save', body);
    status(`saved ${answer.saved}` + (answer.colouring ? ` and its colouring ${answer.colouring}` : ''));
    await listPresets();
  } catch (e) { status(e.message, true); }
}

function modeChanged() {
  $('source-label').hidden = !steal();
  refresh();
  showSource();
  renderer.changed();
}

async function start() {
  if (!token) { status('open the URL that `ifsfx studio` printed: it carries the token', true); return; }
  const [initial, s] = await Promise.all([getJson('/api/preset'), session()]);
  // An image given as --source is the source selected, not the sample.
  const given = s.source && s.source.kind === 'image' ? s.source.name : undefined;
  await Promise.all([listPresets(initial.name), listSources(given)]);
  $('preset').onchange = openSelected;
  $('mode').onchange = modeChanged;
  $('source').onchange = () => { showSource(); renderer.changed(); };
  $('size').onchange = () => {
    const [w, h] = $('size').value.split('x').map(Number);
    canvas.width = w;
    canvas.height = h;
    draw();
    renderer.changed();
  };
  $('reframe').onclick = () => {
    view.rect = null;
    if (!doc.flame) frame = frameRect = null;
    renderer.changed();
  };
  $('reset-view').onclick = () => {
    if (!frameRect) return;
    view.rect = doc.flame ? null : frameRect.slice();  // a flame: its camera's framing
    draw();
    renderer.changed();
  };
  $('undo').onclick = undo;
  $('redo').onclick = redo;
  $('add').onclick = add;
  $('save').onclick = save;
  $('reset-colouring').onclick = () => edit(() => { doc.colouring = null; });
  $('upload').onchange = () => { if ($('upload').files[0]) upload($('upload').files[0]); };
  document.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dropping'); });
  document.addEventListener('dragleave', () => document.body.classList.remove('dropping'));
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    document.body.classList.remove('dropping');
    const file = e.dataTransfer.files[0];
    if (file) upload(file);
  });
  $('source-label').hidden = true;
  loadVariations().catch((e) => status(e.message, true));
  open(initial);
}

document.addEventListener('keydown', (event) => {
  if (event.target.tagName === 'INPUT' || event.target.tagName === 'SELECT') return;
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
