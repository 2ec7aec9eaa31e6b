// The simulation the funnelling page owns: its one world (../world/world.ts: on
// this thread or in Web Workers), the state last drawn from it, the clock
// (play, pause, single steps, slow motion) and the edits that go to it
// (goal, pose, limits, controller settings, avoidance). A rebuild starts
// the playground or a preset from scratch, wherever it is to step.

import { showMessage } from "../ui/page";
import type { View } from "../ui/view";
import { errorText, Lab, StateField, type GoalConfig, type Internals, type VehicleParams } from "../core/wasm";
import { LabAvoidance } from "./avoidance";
import { clampToLimits, FIELDS, limitDefaults, type LabField, type LimitDefaults, type RangeTable } from "./fields";
import { funnelConfig, readingOf, relaxedConfig } from "./funnelsettings";
import { findPreset } from "./presets";
import { recipeFor } from "./recipe";
import { crowdInsets, fitPlayground, goalConfig, loopReach, type LabState, type Pose } from "./state";
import { Trails } from "./trails";
import { UrlSync } from "./urlstate";
import { HereWorld, type LabWorld, type Took } from "../world/world";
import type { BuildInfo, Edit, EditAnswer, Recipe } from "../world/worldcalls";
import { Cancelled } from "../threads/pool";
import { buildTable, cancelBuild, tableKeyFor } from "./tables";
import { workersWanted, WorkerWorld } from "./stepping";
import { splitCrowd, type LabGpu } from "./gpucrowd";

/** The η table in force against the limits in force. */
export interface TableStatus {
  /** `exact`: built for these limits; `building`: the old one, approximate,
   *  while workers build the new one; `error`: no table can be built for
   *  these limits (the old one stays, approximate); `loading`: the page's
   *  first table is still on its way (the scene is drawn, the clock holds
   *  at t = 0). */
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

/** The committed table in byte planes (src/core/tableplanes.ts: the same bytes
 *  once rejoined, less than half the gzipped size of the plain file),
 *  fetched by the page and by the stepping workers. */
export const TABLE_URL = "tables/eta.planes";

const PLAYGROUND_HELP =
  "Playground: drag the vehicle (body: position, white knob: heading), the target (centre), its β knob, " +
  "the tolerance circle's rim and the triangle's corner. The target shows the controller's mode live.";

/** Room kept round a preset's starts and goals for the swing of an
 *  oriented arrival, m: about a walker's turning radius at the presets'
 *  speeds (2.7 m at its full 2 m/s, scenarios/vehicles/pedestrian.json). */
const SWING_M = 2;

/** The most steps one animation frame runs (a slow frame drops the rest). */
const MAX_STEPS_PER_FRAME = 4;

export class LabSim {
  /** Floats per agent in `state`. */
  readonly stride: number;
  readonly trails = new Trails(200, 3000);
  readonly defaults: VehicleParams & LimitDefaults;
  /** The state in the address bar. */
  readonly url: UrlSync;
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
  /** Called when a preset's own vehicle became the page's limits. */
  onLimits: () => void = () => {};
  /** Called once the controller's settings are in force (after an edit or a build). */
  onController: (error: string | null) => void = () => {};

  /** The core's name for the controller in force (`Lab.controllerLabel`:
   *  "paper 001 relaxed", "ours standard", "custom standard", …), where the
   *  world steps on this thread; null where it steps in workers. */
  controllerLabel(): string | null {
    return this.world.core()?.controllerLabel() ?? null;
  }
  /** The η table's status (the HUD's table line). */
  table: TableStatus;
  /** The world: stepped by the page's core (`here`) or by the workers. */
  world: LabWorld;
  /** The world stepped by this page's core. */
  readonly here: HereWorld;
  /** The stepping workers, once asked for (kept for later worlds). */
  stepper: WorkerWorld | null = null;
  /** Workers asked for by `?workers=N` or the default for the agent count. */
  workersWanted = 0;
  /** The random crowd on the GPU (gpucrowd.ts; the engine "gpu"), and why it is not when it cannot be. */
  gpu: LabGpu | null = null;
  onGpuNote: (note: string | null) => void = () => {};
  /** The GPU could not take the crowd: the next build gives it to the workers. */
  private gpuFallback = false;
  private readonly defaultTableKey: string;
  /** The bytes of a table built for other limits (workers load them too). */
  private tableBytes: { key: string; bytes: Uint8Array } | null = null;
  /** The vehicle limits the world holds (restored when an edit is refused). */
  private inForce: VehicleParams;
  /** Avoidance method and obstacles. */
  readonly avoid: LabAvoidance;
  private acc = 0;
  private generation = 0;
  private tableGen = 0;
  /** The next build steps here (the workers failed while stepping). */
  private notInWorkers = false;
  /** Edits made while a world is being built: the new world's, once built. */
  private waiting: Array<[Edit, (a: EditAnswer) => void]> | null = null;
  /** The page's limits as a preset's own vehicle set them (adoptLimits),
   *  null once edited or when the preset brought none. */
  private adopted: string | null = null;
  /** The URL's view, shown once (the first build); later builds fit when asked. */
  private sharedView: LabState["view"];

