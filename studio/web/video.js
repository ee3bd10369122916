// SPDX-License-Identifier: Apache-2.0
// Video (docs/studio.md): a movie of the folder (or --source) scrubbed frame by frame through the
// fractal filter of the editor's preset (the FractalEngine of `ifsfx filter`), played to preview
// the drift, filtered whole as a render job; and with --camera, the live filter on the camera.
import { el, json, blob, panel, say, show, editorRequest, session, fileUrl } from './panels.js';
import { startJob } from './jobs.js';

const body = panel('video', 'Video');
const movie = el('select', { id: 'video-movie' });
const slider = el('input', { id: 'video-frame', type: 'range', min: 0, max: 0, value: 0 });
const frameLabel = el('span', { id: 'video-frame-label' }, '–');
const play = el('button', { id: 'video-play' }, 'Play');
const prev = el('button', { id: 'video-prev', title: 'Previous frame' }, '◀');
const next = el('button', { id: 'video-next', title: 'Next frame' }, '▶');
const filterOn = el('input', { id: 'video-filter', type: 'checkbox', checked: true });
const drift = el('input', { id: 'video-drift', type: 'checkbox' });
const amount = el('input', { id: 'video-drift-amount', type: 'number', min: 0, max: 10,
                             step: 0.01, value: 0.05, size: 4 });
const speed = el('input', { id: 'video-drift-speed', type: 'number', min: 0, max: 100, step: 0.05,
                            value: 0.2, size: 4 });
const mix = el('input', { id: 'video-mix', type: 'range', min: 0, max: 1, step: 0.05, value: 0 });
const width = el('select', { id: 'video-width' },
                 [320, 480, 640, 960].map((w) => el('option', { selected: w === 640 }, String(w))));
const picture = el('img', { id: 'video-picture', alt: '' });
const status = el('p', { id: 'video-status', class: 'status' });
const outFile = el('input', { id: 'video-out', size: 18, value: 'filtered.mp4' });
const filterJob = el('button', { id: 'video-job' }, 'Filter the movie');
const jobStatus = el('span', { id: 'video-job-status', class: 'status' });
body.append(
  el('div', { class: 'row' }, el('label', {}, 'Movie ', movie), prev, slider, next, frameLabel,
     play),
  el('div', { class: 'row' },
     el('label', {}, filterOn, ' filter'), el('label', {}, drift, ' drift'),
     el('label', {}, 'amount ', amount), el('label', {}, 'speed (Hz) ', speed),
     el('label', {}, 'mix ', mix), el('label', {}, 'width ', width)),
  picture, status,
  el('div', { class: 'row' }, el('label', {}, 'Filter all frames into ', outFile), filterJob,
     jobStatus));

const CAMERA = '\u0001camera';  // the select's value for the camera
let info = null;      // {movie, frames, fps, width, height}
let playing = false;
let inFlight = null;  // the request being answered
let wanted = null;    // the frame to show once it is answered
let lastSent = '';
const stats = { frames: 0, errors: 0, shown: -1 };
window.studioVideo = stats;

function settings() {
  // The preset of the editor; its picture's mode, size, view and source are not the filter's
  // (the filter frames the attractor on the movie's frame, as `ifsfx filter` does).
  const request = editorRequest() || {};
  for (const field of ['mode', 'size', 'view', 'source']) delete request[field];
  return Object.assign(request, {
    filter: filterOn.checked, animate: drift.checked ? 'drift' : 'none',
    drift_amount: Number(amount.value), drift_speed: Number(speed.value), mix: Number(mix.value),
    width: Number(width.value),
  });
}

// Asks for the frame the page wants; one request at a time, the newest wish wins.
async function request(frame) {
  wanted = frame;
  if (inFlight) return inFlight;
  inFlight = (async () => {
    while (wanted !== null) {
      const k = wanted;
      wanted = null;
      const body = settings();
      const camera = movie.value === CAMERA;
      if (!camera) Object.assign(body, { movie: movie.value, frame: k });
      lastSent = key(body);
      const started = performance.now();
      try {
        const { blob: b } = await blob(camera ? '/api/camera/frame' : '/api/video/frame',
                                       { method: 'POST', body });
        const old = picture.src;
        picture.style.width = `${body.width}px`;  // small movies shown at the preview's width
        picture.src = URL.createObjectURL(b);
        if (old) URL.revokeObjectURL(old);
        stats.frames++;
        stats.shown = camera ? -1 : k;
        say(status, camera ? `camera: ${Math.round(performance.now() - started)} ms`
          : `frame ${k} of ${info.frames} in ${Math.round(performance.now() - started)} ms`);
      } catch (e) {
        if (e.status === 409) continue;  // newer settings took over
        stats.errors++;
        say(status, e.message, true);
        stopPlaying();
      }
    }
    inFlight = null;
  })();
  return inFlight;
}

