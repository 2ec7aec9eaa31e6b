// The crowd page's animation loop: steps the crowd (playing, or one pending
// single step), draws when something changed, and every 250 ms updates the
// metrics panel and the one-line HUD. The HUD's rates are measured from
// what completed over the last second (ui/speedmeter.ts): steps finished
// (on this thread or in the workers), frames that drew a new state, and
// the ms of the steps and draws that happened; never the display's rate.

import type { Surface } from "../ui/canvas";
import type { CrowdPage } from "./app";
import { drawCrowd } from "./render";
import type { CrowdStats } from "./app";
import { SpeedMeter } from "../ui/speedmeter";

/** A measured time, or "—" when nothing was measured. */
const msText = (ms: number): string => (Number.isFinite(ms) ? `${ms.toFixed(ms < 10 ? 2 : ms < 100 ? 1 : 0)} ms` : "—");

/** Steps completed per second, and plainly when fewer than were asked. */
function rateText(s: CrowdStats): string {
  const r = s.stepsPerSecond;
  const rate = `${r.toFixed(r < 10 ? 1 : 0)} steps/s`;
  if (s.askedPerSecond <= 0) return rate;
  return r < 0.95 * s.askedPerSecond ? `${rate} (slower than the ${s.askedPerSecond.toFixed(0)} asked)` : rate;
}

export function runLoop(page: CrowdPage, surface: Surface, hud: HTMLElement): void {
  const { session: s, stats } = page;
  let stepAcc = 0;
  /** Workers: their steps and the slowest worker's ms in the window. */
  let wSteps = 0;
  let wMs = 0;
  let drawAcc = 0;
  let drawnAcc = 0;
  /** Steps asked for in the window (the rate the page aims at). */
  let askedAcc = 0;
  /** Steps completed in the window. */
  let doneAcc = 0;
  const meter = new SpeedMeter();
  let counted = -1;
  let windowStart = performance.now();
  let lastMetrics = 0;
  const frame = (now: number): void => {
    requestAnimationFrame(frame);
    const lab = s.lab;
    if (!lab) return;
    // Another count: the rates and times measured were another crowd's.
    if (lab.count() !== counted) {
      counted = lab.count();
      stats.stepMs = stats.drawMs = NaN;
      meter.reset();
    }
    const t0 = performance.now();
    const n = s.playing ? s.stepsPerFrame : Math.min(s.singleSteps, 1);
    if (s.playing) askedAcc += n;
    const st = s.stepper?.active ? s.stepper : null;
    const stepsBefore = stats.steps;
    if (st) {
      // Workers step: this frame takes the newest complete state (before
      // asking for more: the workers then leave its buffer alone), asks
      // (never waits) and draws it.
      st.poll();
      if (n > 0) st.request(n);
      if (!s.playing) s.singleSteps = 0;
      st.pump();
      const d = st.takeCompleted();
      stats.steps += d.steps;
      stats.jobMs += d.ms;
      stats.workerStepMs += d.workerMs;
      stats.updates += d.steps * st.count;
      wSteps += d.steps;
      wMs += d.workerMs;
    } else if (n > 0) {
      lab.step(n);
      if (!s.playing) s.singleSteps = 0;
      stats.steps += n;
      stats.updates += n * lab.count();
      s.dirty = true;
    }
    const t1 = performance.now();
    const drawing = s.dirty;
    if (s.dirty) {
      const half = st ? st.state.length >> 1 : 0;
      drawCrowd(surface, s.view, {
        path: lab.pathPoints(),
        radius: lab.pathRadius(),
        closed: lab.pathClosed(),
        positions: st ? st.state.subarray(0, half) : lab.positions(),
        velocities: st ? st.state.subarray(half) : lab.velocities(),
        trace: s.showTrace ? lab.trace() : new Float32Array(),
        traced: lab.tracedBoid(),
        boidRadius: lab.boidRadius(),
        showTrace: s.showTrace,
        showHandles: s.showHandles,
        selected: s.editor.selected,
        hover: s.editor.hover,
      });
      s.dirty = false;
      stats.drawnFrames++;
    }
    const t2 = performance.now();
    page.probe?.(t2 - t0);
    if (!st && n > 0) stepAcc += t1 - t0;
    if (drawing) {
      drawAcc += t2 - t1;
      drawnAcc++;
    }
    stats.frames++;
    doneAcc += stats.steps - stepsBefore;
    meter.tick(now, drawing, lab.time(), stats.steps - stepsBefore);
    if (now - windowStart >= 1000) {
      const span = now - windowStart;
      const done = meter.read(3);
      stats.stepsPerSecond = done.stepsPerSecond;
      // Steps asked for per second: while playing, the steps per frame at the display's rate.
      stats.askedPerSecond = (1000 * askedAcc) / span;
      // ms per step of the steps that completed in the window (with
      // workers the slowest worker's: the page's share is in draw), and per
      // drawn frame; a window without any keeps the last (NaN before one).
      const steps = st ? wSteps : doneAcc;
      if (steps > 0) stats.stepMs = (st ? wMs : stepAcc) / steps;
      wSteps = wMs = 0;
      if (drawnAcc > 0) stats.drawMs = drawAcc / drawnAcc;
      stats.fps = done.fps;
      stepAcc = drawAcc = drawnAcc = askedAcc = doneAcc = 0;
      windowStart = now;
    }
    if (now - lastMetrics > 250) {
      lastMetrics = now;
      if (st) s.panel?.metricsOff(`Measured on the page's thread only: off while ${st.workers === 1 ? "a worker steps" : `${st.workers} workers step`} the crowd (?workers=0 steps it here).`);
      else s.panel?.showMetrics(lab.metrics(), lab.lastOverlaps(), lab.count());
      const c = lab.config();
      const seek = c.seek;
      hud.textContent = [
        // The workers' clock while they step (the page's crowd holds the state it last took).
        `step ${(st ? st.time : lab.time()).toFixed(0)}`,
        `${lab.count().toLocaleString("en")} boids`,
        seek.kind === "reynolds" ? "Reynolds" : `Parker ${+(seek.fraction * 100).toPrecision(3)} %`,
        c.separation ? `separation ${+c.separation_weight.toPrecision(3)}` : "no separation",
        rateText(stats),
        `${stats.fps.toFixed(stats.fps < 10 ? 1 : 0)} fps drawn`,
        `step ${msText(stats.stepMs)}${st ? ` in ${st.workers} worker${st.workers === 1 ? "" : "s"}` : ""}`,
        `draw ${msText(stats.drawMs)}`,
      ].join("  ·  ");
    }
  };
  requestAnimationFrame(frame);
}
