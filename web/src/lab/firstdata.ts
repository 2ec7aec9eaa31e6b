// Issue 17: the default playground at t = 0 as the core builds it, for the
// first frame the lab's HTML draws (firstframe.ts). Run at build time in
// Node on the core's own package (vite.config.ts, firstFrame): the same
// steps as sim.ts's first build of the page without a link (a table-less
// lab, the default limits, the playground agent, the controller settings).

import type * as Core from "../../pkg/steering.js";
import type { FirstFrameData } from "./firstframe";
import { funnelConfig, relaxedConfig } from "./funnelsettings";
import { defaultState, goalConfig } from "./state";

export function firstFrameData(core: typeof Core): FirstFrameData {
  const st = defaultState();
  const lab = core.Lab.withoutTable();
  try {
    lab.setParams(lab.params());
    lab.addAgent({ x: st.vehicle.x, y: st.vehicle.y, theta: st.vehicle.theta, goals: [goalConfig(st)] });
    lab.setFunnel(funnelConfig(st.funnel));
    lab.setRelaxed(relaxedConfig(st.funnel));
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
