// The simulation the funnelling page owns: the core's Lab, the agents'
// state as last read from it, the clock (play, pause, single steps, slow
// motion) and the edits that go to the core (goal, pose, limits, controller
// settings). A rebuild starts the playground or a preset from scratch.

import { showMessage } from "../page";
import type { View } from "../view";
import { errorText, Lab, StateField, type GoalConfig, type Internals, type VehicleParams } from "../wasm";
import { LabAvoidance } from "./avoidance";
import { clampToLimits, FIELDS, type LabField, type RangeTable } from "./fields";
import { funnelConfig, relaxedConfig } from "./funnelsettings";
import { findPreset } from "./presets";
import { fitPlayground, goalConfig, type LabState, type Pose } from "./state";
import { Trails } from "./trails";
import { UrlSync } from "./urlstate";
import { Cancelled } from "../workers/pool";
import { buildTable, cancelBuild, tableKeyFor } from "../workers/tables";
import { type Edit, type Recipe, workersWanted, WorldStepper } from "../workers/stepping";

/** The η table in force against the limits in force (issue 14). */
export interface TableStatus {
  /** `exact`: built for these limits; `building`: the old one, approximate,
   *  while workers build the new one; `error`: no table can be built for
   *  these limits (the old one stays, approximate); `loading`: the page's
   *  first table is still on its way (issue 17: the scene is drawn, the
   *  clock holds at t = 0). */
  state: "exact" | "building" | "error" | "loading";
  /** Build progress, 0..1. */
  progress: number;
  /** Key of the table in force. */
  key: string;
  /** Key wanted for the limits in force. */
  wanted: string;
  /** The last build: wall ms, from the cache or built, workers. */
  ms: number;
  cached: boolean;
  /** The page's committed table, fetched (not built or from the cache). */
  fetched: boolean;
  workers: number;
  /** The last build's phases, ms (tables.ts `BuiltTable.phases`). */
  phases?: Record<string, number>;
  message: string;
}

/** The committed table in byte planes (issue 17: 0.54 MB gzipped, not
 *  1.2; the same bytes once rejoined, src/tableplanes.ts), fetched by the
 *  page and by the stepping workers. */
export const TABLE_URL = "tables/eta.planes";

const PLAYGROUND_HELP =
  "Playground: drag the vehicle (body: position, white knob: heading), the target (centre), its β knob, " +
  "the tolerance circle's rim and the triangle's corner. The target shows the controller's mode live.";

/** The most steps one animation frame runs (a slow frame drops the rest). */
const MAX_STEPS_PER_FRAME = 4;

export class LabSim {
  /** Floats per agent in `state`. */
  readonly stride = Lab.stateStride();
  readonly trails = new Trails(200, 3000);
  readonly defaults: VehicleParams;
  /** The state in the address bar. */
  readonly url: UrlSync;
  count = 0;
  state: Float32Array = new Float32Array(0);
  /** The playground's editable agent, or -1 (presets). */
  focus = -1;
  time = 0;
  dt: number;
  paused = false;
  /** Something changed that the next frame must draw. */
  dirty = true;
  /** Smoothed core cost per agent update, µs. */
  usPerUpdate = 0;
  /** Called by every rebuild: the caption, and whether the playground's target is editable. */
  onScene: (caption: string, playground: boolean, claim?: string, measured?: string) => void = () => {};
  /** The η table's status (HUD, window.__lab.table()). */
  table: TableStatus;
  /** Issue 17: the world stepped in Web Workers (null: on this thread). */
  stepper: WorldStepper | null = null;
  /** Workers asked for by `?workers=N` or the default for the agent count. */
  workersWanted = 0;
  private recipe: Recipe | null = null;
  private readonly defaultTableKey: string;
  /** The bytes of a table built for other limits (workers load them too). */
  private tableBytes: { key: string; bytes: Uint8Array } | null = null;
  /** Avoidance method and obstacles (issue 18). */
  readonly avoid: LabAvoidance;
  private acc = 0;
  private generation = 0;
  private tableGen = 0;
  /** The URL's view, shown once (the first build); later builds fit when asked. */
  private sharedView: LabState["view"];

