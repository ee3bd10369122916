// SPDX-License-Identifier: Apache-2.0
// A fractal flame in the editor (docs/studio.md, "Flames"): the document's flame part (its
// xforms beside the maps, which are their pre-affine maps; the camera, palette and tone as the
// file says them, studio/flame_doc.h), the palette strip, the selected xform's variations table,
// and what reordering, duplicating and deleting maps do to the xaos rows.
import { getJson, status } from './api.js';
import { fmt, numberCell } from './table.js';

let registry = null;  // [{name, params: [{name, default}], pre_only}]: GET /api/flame/variations

export async function loadVariations() {
  if (!registry) registry = await getJson('/api/flame/variations');
  return registry;
}

// The palette entry a colour coordinate c ∈ [0, 1] reads (flame/flame.h's step mode; the linear
// mode's blend is the renderer's), as CSS.
export function paletteColour(flame, c) {
  const k = Math.max(0, Math.min(255, Math.floor(c * 256)));
  const [r, g, b] = flame.palette.colours[k].map((v) => Math.round(Math.max(0, Math.min(1, v)) * 255));
  return `rgb(${r}, ${g}, ${b})`;
}

// The palette as a strip, each xform's colour marked under it (the selected one taller).
export function drawPalette(canvas, flame, selected) {
  const ctx = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height, strip = h - 8;
  ctx.clearRect(0, 0, w, h);
  for (let k = 0; k < 256; k++) {
    ctx.fillStyle = paletteColour(flame, (k + 0.5) / 256);
    ctx.fillRect(Math.floor(k * w / 256), 0, Math.ceil(w / 256), strip);
  }
  flame.xforms.forEach((xf, i) => {
    const x = Math.max(0, Math.min(1, xf.colour)) * (w - 1);
    ctx.fillStyle = i === selected ? '#fff' : '#999';
    ctx.fillRect(x - (i === selected ? 1.5 : 0.5), strip, i === selected ? 3 : 1, i === selected ? 8 : 5);
  });
}

// A new xform for a new map: linear, half the weight, the palette's start.
export const newXform = () => ({ name: '', weight: 0.5, colour: 0, colour_speed: 0.5, opacity: 1,
                                 chaos: [], post: null, pre_variations: [], post_variations: [],
                                 variations: [{ name: 'linear', weight: 1, params: {} }] });

// The xaos rows (chaos[j]: xform j's weight after this one; missing entries are 1) follow the
// xforms when maps are reordered (swap i, j), duplicated (i copied to i + 1) or deleted (i).
export function chaosSwap(xforms, i, j) {
  for (const xf of xforms) {
    if (xf.chaos.length <= Math.max(i, j)) continue;
    [xf.chaos[i], xf.chaos[j]] = [xf.chaos[j], xf.chaos[i]];
  }
}
export function chaosDuplicate(xforms, i) {
  for (const xf of xforms) if (xf.chaos.length > i) xf.chaos.splice(i + 1, 0, xf.chaos[i]);
}
export function chaosRemove(xforms, i) {
  for (const xf of xforms) if (xf.chaos.length > i) xf.chaos.splice(i, 1);
}

const kLists = [['pre_variations', 'pre_'], ['variations', ''], ['post_variations', 'post_']];

function termRow(term, list, prefix, k, on) {
  const tr = document.createElement('tr');
  const name = document.createElement('td');
  name.className = 'variation';
  name.textContent = `${prefix}${term.name}`;
  tr.appendChild(name);
  tr.appendChild(numberCell(`vw-${list}-${k}`, fmt(term.weight), '', (v) => on.set(list, k, null, v), on.restore));
  const params = document.createElement('td');
  params.className = 'params';
  const spec = registry.find((v) => v.name === term.name);
  for (const p of spec ? spec.params : []) {
    const label = document.createElement('label');
    label.textContent = p.name.startsWith(`${term.name}_`) ? p.name.slice(term.name.length + 1) : p.name;
    const value = p.name in term.params ? term.params[p.name] : p.default;
    const cell = numberCell(`vp-${list}-${k}-${p.name}`, fmt(value), '', (v) => on.set(list, k, p.name, v), on.restore);
    label.appendChild(cell.firstChild);
    params.appendChild(label);
  }
  tr.appendChild(params);
  const del = document.createElement('td');
  const b = document.createElement('button');
  b.textContent = '✕';
  b.title = 'Remove this variation';
  b.name = `vdel-${list}-${k}`;
  b.onclick = () => on.remove(list, k);
  del.appendChild(b);
  tr.appendChild(del);
  return tr;
}

// The selected xform's panel: its colour speed and opacity, its variations (the pre_ ones, the
// sum, the post_ ones) with their weights and parameters, and a menu to add one. on: {set(list,
// k, param | null, v), remove(list, k), add(name), field(key, v), restore()}.
export function renderFlamePanel(doc, selected, on) {
  const $ = (id) => document.getElementById(id);
  const xf = doc.flame.xforms[selected];
  $('xform-title').textContent = `xform ${selected + 1}${xf.name ? ` (${xf.name})` : ''}`;
  for (const [id, key] of [['colour-speed', 'colour_speed'], ['opacity', 'opacity']]) {
    const input = $(id);
    if (document.activeElement !== input) input.value = fmt(xf[key]);
    input.onchange = () => {
      const v = Number(input.value);
      if (input.value.trim() === '' || !Number.isFinite(v)) on.restore(); else on.field(key, v);
    };
  }
  if (!registry) { loadVariations().then(on.restore).catch((e) => status(e.message, true)); return; }
  const tbody = document.querySelector('#variations tbody');
  tbody.textContent = '';
  for (const [list, prefix] of kLists)
    xf[list].forEach((term, k) => tbody.appendChild(termRow(term, list, prefix, k, on)));
  const select = $('add-variation');
  select.textContent = '';
  select.appendChild(Object.assign(document.createElement('option'), { textContent: 'Add a variation…', value: '' }));
  for (const v of registry) {
    const list = v.pre_only ? 'pre_variations' : 'variations';
    const o = Object.assign(document.createElement('option'), { textContent: v.name, value: v.name });
    o.disabled = xf[list].some((t) => t.name === v.name);  // a flame file holds one of each
    select.appendChild(o);
  }
  select.onchange = () => { if (select.value) on.add(select.value); };
}

// The list a new variation `name` goes in: the pre_ list for those that only stand there.
export const listFor = (name) => (registry.find((v) => v.name === name) || {}).pre_only ? 'pre_variations' : 'variations';
