// SPDX-License-Identifier: Apache-2.0
// SuperIFS (docs/studio.md): a superIFS preset opened, each of its IFSs edited (numbers here, or
// with the handles of the editor: "Edit in editor" and "Take from editor"), V changed, and its
// V-variable texture sequence stepped and played (the server renders texture k of
// superifs::TextureSequence); saved as .super.toml, or rendered as a texture-sequence job.
import { el, json, blob, panel, say, openInEditor, fileUrl } from './panels.js';
import { startJob } from './jobs.js';

const body = panel('superifs', 'SuperIFS');
const preset = el('select', { id: 'superifs-preset' });
const V = el('input', { id: 'superifs-v', type: 'number', min: 1, max: 64, value: 3, size: 3 });
const mode = el('select', { id: 'superifs-mode' },
                ['attractor', 'tops', 'measure', 'steal'].map((m) => el('option', {}, m)));
const size = el('select', { id: 'superifs-size' },
                ['256x256', '384x384', '512x512'].map((s) => el('option', { selected: s === '384x384' }, s)));
const seed = el('input', { id: 'superifs-seed', type: 'number', min: 0, value: 1, size: 4 });
const step = el('input', { id: 'superifs-step', type: 'number', min: 0, max: 10000, value: 0, size: 5 });
const stepButton = el('button', { id: 'superifs-next' }, 'Step');
const play = el('button', { id: 'superifs-play' }, 'Play');
const reset = el('button', { id: 'superifs-reset' }, 'Reset');
const picture = el('img', { id: 'superifs-picture', alt: '' });
const tables = el('div', { id: 'superifs-ifs', class: 'superifs-tables' });
const status = el('p', { id: 'superifs-status', class: 'status' });
const saveName = el('input', { id: 'superifs-file', size: 20, value: 'studio.super.toml' });
const saveButton = el('button', { id: 'superifs-save' }, 'Save');
const frames = el('input', { id: 'superifs-frames', type: 'number', min: 1, max: 1000, value: 24, size: 4 });
const crossfade = el('input', { id: 'superifs-crossfade', type: 'number', min: 1, max: 100, value: 4, size: 3 });
const jobFile = el('input', { id: 'superifs-job-file', size: 14, value: 'texture.png' });
const jobSize = el('select', { id: 'superifs-job-size' },
                   ['512x512', '1024x1024', '1920x1080'].map((s) => el('option', {}, s)));
const jobButton = el('button', { id: 'superifs-job' }, 'Render sequence');
const jobStatus = el('span', { class: 'status', id: 'superifs-job-status' });
body.append(
  el('div', { class: 'row' }, el('label', {}, 'SuperIFS ', preset), el('label', {}, 'V ', V),
     el('label', {}, 'mode ', mode), el('label', {}, 'size ', size), el('label', {}, 'seed ', seed),
     el('label', {}, 'step ', step), stepButton, play, reset),
  el('div', { class: 'row top' }, picture, tables),
  status,
  el('div', { class: 'row' }, el('label', {}, 'Save as ', saveName), saveButton),
  el('div', { class: 'row' }, el('label', {}, 'Sequence: frames ', frames),
     el('label', {}, 'crossfade ', crossfade), el('label', {}, 'size ', jobSize),
     el('label', {}, 'files ', jobFile), jobButton, jobStatus));

let superifs = null;  // the superIFS being edited (the server's JSON)
let playing = false;
let busy = null;
let again = false;
const stats = { frames: 0, errors: 0, shown: -1 };
window.studioSuperifs = stats;

const fmt = (x) => String(Number(Number(x).toPrecision(6)));

function request(k) {
  return { superifs, V: Number(V.value), mode: mode.value, size: size.value,
           seed: Number(seed.value), step: k,
           source: mode.value === 'steal' ? 'sample' : undefined };
}

// Renders the texture of the current step; a request made while one is answered waits for it.
async function render() {
  if (!superifs) return;
  if (busy) { again = true; return busy; }
  busy = (async () => {
    do {
      again = false;
      const k = Number(step.value);
      const t0 = performance.now();
      try {
        const { blob: b } = await blob('/api/texture/frame', { method: 'POST', body: request(k) });
        const old = picture.src;
        picture.src = URL.createObjectURL(b);
        if (old) URL.revokeObjectURL(old);
        stats.frames++;
        stats.shown = k;
        say(status, `${superifs.name}: texture ${k} (V = ${V.value}, ${mode.value}) in ` +
                    `${Math.round(performance.now() - t0)} ms`);
      } catch (e) {
        if (e.status === 409) continue;
        stats.errors++;
        playing = false;
        play.textContent = 'Play';
        say(status, e.message, true);
      }
    } while (again);
    busy = null;
  })();
  return busy;
}