  constructor(readonly lab: Lab, readonly st: LabState, private readonly view: View, readonly ranges: RangeTable) {
    this.defaults = lab.params();
    this.dt = this.defaults.dt;
    this.sharedView = st.view;
    this.url = new UrlSync(st, view, ranges, this.defaults);
    this.avoid = new LabAvoidance(lab, st);
    const key = lab.tableKey();
    this.defaultTableKey = key;
    this.table = { state: lab.hasTable() ? "exact" : "loading", progress: 1, key, wanted: key, ms: 0, cached: false, fetched: false, workers: 0, message: "" };
  }

  /** Whether the clock can run: the lab has an η table (issue 17: until
   *  the first one arrives the scene is drawn at t = 0, seek steering). */
  get live(): boolean {
    return this.lab.hasTable();
  }

  /** The page's table could not be fetched or was refused, and no other
   *  is in force: the scene stays at t = 0 (the HUD says so). */
  tableFailed(message: string): void {
    this.table = { ...this.table, state: "error", message };
    this.dirty = true;
  }

  /** The page's fetched table arrived (`install` puts it in the core).
   *  Ignored when a table is already in force (one built or cached for
   *  the link's limits came first); else the agents are planned with it
   *  and the clock starts from t = 0: the run is the one a lab made with
   *  the table runs. Returns whether it was installed. */
  tableArrived(install: () => void, ms: number): boolean {
    if (this.lab.hasTable()) return false;
    install();
    if (this.table.state === "loading") {
      const key = this.lab.tableKey();
      this.table = { ...this.table, state: "exact", key, wanted: key, ms, cached: false, fetched: true };
    }
    this.pull();
    return true;
  }

  /** The HUD's table line. */
  tableLine(): string {
    const t = this.table;
    if (t.state === "building") return `approximate — building ${Math.round(100 * t.progress)} %`;
    if (t.state === "error") return this.live ? "approximate — no table for these limits" : "none (could not be loaded; t held at 0)";
    if (t.state === "loading") return "loading… (seek view)";
    const how =
      t.ms === 0
        ? ""
        : t.fetched
          ? ` (fetched, ${t.ms.toFixed(0)} ms)`
          : t.cached
            ? ` (cache, ${t.ms.toFixed(0)} ms)`
            : ` (built, ${(t.ms / 1000).toFixed(1)} s)`;
    return `exact for these limits${how}`;
  }

  /** Brings the η table in line with the limits in force: nothing when it
   *  matches, else the matching one from the browser's cache or built in
   *  Web Workers (the old table, labelled approximate, runs meanwhile). */
  syncTable(): void {
    let wanted: string;
    try {
      wanted = tableKeyFor(this.params());
    } catch (e) {
      this.tableGen++;
      this.table = { ...this.table, state: "error", message: errorText(e) };
      showMessage(`No η table for these limits: ${errorText(e)}`, "warn");
      this.dirty = true;
      return;
    }
    if (wanted === this.table.wanted && this.table.state !== "error") return;
    const gen = ++this.tableGen;
    this.table = { ...this.table, wanted, message: "" };
    if (wanted === this.lab.tableKey()) {
      cancelBuild();
      this.table = { ...this.table, state: this.lab.hasTable() ? "exact" : "loading", progress: 1 };
      this.dirty = true;
      return;
    }
    this.table = { ...this.table, state: "building", progress: 0 };
    this.dirty = true;
    const params = this.params();
    buildTable(
      params,
      (f) => {
        if (gen === this.tableGen) {
          this.table.progress = f;
          this.dirty = true;
        }
      },
      (bytes, key) => {
        // A newer request superseded this one: keep the lab's table.
        if (gen !== this.tableGen) throw new Cancelled();
        this.lab.setTable(bytes, key);
        this.tableBytes = { key, bytes };
        this.toWorkers({ kind: "table", bytes, key });
      },
    ).then(
      (t) => {
        if (gen !== this.tableGen) return;
        this.table = { ...this.table, state: "exact", progress: 1, key: t.key, ms: t.ms, cached: t.cached, fetched: false, workers: t.workers, phases: t.phases };
        // A lab's first table plans its agents (Lab.setTable).
        this.pull();
      },
      (e: unknown) => {
        if (e instanceof Cancelled || gen !== this.tableGen) return;
        this.table = { ...this.table, state: "error", message: errorText(e) };
        showMessage(`The η table could not be built: ${errorText(e)}`, "warn");
        this.dirty = true;
      },
    );
  }

