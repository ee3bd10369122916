// SPDX-License-Identifier: Apache-2.0
// The tables of maps: the IFS's (a–f, probability, colour, contraction factor, and buttons to
// reorder, duplicate, flip and delete) and the colouring IFS's (a–f on the source's unit square).
import { factor } from './geometry.js';

const kFields = ['a', 'b', 'c', 'd', 'e', 'f'];

export const fmt = (x) => String(Number(Number(x).toPrecision(6)));

// A text field for a number (a number field's spinner would hide digits): onValue(number) when
// it changes to a finite number, restore() otherwise.
function numberCell(name, value, placeholder, onValue, restore) {
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

// The IFS's table. doc: the document; on: {select(i), set(i, k, v) (k 0..5: a–f, 6: p),
// colour(i, '#rrggbb'), move(i, by), duplicate(i), flip(i), remove(i), restore()}.
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
    const s = factor(m);
    const ftd = document.createElement('td');
    ftd.className = s >= 1 ? 'warn factor' : 'factor';
    ftd.textContent = s >= 1 ? `${s.toFixed(3)} ⚠ ≥ 1` : s.toFixed(3);
    if (s >= 1) ftd.title = 'This map does not contract: the IFS has no attractor unless it contracts on average';
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

// Puts map i's current numbers into its row's fields (during a drag: no rebuilding the table).
export function updateRow(tbody, prefix, i, m) {
  kFields.forEach((name, k) => {
    const input = tbody.querySelector(`input[name="${prefix}${name}${i}"]`);
    if (input && document.activeElement !== input) input.value = fmt(m[k]);
  });
  const cell = tbody.querySelector(`tr[data-map="${i}"] td.factor`);
  if (cell) {
    const s = factor(m);
    cell.className = s >= 1 ? 'warn factor' : 'factor';
    cell.textContent = s >= 1 ? `${s.toFixed(3)} ⚠ ≥ 1` : s.toFixed(3);
  }
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