  /** `core`: the page's core (its η table; the world while no worker steps). */
  constructor(private readonly core: Lab, readonly st: LabState, private readonly view: View, readonly ranges: RangeTable) {
    this.stride = Lab.stateStride();
    this.defaults = limitDefaults(core.params());
    this.inForce = this.defaults;
    this.dt = this.defaults.dt;
    this.sharedView = st.view;
    this.url = new UrlSync(st, view, ranges, this.defaults);
    this.avoid = new LabAvoidance(st, (e, answer) => this.editAvoid(e, answer));
    this.here = new HereWorld(core);
    this.world = this.here;
    const key = core.tableKey();
    this.defaultTableKey = key;
    this.table = { state: core.hasTable() ? "exact" : "loading", progress: 1, key, wanted: key, ms: 0, cached: false, fetched: false, workers: 0, message: "" };
  }

  get count(): number {
    return this.world.count;
  }

  /** Every agent's record as drawn: a view of the buffer the world writes. */
  get state(): Float32Array {
    return this.world.state;
  }

  /** Whether the clock can run: the page has an η table (until the first
   *  one arrives the scene is drawn at t = 0, seek steering). */
  get live(): boolean {
    return this.core.hasTable();
  }

  /** True when workers step the world. */
  stepping(): boolean {
    return this.world !== this.here;
  }

  /** The page's table could not be fetched or was refused, and no other
   *  is in force: the scene stays at t = 0 (the HUD says so). */
  tableFailed(message: string): void {
    this.table = { ...this.table, state: "error", message };
    this.dirty = true;
  }