  params(): VehicleParams {
    return { ...this.defaults, ...this.st.limits };
  }

  goal(): GoalConfig {
    return goalConfig(this.st);
  }

  /** Reads the agents' state back from the core. */
  pull(): void {
    this.count = this.lab.count();
    this.state = this.stepping() ? (this.stepper as WorldStepper).state : this.lab.state();
    this.dirty = true;
  }

  /** True when the workers step the world (the page's core only checks edits). */
  stepping(): boolean {
    return this.stepper?.active === true;
  }

  /** The HUD's stepping line (issue 17); null when no workers were asked for. */
  steppingLine(): string | undefined {
    const s = this.stepper;
    if (!s || this.workersWanted === 0) return undefined;
    const i = s.info(this.workersWanted);
    if (i.mode === "main") return i.error ? "this thread (workers failed)" : "this thread";
    const how = i.mode === "shared" ? "shared memory" : "messages";
    return `${i.workers} worker${i.workers === 1 ? "" : "s"}, ${how}${i.starting ? " (starting)" : ""}`;
  }

  /** An edit for the workers too, if they step the world. */
  private toWorkers(e: Edit): void {
    if (this.stepping()) (this.stepper as WorldStepper).edit(e);
  }

  /** Agent i's pose as last read. */
  pose(i: number): Pose {
    const o = i * this.stride;
    return {
      x: this.state[o + StateField.X] ?? 0,
      y: this.state[o + StateField.Y] ?? 0,
      theta: this.state[o + StateField.Theta] ?? 0,
    };
  }

  /** Agent i's float `f` as last read. */
  field(i: number, f: StateField): number | undefined {
    return this.state[i * this.stride + f];
  }

  /** The agent the HUD and the overlays follow: the focus, else the first. */
  get shown(): number {
    return this.focus >= 0 ? this.focus : 0;
  }

  /** Internals of agent i, or null (no such agent: the world is being rebuilt). */
  internals(i: number): Internals | null {
    if (i < 0 || i >= this.count) return null;
    if (this.stepping()) return i === this.shown ? (this.stepper as WorldStepper).internals : null;
    try {
      return this.lab.internals(i);
    } catch {
      return null;
    }
  }

  /** The page's vehicle limits to the core. A desired speed above a new
   *  max speed (or a field-view speed) is first clamped to it, and the
   *  playground's goal updated: the core would refuse the goal, and a reset
   *  would leave an empty playground. Returns what was clamped, with a
   *  message for its field. A limit the core refuses (none within the
   *  ranges) restores the previous limits. */
  applyParams(): Array<{ field: LabField; message: string }> {
    const before = this.lab.params();
    const clamped = clampToLimits(this.ranges, this.st, this.defaults);
    try {
      // A mismatched table is labelled approximate in the HUD while the
      // matching one is built (syncTable), not warned about.
      this.lab.setParams(this.params());
      this.toWorkers({ kind: "params", params: this.params() });
    } catch (e) {
      showMessage(`Vehicle limits rejected: ${errorText(e)}`, "warn");
      for (const f of FIELDS) if (f.limit) this.st.limits[f.limit] = before[f.limit];
    }
    this.syncTable();
    if (clamped.fields.length > 0) {
      this.dirty = true;
      this.updateGoal();
    }
    return clamped.fields.map((field, i) => ({ field, message: clamped.messages[i] ?? "" }));
  }

  /** The page's controller settings to the core (world-wide, presets included). */
  applyFunnel(): void {
    try {
      this.lab.setFunnel(funnelConfig(this.st.funnel));
      this.lab.setRelaxed(relaxedConfig(this.st.funnel));
      this.toWorkers({ kind: "funnel", funnel: funnelConfig(this.st.funnel), relaxed: relaxedConfig(this.st.funnel) });
    } catch (e) {
      showMessage(`Controller settings rejected: ${errorText(e)}`, "warn");
    }
    this.dirty = true;
  }

  /** The focus agent's goal from the page's state. */
  updateGoal(): void {
    if (this.focus < 0) return;
    try {
      this.lab.setGoal(this.focus, this.goal());
      this.toWorkers({ kind: "goal", i: this.focus, goal: this.goal() });
    } catch (e) {
      showMessage(`Goal rejected: ${errorText(e)}`, "warn");
    }
    this.pull();
    this.url.save();
  }

