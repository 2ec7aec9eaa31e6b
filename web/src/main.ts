// Wiring: loads the core and the η table, builds the panel, owns the
// simulation clock and the animation loop, and routes drags to the core.

import { beginFrame, setupCanvas, type Surface } from "./canvas";
import { controllerSection, funnelConfig } from "./controller";
import { button, checkbox, section, slider, type Control } from "./controls";
import { downloadCsv, downloadJson, downloadPng } from "./export";
import { renderHud } from "./hud";
import { attachDrags, handlePositions, type Handles } from "./handles";
import { findPreset, PRESETS, presetNames } from "./presets";
import { COLOURS, CROWD_THRESHOLD, drawScene, type FieldDraw, type Overlay, type Scene, type TargetDraw } from "./render";
import { defaultState, type LabState, type Overlays, type Pose } from "./state";
import { Trails } from "./trails";
import { decodeState, encodeState } from "./urlstate";
import { View } from "./view";
import {
  createLab,
  errorText,
  loadCore,
  S,
  STATE_STRIDE,
  type FunnelConfig,
  type GoalConfig,
  type Internals,
  type Lab,
  type VehicleParams,
} from "./wasm";

const DEG = Math.PI / 180;
const HANDLE_PX = 56;
const TABLE_URL = "tables/eta.bin";
const PLAYGROUND_HELP =
  "Playground: drag the vehicle (body: position, white knob: heading), the target (centre), its β knob, " +
  "the tolerance circle's rim and the triangle's corner. The target shows the controller's mode live.";

/** What the end-to-end tests and the perf harness read (window.__lab). */
export interface LabHook {
  ready: boolean;
  error: string | null;
  problems: string[];
  version: string;
  /** performance.now() when the first frame with agents was drawn. */
  firstFrameMs: number;
  frames: number;
  count(): number;
  mode(): number | null;
  internals(): Internals | null;
  /** The funnelling settings in force in the core. */
  funnel(): FunnelConfig | null;
  state(): LabState;
  /** CSS-pixel canvas coordinates of the focus target's centre, rim, handles and of the vehicle. */
  handles(): Handles | null;
  setPreset(name: string): Promise<void>;
  presets(): string[];
  setPaused(p: boolean): void;
  perfReset(): void;
  perfStats(): { frames: number; meanIntervalMs: number; meanWorkMs: number; p95WorkMs: number; meanStepMs: number; meanDrawMs: number; usPerUpdate: number; agents: number };
}

declare global {
  interface Window {
    __lab?: LabHook;
  }
}

const $ = <T extends HTMLElement>(id: string): T => {
  const el = document.getElementById(id);
  if (!el) throw new Error(`#${id} missing from index.html`);
  return el as T;
};

const messageEl = $<HTMLDivElement>("message");
function showMessage(text: string, kind: "warn" | "error"): void {
  messageEl.hidden = false;
  messageEl.className = `message ${kind}`;
  messageEl.textContent = text;
}

const hook: LabHook = {
  ready: false,
  error: null,
  problems: [],
  version: "",
  firstFrameMs: NaN,
  frames: 0,
  count: () => 0,
  mode: () => null,
  internals: () => null,
  funnel: () => null,
  state: () => defaultState(),
  handles: () => null,
  setPreset: async () => {},
  presets: () => presetNames(),
  setPaused: () => {},
  perfReset: () => {},
  perfStats: () => ({ frames: 0, meanIntervalMs: 0, meanWorkMs: 0, p95WorkMs: 0, meanStepMs: 0, meanDrawMs: 0, usPerUpdate: 0, agents: 0 }),
};
window.__lab = hook;

