// The funnelling page's animation loop: advances the simulation clock by
// the wall time since the last frame, draws when something changed, counts
// the frames drawn and tells the probe (the test build's frame-time record)
// each frame's timings.

import { beginFrame, type Surface } from "../ui/canvas";
import type { View } from "../ui/view";
import type { FrameProbe, LoopStats } from "./app";
import { Hud } from "./hud";
import { SpeedMeter } from "../ui/speedmeter";
import { COLOURS, drawScene } from "./render";
import type { SceneBuilder } from "./scene";
import type { LabSim } from "./sim";

/** Starts the loop; `since` is when the page's clock started (the first
 *  frame's interval); `over` draws over each drawn scene (the compare view). */
export function runLoop(sim: LabSim, scenes: SceneBuilder, surface: Surface, view: View, hudEl: HTMLElement, stats: LoopStats, probe: FrameProbe | null, since: number, over: (s: Surface, v: View) => void = () => {}): void {
  let lastFrame = since;
  let frameMsEma = 0;
  const hud = new Hud(hudEl);
  // Frames drawn and simulation time over the last second: the HUD's speed line.
  const meter = new SpeedMeter();
  let simTime = sim.time;
  const frame = (now: number): void => {
    const interval = now - lastFrame;
    lastFrame = now;
    const t0 = performance.now();
    const stepped = sim.advance(interval);
    if (stepped.updates > 0) probe?.stepped(stepped.updates, stepped.ms);
    // A rebuild or a reset starts the clock again: so does the reading.
    if (sim.time < simTime) meter.reset();
    simTime = sim.time;
    const drawing = sim.dirty;
    meter.tick(now, drawing, sim.time, 0);
    let drawMs = 0;
    // A frame draws only a new state, an edit or a new view: redrawing the
    // same picture would take a core from the stepping workers.
    if (sim.dirty) {
      beginFrame(surface, COLOURS.background);
      const inter = sim.internals;
      const scene = scenes.scene(inter);
      const d0 = performance.now();
      drawScene(surface, view, scene);
      over(surface, view);
      drawMs = performance.now() - d0;
      hud.show(scenes.hud(inter, frameMsEma, meter.read()), now);
      sim.dirty = false;
      stats.frames++;
      if (stats.frames === 1) performance.mark("lab:loop");
      if (Number.isNaN(stats.firstDrawnMs) && sim.count > 0) stats.firstDrawnMs = performance.now();
    }
    hud.flush(now);
    const work = performance.now() - t0;
    frameMsEma = frameMsEma === 0 ? work : 0.95 * frameMsEma + 0.05 * work;
    probe?.frame(interval, work, stepped.ms, drawMs);
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}