  /** The focus agent moved to the page's vehicle pose (its trail restarts). */
  placeVehicle(): void {
    if (this.focus < 0) return;
    const v = this.st.vehicle;
    try {
      this.lab.setPose(this.focus, v.x, v.y, v.theta);
      this.toWorkers({ kind: "pose", i: this.focus, x: v.x, y: v.y, theta: v.theta });
    } catch (e) {
      showMessage(`Pose rejected: ${errorText(e)}`, "warn");
    }
    this.trails.clearAgent(this.focus);
    this.pull();
    this.url.save();
  }

  /** Starts over: the preset named in the state, else the playground. */
  async rebuild(fitAsked: boolean): Promise<void> {
    const { lab, st, view } = this;
    const fit = fitAsked && this.sharedView === null;
    if (this.sharedView) {
      view.cx = this.sharedView.cx;
      view.cy = this.sharedView.cy;
      view.scale = this.sharedView.scale;
      this.sharedView = null;
    }
    const gen = ++this.generation;
    this.stepper?.stop();
    this.recipe = null;
    lab.clear();
    this.pull();
    this.applyParams();
    this.trails.clear();
    this.time = 0;
    this.acc = 0;
    this.focus = -1;
    if (st.preset) {
      const p = findPreset(st.preset);
      try {
        if (!p) throw new Error(`no preset named ${st.preset}`);
        const text = await p.load();
        if (gen !== this.generation) return;
        const info = lab.loadScenario(text);
        this.recipe = this.recipeFor({ kind: "scenario", text });
        // The page's vehicle limits apply to presets too (issue 14:
        // `#preset=…&vmax=0.05` runs at 0.05 m/s).
        lab.setParams(this.params());
        this.onScene(`${info.description}${info.source ? ` (${info.source})` : ""} — ${info.agents} agents.`, false, info.claim, info.measured);
        if (info.warning) showMessage(`Preset ${st.preset}: ${info.warning}`, "warn");
        if (fit) view.fit(info.minX, info.minY, info.maxX, info.maxY);
      } catch (e) {
        showMessage(`Preset ${st.preset} could not be loaded: ${errorText(e)}`, "error");
      }
    } else {
      this.onScene(PLAYGROUND_HELP, true);
      const extent = Math.max(10, Math.sqrt(st.agents) * 1.5);
      try {
        const agent = { x: st.vehicle.x, y: st.vehicle.y, theta: st.vehicle.theta, goals: [this.goal()] };
        lab.addAgent(agent);
        this.focus = 0;
        const spawn = st.agents > 0 ? { n: st.agents, seed: st.seed, extent, speed: st.speed } : null;
        if (spawn) lab.spawnRandom(spawn.n, spawn.seed, spawn.extent, spawn.speed);
        this.recipe = this.recipeFor({ kind: "playground", agent, spawn });
      } catch (e) {
        showMessage(`The playground could not be set up: ${errorText(e)}`, "error");
      }
      if (fit) {
        if (st.agents > 0) {
          const r = extent + 3;
          view.fit(-r, -r, r, r);
        } else {
          fitPlayground(view, st);
        }
      }
    }
    this.applyFunnel();
    this.avoid.apply();
    this.dt = lab.params().dt;
    this.pull();
    this.trails.record(0, this.state, this.stride, this.count);
    this.startWorkers();
  }

  /** What the workers replay to build this world (null: they cannot). */
  private recipeFor(build: Recipe["build"]): Recipe | null {
    const key = this.lab.tableKey();
    const bytes = this.tableBytes?.key === key ? this.tableBytes.bytes : null;
    if (key !== this.defaultTableKey && !bytes) return null;
    const url = new URL(TABLE_URL, location.href).href;
    return { table: { key, url, bytes }, params: this.params(), funnel: funnelConfig(this.st.funnel), relaxed: relaxedConfig(this.st.funnel), build };
  }

