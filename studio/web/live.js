// SPDX-License-Identifier: Apache-2.0
// The live picture: every edit asks for a new one, and the pointer must feel the picture follow.
// - While the picture of the newest edit is not shown, a coarse one (a fraction of the size, drawn
//   scaled up) is asked for first; the full-size one follows once the pointer rests (no edit for
//   kSettleMs during a drag) or at once after a single edit.
// - Nothing queues: at most one render of this tab is in flight. An edit during a coarse render
//   waits for it (its picture is newer than the one shown) and then asks for the newest state
//   only; an edit during a full-size render cancels it (the server answers it 409).
// - The coarse fraction adapts: finer while coarse renders come back well within the mode's
//   budget, coarser when they do not.
// - Pictures come as raw RGBA ("format": "rgba"): no PNG to encode or decode.
import { api } from './api.js';

const kScales = [1, 1 / 2, 1 / 3, 1 / 4, 1 / 6, 1 / 8];
const kSettleMs = 150;
// The round trip a coarse render should stay within (ms): the figures less a margin.
const kBudget = { attractor: 35, tops: 35, steal: 35, measure: 75 };

export class LiveRenderer {
  // body(): the request's JSON (the preset, mode, view...) without size and format;
  // size(): [w, h] of the full picture; show(picture): draws {image, width, height, view, full,
  // renderMs, colouring}; fail(message): shows an error; stats: the page's figures (latencies...).
  constructor({ body, size, show, fail, stats }) {
    Object.assign(this, { body, size, show, fail, stats });
    this.version = 0;        // the newest edit
    this.shown = { version: 0, full: true };
    this.inFlight = null;    // {version, full, controller}
    this.interactive = false;
    this.lastChange = 0;
    this.timer = null;
    this.events = [];        // edits whose picture is not shown yet: {version, time}
    this.scale = 3;          // index in kScales: 1/4 to start with
    this.lastFullMs = Infinity;
  }

  // Something changed (eventTime: when the user did it, performance.now() clock); interactive:
  // part of a drag, pan or zoom, so that the full picture waits for the pointer to rest.
  changed(eventTime = performance.now(), interactive = false) {
    this.version++;
    this.events.push({ version: this.version, time: eventTime });
    this.interactive = interactive;
    this.lastChange = performance.now();
    clearTimeout(this.timer);
    if (interactive) this.timer = setTimeout(() => this.pump(), kSettleMs + 5);
    this.pump();
  }

  // The drag ended: the full picture now.
  rest() {
    this.interactive = false;
    clearTimeout(this.timer);
    this.pump();
  }

  // Whether the newest state is shown at full size with nothing in flight.
  settled() {
    return !this.inFlight && this.shown.version === this.version && this.shown.full;
  }

  pump() {
    const mode = this.body().mode;
    if (this.inFlight) {
      if (this.inFlight.full && this.inFlight.version < this.version) {
        this.inFlight.controller.abort();  // stale and slow: the server cancels it too
        this.inFlight = null;
      } else {
        return;
      }
    }
    const resting = !this.interactive || performance.now() - this.lastChange >= kSettleMs;
    if (this.shown.version < this.version) {
      // A full picture that is known to come back within the budget needs no coarse one first.
      const fullIsFast = this.lastFullMs <= (kBudget[mode] || 35) && resting;
      this.start(this.version, fullIsFast);
    } else if (!this.shown.full && resting) {
      this.start(this.version, true);
    } else if (!resting) {
      clearTimeout(this.timer);
      this.timer = setTimeout(() => this.pump(), kSettleMs - (performance.now() - this.lastChange) + 5);
    }
  }

  async start(version, full) {
    const [w, h] = this.size();
    const scale = full ? 1 : kScales[this.scale];
    const width = Math.max(16, Math.round(w * scale));
    const height = Math.max(16, Math.round(h * scale));
    const body = Object.assign(this.body(), { size: `${width}x${height}`, format: 'rgba' });
    const controller = new AbortController();
    const flight = { version, full, controller };
    this.inFlight = flight;
    const t0 = performance.now();
    try {
      const res = await api('/api/render', {
        method: 'POST', body: JSON.stringify(body), signal: controller.signal,
      });
      if (res.status === 409) return;  // a newer request of this tab took over
      if (!res.ok) {
        this.stats.errors++;
        const answer = await res.json().catch(() => ({ error: `HTTP ${res.status}` }));
        this.fail(answer.error);
        this.shown = { version, full: true };  // nothing to retry until the next edit
        this.events = this.events.filter((e) => e.version > version);
        return;
      }
      const bytes = new Uint8ClampedArray(await res.arrayBuffer());
      if (version < this.shown.version || (version === this.shown.version && this.shown.full)) return;
      const image = new ImageData(bytes, width, height);
      const colouring = res.headers.get('X-Ifsfx-Colouring');
      const renderMs = Number(res.headers.get('X-Ifsfx-Render-Ms'));
      this.show({ image, width, height, full, renderMs,
                  view: res.headers.get('X-Ifsfx-View').split(',').map(Number),
                  colouring: colouring ? JSON.parse(colouring) : null });
      const now = performance.now();
      this.shown = { version, full };
      this.stats.drawnSeq = version;
      for (const e of this.events) if (e.version <= version) this.stats.latencies.push(now - e.time);
      this.events = this.events.filter((e) => e.version > version);
      const took = now - t0;
      (full ? this.stats.fullRenderMs : this.stats.renderMs).push(renderMs);
      if (!full && this.stats.sizes) this.stats.sizes.push(body.size);
      if (full) {
        this.lastFullMs = took;
        if (version === this.version) this.stats.fullLatencies.push(now - this.lastChange);
      } else {
        const budget = kBudget[body.mode] || 35;
        if (took > 0.75 * budget && this.scale < kScales.length - 1) this.scale++;
        else if (took < 0.3 * budget && this.scale > 1) this.scale--;
      }
    } catch (e) {
      if (e.name !== 'AbortError') {
        this.stats.errors++;
        this.fail(String(e.message || e));
      }
    } finally {
      if (this.inFlight === flight) this.inFlight = null;
      this.pump();
    }
  }
}
