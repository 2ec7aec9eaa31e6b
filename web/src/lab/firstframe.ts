// The first drawn frame: the default playground drawn while the page's
// scripts and the wasm core are still on their way.
//
// Problem: a first frame drawn by the page's modules waits for its script
// chunks, then for the core to compile and build the scene (`make
// bench-web` times where that time goes).
// Design: the scene at t = 0 of the page without a link (no hash) is always
// the same: the build (vite.config.ts, `firstFrame`) runs the core itself in
// Node on that state (`Lab.withoutTable`, the playground agent as sim.ts
// builds it) and writes what the page's core will read at t = 0 into
// index.html: the state record, the focus agent's internals and its
// predicted seek path. This module, inlined into the same HTML (no request),
// draws them with the page's own renderer (SceneBuilder + drawScene + HUD)
// as soon as it runs, while the HTML is parsed (its time: the start of the
// animation frame that shows it; the page's loop times a frame after drawing
// it, in that frame). The core then builds the same scene from the same
// state (recipe.ts, the calls of firstdata.ts): main.ts checks the core's state against this one bit for bit (a
// warning if they differ; the e2e suite fails on it) and its first frame
// replaces this one. Fallback: a link with a hash, a `?workers=` page, or a
// build without the data draws nothing here; the page's own first frame
// is the first.

import { beginFrame, fitSurface, type Surface } from "../ui/canvas";
import { View } from "../ui/view";
import { StateField, type Ghost, type Internals } from "../core/wasm";
import { renderHud } from "./hud";
import { COLOURS, drawScene } from "./render";
import { SceneBuilder, type SceneSource } from "./scene";
import { defaultState, fitPlayground, type Pose } from "./state";
import { Trails } from "./trails";

/** What the build writes into index.html (window.__firstFrameData). */
export interface FirstFrameData {
  stride: number;
  /** The core's state records at t = 0 (f32 values). */
  state: number[];
  /** The focus agent's internals at t = 0 (`Lab.internals(0)`). */
  internals: Internals;
  /** Its predicted seek path (`Lab.ghost(0)`), points as x, y pairs. */
  ghost: { points: number[]; reached: boolean; finalDir: number; slowed: boolean } | null;
}

/** What was drawn, and when (window.__firstFrame; hook.ts and main.ts read it). */
export interface FirstFrameRecord {
  /** performance.now() after the frame was drawn. */
  ms: number;
  state: Float32Array;
  view: { cx: number; cy: number; scale: number; width: number; height: number };
}

declare global {
  interface Window {
    __firstFrameData?: FirstFrameData;
    __firstFrame?: FirstFrameRecord;
  }
}

/** Whether this page's first scene is the default playground's. */
export function defaultScene(loc: Location): boolean {
  return (loc.hash === "" || loc.hash === "#") && !new URLSearchParams(loc.search).has("workers");
}

/** Draws the carried first frame now, while the HTML is parsed (the first
 *  rendering opportunity then shows it; its time is that frame's start). */
export function drawFirstFrame(data: FirstFrameData | undefined): void {
  if (!data || !defaultScene(location)) return;
  const canvas = document.getElementById("lab");
  const hud = document.getElementById("hud");
  if (!(canvas instanceof HTMLCanvasElement) || !hud) return;
  performance.mark("lab:firstscript");
  {
    const ctx = canvas.getContext("2d", { alpha: false });
    if (!ctx) return;
    // Sized as the page will size it (../ui/canvas.ts).
    const surface: Surface = { canvas, ctx, width: 1, height: 1, dpr: 1 };
    fitSurface(surface);
    const view = new View();
    view.resize(surface.width, surface.height);
    const st = defaultState();
    fitPlayground(view, st);
    const state = Float32Array.from(data.state);
    const trails = new Trails();
    trails.record(0, state, data.stride, 1);
    const ghost: Ghost | null = data.ghost ? ({ ...data.ghost, points: Float32Array.from(data.ghost.points) } as unknown as Ghost) : null;
    const at = (i: number, f: StateField): number | undefined => state[i * data.stride + f];
    const pose = (i: number): Pose => ({ x: at(i, StateField.X) ?? 0, y: at(i, StateField.Y) ?? 0, theta: at(i, StateField.Theta) ?? 0 });
    const source: SceneSource = {
      st, count: 1, state, stride: data.stride, focus: 0, shown: 0, live: false, trails,
      usPerUpdate: 0, time: 0, paused: false,
      pose: (i) => pose(i),
      field: at,
      // sim.ts's line while the table loads.
      tableLine: () => "loading… (seek view)",
      steppingLine: () => undefined,
      etaField: () => new Float32Array(0),
      world: { ghost: () => ghost, ring: () => null },
      avoid: { method: "off", radius: 0, obstacles: [] },
    };
    const scenes = new SceneBuilder(source);
    beginFrame(surface, COLOURS.background);
    drawScene(surface, view, scenes.scene(data.internals));
    renderHud(hud, scenes.hud(data.internals, 0));
    const first: FirstFrameRecord = { ms: NaN, state, view: { cx: view.cx, cy: view.cy, scale: view.scale, width: view.width, height: view.height } };
    // Drawn while the HTML is parsed; the frame that shows it is the next
    // one: its time is the first frame's.
    requestAnimationFrame(() => {
      first.ms = performance.now();
      performance.mark("lab:firstraf");
      window.__firstFrame = first;
    });
  }
}
