// SPDX-License-Identifier: Apache-2.0
// The studio's Fit, Video, Jobs and SuperIFS panels in a real browser: Debian's chromium,
// headless, driven by playwright-core (docs/studio.md). Drops a shape on the fit zone and runs a
// fit with a short time budget (its phase and best IoU shown, the result opened in the editor),
// scrubs a small movie and plays it with drift, filters it as a job, starts and cancels a texture
// sequence job (no file left), exports a still and checks it is `ifsfx render`'s of the saved
// preset byte for byte, steps and edits a superIFS, and checks that a refused request shows its
// error in the page. Screenshots in WORK/*.png.
// Usage: node studio_jobs_browser_test.mjs IFSFX WORK NODE_MODULES
import { spawn, execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, rmSync, readFileSync, readdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const [ifsfx, work, nodeModules] = process.argv.slice(2);
const chromium = '/usr/bin/chromium';
if (!existsSync(chromium)) { console.log('SKIP: /usr/bin/chromium is missing'); process.exit(77); }
const require = createRequire(path.join(nodeModules, 'x.js'));
const { chromium: launcher } = require('playwright-core');
const slow = Number(process.env.IFSFX_TIME_SCALE || 1);  // the sanitizer pass is slower

rmSync(work, { recursive: true, force: true });
const folder = path.join(work, 'folder');
mkdirSync(folder, { recursive: true });
let failures = 0;
const check = (ok, what) => { console.log(`${ok ? 'ok' : 'FAIL'}: ${what}`); if (!ok) failures++; };

// A small movie and a shape with alpha (the Sierpinski triangle's tops picture).
execFileSync('ffmpeg', ['-v', 'error', '-y', '-f', 'lavfi', '-i', 'testsrc2=size=128x96:rate=25',
                        '-frames:v', '24', '-c:v', 'mpeg4', '-q:v', '3', path.join(folder, 'clip.mp4')]);
execFileSync(ifsfx, ['render', 'sierpinski-triangle', '--mode', 'tops', '--size', '64x64', '-q',
                     '-o', path.join(work, 'shape.png')]);

const server = spawn(ifsfx, ['studio', 'barnsley-fern', '--folder', folder],
                     { stdio: ['ignore', 'pipe', 'inherit'], env: { ...process.env, TMPDIR: work } });
const url = await new Promise((resolve, reject) => {
  let out = '';
  server.stdout.on('data', (d) => {
    out += d;
    const m = out.match(/^ifsfx studio: (\S+)$/m);
    if (m) resolve(m[1]);
  });
  server.on('exit', (code) => reject(new Error(`ifsfx studio exited with ${code}`)));
  setTimeout(() => reject(new Error('no URL in 10 s')), 10000 * slow);
});

const browser = await launcher.launch({ executablePath: chromium, headless: true,
                                        args: ['--no-sandbox', '--disable-gpu'] });
const timeout = 60000 * slow;
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1400 } });
  page.on('pageerror', (e) => check(false, `page error: ${e.message}`));
  page.on('response', (r) => { if (r.status() >= 400 && !r.url().endsWith('favicon.ico')) console.log(`note: ${r.status()} ${r.url()}`); });
  await page.goto(url);
  await page.waitForFunction(() => window.studio && window.studio.drawnSeq >= 1, null, { timeout });
  const shot = (name) => page.screenshot({ path: path.join(work, name), fullPage: true });
  const text = (selector) => page.$eval(selector, (e) => e.textContent);

  // ---- Fit: drop a shape, a short budget, the result opens in the editor ----
  await page.click('#tab-fit');
  await page.fill('#fit-maps', '3');
  await page.fill('#fit-seconds', '2');
  await page.selectOption('#fit-size', '64');
  const shape = readFileSync(path.join(work, 'shape.png')).toString('base64');
  const t0 = Date.now();
  await page.evaluate((b64) => {
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const data = new DataTransfer();
    data.items.add(new File([bytes], 'triangle.png', { type: 'image/png' }));
    document.getElementById('fit-drop').dispatchEvent(
      new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
  }, shape);
  await page.waitForFunction(() => /best IoU/.test(document.getElementById('fit-phase').textContent),
                             null, { timeout });
  check(true, `the fit shows its progress: "${await text('#fit-phase')}"`);
  await page.waitForFunction(() => /^IoU/.test(document.getElementById('fit-report').textContent) ||
                             document.getElementById('fit-report').classList.contains('error'),
                             null, { timeout });
  const report = await text('#fit-report');
  const iou = Number(report.match(/^IoU ([0-9.]+)/)?.[1]);
  check(iou > 0.3, `a 2-second fit of a dropped triangle: ${report} (${((Date.now() - t0) / 1000).toFixed(1)} s)`);
  await page.waitForFunction(() => window.studio.state().name === 'triangle', null, { timeout });
  const fitted = await page.evaluate(() => window.studio.state());
  check(fitted.maps.length === 3, `the fitted preset opens in the editor (${fitted.maps.length} maps)`);
  await page.waitForFunction(() => document.getElementById('fit-preview').naturalWidth > 0, null, { timeout });
  await page.waitForFunction(() => window.studio.drawnSeq === window.studio.seq, null, { timeout });
  await shot('jobs-fit.png');
  await page.click('#undo');  // back to the fern
  await page.waitForFunction(() => window.studio.state().name === 'barnsley-fern', null, { timeout });
  check(true, 'Undo goes back to the preset before the fit');

  // ---- Video: scrub, play with drift, filter the movie as a job ----
  await page.click('#tab-video');
  await page.waitForFunction(() => window.studioVideo.shown === 0, null, { timeout });
  const first = await page.$eval('#video-picture', (img) => img.src);
  await page.$eval('#video-frame', (e) => { e.value = 17; e.dispatchEvent(new Event('input')); });
  await page.waitForFunction(() => window.studioVideo.shown === 17, null, { timeout });
  check(await text('#video-frame-label') === '17 / 23', 'scrubbing to frame 17 shows it');
  check(await page.$eval('#video-picture', (img) => img.src) !== first, 'the picture changed');
  await page.check('#video-drift');
  await page.fill('#video-drift-amount', '0.2');
  await page.$eval('#video-frame', (e) => { e.value = 0; e.dispatchEvent(new Event('input')); });
  await page.waitForFunction(() => window.studioVideo.shown === 0, null, { timeout });
  await page.click('#video-play');
  await page.waitForFunction(() => window.studioVideo.shown >= 6, null, { timeout });
  await page.click('#video-play');  // pause
  check(await page.evaluate(() => window.studioVideo.errors === 0),
        `playing with drift: ${await text('#video-status')}`);
  await page.fill('#video-out', 'clip-filtered.mp4');
  await page.click('#video-job');
  await page.waitForFunction(() => /done/.test(document.getElementById('video-job-status').textContent),
                             null, { timeout });
  check(existsSync(path.join(folder, 'clip-filtered.mp4')), 'the movie filter job wrote clip-filtered.mp4');
  await shot('jobs-video.png');

  // ---- SuperIFS: open, step, edit, play ----
  await page.click('#tab-superifs');
  await page.waitForFunction(() => window.studioSuperifs.shown === 0, null, { timeout });
  await page.click('#superifs-next');
  await page.click('#superifs-next');
  await page.waitForFunction(() => window.studioSuperifs.shown === 2, null, { timeout });
  check(true, `two steps: ${await text('#superifs-status')}`);
  await page.fill('#superifs-v', '2');
  await page.fill('input[name="ifs1-0-4"]', '0.05');
  await page.press('input[name="ifs1-0-4"]', 'Tab');
  await page.waitForFunction(() => /V = 2/.test(document.getElementById('superifs-status').textContent),
                             null, { timeout });
  await page.click('#superifs-play');
  await page.waitForFunction(() => window.studioSuperifs.shown >= 5, null, { timeout });
  await page.click('#superifs-play');
  check(await page.evaluate(() => window.studioSuperifs.errors === 0), 'an edited superIFS plays');
  await shot('jobs-superifs.png');
  // A texture sequence job, cancelled: its frames go in place together, so none is left.
  await page.fill('#superifs-frames', '1000');
  await page.fill('#superifs-job-file', 'long.png');
  await page.click('#superifs-job');
  await page.click('#tab-jobs');
  const row = '#jobs tbody tr.running button.cancel, #jobs tbody tr.queued button.cancel';
  await page.waitForSelector(row, { timeout });
  await page.click(row);
  await page.waitForSelector('#jobs tbody tr.cancelled', { timeout });
  check(!readdirSync(folder).some((f) => f.startsWith('long_') || f.startsWith('.')),
        'a cancelled texture job leaves no file');

  // ---- Export a still: byte for byte `ifsfx render` of the saved preset ----
  await page.fill('#still-file', 'export.png');
  await page.fill('#still-size', '256x256');
  await page.click('#still-export');
  await page.waitForFunction(() => [...document.querySelectorAll('#jobs tbody tr.done a')]
    .some((a) => a.textContent === 'export.png'), null, { timeout });
  await page.fill('#file', 'export.toml');
  await page.click('#save');
  await page.waitForFunction(() => /saved|error/.test(document.getElementById('status').textContent));
  const { view, mode } = await page.evaluate(() => window.studio.requestBody());
  check(mode === 'tops', `the editor is still in tops mode (a shape dropped to fit is no source; got ${mode})`);
  execFileSync(ifsfx, ['render', path.join(folder, 'export.toml'), '--mode', mode, '--size', '256x256',
                       '--view', view, '-q', '-o', path.join(work, 'cli-export.png')]);
  check(readFileSync(path.join(folder, 'export.png')).equals(readFileSync(path.join(work, 'cli-export.png'))),
        `the exported still is ifsfx render's byte for byte (${mode}, view ${view})`);
  // A refused job shows its error in the page.
  await page.fill('#still-file', '../outside.png');
  await page.click('#still-export');
  await page.waitForFunction(() => document.getElementById('jobs-status').classList.contains('error'),
                             null, { timeout });
  check(/plain name/.test(await text('#jobs-status')), `a refused still: "${await text('#jobs-status')}"`);
  await shot('jobs-list.png');
} finally {
  await browser.close();
  server.kill('SIGINT');
}
const code = await new Promise((resolve) => server.on('exit', (c, s) => resolve(c ?? s)));
check(code === 130, `the server ends with exit 130 on SIGINT (got ${code})`);
console.log(failures ? `${failures} failure(s)` : 'all passed');
process.exit(failures ? 1 : 0);
