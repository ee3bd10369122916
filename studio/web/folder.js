// SPDX-License-Identifier: Apache-2.0
// What the folder offers the page (docs/studio.md, "Presets" and "Colour stealing"): the Open
// menu (shipped presets, the folder's .toml files, Fractint entries and flames, the unusable ones listed
// with their reason), the sources, and images dropped on the page, saved in the folder.
import { $, api, getJson } from './api.js';

export const kMaxUpload = 32 << 20;  // the server's cap (studio/folder.h)

// A name the server takes (plain: letters, digits, `_ . + -`, spaces) for a dropped file.
export function sanitisedName(name) {
  const plain = name.replace(/[^A-Za-z0-9_.+ -]/g, '-').replace(/\.\.+/g, '.').replace(/^[^A-Za-z0-9_]+/, '');
  return plain || 'dropped.png';
}

// Saves `file` in the folder; returns the name it was saved under, or throws the server's message.
export async function uploadImage(file) {
  if (file.size > kMaxUpload)
    throw new Error(`${file.name}: at most ${kMaxUpload >> 20} MiB (got ${file.size} bytes)`);
  const res = await api(`/api/upload?name=${encodeURIComponent(sanitisedName(file.name))}`, {
    method: 'POST', body: file, headers: { 'Content-Type': 'application/octet-stream' },
  });
  const answer = await res.json();
  if (!res.ok) throw new Error(answer.error);
  return answer.saved;
}

function option(text, value, title = '') {
  const o = document.createElement('option');
  o.textContent = text;
  o.value = JSON.stringify(value);
  if (title) o.title = title;
  return o;
}

// Fills the Open menu (its value: the JSON of {initial}, {name} or {file, entry}) and the list of
// unusable presets.
export async function listPresets(initialName) {
  const [shipped, folder] = await Promise.all([getJson('/api/presets'), getJson('/api/folder')]);
  const select = $('preset');
  const first = select.querySelector('option[data-initial]');
  select.textContent = '';
  // A menu rather than a state: it shows "Open a preset…" again after each choice.
  select.appendChild(Object.assign(option('Open a preset…', {}), { selected: true }));
  const initial = first || option(`${initialName} (command line)`, { initial: true });
  initial.dataset.initial = '';
  select.appendChild(initial);
  const group = (label) => {
    const g = document.createElement('optgroup');
    g.label = label;
    select.appendChild(g);
    return g;
  };
  const s = group('Shipped');
  for (const p of shipped) s.appendChild(option(`${p.name} (${p.maps} maps)`, { name: p.name }, p.description));
  const f = group('Folder');
  const unusable = [];
  for (const p of folder) {
    // A flame as FILE.flame:NAME (as `ifsfx render` names it), a Fractint entry as FILE: NAME.
    const label = p.flame ? `${p.file}:${p.entry}` : p.entry !== undefined ? `${p.file}: ${p.entry}` : p.file;
    const o = option(p.problem ? `${label} — unusable` : `${label} (${p.maps} ${p.flame ? 'xforms' : 'maps'})`,
                     { file: p.file, entry: p.entry }, p.problem || p.description);
    o.disabled = Boolean(p.problem);
    f.appendChild(o);
    if (p.problem) unusable.push([label, p.problem]);
  }
  if (!folder.length) f.appendChild(Object.assign(option('(no .toml, .ifs or .flame file)', {}), { disabled: true }));
  const list = $('unusable-list');
  list.textContent = '';
  for (const [label, problem] of unusable) {
    const li = document.createElement('li');
    const b = document.createElement('b');
    b.textContent = label;
    li.append(b, `: ${problem}`);
    list.appendChild(li);
  }
  $('unusable').hidden = !unusable.length;
  $('unusable-count').textContent = `${unusable.length} unusable preset${unusable.length === 1 ? '' : 's'} in the folder`;
}

// Fills the Source menu, choosing `choose` (or keeping the choice) when it is there.
export async function listSources(choose) {
  const sources = await getJson('/api/sources');
  const select = $('source');
  const keep = choose || select.value;
  select.textContent = '';
  for (const s of sources) {
    const o = document.createElement('option');
    o.value = o.textContent = s;
    select.appendChild(o);
  }
  if (keep && sources.includes(keep)) select.value = keep;
}
