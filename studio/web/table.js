// SPDX-License-Identifier: Apache-2.0
// The tables of maps: the IFS's (a–f, probability, colour, contraction factor, and buttons to
// reorder, duplicate, flip and delete) or a flame's (its xforms' pre-affine maps, weights and
// colour coordinates), and the colouring IFS's (a–f on the source's unit square).
import { factor } from './geometry.js';

const kFields = ['a', 'b', 'c', 'd', 'e', 'f'];

export const fmt = (x) => String(Number(Number(x).toPrecision(6)));

// A text field for a number (a number field's spinner would hide digits): onValue(number) when
// it changes to a finite number, restore() otherwise.
export function numberCell(name, value, placeholder, onValue, restore) {
  const td = document.createElement('td');
  const input = document.createElement('input');
  input.name = name;
  input.inputMode = 'decimal';
  input.value = value;
  if (placeholder) input.placeholder = placeholder;
  input.onchange = () => {
    const v = Number(input.value);
    if (input.value.trim() === '' || !Number.isFinite(v)) restore();
    else onValue(v);
  };
  td.appendChild(input);
  return td;
}

function headCell(i, colour, onSelect) {
  const td = document.createElement('td');
  td.className = 'index';
  const swatch = document.createElement('span');
  swatch.className = 'swatch';
  swatch.style.background = colour;
  td.append(swatch, ` ${i + 1}`);
  td.onclick = onSelect;
  return td;
}

// A flame's weight and colour coordinate cells (in place of p and the colour field): on.set(i, 6,
// weight), on.set(i, 7, colour in [0, 1]).
function flameCells(tr, xf, i, on) {
  tr.appendChild(numberCell(`w${i}`, fmt(xf.weight), '', (v) => on.set(i, 6, v), on.restore));
  const c = numberCell(`colour${i}`, fmt(xf.colour), '', (v) => on.set(i, 7, v), on.restore);
  c.firstChild.title = 'The colour coordinate, 0 to 1: where on the palette this xform draws';
  tr.appendChild(c);
}

// The IFS's table. doc: the document; on: {select(i), set(i, k, v) (k 0..5: a–f, 6: p),
// colour(i, '#rrggbb'), move(i, by), duplicate(i), flip(i), remove(i), restore()}. A flame's
// rows have its xforms' weights and colour coordinates instead (flameCells), and a factor that
// may be 1 or more (a flame's maps need not contract).
export function renderMapsTable(tbody, doc, selected, colourOf, on) {
  tbody.textContent = '';
  const n = doc.maps.length;
  doc.maps.forEach((m, i) => {
    const tr = document.createElement('tr');
    tr.dataset.map = i;
    if (i === selected) tr.className = 'selected';
    tr.appendChild(headCell(i, colourOf(i), () => on.select(i)));
    kFields.forEach((name, k) =>
      tr.appendChild(numberCell(`${name}${i}`, fmt(m[k]), '', (v) => on.set(i, k, v), on.restore)));
    if (doc.flame) flameCells(tr, doc.flame.xforms[i], i, on);
    else ifsCells(tr, doc, i, colourOf, on);
    const ftd = document.createElement('td');
    showFactor(ftd, m, !doc.flame);
    tr.appendChild(ftd);
    const actions = document.createElement('td');
    actions.className = 'actions';
    for (const [label, title, action] of [['↑', 'Move up (lower tops priority)', () => on.move(i, -1)],
                                          ['↓', 'Move down (higher tops priority)', () => on.move(i, 1)],
                                          ['+', 'Duplicate', () => on.duplicate(i)],
                                          ['⇋', 'Flip (mirror) left to right', () => on.flip(i)],
                                          ['✕', 'Delete', () => on.remove(i)]]) {
      const b = document.createElement('button');
      b.textContent = label;
      b.title = title;
      b.name = `${title.split(' ')[0].toLowerCase()}${i}`;
      b.onclick = action;
      actions.appendChild(b);
    }
    tr.appendChild(actions);
    tbody.appendChild(tr);
  });
}

// An IFS's probability and colour cells.
function ifsCells(tr, doc, i, colourOf, on) {
  const n = doc.maps.length;
  const p = doc.probabilities.length === n ? fmt(doc.probabilities[i]) : '';
  tr.appendChild(numberCell(`p${i}`, p, 'auto', (v) => on.set(i, 6, v), on.restore));
  const ctd = document.createElement('td');
  const colour = document.createElement('input');
  colour.type = 'color';
  colour.name = `colour${i}`;
  colour.value = colourOf(i);
  colour.title = doc.colours.length === n ? 'The colour of this map' : 'The default palette (pick one to set every map\'s colour)';
  colour.onchange = () => on.colour(i, colour.value);
  ctd.appendChild(colour);
  tr.appendChild(ctd);
}

// The contraction factor of map m in its cell, flagged at 1 or more where that matters (`warn`:
// an IFS's maps; a flame's need not contract).
function showFactor(cell, m, warn) {
  const s = factor(m);
  const flagged = warn && s >= 1;
  cell.className = flagged ? 'warn factor' : 'factor';
  cell.textContent = flagged ? `${s.toFixed(3)} ⚠ ≥ 1` : s.toFixed(3);
  cell.title = flagged ? 'This map does not contract: the IFS has no attractor unless it contracts on average' : '';
}

// Puts map i's current numbers into its row's fields (during a drag: no rebuilding the table);
// `warn`: flag a factor of 1 or more.
export function updateRow(tbody, prefix, i, m, warn = true) {
  kFields.forEach((name, k) => {
    const input = tbody.querySelector(`input[name="${prefix}${name}${i}"]`);
    if (input && document.activeElement !== input) input.value = fmt(m[k]);
  });
  const cell = tbody.querySelector(`tr[data-map="${i}"] td.factor`);
  if (cell) showFactor(cell, m, warn);
}

// The colouring IFS's table: maps on the source's unit square. on: {select(i), set(i, k, v),
// restore()}.
export function renderColouringTable(tbody, maps, selected, colourOf, on) {
  tbody.textContent = '';
  maps.forEach((m, i) => {
    const tr = document.createElement('tr');
    tr.dataset.map = i;
    if (i === selected) tr.className = 'selected';
    tr.appendChild(headCell(i, colourOf(i), () => on.select(i)));
    kFields.forEach((name, k) =>
      tr.appendChild(numberCell(`g${name}${i}`, fmt(m[k]), '', (v) => on.set(i, k, v), on.restore)));
    tbody.appendChild(tr);
  });
}
