// SPDX-License-Identifier: Apache-2.0
// What the panels below the editor share (jobs.js, fit.js, video.js, superifs.js;
// docs/studio.md): requests through api.js (the token and this tab's id: a newer preview of this
// tab replaces its older one on the server, other tabs are untouched) with their errors turned
// into exceptions, the panel tabs, and the editor's preset (window.studio.requestBody(), set by
// studio.js).
import { api as fetchApi } from './api.js';

// fetch() through api.js; `body` as JSON unless it is a Blob or File (an upload).
export function api(path, { method = 'GET', body, signal } = {}) {
  const options = { method, signal };
  if (body instanceof Blob) {
    options.body = body;
    options.headers = { 'Content-Type': body.type || 'application/octet-stream' };
  } else if (body !== undefined) {
    options.body = JSON.stringify(body);
  }
  return fetchApi(path, options);
}

// The answer's JSON, or an Error carrying the server's message and status.
export async function json(path, options = {}) {
  const res = await api(path, options);
  const body = await res.json().catch(() => ({ error: `HTTP ${res.status}` }));
  if (!res.ok) throw Object.assign(new Error(body.error || `HTTP ${res.status}`), { status: res.status });
  return body;
}

// The answer as a Blob (a picture), or an Error with the server's message (409: superseded).
export async function blob(path, options = {}) {
  const res = await api(path, options);
  if (!res.ok) {
    const body = await res.json().catch(() => ({ error: `HTTP ${res.status}` }));
    throw Object.assign(new Error(body.error || `HTTP ${res.status}`), { status: res.status });
  }
  return { blob: await res.blob(), headers: res.headers };
}

// A link to a file of the folder.
export const fileUrl = (name) => `/api/file?name=${encodeURIComponent(name)}`;

// document.createElement with attributes, properties (on*, value, ...) and children.
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k.startsWith('on') || k === 'value' || k === 'checked' || k === 'disabled') node[k] = v;
    else if (v !== undefined && v !== null && v !== false) node.setAttribute(k, v === true ? '' : v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) node.append(c);
  return node;
}

// The editor's preset and render settings ({name, maps, ..., mode, size, view, source}).
export function editorRequest() {
  return window.studio && window.studio.requestBody ? window.studio.requestBody() : null;
}

// Opens a preset in the editor (an undoable edit).
export function openInEditor(preset) {
  if (window.studio && window.studio.openPreset) window.studio.openPreset(preset);
}

// A status line: text, red when `error`.
export function say(node, text, error = false) {
  node.textContent = text;
  node.classList.toggle('error', error);
}

// ---- the panels below the editor: one tab each ----

const tabs = new Map();

function extras() {
  let root = document.getElementById('extras');
  if (!root) {
    root = el('section', { id: 'extras' });
    document.body.append(root);
  }
  if (!root.querySelector('.tabs')) root.append(el('nav', { class: 'tabs', role: 'tablist' }));
  return root;
}

// A panel with a tab; returns its body. The first panel is shown.
export function panel(id, title) {
  const root = extras();
  const body = el('div', { class: 'panel', id: `panel-${id}`, role: 'tabpanel' });
  const tab = el('button', { class: 'tab', id: `tab-${id}`, role: 'tab', onclick: () => show(id) },
                 title);
  root.querySelector('.tabs').append(tab);
  root.append(body);
  tabs.set(id, { tab, body });
  if (tabs.size === 1) show(id);
  else body.hidden = true;
  return body;
}

export function show(id) {
  for (const [key, { tab, body }] of tabs) {
    body.hidden = key !== id;
    tab.classList.toggle('active', key === id);
    tab.setAttribute('aria-selected', key === id ? 'true' : 'false');
  }
}

// The session: {source: {name, file, kind} | null, camera: DEVICE | null, upload_limit}.
let sessionPromise = null;
export function session() {
  if (!sessionPromise) sessionPromise = json('/api/session');
  return sessionPromise;
}
