#!/usr/bin/env node
// SPDX-License-Identifier: Apache-2.0
// The feel of `ifsfx studio` (issue 24 item 3): from a drag event to new pixels on the canvas, at
// 768x768, in tops, steal and measure modes (exact descent), over a scripted drag of 100 moves of
// the fern's largest map, in Debian's chromium driven headless by playwright-core. Two drags per
// mode:
//   paced: each move waits for its picture (the latency of every single move);
//   fast:  100 moves 16 ms apart, as a hand drags (the latency of each move to the first picture
//          that shows it or a later one; coarse pictures of the newest state only, nothing queued).
// Then the pointer rests: the time from the last move to the full-size picture. Prints p50, p95
// and max of each, the server's render times (coarse and full), the coarse sizes the page chose
// and the load average. Figures only: nothing is asserted.
// Usage: node bench/studio_latency.mjs [IFSFX [NODE_MODULES]] [--moves N] [--modes a,b]
//   IFSFX defaults to build/release/cli/ifsfx, NODE_MODULES to build/release/studio-node/
//   node_modules (ctest -R studio.node_setup installs playwright-core there).
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import os from 'node:os';
import path from 'node:path';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const [value] = args.splice(i, 2).slice(1);
  return value;
};
const moves = Number(option('--moves', '100'));
const modes = option('--modes', 'tops,steal,measure').split(',');
const root = path.resolve(path.dirname(new URL(import.meta.url).pathname), '..');
const ifsfx = args[0] || path.join(root, 'build/release/cli/ifsfx');
const nodeModules = args[1] || path.join(root, 'build/release/studio-node/node_modules');
const chromium = '/usr/bin/chromium';
for (const [what, p] of [['ifsfx', ifsfx], ['playwright-core', path.join(nodeModules, 'playwright-core')], ['chromium', chromium]])
  if (!existsSync(p)) { console.error(`studio_latency: ${what} is missing (${p})`); process.exit(2); }
const require = createRequire(path.join(nodeModules, 'x.js'));
const { chromium: launcher } = require('playwright-core');

const folder = mkdtempSync(path.join(os.tmpdir(), 'studio-latency-'));
const server = spawn(ifsfx, ['studio', 'barnsley-fern', '--folder', folder], { stdio: ['ignore', 'pipe', 'inherit'] });
const url = await new Promise((resolve, reject) => {
  let out = '';
  server.stdout.on('data', (d) => {
    out += d;
    const m = out.match(/^ifsfx studio: (\S+)$/m);
    if (m) resolve(m[1]);
  });
  server.on('exit', (code) => reject(new Error(`ifsfx studio exited with ${code}`)));
});

const quantile = (xs, q) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.floor(q * s.length))] : NaN;
};
const figures = (xs) => `p50 ${quantile(xs, 0.5).toFixed(1)} ms, p95 ${quantile(xs, 0.95).toFixed(1)} ms, ` +
  `max ${Math.max(...xs).toFixed(1)} ms (${xs.length})`;

const browser = await launcher.launch({ executablePath: chromium, headless: true,
                                        args: ['--no-sandbox', '--disable-gpu'] });
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  page.on('pageerror', (e) => console.error(`page error: ${e.message}`));
  await page.goto(url);
  const settled = () => page.waitForFunction(() => window.studio.seq > 0 && window.studio.settled(),
                                             null, { timeout: 60000 });
  await settled();
  console.log(`ifsfx studio drag-to-pixels latency, 768x768, fern map 2 dragged by its centre; ` +
              `${os.cpus().length} cores, ${os.cpus()[0].model}`);
  for (const mode of modes) {
    await page.selectOption('#mode', mode);
    await settled();
    for (const kind of ['paced', 'fast']) {
      await page.evaluate(() => {
        for (const k of ['latencies', 'fullLatencies', 'renderMs', 'fullRenderMs']) window.studio[k].length = 0;
        window.studio.sizes = [];
      });
      const load = os.loadavg()[0];
      const h = await page.evaluate(() => window.studio.handle(1, 'centre'));
      await page.mouse.move(h.x, h.y);
      await page.mouse.down();
      for (let i = 1; i <= moves; i++) {
        // Back and forth over 40 px, a little up and down: the picture changes at every move.
        const t = i / moves;
        await page.mouse.move(h.x + 40 * Math.sin(2 * Math.PI * t), h.y + 10 * Math.sin(6 * Math.PI * t));
        if (kind === 'paced')
          await page.waitForFunction(() => window.studio.drawnSeq === window.studio.seq, null, { timeout: 60000 });
        else
          await page.waitForTimeout(16);
      }
      await page.mouse.up();
      await settled();
      const s = await page.evaluate(() => ({
        latencies: window.studio.latencies, full: window.studio.fullLatencies,
        renderMs: window.studio.renderMs, fullRenderMs: window.studio.fullRenderMs,
        sizes: window.studio.sizes,
      }));
      const sizes = [...new Set(s.sizes)].join(', ');
      console.log(`${mode} ${kind}: event to pixels ${figures(s.latencies)}; rest to full picture ` +
                  `${figures(s.full)}; server render coarse p50 ${quantile(s.renderMs, 0.5).toFixed(1)} ms ` +
                  `(${sizes}), full p50 ${quantile(s.fullRenderMs, 0.5).toFixed(1)} ms; load ${load.toFixed(1)}`);
    }
    await page.evaluate(() => { window.studio.state(); });
    await page.keyboard.press('Control+z');  // the drag undone: every mode starts from the fern
    await page.keyboard.press('Control+z');
    await settled();
  }
} finally {
  await browser.close();
  server.kill('SIGINT');
  await new Promise((resolve) => server.on('exit', resolve));
  rmSync(folder, { recursive: true, force: true });
}