  /** The page's fetched table arrived (`install` puts it in the page's
   *  core). Ignored when a table is already in force (one built or cached
   *  for the link's limits came first); else the agents are planned with
   *  it and the clock starts from t = 0: the run is the one a lab made with
   *  the table runs. Returns whether it was installed. */
  tableArrived(install: () => void, ms: number): boolean {
    if (this.core.hasTable()) return false;
    install();
    if (this.table.state === "loading") {
      const key = this.core.tableKey();
      this.table = { ...this.table, state: "exact", key, wanted: key, ms, cached: false, fetched: true };
    }
    // The workers fetched the committed table themselves; the page's core holds the world here.
    this.here.tableChanged();
    this.dirty = true;
    // The GPU crowd waited for the table (gpucrowd.ts packs it with it).
    if (this.st.engine === "gpu") void this.rebuild(false);
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
    if (wanted === this.core.tableKey()) {
      cancelBuild();
      this.table = { ...this.table, state: this.core.hasTable() ? "exact" : "loading", progress: 1 };
      this.dirty = true;
      return;
    }
    this.table = { ...this.table, state: "building", progress: 0 };
    this.dirty = true;
    buildTable(
      this.params(),
      (f) => {
        if (gen === this.tableGen) {
          this.table.progress = f;
          this.dirty = true;
        }
      },
      (bytes, key) => {
        // A newer request superseded this one: keep the table in force.
        if (gen !== this.tableGen) throw new Cancelled();
        this.core.setTable(bytes, key);
        this.tableBytes = { key, bytes };
        this.world.tableChanged(bytes, key);
      },
    ).then(
      (t) => {
        if (gen !== this.tableGen) return;
        this.table = { ...this.table, state: "exact", progress: 1, key: t.key, ms: t.ms, cached: t.cached, fetched: false, workers: t.workers, phases: t.phases };
        this.dirty = true;
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

  /** The η field around a vehicle at these speeds (the page's table; empty before it). */
  etaField(vC: number, omegaC: number, vD: number): Float32Array {
    return this.core.etaField(vC, omegaC, vD);
  }

  /** The HUD's stepping line; undefined when no workers were asked for. */
  steppingLine(): string | undefined {
    const g = this.gpu?.line();
    if (g) return g;
    const s = this.stepper;
    if (!s || this.workersWanted === 0) return undefined;
    const i = s.info(this.workersWanted);
    if (i.mode === "main") return i.error ? "this thread (workers failed)" : "this thread";
    const how = i.mode === "shared" ? "shared memory" : "messages";
    return `${i.workers} worker${i.workers === 1 ? "" : "s"}, ${how}${i.starting ? " (starting)" : ""}`;
  }

  /** `e` to the world; a refusal is shown, then `answer` has the rest. */
  edit(e: Edit, answer: (a: EditAnswer) => void = () => undefined): void {
    const told = (a: EditAnswer): void => {
      if (a.error) showMessage(a.error, "warn");
      answer(a);
      this.dirty = true;
    };
    if (this.waiting) this.waiting.push([e, told]);
    else this.world.edit(e, told);
    this.dirty = true;
  }

  /** An avoidance edit. The workers step worlds without avoidance only
   *  (it couples every agent): a method switched on while they step
   *  rebuilds the world, at t = 0, on this page's core. The GPU crowd is
   *  packed with the avoidance in force (separation runs on the GPU,
   *  obstacles and ORCA are refused there): any avoidance edit while it
   *  runs rebuilds it. */
  private editAvoid(e: Edit & { kind: "avoid" }, answer: (a: EditAnswer) => void): void {
    const onGpu = (this.gpu?.agents ?? 0) > 0;
    if (onGpu || (this.stepping() && e.method !== undefined && e.method !== "off")) void this.rebuild(false);
    else this.edit(e, answer);
  }

  /** Agent i's pose as drawn. */
  pose(i: number): Pose {
    const o = i * this.stride;
    const s = this.state;
    return { x: s[o + StateField.X] ?? 0, y: s[o + StateField.Y] ?? 0, theta: s[o + StateField.Theta] ?? 0 };
  }

  /** Agent i's float `f` as drawn. */
  field(i: number, f: StateField): number | undefined {
    return this.state[i * this.stride + f];
  }

  /** The agent the HUD and the overlays follow: the focus, else the first. */
  get shown(): number {
    return this.focus >= 0 ? this.focus : 0;
  }

  /** The shown agent's internals in the drawn state (null: none yet). */
  get internals(): Internals | null {
    return this.count > 0 ? this.world.internals : null;
  }

  /** The page's vehicle limits to the world. A desired speed above a new
   *  max speed (or a field-view speed) is first clamped to it, and the
   *  playground's goal updated: the core would refuse the goal, and a reset
   *  would leave an empty playground. Returns what was clamped, with a
   *  message for its field. Limits the core refuses (none within the
   *  ranges) give way to those in force, and `refused` has the core's reason. */
  applyParams(refused: (error: string) => void = () => {}): Array<{ field: LabField; message: string }> {
    const clamped = clampToLimits(this.ranges, this.st, this.defaults);
    const params = this.params();
    // A mismatched table is labelled approximate in the HUD while the
    // matching one is built (syncTable), not warned about.
    this.edit({ kind: "params", params }, (a) => {
      if (a.error) {
        this.restoreLimits(this.inForce);
        refused(a.error);
      } else this.inForce = params;
    });
    this.syncTable();
    if (clamped.fields.length > 0) this.updateGoal();
    return clamped.fields.map((field, i) => ({ field, message: clamped.messages[i] ?? "" }));
  }

  private restoreLimits(p: VehicleParams): void {
    for (const f of FIELDS) if (f.limit) this.st.limits[f.limit] = p[f.limit] ?? this.defaults[f.limit];
  }

  /** The world's vehicle (a preset's own, under the page's limits) as the
   *  page's limits: the controls, the link and the η table follow it, so a
   *  car-like preset runs on its own table and a reset keeps its vehicle. */
  private adoptLimits(p: VehicleParams): void {
    let changed = false;
    for (const f of FIELDS) {
      if (!f.limit) continue;
      const v = p[f.limit] ?? this.defaults[f.limit];
      if (v === (this.st.limits[f.limit] ?? this.defaults[f.limit])) continue;
      this.st.limits[f.limit] = v;
      changed = true;
    }
    if (!changed) return;
    this.adopted = JSON.stringify(this.st.limits);
    this.onLimits();
    this.syncTable();
    this.url.save();
  }

  /** Before another preset (or the playground): the vehicle the last
   *  preset brought goes with it, unless its limits were edited since. */
  dropPresetVehicle(): void {
    if (this.adopted !== null && this.adopted === JSON.stringify(this.st.limits)) {
      this.st.limits = {};
      this.onLimits();
    }
    this.adopted = null;
  }

  /** The playground's view fitted again (a vehicle of another turning
   *  radius loops round further); a preset's or a crowd's view stays. */
  refitPlayground(): void {
    if (this.st.preset || this.st.agents > 0) return;
    fitPlayground(this.view, this.st);
    this.dirty = true;
    this.url.save();
  }

  /** The page's controller settings to the world (presets included). */
  applyFunnel(): void {
    this.edit({ kind: "funnel", funnel: funnelConfig(this.st.funnel), relaxed: relaxedConfig(this.st.funnel), reading: readingOf(this.st.funnel) }, (a) => this.onController(a.error));
  }

  /** The focus agent's goal from the page's state. */
  updateGoal(): void {
    if (this.focus < 0) return;
    this.edit({ kind: "goal", i: this.focus, goal: this.goal() });
    this.url.save();
  }

  /** The focus agent moved to the page's vehicle pose (its trail restarts). */
  placeVehicle(): void {
    if (this.focus < 0) return;
    const v = this.st.vehicle;
    this.edit({ kind: "pose", i: this.focus, x: v.x, y: v.y, theta: v.theta });
    this.trails.clearAgent(this.focus);
    this.url.save();
  }

  /** Starts over: the preset named in the state, else the playground, on
   *  this page's core or in workers (`workersWanted`, `?workers=`). */
  async rebuild(fitAsked: boolean): Promise<void> {
    const { st, view } = this;
    const fit = fitAsked && this.sharedView === null;
    if (this.sharedView) {
      view.show(this.sharedView.cx, this.sharedView.cy, this.sharedView.scale);
      this.sharedView = null;
    }
    const gen = ++this.generation;
    this.world.stop();
    this.world = this.here;
    this.waiting = [];
    this.trails.clear();
    this.time = 0;
    this.acc = 0;
    this.focus = -1;
    this.dirty = true;
    // The limits as the world will take them (desired speed ≤ max speed), and their table.
    clampToLimits(this.ranges, st, this.defaults);
    this.syncTable();
    const whole = await this.recipe();
    if (gen !== this.generation) return;
    if (typeof whole === "string") {
      showMessage(whole, "error");
      this.waiting = null;
      return;
    }
    this.gpu?.stop();
    const split = splitCrowd(st, whole, !this.gpuFallback);
    this.gpuFallback = false;
    const recipe = split.recipe;
    let info: BuildInfo | null = null;
    const workers = this.workersFor(recipe);
    if (workers) {
      info = await workers.start(recipe, 0);
      if (gen !== this.generation) return;
      // The page's core steps what the workers cannot: a world with
      // avoidance, or any world once they have failed.
      if (workers.error !== null) showMessage(`Stepping in workers failed, stepping here: ${workers.error}`, "warn");
      if (info) this.world = workers;
    }
    info ??= await this.here.start(recipe, 0);
    this.built(recipe, info, fit);
    if (split.spawn && this.gpu && this.core.hasTable()) {
      const why = await this.gpu.start(this.core, split.spawn);
      if (gen !== this.generation) return;
      this.onGpuNote(why);
      if (why !== null) {
        showMessage(why, "warn");
        this.gpuFallback = true;
        void this.rebuild(false);
        return;
      }
      if (fit) this.view.fit(-split.spawn.extent - 3, -split.spawn.extent - 3, split.spawn.extent + 3, split.spawn.extent + 3, (v) => crowdInsets(v, 40));
    } else if (st.engine !== "gpu") this.onGpuNote(null);
    const waiting = this.waiting;
    this.waiting = null;
    for (const [e, answer] of waiting) this.world.edit(e, answer);
  }

  /** What builds the world the state describes (a preset's text loaded),
   *  or why it cannot be built. */
  private async recipe(): Promise<Recipe | string> {
    const { st } = this;
    const key = this.core.tableKey();
    const table = { key, url: new URL(TABLE_URL, location.href).href, bytes: this.tableBytes?.key === key ? this.tableBytes.bytes : null };
    if (!st.preset) return recipeFor(st, this.params(), table, null);
    const p = findPreset(st.preset);
    try {
      if (!p) throw new Error(`no preset named ${st.preset}`);
      return recipeFor(st, this.params(), table, { name: st.preset, text: await p.load() });
    } catch (e) {
      return `Preset ${st.preset} could not be loaded: ${errorText(e)}`;
    }
  }

  /** The workers to build `recipe`'s world in, or null: this page's core.
   *  A preset's agent count is known once built: it goes to workers only
   *  when `?workers=N` asks. Workers need the table's bytes or its URL. */
  private workersFor(recipe: Recipe): WorkerWorld | null {
    const b = recipe.build;
    const count = b.kind === "playground" ? 1 + (b.spawn?.n ?? 0) : 0;
    const wanted = workersWanted(count);
    this.workersWanted = wanted.n;
    if (wanted.problem) showMessage(wanted.problem, "warn");
    const coupled = recipe.avoid.method !== null && recipe.avoid.method !== "off";
    const failed = this.notInWorkers;
    this.notInWorkers = false;
    if (wanted.n === 0 || coupled || failed || (recipe.table.key !== this.defaultTableKey && !recipe.table.bytes)) return null;
    this.stepper ??= new WorkerWorld(wanted.n, this.stride);
    return this.stepper;
  }

  /** The new world is in: the page's side of it (messages, caption, view). */
  private built(recipe: Recipe, info: BuildInfo, fit: boolean): void {
    for (const m of info.messages) showMessage(m.text, m.level);
    if (info.paramsRefused) this.restoreLimits(info.params);
    else if (recipe.build.kind === "scenario") this.adoptLimits(info.params);
    this.inForce = info.params;
    this.dt = info.dt;
    this.avoid.take(info.avoid);
    const b = recipe.build;
    if (b.kind === "scenario") {
      const sc = info.scenario;
      this.onScene(sc?.caption ?? "", false, sc?.claim, sc?.measured);
      if (fit && sc) {
        const [x0, y0, x1, y1] = sc.box;
        // The box holds the starts and the goals; a vehicle arriving
        // oriented swings out beyond a goal (Fig. 3's first agent comes
        // round above its own), so the room of a loop is kept round it.
        const r = Math.max(loopReach(info.params.minTurnRadius), SWING_M);
        this.view.fit(x0 - r, y0 - r, x1 + r, y1 + r, (v) => crowdInsets(v, 40));
      }
    } else {
      this.focus = info.count > 0 ? 0 : -1;
      this.onScene(PLAYGROUND_HELP, true);
      if (fit && b.spawn) {
        const r = b.spawn.extent + 3;
        this.view.fit(-r, -r, r, r, (v) => crowdInsets(v, 40));
      } else if (fit) fitPlayground(this.view, this.st);
    }
    this.trails.record(0, this.state, this.stride, this.count);
    this.onController(null);
    this.dirty = true;
  }

  /** One step, paused afterwards (the caller shows the pause). */
  stepOnce(): void {
    if (this.live) void this.stepNow(1);
  }

  /** Runs the steps that `intervalMs` of wall time is worth (none when
   *  paused, or before the η table: edits still reach the world); returns
   *  the agent updates drawn now and the ms they took. */
  advance(intervalMs: number): { updates: number; ms: number } {
    if (this.stepper && this.world === this.stepper && !this.stepper.active) {
      // A worker failed while stepping: the world starts over here (the
      // page's state holds every edit).
      showMessage(`Stepping in workers failed, stepping here from t = 0: ${this.stepper.error ?? "?"}`, "warn");
      this.notInWorkers = true;
      void this.rebuild(false);
    }
    if (this.count === 0) return { updates: 0, ms: 0 };
    let k = 0;
    if (!this.paused && this.live) {
      this.acc += Math.min(0.1, intervalMs / 1000) * (this.st.slow ? 0.25 : 1);
      k = Math.floor(this.acc / this.dt);
      if (k > MAX_STEPS_PER_FRAME) {
        k = MAX_STEPS_PER_FRAME;
        this.acc = 0;
      } else this.acc -= k * this.dt;
    }
    if (k > 0 && this.gpu?.agents) {
      this.gpu.step(k);
      this.dirty = true;
    }
    return this.took(this.world.frame(k, this.shown));
  }

  /** The clock, trails and cost per update after the world took steps. */
  private took(d: Took): { updates: number; ms: number } {
    if (!d.fresh) return { updates: 0, ms: 0 };
    this.dirty = true;
    if (d.steps === 0) return { updates: 0, ms: 0 };
    this.time += d.steps * this.dt;
    if (this.st.overlays.trails && this.count <= this.trails.maxAgents) this.trails.record(this.time, this.state, this.stride, this.count);
    const updates = d.steps * this.count;
    // The stepping time alone (with workers, the slowest worker's: a job's
    // wall time also holds the hand-over and the wait for a frame).
    const us = (d.stepMs * 1000) / updates;
    this.usPerUpdate = this.usPerUpdate === 0 ? us : 0.9 * this.usPerUpdate + 0.1 * us;
    return { updates, ms: d.ms };
  }

  /** Runs `k` steps now (paused single steps, tests); resolves once the
   *  state drawn is theirs. */
  async stepNow(k: number): Promise<void> {
    this.gpu?.step(k);
    this.took(await this.world.run(k, this.shown));
  }
}
