// <funnel-figure>: the lab's playground (or one of its presets) as an
// element any page drops in. Its attributes are the lab's link keys
// (attributes.ts); it draws with the lab's own scene builder and renderer
// (lab/scene.ts, lab/render.ts), its handles are the learn page's
// (learn/handle.ts: pointer drags and arrow keys), and it sizes itself to
// its box (ui/canvas.ts: ResizeObserver, devicePixelRatio).
//
// Events: `modechange` (the shown agent's control mode changed; detail:
// mode number, its name and the lab's word for it, time) and `arrive`
// (every agent done and at rest; detail: time, the shown agent's pose and
// its distance and heading error to its target). Editing the target with
// a handle sends the agent on from where it is (the lab's drag); a changed
// attribute builds the set-up anew from its start.

import { beginFrame, setupCanvas, type Surface } from "../ui/canvas";
import { modeWords } from "../ui/modes";
import { View } from "../ui/view";
import { errorText, Mode, StateField, type VehicleParams } from "../core/wasm";
import { COLOURS, drawScene } from "../lab/render";
import { HANDLE_PX, SceneBuilder } from "../lab/scene";
import { goalConfig, type LabState } from "../lab/state";
import { Handle, type HandleSpec } from "../learn/handle";
import { ATTRIBUTES, fragmentOf, stateOf } from "./attributes";
import { figureContext, presetText, tableFor, tableKey, type FigureContext } from "./context";
import { FigureSim } from "./sim";
import { STYLE } from "./style";

/** Where the element's module is (its table and presets are beside it). */
let home = "";

/** Set once by the module that defines the element (main.ts). */
export function setHome(url: string): void {
  home = url;
}

/** World metres kept round the playground's vehicle and target. */
const PAD = 1.5;

export class FunnelFigure extends HTMLElement {
  static readonly observedAttributes = ATTRIBUTES;

  private readonly root: ShadowRoot;
  private readonly stage: HTMLDivElement;
  private readonly status: HTMLOutputElement;
  private readonly playBtn: HTMLButtonElement;
  private readonly view = new View();
  private surface: Surface | null = null;
  private cx: FigureContext | null = null;
  private sim: FigureSim | null = null;
  private scenes: SceneBuilder | null = null;
  private handles: Handle[] = [];
  private dt = 1 / 60;
  private raf = 0;
  private last = 0;
  private acc = 0;
  private mode = -1;
  private arrived = false;
  private rebuildQueued = false;
  private generation = 0;
  private reflecting = false;
  private note = "";
  /** Resolves once the first set-up is built (tests and hosts await it). */
  readonly ready: Promise<void>;
  private resolveReady: () => void = () => undefined;

  constructor() {
    super();
    this.root = this.attachShadow({ mode: "open" });
    this.root.innerHTML = `<style>${STYLE}</style><div class="stage" part="stage"><canvas role="img"></canvas></div>` +
      `<div class="bar" part="bar"><button type="button" data-role="play">Pause</button><button type="button" data-role="restart">Restart</button><output part="status" aria-live="polite"></output></div>`;
    this.stage = this.root.querySelector<HTMLDivElement>(".stage")!;
    this.status = this.root.querySelector("output")!;
    this.playBtn = this.root.querySelector<HTMLButtonElement>('[data-role="play"]')!;
    this.playBtn.addEventListener("click", () => this.setPlaying(this.sim?.paused ?? false));
    this.root.querySelector('[data-role="restart"]')!.addEventListener("click", () => this.rebuild());
    this.ready = new Promise((ok) => (this.resolveReady = ok));
  }

  connectedCallback(): void {
    // Moved in the page: the run goes on where it was.
    if (this.surface) {
      if (this.sim && !this.sim.paused) this.setPlaying(true);
      return;
    }
    const canvas = this.root.querySelector("canvas")!;
    this.surface = setupCanvas(canvas, (s) => {
      this.view.resize(s.width, s.height);
      this.draw();
    });
    figureContext(home).then((cx) => {
      this.cx = cx;
      this.dt = cx.base.params().dt;
      this.rebuild();
    }, (e: unknown) => this.fail(`the core or its η table did not load: ${errorText(e)}`));
  }

  disconnectedCallback(): void {
    cancelAnimationFrame(this.raf);
    this.raf = 0;
  }

  attributeChangedCallback(): void {
    if (this.reflecting || !this.cx || this.rebuildQueued) return;
    // Several attributes set in one task: one rebuild.
    this.rebuildQueued = true;
    queueMicrotask(() => {
      this.rebuildQueued = false;
      this.rebuild();
    });
  }

