// The default playground at t = 0 as the core builds it, for the first
// frame the lab's HTML draws (firstframe.ts). Run at build time in Node on
// the core's own package (vite.config.ts, firstFrame): the page's first
// build of the page without a link, by the same calls (recipe.ts,
// ../world/worldcalls.ts `buildWorld`) on a table-less lab.

import type { Lab } from "../core/wasm";
import type { FirstFrameData } from "./firstframe";
import { recipeFor } from "./recipe";
import { defaultState } from "./state";
import { buildWorld } from "../world/worldcalls";

/** `core`: the core's package (its `Lab`), loaded by the caller. */
export function firstFrameData(core: { Lab: typeof Lab }): FirstFrameData {
  const st = defaultState();
  const lab = core.Lab.withoutTable();
  try {
    const info = buildWorld(lab, recipeFor(st, lab.params(), { key: lab.tableKey(), url: "", bytes: null }, null));
    if (info.messages.length > 0) throw new Error(info.messages.map((m) => m.text).join("; "));
    const g = lab.ghost(0);
    return {
      stride: core.Lab.stateStride(),
      state: Array.from(lab.state()),
      internals: lab.internals(0),
      ghost: { points: Array.from(g.points), reached: g.reached, finalDir: g.finalDir, slowed: g.slowed },
    };
  } finally {
    lab.free();
  }
}
