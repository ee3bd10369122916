// SPDX-License-Identifier: Apache-2.0
// Fit (docs/studio.md): a shape dropped on the zone (or chosen) is fitted by the collage theorem
// in a render job, as `ifsfx fit` fits it; the phase and the best IoU so far show while it runs,
// it can be cancelled, and the fitted preset opens in the editor.
import { api, el, panel, say, openInEditor, session } from './panels.js';
import { startJob, cancelJob } from './jobs.js';

const body = panel('fit', 'Fit');
const maps = el('input', { id: 'fit-maps', type: 'number', min: 1, max: 32, value: 4, size: 3 });
const seconds = el('input', { id: 'fit-seconds', type: 'number', min: 0.5, max: 600, step: 0.5,
                              value: 5, size: 4 });
const raster = el('select', { id: 'fit-size' },
                  [64, 96, 128, 192, 256].map((s) => el('option', { selected: s === 128 }, String(s))));
const chooser = el('input', { id: 'fit-file', type: 'file', accept: 'image/*' });
const zone = el('div', { id: 'fit-drop', class: 'drop' }, 'Drop a shape here (dark on light, or',
                ' with alpha) — or choose one: ', chooser);
const thumb = el('img', { id: 'fit-target', alt: '' });
const bar = el('progress', { id: 'fit-progress', max: 1, value: 0 });
const phase = el('span', { id: 'fit-phase' });
const cancel = el('button', { id: 'fit-cancel', disabled: true }, 'Cancel');
const preview = el('img', { id: 'fit-preview', alt: '' });
const report = el('p', { id: 'fit-report', class: 'status' });
const openButton = el('button', { id: 'fit-open', disabled: true }, 'Open in editor');
body.append(
  el('div', { class: 'row' },
     el('label', {}, 'Maps ', maps), el('label', {}, 'Budget (s) ', seconds),
     el('label', {}, 'Working raster ', raster)),
  zone,
  el('div', { class: 'row' }, thumb, el('div', {}, el('div', { class: 'row' }, bar, phase, cancel),
                                          preview, report, openButton)));

let current = null;  // the fit job running
let result = null;   // its preset

async function fit(file) {
  const limit = (await session()).upload_limit;
  if (file.size > limit) {
    say(report, `${file.name}: at most ${limit} bytes (got ${file.size})`, true);
    return;
  }
  thumb.src = URL.createObjectURL(file);
  preview.removeAttribute('src');
  openButton.disabled = true;
  result = null;
  bar.value = 0;
  const query = new URLSearchParams({ maps: maps.value, seconds: seconds.value,
                                      size: raster.value, name: file.name });
  try {
    const job = await startJob(file, { path: `/api/fit?${query}`, onUpdate: update });
    current = job.id;
    cancel.disabled = false;
    say(report, `fitting ${file.name}: ${maps.value} maps, ${seconds.value} s`);
  } catch (e) {
    say(report, e.message, true);
  }
}

function update(job) {
  if (job.id !== current) return;
  if (job.progress !== null) bar.value = job.progress;
  const iou = job.result && job.result.best_iou !== undefined ? job.result.best_iou : 0;
  phase.textContent = `${job.phase} · best IoU ${iou.toFixed(3)}`;
  phase.dataset.iou = iou;
  if (job.state === 'running' || job.state === 'queued') return;
  cancel.disabled = true;
  if (job.state !== 'done') {
    say(report, job.error || job.state, job.state === 'failed');
    return;
  }
  const r = job.result;
  result = r.preset;
  say(report, `IoU ${r.iou.toFixed(3)}, contraction ${r.contraction.toFixed(3)}, ` +
              `${r.runs} runs in ${r.seconds.toFixed(1)} s${r.time_capped ? ' (budget reached)' : ''}`);
  showPreview(job.id);
  openButton.disabled = false;
  openInEditor(result);  // the fitted maps, ready to edit (Ctrl-Z goes back)
}

async function showPreview(id) {
  const res = await api(`/api/jobs/${id}/preview`);
  if (res.ok) preview.src = URL.createObjectURL(await res.blob());
}

cancel.onclick = () => current && cancelJob(current);
openButton.onclick = () => result && openInEditor(result);
chooser.onchange = () => chooser.files[0] && fit(chooser.files[0]);
// A drop here is a shape to fit, not the editor's new source (the page's own drop target).
zone.addEventListener('dragover', (e) => {
  e.preventDefault();
  e.stopPropagation();
  zone.classList.add('over');
});
zone.addEventListener('dragleave', () => zone.classList.remove('over'));
zone.addEventListener('drop', (e) => {
  e.preventDefault();
  e.stopPropagation();
  zone.classList.remove('over');
  const file = [...e.dataTransfer.files].find((f) => f.type.startsWith('image/'));
  if (file) fit(file);
  else say(report, 'drop an image file (PNG, JPEG, ...)', true);
});

// For scripts and tests: fit the image at `url` as if dropped.
window.studioFit = async (url, name = 'shape.png') => {
  const b = await (await fetch(url)).blob();
  await fit(new File([b], name, { type: b.type || 'image/png' }));
};