async function start(): Promise<void> {
  const decoded = decodeState(location.hash, presetNames());
  const st: LabState = decoded.state;
  hook.problems = decoded.problems;
  if (decoded.problems.length > 0) {
    showMessage(`Some of the link's state was ignored:\n• ${decoded.problems.join("\n• ")}`, "warn");
  }

  const version = await loadCore();
  hook.version = version;
  $("version").textContent = `core ${version}`;

  let lab: Lab;
  try {
    lab = await createLab(TABLE_URL);
  } catch (e) {
    const msg = `The lab cannot start: ${errorText(e)}`;
    hook.error = msg;
    showMessage(msg, "error");
    return;
  }
  const defaults: VehicleParams = lab.params();

  // ---- simulation state owned by the page ----------------------------------
  const trails = new Trails(200, 3000);
  let paused = false;
  let simTime = 0;
  let acc = 0;
  let focus = -1;
  let dirty = true;
  let usPerUpdate = 0;
  let fieldCache: { key: string; samples: Float32Array } | null = null;
  let stateBuf: Float32Array = new Float32Array(0);
  let count = 0;

  const canvas = $<HTMLCanvasElement>("lab");
  const view = new View();
  const surface: Surface = setupCanvas(canvas, (sf) => {
    view.resize(sf.width, sf.height);
    dirty = true;
  });

  const params = (): VehicleParams => ({ ...defaults, ...st.limits });
  const goal = (): GoalConfig => ({
    x: st.target.x,
    y: st.target.y,
    beta: st.target.theta,
    dTol: st.dTol,
    epsTol: st.epsTol,
    speed: st.speed,
    halting: st.halting,
    relaxed: st.relaxed,
  });

  let urlTimer = 0;
  const saveUrl = (): void => {
    if (urlTimer) return;
    urlTimer = window.setTimeout(() => {
      urlTimer = 0;
      st.view = { cx: view.cx, cy: view.cy, scale: view.scale };
      history.replaceState(null, "", `#${encodeState(st)}`);
    }, 250);
  };

  const pull = (): void => {
    count = lab.count();
    stateBuf = lab.state();
    dirty = true;
  };

  /** Internals of agent i, or null (no such agent: the world is being rebuilt). */
  const internalsOf = (i: number): Internals | null => {
    if (i < 0 || i >= count) return null;
    try {
      return lab.internals(i);
    } catch {
      return null;
    }
  };

  const applyParams = (): void => {
    try {
      const warning = lab.setParams(params());
      if (warning) showMessage(`Vehicle limits: ${warning}`, "warn");
    } catch (e) {
      showMessage(`Vehicle limits rejected: ${errorText(e)}`, "warn");
    }
  };

  /** The page's controller settings to the core (world-wide, presets included). */
  const applyFunnel = (): void => {
    try {
      lab.setFunnel(funnelConfig(st.funnel));
    } catch (e) {
      showMessage(`Controller settings rejected: ${errorText(e)}`, "warn");
    }
    dirty = true;
  };

  let generation = 0;
  let dt = defaults.dt;
  /** Shows the URL's view once (the first build), else fits when asked. */
  let sharedView = st.view;
  const rebuild = async (fitAsked: boolean): Promise<void> => {
    const fit = fitAsked && sharedView === null;
    if (sharedView) {
      view.cx = sharedView.cx;
      view.cy = sharedView.cy;
      view.scale = sharedView.scale;
      sharedView = null;
    }
    const gen = ++generation;
    lab.clear();
    pull();
    applyParams();
    trails.clear();
    simTime = 0;
    acc = 0;
    focus = -1;
    if (st.preset) {
      const p = findPreset(st.preset);
      try {
        if (!p) throw new Error(`no preset named ${st.preset}`);
        const text = await p.load();
        if (gen !== generation) return;
        const info = lab.loadScenario(text);
        goalBox.disabled = true;
        caption.textContent = `${info.description}${info.source ? ` (${info.source})` : ""} — ${info.agents} agents.`;
        if (info.warning) showMessage(`Preset ${st.preset}: ${info.warning}`, "warn");
        if (fit) view.fit(info.minX, info.minY, info.maxX, info.maxY);
      } catch (e) {
        showMessage(`Preset ${st.preset} could not be loaded: ${errorText(e)}`, "error");
      }
    } else {
      caption.textContent = PLAYGROUND_HELP;
      goalBox.disabled = false;
      try {
        lab.addAgent({ x: st.vehicle.x, y: st.vehicle.y, theta: st.vehicle.theta, goals: [goal()] });
        focus = 0;
        if (st.agents > 0) lab.spawnRandom(st.agents, st.seed, Math.max(10, Math.sqrt(st.agents) * 1.5), st.speed);
      } catch (e) {
        showMessage(`The playground could not be set up: ${errorText(e)}`, "error");
      }
      if (fit) {
        if (st.agents > 0) {
          const r = Math.max(10, Math.sqrt(st.agents) * 1.5) + 3;
          view.fit(-r, -r, r, r);
        } else {
          const xs = [st.vehicle.x, st.target.x];
          const ys = [st.vehicle.y, st.target.y];
          view.fit(Math.min(...xs) - 3, Math.min(...ys) - 3, Math.max(...xs) + 3, Math.max(...ys) + 3, 60);
        }
      }
    }
    applyFunnel();
    dt = lab.params().dt;
    pull();
    trails.record(0, stateBuf, STATE_STRIDE, count);
  };

  const updateGoal = (): void => {
    if (focus < 0) return;
    try {
      lab.setGoal(focus, goal());
    } catch (e) {
      showMessage(`Goal rejected: ${errorText(e)}`, "warn");
    }
    pull();
    saveUrl();
  };

  const placeVehicle = (): void => {
    if (focus < 0) return;
    try {
      lab.setPose(focus, st.vehicle.x, st.vehicle.y, st.vehicle.theta);
    } catch (e) {
      showMessage(`Pose rejected: ${errorText(e)}`, "warn");
    }
    trails.clearAgent(focus);
    pull();
    saveUrl();
  };

  // ---- panel ---------------------------------------------------------------
  const panel = $("panel");
  const caption = $("caption");
  const controls: Record<string, Control> = {};
  const transport = $("transport");
  const playBtn = button(transport, "play", "Pause", "Play / pause (space)", () => setPaused(!paused));
  button(transport, "step", "Step", "Single step (s)", () => stepOnce());
  const slowBtn = button(transport, "slow", "Slow ×¼", "Slow motion", () => {
    st.slow = !st.slow;
    slowBtn.setAttribute("aria-pressed", String(st.slow));
    saveUrl();
  });
  slowBtn.setAttribute("aria-pressed", String(st.slow));
  button(transport, "reset", "Reset", "Reset (r)", () => void rebuild(false));

  const setPaused = (p: boolean): void => {
    paused = p;
    playBtn.textContent = paused ? "▶ Play" : "Pause";
    playBtn.setAttribute("aria-pressed", String(paused));
  };
  const stepOnce = (): void => {
    setPaused(true);
    lab.step(1);
    simTime += dt;
    pull();
    trails.record(simTime, stateBuf, STATE_STRIDE, count);
  };

  const goalBox = section(panel, "Target (playground)");
  controls.speed = slider(goalBox, {
    id: "speed", label: "desired speed v_d", unit: "m/s", min: 0.1, max: 4, step: 0.05, value: st.speed,
    onInput: (v) => { st.speed = v; updateGoal(); },
  });
  controls.dTol = slider(goalBox, {
    id: "dtol", label: "position tol. D_tol", unit: "m", min: 0.02, max: 3, step: 0.01, value: st.dTol,
    onInput: (v) => { st.dTol = v; updateGoal(); },
  });
  controls.epsTol = slider(goalBox, {
    id: "etol", label: "orient. tol. ε_tol", unit: "°", min: 0.5 * DEG, max: 90 * DEG, step: 0.5 * DEG, value: st.epsTol,
    display: 1 / DEG, digits: 1, onInput: (v) => { st.epsTol = v; updateGoal(); },
  });
  controls.beta = slider(goalBox, {
    id: "beta", label: "orientation β", unit: "°", min: -180 * DEG, max: 180 * DEG, step: DEG, value: st.target.theta,
    display: 1 / DEG, digits: 0, onInput: (v) => { st.target.theta = v; updateGoal(); },
  });
  const goalRow = document.createElement("div");
  goalRow.className = "row";
  goalBox.append(goalRow);
  checkbox(goalRow, "halting", "final halting", st.halting, (v) => { st.halting = v; updateGoal(); });
  const relaxedBox = checkbox(goalRow, "relaxed", "relaxed (region goal)", st.relaxed, (v) => { st.relaxed = v; updateGoal(); });
  relaxedBox.el.title = "paper 001: any point of the disk and any heading within β ± ε_tol is a valid goal";

  controllerSection(panel, st.funnel, () => { applyFunnel(); saveUrl(); });

  const limBox = section(panel, "Vehicle limits");
  const lim = (id: string, key: "vMax" | "accelMax" | "omegaMax" | "omegaAccelMax" | "normalAccelMax", label: string, unit: string, max: number): void => {
    controls[id] = slider(limBox, {
      id, label, unit, min: 0.05, max, step: 0.05, value: st.limits[key] ?? defaults[key],
      onInput: (v) => { st.limits[key] = v; applyParams(); saveUrl(); },
    });
  };
  lim("vmax", "vMax", "max speed", "m/s", 6);
  lim("amax", "accelMax", "max accel.", "m/s²", 10);
  lim("wmax", "omegaMax", "max ang. speed", "rad/s", 10);
  lim("awmax", "omegaAccelMax", "max ang. accel.", "rad/s²", 60);
  lim("anmax", "normalAccelMax", "max normal acc. A", "m/s²", 10);

  const ovBox = section(panel, "Overlays");
  const ov = (key: keyof Overlays, label: string): void => {
    checkbox(ovBox, `ov-${key}`, label, st.overlays[key], (v) => { st.overlays[key] = v; dirty = true; saveUrl(); });
  };
  ov("radial", "radial direction");
  ov("eta", "η at target");
  ov("gamma", "heading γ");
  ov("ring", "nearest η ring");
  ov("arc", "relaxed arc 𝒜, α_r");
  ov("trails", "trails");
  ov("field", "η field (Fig. 3b/c)");

  const fieldBox = section(panel, "η field view");
  const fieldSlider = (id: string, key: "vC" | "omegaC" | "vD", label: string, unit: string, min: number, max: number): void => {
    controls[id] = slider(fieldBox, {
      id, label, unit, min, max, step: 0.05, value: st.field[key],
      onInput: (v) => { st.field[key] = v; fieldCache = null; dirty = true; saveUrl(); },
    });
  };
  fieldSlider("fvc", "vC", "current v_c", "m/s", 0, 4);
  fieldSlider("fwc", "omegaC", "current ω_c", "rad/s", -3, 3);
  fieldSlider("fvd", "vD", "desired v_d", "m/s", 0.1, 4);
  const fieldHelp = document.createElement("p");
  fieldHelp.className = "help";
  fieldHelp.textContent = "Arrows: final direction α+η at each sampled target around the vehicle; darker = unreachable at v_d (η shown for the stored v_dt).";
  fieldBox.append(fieldHelp);

  const exBox = section(panel, "Share and export");
  const exRow = document.createElement("div");
  exRow.className = "row";
  exBox.append(exRow);
  button(exRow, "copy-link", "Copy link", "Copy a link with the whole state", () => {
    st.view = { cx: view.cx, cy: view.cy, scale: view.scale };
    history.replaceState(null, "", `#${encodeState(st)}`);
    void navigator.clipboard?.writeText(location.href).catch(() => {});
  });
  button(exRow, "csv", "CSV", "Trajectories as CSV", () => downloadCsv(trails));
  button(exRow, "json", "JSON", "Trajectories as JSON", () => downloadJson(trails, { state: st, params: params() }));
  button(exRow, "png", "PNG", "The canvas as PNG", () => downloadPng(canvas));
  const keys = document.createElement("p");
  keys.className = "help";
  keys.innerHTML = "<kbd>space</kbd> pause · <kbd>s</kbd> step · <kbd>r</kbd> reset · drag empty space to pan, wheel to zoom.";
  exBox.append(keys);

  const presetSel = $<HTMLSelectElement>("preset");
  const addOpt = (value: string, label: string): void => {
    const o = document.createElement("option");
    o.value = value;
    o.textContent = label;
    presetSel.append(o);
  };
  addOpt("", "playground");
  for (const p of PRESETS) addOpt(p.name, p.name);
  presetSel.value = st.preset;
  const setPreset = async (name: string): Promise<void> => {
    st.preset = name;
    presetSel.value = name;
    await rebuild(true);
    saveUrl();
  };
  presetSel.addEventListener("change", () => void setPreset(presetSel.value));

  window.addEventListener("keydown", (e) => {
    const t = e.target;
    if (t instanceof HTMLSelectElement || t instanceof HTMLButtonElement || (t instanceof HTMLInputElement && t.type === "text")) return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (e.key === " ") {
      e.preventDefault();
      setPaused(!paused);
    } else if (e.key === "s" || e.key === "S") {
      stepOnce();
    } else if (e.key === "r" || e.key === "R") {
      void rebuild(false);
    }
  });

  // ---- dragging --------------------------------------------------------------
  const agentPose = (i: number): Pose => ({
    x: stateBuf[i * STATE_STRIDE + S.x] ?? 0,
    y: stateBuf[i * STATE_STRIDE + S.y] ?? 0,
    theta: stateBuf[i * STATE_STRIDE + S.theta] ?? 0,
  });
  const handles = (): Handles | null =>
    focus >= 0 && focus < count ? handlePositions(view, st, agentPose(focus), HANDLE_PX) : null;
  attachDrags(canvas, view, handles, {
    target: (x, y) => { st.target.x = x; st.target.y = y; updateGoal(); },
    beta: (b) => { st.target.theta = b; controls.beta?.set(b); updateGoal(); },
    epsTol: (e) => { st.epsTol = e; controls.epsTol?.set(e); updateGoal(); },
    dTol: (d) => { st.dTol = d; controls.dTol?.set(d); updateGoal(); },
    vehicle: (pose) => { st.vehicle = pose; placeVehicle(); },
    vehiclePose: () => ({ ...agentPose(focus) }),
    redraw: () => { dirty = true; saveUrl(); },
  });

  // ---- frame loop --------------------------------------------------------------
  const hudEl = $("hud");
  const perf = { intervals: [] as number[], work: [] as number[], step: [] as number[], draw: [] as number[], updates: 0, updateMs: 0 };
  let lastFrame = performance.now();
  let frameMsEma = 0;

  const targetsOf = (): TargetDraw[] => {
    const out: TargetDraw[] = [];
    if (count > CROWD_THRESHOLD) return out;
    for (let i = 0; i < count; i++) {
      if (i === focus) continue;
      const o = i * STATE_STRIDE;
      out.push({
        x: stateBuf[o + S.goalX]!, y: stateBuf[o + S.goalY]!, beta: stateBuf[o + S.goalBeta]!,
        dTol: stateBuf[o + S.goalDTol]!, epsTol: stateBuf[o + S.goalEpsTol]!, mode: stateBuf[o + S.mode]!,
      });
    }
    return out;
  };

  const frame = (now: number): void => {
    const interval = now - lastFrame;
    lastFrame = now;
    const t0 = performance.now();
    let stepMs = 0;
    let drawMs = 0;
    if (!paused && count > 0) {
      acc += Math.min(0.1, interval / 1000) * (st.slow ? 0.25 : 1);
      let k = Math.floor(acc / dt);
      if (k > 4) { k = 4; acc = 0; } else acc -= k * dt;
      if (k > 0) {
        const s0 = performance.now();
        lab.step(k);
        stepMs = performance.now() - s0;
        perf.updates += k * count;
        perf.updateMs += stepMs;
        usPerUpdate = usPerUpdate === 0 ? (stepMs * 1000) / (k * count) : 0.9 * usPerUpdate + 0.1 * (stepMs * 1000) / (k * count);
        simTime += k * dt;
        pull();
        if (st.overlays.trails && count <= trails.maxAgents) trails.record(simTime, stateBuf, STATE_STRIDE, count);
      }
    }
    if (dirty || !paused) {
      beginFrame(surface, COLOURS.background);
      const inter = internalsOf(focus >= 0 ? focus : 0);
      const who = focus >= 0 ? focus : 0;
      const pose = agentPose(who);
      let overlay: Overlay | null = null;
      if (inter && count > 0) {
        const g = who * STATE_STRIDE;
        overlay = {
          x: pose.x, y: pose.y, theta: pose.theta,
          targetX: stateBuf[g + S.goalX] ?? 0, targetY: stateBuf[g + S.goalY] ?? 0,
          etaDir: st.overlays.eta && Number.isFinite(inter.eta) ? pose.theta + inter.alpha + inter.eta : null,
          gamma: st.overlays.gamma && Number.isFinite(inter.gamma) ? inter.gamma : null,
          arc: st.overlays.arc && inter.arc ? { r: inter.arc.radius, a0: pose.theta + inter.arc.alphaMin, a1: pose.theta + inter.arc.alphaMax, ar: pose.theta + inter.arc.alphaR } : null,
        };
      }
      let ring: FieldDraw | null = null;
      if (st.overlays.ring && count > 0) {
        ring = { samples: count > who ? lab.etaRing(who) : new Float32Array(0), originX: pose.x, originY: pose.y, theta: pose.theta, light: COLOURS.ring, dark: COLOURS.ringDark };
      }
      let field: FieldDraw | null = null;
      if (st.overlays.field && count > 0) {
        const key = `${st.field.vC}|${st.field.omegaC}|${st.field.vD}`;
        if (!fieldCache || fieldCache.key !== key) fieldCache = { key, samples: lab.etaField(st.field.vC, st.field.omegaC, st.field.vD) };
        field = { samples: fieldCache.samples, originX: pose.x, originY: pose.y, theta: pose.theta, light: COLOURS.field, dark: COLOURS.fieldDark };
      }
      const focusTarget: TargetDraw | null = focus >= 0
        ? { x: st.target.x, y: st.target.y, beta: st.target.theta, dTol: st.dTol, epsTol: st.epsTol, mode: inter?.mode ?? 3 }
        : null;
      const scene: Scene = {
        state: stateBuf, stride: STATE_STRIDE, count,
        targets: targetsOf(),
        trails: st.overlays.trails && count <= trails.maxAgents ? trails : null,
        focus, focusTarget, overlay,
        showRadial: st.overlays.radial,
        ring, field, handlePx: HANDLE_PX,
      };
      const d0 = performance.now();
      drawScene(surface, view, scene);
      drawMs = performance.now() - d0;
      renderHud(hudEl, {
        mode: inter?.mode ?? null,
        d: inter?.d ?? NaN, alpha: inter?.alpha ?? NaN, eta: inter?.eta ?? NaN,
        deltaEta: inter?.deltaEta ?? NaN, mu: inter?.mu ?? NaN, muMax: inter?.muMax ?? NaN,
        speed: stateBuf[who * STATE_STRIDE + 3] ?? 0,
        reachable: inter?.reachable ?? true,
        usPerUpdate, frameMs: frameMsEma, agents: count, time: simTime, paused, slow: st.slow,
      });
      dirty = false;
      hook.frames++;
      if (Number.isNaN(hook.firstFrameMs) && count > 0) hook.firstFrameMs = performance.now();
    }
    const work = performance.now() - t0;
    frameMsEma = frameMsEma === 0 ? work : 0.95 * frameMsEma + 0.05 * work;
    perf.intervals.push(interval);
    perf.work.push(work);
    perf.step.push(stepMs);
    perf.draw.push(drawMs);
    if (perf.intervals.length > 2000) { perf.intervals.shift(); perf.work.shift(); perf.step.shift(); perf.draw.shift(); }
    requestAnimationFrame(frame);
  };

  // ---- hook ------------------------------------------------------------------
  hook.count = () => count;
  hook.mode = () => internalsOf(focus >= 0 ? focus : 0)?.mode ?? null;
  hook.internals = () => internalsOf(focus >= 0 ? focus : 0);
  hook.funnel = () => lab.funnel();
  hook.state = () => structuredClone(st);
  hook.handles = handles;
  hook.setPreset = setPreset;
  hook.setPaused = setPaused;
  hook.perfReset = () => { perf.intervals = []; perf.work = []; perf.step = []; perf.draw = []; perf.updates = 0; perf.updateMs = 0; };
  hook.perfStats = () => {
    const mean = (a: number[]): number => (a.length ? a.reduce((x, y) => x + y, 0) / a.length : 0);
    const sorted = [...perf.work].sort((a, b) => a - b);
    return {
      frames: perf.intervals.length,
      meanIntervalMs: mean(perf.intervals),
      meanWorkMs: mean(perf.work),
      p95WorkMs: sorted[Math.floor(sorted.length * 0.95)] ?? 0,
      meanStepMs: mean(perf.step),
      meanDrawMs: mean(perf.draw),
      usPerUpdate: perf.updates ? (perf.updateMs * 1000) / perf.updates : 0,
      agents: count,
    };
  };

  await rebuild(true);
  setPaused(false);
  hook.ready = true;
  requestAnimationFrame(frame);
}

start().catch((e: unknown) => {
  const msg = `The lab failed to start: ${errorText(e)}`;
  hook.error = msg;
  showMessage(msg, "error");
});