  /** The control mode of the shown agent (the core's `Mode` name), or null before the first build. */
  get modeName(): string | null {
    return this.mode < 0 ? null : (Mode[this.mode] ?? null);
  }

  /** Simulated seconds since the set-up's start. */
  get time(): number {
    return this.sim?.time ?? 0;
  }

  /** The set-up's lab link fragment (no '#'): `LAB/index.html#` + this is the
   *  same figure in the lab (an iframe for hosts that refuse scripts). */
  get fragment(): string {
    return this.sim && this.cx ? fragmentOf(this.sim.st, this.cx) : "";
  }

  /** The shown agent's state now: x, y (m), θ (rad), v (m/s). */
  get agent(): { x: number; y: number; theta: number; v: number } | null {
    const s = this.sim;
    if (!s || s.count === 0) return null;
    return { ...s.pose(0), v: s.field(0, StateField.V) ?? 0 };
  }

  setPlaying(on: boolean): void {
    if (!this.sim) return;
    this.sim.paused = !on;
    this.playBtn.textContent = on ? "Pause" : "Play";
    this.playBtn.setAttribute("aria-pressed", String(on));
    if (on && this.raf === 0 && this.isConnected) {
      this.last = 0;
      this.raf = requestAnimationFrame((t) => this.frame(t));
    }
  }

  private fail(message: string): void {
    this.note = message;
    this.status.textContent = message;
    this.dispatchEvent(new CustomEvent("error", { detail: { message } }));
  }

  /** The set-up from the attributes, at its start; the view fitted to it
   *  unless `refit` is false (a drag of the start: the view holds still
   *  under the pointer). */
  private async rebuild(refit = true): Promise<void> {
    const cx = this.cx;
    if (!cx) return;
    const gen = ++this.generation;
    const { state, problems } = stateOf(this, cx);
    let scenario: { name: string; text: string } | null = null;
    if (state.preset) {
      try {
        scenario = { name: state.preset, text: await presetText(cx.home, state.preset) };
      } catch (e) {
        problems.push(errorText(e));
        state.preset = "";
      }
      if (gen !== this.generation) return;
    }
    this.sim ??= new FigureSim(cx.base.fork(), state);
    this.scenes ??= new SceneBuilder(this.sim);
    const params = { ...cx.defaults, ...state.limits };
    const info = this.sim.build(state, params, scenario);
    this.dt = info.dt;
    this.note = [...problems, ...info.messages.map((m) => m.text)].join("; ");
    if (this.note) console.warn(`<funnel-figure>: ${this.note}`);
    this.syncTable(info.params, gen);
    this.placeHandles();
    if (refit) this.fit(info.scenario?.box ?? null);
    this.mode = -1;
    this.arrived = false;
    this.observe();
    this.setPlaying(!window.matchMedia("(prefers-reduced-motion: reduce)").matches);
    this.draw();
    this.resolveReady();
  }

  /** The η table of the vehicle in force: the shared one, or one built for
   *  other limits (the world steps on the shared one, approximate,
   *  meanwhile, as the lab's does). */
  private syncTable(p: VehicleParams, gen: number): void {
    const sim = this.sim;
    if (!sim) return;
    if (tableKey(p) === sim.lab.tableKey()) return;
    tableFor(p, (share) => {
      if (gen === this.generation) this.status.textContent = `building the η table for this vehicle… ${Math.round(100 * share)}%`;
    }).then((bytes) => {
      if (gen !== this.generation) return;
      sim.lab.setTable(bytes);
      void this.rebuild(false);
    }, (e: unknown) => this.fail(errorText(e)));
  }

  /** Fits the view: a preset's box, or the playground's vehicle and target. */
  private fit(box: readonly [number, number, number, number] | null): void {
    const st = this.sim!.st;
    const b = box ?? [
      Math.min(st.vehicle.x, st.target.x) - PAD, Math.min(st.vehicle.y, st.target.y) - PAD,
      Math.max(st.vehicle.x, st.target.x) + PAD, Math.max(st.vehicle.y, st.target.y) + PAD,
    ];
    this.view.fit(b[0], b[1], b[2], b[3], 24);
  }