// One table per IFS: its maps' a..f and its probability P_n.
function drawTables() {
  tables.replaceChildren();
  superifs.ifs.forEach((f, n) => {
    const P = superifs.probabilities.length === superifs.ifs.length ? superifs.probabilities[n] : '';
    const pInput = el('input', { name: `P${n}`, value: P === '' ? '' : fmt(P), placeholder: 'auto', size: 5,
                                 onchange: () => edit(() => {
                                   const x = Number(pInput.value);
                                   if (pInput.value === '' || !Number.isFinite(x)) return false;
                                   if (superifs.probabilities.length !== superifs.ifs.length)
                                     superifs.probabilities = superifs.ifs.map(() => 1);
                                   superifs.probabilities[n] = x;
                                 }) });
    const rows = f.maps.map((m, i) => el('tr', {}, el('td', {}, String(i + 1)),
      m.map((x, k) => el('td', {}, el('input', {
        name: `ifs${n}-${i}-${k}`, value: fmt(x), size: 6,
        onchange: (e) => edit(() => {
          const v = Number(e.target.value);
          if (e.target.value === '' || !Number.isFinite(v)) return false;
          f.maps[i][k] = v;
        }),
      })))));
    tables.append(el('div', { class: 'superifs-ifs' },
      el('div', { class: 'row' }, el('strong', {}, `IFS ${n + 1}${f.name ? ` (${f.name})` : ''}`),
         el('label', {}, 'P ', pInput),
         el('button', { class: 'to-editor', onclick: () => toEditor(n) }, 'Edit in editor'),
         el('button', { class: 'from-editor', onclick: () => fromEditor(n) }, 'Take from editor')),
      el('table', {}, el('thead', {}, el('tr', {}, ['#', 'a', 'b', 'c', 'd', 'e', 'f'].map((h) => el('th', {}, h)))),
         el('tbody', {}, rows))));
  });
}

// An edit: `change` returns false to refuse it; the texture is made again from step 0's burn-in.
function edit(change) {
  const before = JSON.stringify(superifs);
  if (change() === false) { drawTables(); return; }
  if (JSON.stringify(superifs) !== before) { drawTables(); render(); }
}

function toEditor(n) {
  const f = superifs.ifs[n];
  openInEditor({ name: `${superifs.name}-ifs${n + 1}`, description: '', maps: f.maps.map((m) => m.slice()),
                 probabilities: f.probabilities.slice(), colours: [] });
  say(status, `IFS ${n + 1} is in the editor: drag its maps, then "Take from editor"`);
}

function fromEditor(n) {
  const state = window.studio && window.studio.state ? window.studio.state() : null;
  if (!state) return;
  if (state.maps.length !== superifs.ifs[n].maps.length) {
    say(status, `IFS ${n + 1}: needs ${superifs.ifs[n].maps.length} maps, as every IFS of the ` +
                `superIFS (got ${state.maps.length} in the editor)`, true);
    return;
  }
  edit(() => {
    superifs.ifs[n].maps = state.maps.map((m) => m.slice());
    superifs.ifs[n].probabilities =
      state.probabilities.length === state.maps.length ? state.probabilities.slice() : [];
  });
}

async function open(value) {
  try {
    const [kind, name] = value.split(':');
    superifs = await json(kind === 'file' ? `/api/superifs/preset?file=${encodeURIComponent(name)}`
      : `/api/superifs/preset?name=${encodeURIComponent(name)}`);
    saveName.value = `${superifs.name}-edited.super.toml`;
    jobFile.value = `${superifs.name}.png`;
    step.value = 0;
    drawTables();
    await render();
  } catch (e) {
    say(status, e.message, true);
  }
}

async function loop() {
  while (playing) {
    const t0 = performance.now();
    step.value = Number(step.value) + 1;
    await render();
    await new Promise((r) => setTimeout(r, Math.max(0, 150 - (performance.now() - t0))));
  }
}

preset.onchange = () => open(preset.value);
for (const input of [V, mode, size, seed]) input.onchange = () => render();
step.onchange = () => render();
stepButton.onclick = () => { step.value = Number(step.value) + 1; render(); };
reset.onclick = () => { step.value = 0; render(); };
play.onclick = () => {
  playing = !playing;
  play.textContent = playing ? 'Pause' : 'Play';
  if (playing) loop();
};
saveButton.onclick = async () => {
  try {
    const r = await json('/api/superifs/save', { method: 'POST',
                                                 body: { superifs, file: saveName.value } });
    say(status, `saved ${r.saved}`);
  } catch (e) {
    say(status, e.message, true);
  }
};
jobButton.onclick = async () => {
  const r = Object.assign(request(0), { kind: 'texture', file: jobFile.value, size: jobSize.value,
                                        frames: Number(frames.value), crossfade: Number(crossfade.value) });
  delete r.step;
  try {
    const job = await startJob(r, {
      onUpdate: (j) => {
        say(jobStatus, `job ${j.id}: ${j.state} ${j.detail}`, j.state === 'failed');
        if (j.state === 'done')
          jobStatus.append(' ', el('a', { href: fileUrl(j.files[0]), target: '_blank' }, j.files[0]),
                           j.files.length > 1 ? ` … ${j.files[j.files.length - 1]}` : '');
      },
    });
    say(jobStatus, `job ${job.id} started`);
  } catch (e) {
    say(jobStatus, e.message, true);
  }
};

(async () => {
  try {
    const list = await json('/api/superifs');
    for (const s of list.shipped)
      preset.append(el('option', { value: `name:${s.name}` }, `${s.name} (N = ${s.ifs}, M = ${s.maps})`));
    for (const f of list.files) preset.append(el('option', { value: `file:${f}` }, f));
    const fig4 = [...preset.options].find((o) => o.value === 'name:paper-fig4');
    if (fig4) preset.value = fig4.value;
    // Opened when first shown: no burn-in before the panel is looked at.
    document.getElementById('tab-superifs').addEventListener('click', () => superifs || open(preset.value));
  } catch (e) {
    say(status, e.message, true);
  }
})();