const key = (body) => JSON.stringify(body);

function setFrame(k) {
  if (!info) return;
  k = Math.max(0, Math.min(info.frames - 1, k));
  slider.value = k;
  frameLabel.textContent = `${k} / ${info.frames - 1}`;
  return request(k);
}

async function openMovie(name) {
  stopPlaying();
  if (name === CAMERA) {
    info = null;
    slider.disabled = prev.disabled = next.disabled = true;
    frameLabel.textContent = 'live';
    return;
  }
  try {
    info = await json(`/api/video/info?movie=${encodeURIComponent(name)}`);
    slider.disabled = prev.disabled = next.disabled = false;
    slider.max = Math.max(0, info.frames - 1);
    const stem = name.replace(/^@/, '').replace(/\.[^.]*$/, '');
    outFile.value = `${stem}-filtered.mp4`;
    await setFrame(0);
  } catch (e) {
    say(status, e.message, true);
  }
}

// Playing: the next frame once the last is shown, no faster than the movie's rate (the camera:
// about ten frames a second).
async function loop() {
  while (playing) {
    const t0 = performance.now();
    if (movie.value === CAMERA) {
      await request(0);
    } else {
      const k = Number(slider.value) + 1;
      if (k >= info.frames) { stopPlaying(); break; }
      await setFrame(k);
    }
    const period = movie.value === CAMERA ? 100 : 1000 / (info ? info.fps || 25 : 25);
    await new Promise((r) => setTimeout(r, Math.max(0, period - (performance.now() - t0))));
  }
}

function stopPlaying() {
  if (playing && movie.value === CAMERA) json('/api/camera/stop', { method: 'POST', body: {} })
    .catch(() => {});
  playing = false;
  play.textContent = 'Play';
}

play.onclick = () => {
  if (playing) { stopPlaying(); return; }
  if (movie.value !== CAMERA && !info) return;
  if (movie.value !== CAMERA && Number(slider.value) >= info.frames - 1) setFrame(0);
  playing = true;
  play.textContent = 'Pause';
  loop();
};
slider.oninput = () => setFrame(Number(slider.value));
prev.onclick = () => setFrame(Number(slider.value) - 1);
next.onclick = () => setFrame(Number(slider.value) + 1);
movie.onchange = () => openMovie(movie.value);
for (const input of [filterOn, drift, amount, speed, mix, width])
  input.onchange = () => !playing && info && setFrame(Number(slider.value));

filterJob.onclick = async () => {
  if (!info) { say(jobStatus, 'open a movie first', true); return; }
  const request = Object.assign(settings(), { kind: 'filter', movie: movie.value,
                                              file: outFile.value });
  try {
    const job = await startJob(request, {
      onUpdate: (j) => {
        const pct = j.progress === null ? '' : ` ${Math.round(100 * j.progress)}%`;
        say(jobStatus, `job ${j.id}: ${j.state}${pct} ${j.detail}`, j.state === 'failed');
        jobStatus.replaceChildren(jobStatus.textContent, ...j.files.map(
          (f) => el('a', { href: fileUrl(f), target: '_blank' }, ` ${f}`)));
      },
    });
    say(jobStatus, `job ${job.id} started`);
  } catch (e) {
    say(jobStatus, e.message, true);
  }
};

// The editor's preset changed while a frame is shown: show it through the new preset.
setInterval(() => {
  if (playing || body.hidden || inFlight || (!info && movie.value !== CAMERA)) return;
  const body2 = settings();
  if (movie.value !== CAMERA) Object.assign(body2, { movie: movie.value, frame: Number(slider.value) });
  if (key(body2) !== lastSent && movie.value !== CAMERA) request(Number(slider.value));
}, 400);

(async () => {
  try {
    const [movies, s] = await Promise.all([json('/api/movies'), session()]);
    for (const m of movies) movie.append(el('option', { value: m }, m === '@source' ? `${s.source.file} (--source)` : m));
    if (s.camera) movie.append(el('option', { value: CAMERA }, `camera ${s.camera}`));
    if (!movies.length && !s.camera) say(status, 'no movie in the folder (.mp4, .mkv, .mov, ...)');
    // Opened when first shown (or at once for a --source movie): no work before it is looked at.
    let opened = false;
    const first = () => { if (!opened && movie.options.length) { opened = true; openMovie(movie.value); } };
    document.getElementById('tab-video').addEventListener('click', first);
    if (s.source && s.source.kind === 'movie') { show('video'); first(); }
  } catch (e) {
    say(status, e.message, true);
  }
})();
