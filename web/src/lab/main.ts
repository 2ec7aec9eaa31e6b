// The funnelling page (index.html): loads the core and the η table, then
// wires the simulation, the panel, the canvas drags and the loop together.

import { setupCanvas } from "../ui/canvas";
import { $, currentMessage, showMessage, showMessages, showVersion } from "../ui/page";
import { View } from "../ui/view";
import { errorText, fetchTable, installTable, Lab, loadCore, precision, ranges } from "../core/wasm";
import { limitDefaults, RangeTable } from "./fields";
import { obstacleDrags } from "./avoidance";
import { avoidanceSection } from "./avoidpanel";
import { crowdSection } from "./crowdpanel";
import { attachDrags, handlePositions, type DragSink, type Handles } from "./handles";
import { labKeyboard } from "./keyboard";
import { obstacleLimits } from "./obstacles";
import { fnvHex } from "../ui/fnv";
import type { LabPage } from "./app";
import { installHook } from "./hook";
import { runLoop } from "./loop";
import { buildPanel } from "./panel";
import { presetNames } from "./presets";
import { HANDLE_PX, SceneBuilder } from "./scene";
import { LabSim, TABLE_URL } from "./sim";
import { buildTransport } from "./transport";
import { decodeState } from "./urlstate";
import { openTableCache } from "./tablecache";
import { tableBadge } from "./loading";
import { buildLegend, legendCarLike } from "./legend";
import { PeerCompare } from "./compareview";
import { LabGpu } from "./gpucrowd";
import { gpuSection } from "./gpupanel";

const page: LabPage = {
  status: { ready: false, error: null, problems: [], version: "", tableAt: NaN },
  loop: { frames: 0, firstDrawnMs: NaN },
  parts: null,
  probe: null,
};
const status = page.status;
// The test build's window.__lab; the shipped build drops this line and hook.ts.
if (import.meta.env.MODE === "test") installHook(page);
performance.mark("lab:main");
const legendEl = document.querySelector<HTMLElement>(".stage .legend");
if (legendEl) buildLegend(legendEl);

async function start(): Promise<void> {
  // The table's fetch starts with the core's instantiation, and the first
  // frame does not wait for it (Lab.withoutTable: the scene at t = 0 with
  // seek steering, the clock held until the table is in).
  const tableBytes = fetchTable(TABLE_URL);
  // The table cache opens beside the core's loading (a reload with other
  // limits reads its table from there as soon as the lab starts).
  openTableCache();
  const version = await loadCore();
  performance.mark("lab:core");
  status.version = version;
  showVersion(version);
  const lab = Lab.withoutTable();

  // The link is read against the core's ranges and default limits.
  const table = new RangeTable(ranges(), precision());
  const decoded = decodeState(location.hash, presetNames(), table, limitDefaults(lab.params()));
  const st = decoded.state;
  status.problems = decoded.problems;
  const title = "Some of the link's state was ignored:";
  if (decoded.problems.length > 0) showMessages(title, decoded.problems, "warn");
  const shown = currentMessage();

  const canvas = $<HTMLCanvasElement>("lab");
  const view = new View();
  const sim = new LabSim(lab, st, view, table);
  const surface = setupCanvas(canvas, (sf) => {
    view.resize(sf.width, sf.height);
    sim.dirty = true;
  });
  const transport = buildTransport(sim);
  const goal = buildPanel(sim, canvas);
  const changed = (): void => {
    sim.dirty = true;
    sim.url.save();
  };
  avoidanceSection($("panel"), sim.avoid, () => ({ x: view.cx, y: view.cy }), changed);
  crowdSection($("panel"), sim, transport);
  const compare = new PeerCompare(sim, lab);
  compare.section($("panel"));
  const gpu = new LabGpu(canvas.parentElement ?? document.body);
  sim.gpu = gpu;
  const engine = gpuSection($("panel"), sim);
  sim.onGpuNote = (t) => engine.note(t);

  const handles = (): Handles | null =>
    sim.focus >= 0 && sim.focus < sim.count ? handlePositions(view, st, sim.pose(sim.focus), HANDLE_PX) : null;
  const sink: DragSink = {
    target: (x, y) => { st.target.x = x; st.target.y = y; sim.updateGoal(); },
    beta: (b) => { st.target.theta = b; goal.beta.set(b); sim.updateGoal(); },
    epsTol: (e) => { st.epsTol = e; goal.epsTol.set(e); sim.updateGoal(); },
    dTol: (d) => { st.dTol = d; goal.dTol.set(d); sim.updateGoal(); },
    vehicle: (pose) => { st.vehicle = pose; sim.placeVehicle(); },
    vehiclePose: () => sim.pose(sim.focus),
    dTolNow: () => st.dTol,
    redraw: () => { sim.dirty = true; sim.url.save(); },
  };
  const limits = obstacleLimits(table);
  attachDrags(canvas, view, handles, sink, obstacleDrags(view, sim.avoid, limits, changed));
  const keyboard = labKeyboard(canvas, {
    view, sink, handles, avoid: sim.avoid, limits, changed,
    target: () => ({ x: st.target.x, y: st.target.y, beta: st.target.theta, dTol: st.dTol, epsTol: st.epsTol }),
  });

  page.parts = { sim, view, transport, handles, compare };
  const since = performance.now();
  await sim.rebuild(true);
  performance.mark("lab:scene");
  // The frame the HTML drew (firstframe.ts) must be this scene.
  const early = window.__firstFrame;
  if (early && (fnvHex(early.state) !== fnvHex(sim.state) || early.view.scale !== view.scale || early.view.cx !== view.cx || early.view.cy !== view.cy)) {
    console.warn("the first frame drawn from the HTML is not the core's scene at t = 0 (rebuild web/dist)");
  }
  // A refused value does not stick in the address bar: it now holds the state in force.
  if (decoded.problems.length > 0) {
    // The build may have warned too (a vehicle limit the table was not built for): both stay.
    const other = currentMessage();
    showMessages(title, other !== null && other !== shown ? [...decoded.problems, other] : decoded.problems, "warn");
    sim.url.writeNow();
  }
  transport.setPaused(false);
  const badge = tableBadge(canvas.parentElement ?? document.body);
  runLoop(sim, new SceneBuilder(sim), surface, view, $("hud"), page.loop, page.probe, since, (s, v) => {
    compare.draw(s, v);
    keyboard.place();
    if (legendEl) legendCarLike(legendEl, (sim.params().minTurnRadius ?? 0) > 0);
    gpu.draw(v);
  });

  // The table: the agents are planned with it and the clock starts.
  const t0 = performance.now();
  try {
    const bytes = await tableBytes;
    sim.tableArrived(() => installTable(lab, bytes, TABLE_URL), performance.now() - t0);
  } catch (e) {
    // A table built or cached for the link's limits may have come first.
    if (!lab.hasTable()) {
      const msg = `The lab cannot run: ${errorText(e)}`;
      status.error = msg;
      sim.tableFailed(msg);
      badge.fail("no η table");
      showMessage(msg, "error");
      return;
    }
  }
  performance.mark("lab:table");
  status.tableAt = performance.now();
  badge.done();
  sim.dirty = true;
  status.ready = true;
}

start().catch((e: unknown) => {
  const msg = `The lab failed to start: ${errorText(e)}`;
  status.error = msg;
  showMessage(msg, "error");
});
