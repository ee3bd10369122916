// SPDX-License-Identifier: Apache-2.0
// Render jobs (docs/studio.md): a full-size still of the editor's preset, and the list of every
// job of the server — the movie filter and texture sequences started from the Video and SuperIFS
// panels, fits — with progress bars, cancel buttons and links to the files made.
import { el, json, fileUrl, panel, say, editorRequest, openInEditor } from './panels.js';

const body = panel('jobs', 'Jobs');
const status = el('p', { class: 'status', id: 'jobs-status' });
const stillFile = el('input', { id: 'still-file', size: 18, value: 'still.png',
                                title: 'In the folder: .png, .tif, .exr or .jpg' });
const stillSize = el('input', { id: 'still-size', size: 10, value: '2048x2048', list: 'still-sizes',
                                title: 'WxH, at most 4096x4096' });
const sizes = el('datalist', { id: 'still-sizes' },
                 ['1024x1024', '2048x2048', '4096x4096', '1920x1080', '3840x2160'].map(
                   (s) => el('option', { value: s })));
const stillButton = el('button', { id: 'still-export', onclick: () => exportStill() },
                       'Export still');
const list = el('table', { id: 'jobs', class: 'jobs' },
                el('thead', {}, el('tr', {}, ['#', 'job', 'state', 'progress', '', 'files', ''].map(
                  (h) => el('th', {}, h)))),
                el('tbody'));
body.append(
  el('div', { class: 'row' },
     el('label', {}, 'Still ', stillFile), el('label', {}, 'size ', stillSize, sizes), stillButton,
     el('span', { class: 'help' },
        'the editor\'s preset, mode and view at full size, as `ifsfx render` writes it')),
  list, status);

const listeners = new Map();  // job id → callbacks(job) of the panels that started it
let timer = null;

// Starts a job (POST /api/jobs, or another path such as /api/fit) and watches it: `onUpdate(job)`
// on every change until it ends. Returns the job; throws the server's error.
export async function startJob(request, { path = '/api/jobs', onUpdate } = {}) {
  const job = await json(path, { method: 'POST', body: request });
  if (onUpdate) listeners.set(job.id, onUpdate);
  refresh();
  return job;
}

export async function cancelJob(id) {
  await json(`/api/jobs/${id}/cancel`, { method: 'POST', body: {} });
  refresh();
}

async function exportStill() {
  const request = editorRequest();
  if (!request) return;
  // The editor's view, so that the still shows what the canvas shows, widened about its centre
  // to the still's shape (a view of another shape would be stretched).
  Object.assign(request, { kind: 'still', file: stillFile.value, size: stillSize.value });
  const [w, h] = stillSize.value.split('x').map(Number);
  if (request.view && w > 0 && h > 0) {
    const [x0, y0, x1, y1] = request.view.split(',').map(Number);
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    let hw = (x1 - x0) / 2, hh = (y1 - y0) / 2;
    if (hw / hh < w / h) hw = hh * w / h; else hh = hw * h / w;
    if (Math.abs(hw * 2 - (x1 - x0)) > 1e-12 || Math.abs(hh * 2 - (y1 - y0)) > 1e-12)
      request.view = [cx - hw, cy - hh, cx + hw, cy + hh].join(',');
  }
  try {
    const job = await startJob(request);
    say(status, `job ${job.id}: ${job.title} started`);
  } catch (e) {
    say(status, e.message, true);
  }
}

// A job's row; rebuilt only when its state, files or result change, so that its buttons stay
// put while its progress moves (updated in place).
const rows = new Map();  // id → {tr, signature, bar, detail}

function detailOf(job) {
  const detail = job.state === 'failed' || job.state === 'cancelled' ? job.error || job.detail
    : job.detail;
  return `${job.phase}${detail ? ` · ${detail}` : ''}`;
}

function row(job) {
  const signature = JSON.stringify([job.state, job.files, Boolean(job.result && job.result.preset)]);
  const known = rows.get(job.id);
  if (known && known.signature === signature) {
    if (job.progress !== null) known.bar.value = job.progress;
    known.detail.textContent = detailOf(job);
    return known.tr;
  }
  const pending = job.state === 'queued' || job.state === 'running';
  const bar = el('progress', { max: 1 });
  if (job.progress !== null) bar.value = job.progress;  // no value: an indeterminate bar
  const files = el('td', { class: 'files' },
                   job.files.map((f) => el('a', { href: fileUrl(f), target: '_blank' }, f)));
  const actions = el('td');
  if (pending)
    actions.append(el('button', { class: 'cancel', onclick: () => cancelJob(job.id) }, 'Cancel'));
  if (job.kind === 'fit' && job.result && job.result.preset)
    actions.append(el('button', { class: 'open', onclick: () => openInEditor(job.result.preset) },
                      'Open'));
  const detail = el('td', { class: 'detail' }, detailOf(job));
  const tr = el('tr', { 'data-job': job.id, class: `job ${job.state}` },
                el('td', {}, String(job.id)),
                el('td', {}, `${job.kind}: ${job.title}`),
                el('td', { class: 'state' }, job.state),
                el('td', {}, bar), detail, files, actions);
  if (known) known.tr.replaceWith(tr);
  rows.set(job.id, { tr, signature, bar, detail });
  return tr;
}

let last = '';
async function refresh() {
  clearTimeout(timer);
  let pending = false;
  try {
    const { jobs } = await json('/api/jobs');
    pending = jobs.some((j) => j.state === 'queued' || j.state === 'running');
    const text = JSON.stringify(jobs);
    if (text !== last) {
      last = text;
      const tbody = list.querySelector('tbody');
      const shown = jobs.map(row);
      for (const [id, r] of rows)
        if (!jobs.some((j) => j.id === id)) { r.tr.remove(); rows.delete(id); }
      // Newest first; a row is moved only when the order differs.
      shown.forEach((tr, i) => { if (tbody.children[i] !== tr) tbody.insertBefore(tr, tbody.children[i] || null); });
      for (const job of jobs) {
        const callback = listeners.get(job.id);
        if (callback) {
          callback(job);
          if (job.state !== 'queued' && job.state !== 'running') listeners.delete(job.id);
        }
      }
    }
  } catch (e) {
    say(status, e.message, true);
  }
  // Quick while a job runs; slowly otherwise, to see the jobs other tabs start.
  timer = setTimeout(refresh, pending || listeners.size ? 300 : 3000);
}

refresh();