  /** The playground's handles: the start, the target and its heading
   *  knob (kept across rebuilds, so a drag of the start that rebuilds the
   *  run keeps its pointer; they read the state in force). */
  private placeHandles(): void {
    const on = (this.sim?.focus ?? -1) >= 0;
    if (on === this.handles.length > 0) return;
    for (const h of this.handles) h.el.remove();
    this.handles = [];
    if (!on) return;
    const st = (): LabState => this.sim!.st;
    const knob = (): number => (HANDLE_PX + 24) / this.view.scale;
    const specs: HandleSpec[] = [
      { name: "vehicle", label: "start of the vehicle", colour: COLOURS.vehicle, get: () => st().vehicle, set: (p) => { st().vehicle.x = p.x; st().vehicle.y = p.y; } },
      { name: "target", label: "target", colour: COLOURS.seek, get: () => st().target, set: (p) => { st().target.x = p.x; st().target.y = p.y; } },
      {
        name: "beta", label: "target heading β", colour: COLOURS.seek,
        get: () => ({ x: st().target.x + knob() * Math.cos(st().target.theta), y: st().target.y + knob() * Math.sin(st().target.theta) }),
        set: (p) => { st().target.theta = Math.atan2(p.y - st().target.y, p.x - st().target.x); },
      },
    ];
    this.handles = specs.map((s) => new Handle(s, this.stage, this.view, () => this.edited(s.name)));
  }

  /** A handle moved: the target is sent to the agent where it is (the
   *  lab's drag); a moved start restarts the run from there. The
   *  attributes follow, without a rebuild. */
  private edited(which: string): void {
    const sim = this.sim;
    const cx = this.cx;
    if (!sim || !cx) return;
    const st = sim.st;
    const set: Array<[string, number]> = which === "vehicle"
      ? [["vx", st.vehicle.x], ["vy", st.vehicle.y]]
      : [["tx", st.target.x], ["ty", st.target.y], ["tb", (st.target.theta * 180) / Math.PI]];
    this.reflecting = true;
    for (const [k, v] of set) this.setAttribute(k, String(Math.round(v * 1e4) / 1e4));
    this.reflecting = false;
    if (which === "vehicle") {
      void this.rebuild(false);
      return;
    }
    try {
      sim.lab.setGoal(0, goalConfig(st));
      sim.pull();
      this.arrived = false;
      this.setPlaying(true);
    } catch (e) {
      this.fail(errorText(e));
    }
    this.draw();
  }

  private frame(now: number): void {
    this.raf = 0;
    const sim = this.sim;
    if (!sim || sim.paused || !this.isConnected) return;
    const ms = this.last === 0 ? 1000 / 60 : Math.min(100, now - this.last);
    this.last = now;
    this.acc += ms / 1000;
    const n = Math.min(8, Math.floor(this.acc / this.dt));
    this.acc = n === 8 ? 0 : this.acc - n * this.dt;
    sim.step(n, this.dt);
    this.observe();
    this.draw();
    if (!sim.paused) this.raf = requestAnimationFrame((t) => this.frame(t));
  }

  /** Sends `modechange` and `arrive` when they happen. */
  private observe(): void {
    const sim = this.sim!;
    const m = sim.internals?.mode ?? -1;
    if (m !== this.mode) {
      const previous = this.mode;
      this.mode = m;
      this.dispatchEvent(new CustomEvent("modechange", { detail: { mode: m, name: Mode[m] ?? null, word: modeWords(m)?.word ?? null, previous, time: sim.time } }));
    }
    if (!this.arrived && sim.arrived()) {
      this.arrived = true;
      const p = sim.pose(0);
      const gx = sim.field(0, StateField.GoalX) ?? NaN;
      const gy = sim.field(0, StateField.GoalY) ?? NaN;
      const e = (sim.field(0, StateField.GoalBeta) ?? NaN) - p.theta;
      const detail = { time: sim.time, x: p.x, y: p.y, theta: p.theta, distance: Math.hypot(gx - p.x, gy - p.y), headingError: Math.abs(Math.atan2(Math.sin(e), Math.cos(e))) };
      this.setPlaying(false);
      this.dispatchEvent(new CustomEvent("arrive", { detail }));
    }
  }

  private draw(): void {
    const s = this.surface;
    const sim = this.sim;
    if (!s || !sim || !this.scenes) return;
    beginFrame(s, COLOURS.background);
    drawScene(s, this.view, this.scenes.scene(sim.internals));
    for (const h of this.handles) h.place();
    const w = modeWords(this.mode);
    const head = w ? `<b style="color:${w.text}">${w.word}</b>` : "";
    this.status.innerHTML = `${head} · t ${sim.time.toFixed(1)} s${this.note ? ` · <span class="note">${escapeHtml(this.note)}</span>` : ""}`;
    this.root.querySelector("canvas")!.setAttribute("aria-label", `a vehicle steering to an oriented target; ${w?.word ?? "loading"}`);
  }
}

function escapeHtml(s: string): string {
  return s.replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
}
