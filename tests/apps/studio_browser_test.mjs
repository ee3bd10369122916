// SPDX-License-Identifier: Apache-2.0
// `ifsfx studio` in a real browser: Debian's chromium, headless, driven by playwright-core (no
// browser download). Loads the page, drags a map's translate handle and checks that the picture and
// the numeric fields changed, undoes (Ctrl-Z) and checks the fields are back, saves, and checks that
// `ifsfx render` accepts the saved TOML. Takes a screenshot (WORK/studio.png). Measures the
// drag-to-pixels latency over a scripted drag of 50 moves at 768x768 in tops mode: from the
// pointer event to the new picture drawn on the canvas, each move waiting for its picture; p50 and
// p95 are printed, never asserted.
// Usage: node studio_browser_test.mjs IFSFX WORK NODE_MODULES
import { spawn, execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, rmSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';

const [ifsfx, work, nodeModules] = process.argv.slice(2);
const chromium = '/usr/bin/chromium';
if (!existsSync(chromium)) { console.log('SKIP: /usr/bin/chromium is missing'); process.exit(77); }
const require = createRequire(path.join(nodeModules, 'x.js'));
const { chromium: launcher } = require('playwright-core');

rmSync(work, { recursive: true, force: true });
mkdirSync(path.join(work, 'folder'), { recursive: true });
let failures = 0;
const check = (ok, what) => { console.log(`${ok ? 'ok' : 'FAIL'}: ${what}`); if (!ok) failures++; };

const server = spawn(ifsfx, ['studio', 'barnsley-fern', '--folder', path.join(work, 'folder')],
                     { stdio: ['ignore', 'pipe', 'inherit'], env: { ...process.env, TMPDIR: work } });
const url = await new Promise((resolve, reject) => {
  let out = '';
  server.stdout.on('data', (d) => {
    out += d;
    const m = out.match(/^ifsfx studio: (\S+)$/m);
    if (m) resolve(m[1]);
  });
  server.on('exit', (code) => reject(new Error(`ifsfx studio exited with ${code}`)));
  setTimeout(() => reject(new Error('no URL in 10 s')), 10000);
});

const browser = await launcher.launch({ executablePath: chromium, headless: true,
                                        args: ['--no-sandbox', '--disable-gpu'] });
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  page.on('pageerror', (e) => check(false, `page error: ${e.message}`));
  await page.goto(url);
  const drawn = (n) => page.waitForFunction((k) => window.studio.drawnSeq >= k && window.studio.drawnSeq === window.studio.seq, n, { timeout: 20000 });
  await drawn(1);
  const canvasPixels = () => page.evaluate(() => {
    const c = document.getElementById('canvas');
    return c.toDataURL('image/png');
  });
  const fields = () => page.evaluate(() => [...document.querySelectorAll('#maps tbody tr')].map(
    (tr) => [...tr.querySelectorAll('input')].map((i) => i.value)));
  check((await fields()).length === 4, 'the fern opens with 4 fields rows');
  check(await page.evaluate(() => document.querySelectorAll('.factor').length === 4), 'a factor per map');
  const before = await fields();
  const pictureBefore = await canvasPixels();

  // Drag map 2's translate handle by 60 px right and 40 px up, in 10 steps.
  const h = await page.evaluate(() => window.studio.handle(1, 'centre'));
  await page.mouse.move(h.x, h.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(h.x + 6 * i, h.y - 4 * i);
  await page.mouse.up();
  await drawn(await page.evaluate(() => window.studio.seq));
  const after = await fields();
  check(after[1][4] !== before[1][4] && after[1][5] !== before[1][5],
        `dragging moves e and f of map 2 (${before[1][4]}, ${before[1][5]} -> ${after[1][4]}, ${after[1][5]})`);
  check(JSON.stringify(after[0]) === JSON.stringify(before[0]) && after[1][0] === before[1][0],
        'the other fields stay');
  check(await canvasPixels() !== pictureBefore, 'the picture changed');
  await page.screenshot({ path: path.join(work, 'studio.png') });

  // Undo restores the fields; redo brings the drag back.
  await page.keyboard.press('Control+z');
  await drawn(await page.evaluate(() => window.studio.seq));
  check(JSON.stringify(await fields()) === JSON.stringify(before), 'Ctrl-Z restores the fields');
  await page.keyboard.press('Control+Shift+z');
  check(JSON.stringify(await fields()) === JSON.stringify(after), 'Ctrl-Shift-Z redoes the drag');

  // A corner of map 3 rotates and scales it about its centre: a, b, c, d change, e, f follow so
  // that the centre's image stays; Shift + a corner shears it. Each is one undo step.
  const beforeCorner = await fields();
  for (const shift of [false, true]) {
    const k = await page.evaluate(() => window.studio.handle(2, 'corner', 2));
    if (shift) await page.keyboard.down('Shift');
    await page.mouse.move(k.x, k.y);
    await page.mouse.down();
    for (let i = 1; i <= 5; i++) await page.mouse.move(k.x + 4 * i, k.y + 3 * i);
    await page.mouse.up();
    if (shift) await page.keyboard.up('Shift');
    await drawn(await page.evaluate(() => window.studio.seq));
  }
  const cornered = await fields();
  check([0, 1, 2, 3].every((j) => cornered[2][j] !== beforeCorner[2][j]),
        `corners change a, b, c, d of map 3 (${beforeCorner[2].slice(0, 4)} -> ${cornered[2].slice(0, 4)})`);
  await page.keyboard.press('Control+z');
  await page.keyboard.press('Control+z');
  check(JSON.stringify(await fields()) === JSON.stringify(beforeCorner), 'two Ctrl-Z undo both corner drags');
  await drawn(await page.evaluate(() => window.studio.seq));

  // Save, and the command line renders what was saved.
  await page.fill('#file', 'dragged.toml');
  await page.click('#save');
  await page.waitForFunction(() => /saved|error/.test(document.getElementById('status').textContent));
  const saved = path.join(work, 'folder', 'dragged.toml');
  check(existsSync(saved), `save writes ${saved}`);
  if (existsSync(saved)) {
    try {
      execFileSync(ifsfx, ['render', saved, '--mode', 'tops', '--size', '64x64', '-q', '-o',
                           path.join(work, 'dragged.png')]);
      check(true, 'ifsfx render accepts the saved TOML');
    } catch (e) { check(false, `ifsfx render refused the saved TOML: ${e.stderr}`); }
    const rows = [...readFileSync(saved, 'utf8').matchAll(/^\s*\[([^\]]+)\],/gm)].map(
      (m) => m[1].split(',').map(Number));
    check(rows.length === 4 && Math.abs(rows[1][4] - Number(after[1][4])) < 1e-5 &&
          Math.abs(rows[1][5] - Number(after[1][5])) < 1e-5,
          `the saved TOML holds the dragged map (${JSON.stringify(rows[1])})`);
  }

  // Steal mode with the shipped sample shows a picture too.
  await page.selectOption('#mode', 'steal');
  await drawn(await page.evaluate(() => window.studio.seq));
  check(await page.evaluate(() => window.studio.errors === 0), 'steal mode renders without error');
  await page.screenshot({ path: path.join(work, 'studio-steal.png') });
  await page.selectOption('#mode', 'tops');
  await drawn(await page.evaluate(() => window.studio.seq));

  // Latency: 50 moves of map 1's translate handle at 768x768 in tops mode, each waiting for its
  // picture: from the pointer event to the picture on the canvas.
  await page.evaluate(() => { window.studio.latencies.length = 0; window.studio.renderMs.length = 0; });
  const g = await page.evaluate(() => window.studio.handle(2, 'centre'));
  await page.mouse.move(g.x, g.y);
  await page.mouse.down();
  for (let i = 1; i <= 50; i++) {
    await page.mouse.move(g.x + 2 * i, g.y + (i % 2));
    await drawn(await page.evaluate(() => window.studio.seq));
  }
  await page.mouse.up();
  const ms = (await page.evaluate(() => window.studio.latencies)).sort((a, b) => a - b);
  const q = (p) => ms[Math.min(ms.length - 1, Math.floor(p * ms.length))];
  const r = (await page.evaluate(() => window.studio.renderMs)).sort((a, b) => a - b);
  console.log(`of which the server's render: p50 ${r[Math.floor(r.length / 2)].toFixed(1)} ms, p95 ${r[Math.min(r.length - 1, Math.floor(0.95 * r.length))].toFixed(1)} ms; load average ${(await import('node:os')).loadavg()[0].toFixed(1)} on ${(await import('node:os')).cpus().length} cores`);
  console.log(`drag-to-pixels latency, tops 768x768, ${ms.length} moves: p50 ${q(0.5).toFixed(1)} ms, p95 ${q(0.95).toFixed(1)} ms, max ${ms[ms.length - 1].toFixed(1)} ms`);
} finally {
  await browser.close();
  server.kill('SIGINT');
}
const code = await new Promise((resolve) => server.on('exit', (c, s) => resolve(c ?? s)));
check(code === 130, `the server ends with exit 130 on SIGINT (got ${code})`);
console.log(failures ? `${failures} failure(s)` : 'all passed');
process.exit(failures ? 1 : 0);
