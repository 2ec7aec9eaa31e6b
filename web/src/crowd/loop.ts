// The crowd page's animation loop: steps the crowd (playing, or one pending
// single step), draws when something changed, and every 250 ms updates the
// metrics panel and the one-line HUD; step/draw/fps figures per second.

import type { Surface } from "../ui/canvas";
import type { CrowdPage } from "./app";
import { drawCrowd } from "./render";

export function runLoop(page: CrowdPage, surface: Surface, hud: HTMLElement): void {
  const { session: s, stats } = page;
  let stepAcc = 0;
  /** Workers: their steps and the slowest worker's ms in the window. */
  let wSteps = 0;
  let wMs = 0;
  let drawAcc = 0;
  let frameAcc = 0;
  let windowStart = performance.now();
  let lastMetrics = 0;
  const frame = (now: number): void => {
    requestAnimationFrame(frame);
    const lab = s.lab;
    if (!lab) return;
    const t0 = performance.now();
    const n = s.playing ? s.stepsPerFrame : Math.min(s.singleSteps, 1);
    const st = s.stepper?.active ? s.stepper : null;
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
    stepAcc += t1 - t0;
    drawAcc += t2 - t1;
    frameAcc++;
    stats.frames++;
    if (now - windowStart >= 1000) {
      // With workers: the slowest worker's ms per step (the page's share is in draw).
      stats.stepMs = s.stepper?.active ? (wSteps > 0 ? wMs / wSteps : 0) : stepAcc / frameAcc;
      wSteps = wMs = 0;
      stats.drawMs = drawAcc / frameAcc;
      stats.fps = (1000 * frameAcc) / (now - windowStart);
      stepAcc = drawAcc = frameAcc = 0;
      windowStart = now;
    }
    if (now - lastMetrics > 250) {
      lastMetrics = now;
      if (st) s.panel?.metricsOff(`Measured on the page's thread only: off while ${st.workers === 1 ? "a worker steps" : `${st.workers} workers step`} the crowd (?workers=0 steps it here).`);
      else s.panel?.showMetrics(lab.metrics(), lab.lastOverlaps(), lab.count());
      const c = lab.config();
      const seek = c.seek;
      hud.textContent = [
        `step ${lab.time().toFixed(0)}`,
        `${lab.count().toLocaleString("en")} boids`,
        seek.kind === "reynolds" ? "Reynolds" : `Parker ${+(seek.fraction * 100).toPrecision(3)} %`,
        c.separation ? `separation ${+c.separation_weight.toPrecision(3)}` : "no separation",
        `${stats.fps.toFixed(0)} fps`,
        st ? `step ${stats.stepMs.toFixed(1)} ms in ${st.workers} worker${st.workers === 1 ? "" : "s"}` : `step ${stats.stepMs.toFixed(2)} ms`,
        `draw ${stats.drawMs.toFixed(2)} ms`,
      ].join("  ·  ");
    }
  };
  requestAnimationFrame(frame);
}