  /** Issue 17: hands the world just built to the stepping workers when
   *  `?workers=N` or the agent count asks for them. The page's core keeps
   *  its copy for the edits' checks; the workers' states are drawn. */
  private startWorkers(): void {
    const wanted = workersWanted(this.count);
    this.workersWanted = wanted.n;
    if (wanted.problem) showMessage(wanted.problem, "warn");
    if (wanted.n === 0 || !this.recipe || this.count === 0 || this.lab.avoidance() !== "off") return;
    if (!this.stepper) {
      this.stepper = new WorldStepper(wanted.n, this.stride);
      this.stepper.onSwap = (state) => {
        this.state = state;
        this.dirty = true;
      };
    }
    const gen = this.generation;
    this.stepper.start(this.recipe, this.lab, this.state, this.shown).then(
      () => {
        if (gen !== this.generation) return;
        const s = this.stepper as WorldStepper;
        if (s.error) {
          // The page's core steps on from its copy of the world.
          showMessage(`Stepping in workers failed, stepping here: ${s.error}`, "warn");
        }
        this.pull();
      },
      () => undefined,
    );
  }

  /** One step, paused afterwards (the caller shows the pause). */
  stepOnce(): void {
    if (!this.live) return;
    if (this.stepping()) {
      void this.stepN(1);
      return;
    }
    this.lab.step(1);
    this.time += this.dt;
    this.pull();
    this.trails.record(this.time, this.state, this.stride, this.count);
  }

  /** Runs the steps that `intervalMs` of wall time is worth (none when
   *  paused); returns the agent updates done and the ms they took. */
  advance(intervalMs: number): { updates: number; ms: number } {
    if (this.count === 0 || !this.live) return { updates: 0, ms: 0 };
    // Paused, the workers still take the edits (drags) and single steps.
    if (this.paused) return this.stepping() ? this.advanceInWorkers(0) : { updates: 0, ms: 0 };
    this.acc += Math.min(0.1, intervalMs / 1000) * (this.st.slow ? 0.25 : 1);
    let k = Math.floor(this.acc / this.dt);
    if (k > MAX_STEPS_PER_FRAME) {
      k = MAX_STEPS_PER_FRAME;
      this.acc = 0;
    } else this.acc -= k * this.dt;
    if (this.stepping()) return this.advanceInWorkers(k);
    if (k <= 0) return { updates: 0, ms: 0 };
    const s0 = performance.now();
    this.lab.step(k);
    const ms = performance.now() - s0;
    const updates = k * this.count;
    const us = (ms * 1000) / updates;
    this.usPerUpdate = this.usPerUpdate === 0 ? us : 0.9 * this.usPerUpdate + 0.1 * us;
    this.time += k * this.dt;
    this.pull();
    if (this.st.overlays.trails && this.count <= this.trails.maxAgents) this.trails.record(this.time, this.state, this.stride, this.count);
    return { updates, ms };
  }

  /** Issue 17: asks the workers for `k` steps and takes what they finished
   *  since the last frame; never waits (the last complete state is drawn). */
  private advanceInWorkers(k: number): { updates: number; ms: number } {
    const s = this.stepper as WorldStepper;
    // Shared memory: this frame's state first (before asking for more: the
    // workers then leave its buffer alone).
    s.poll();
    if (k > 0) s.request(k);
    s.pump(this.shown);
    return this.takeFromWorkers();
  }

  private takeFromWorkers(): { updates: number; ms: number } {
    const s = this.stepper as WorldStepper;
    if (!s.fresh) return { updates: 0, ms: 0 };
    s.fresh = false;
    const done = s.takeCompleted();
    this.time += done.steps * this.dt;
    this.pull();
    if (done.steps > 0 && this.st.overlays.trails && this.count <= this.trails.maxAgents) this.trails.record(this.time, this.state, this.stride, this.count);
    const updates = done.steps * this.count;
    if (updates > 0) {
      // The HUD's cost per update: the slowest worker's stepping time (the
      // jobs' wall time also holds the hand-over and the wait for a frame).
      const us = (done.workerMs * 1000) / updates;
      this.usPerUpdate = this.usPerUpdate === 0 ? us : 0.9 * this.usPerUpdate + 0.1 * us;
    }
    return { updates, ms: done.ms };
  }

  /** Runs `k` steps now (paused single steps, tests); resolves once the
   *  state drawn is theirs, on this thread or in the workers. */
  async stepN(k: number): Promise<void> {
    if (!this.stepping()) {
      this.lab.step(k);
      this.time += k * this.dt;
      this.pull();
      this.trails.record(this.time, this.state, this.stride, this.count);
      return;
    }
    const s = this.stepper as WorldStepper;
    await s.run(k, this.shown);
    this.takeFromWorkers();
  }
}
