// What the crowd page holds between frames: the core's CrowdLab (rebuilt
// when a preset loads or the clock resets), the clock's state (playing,
// steps per frame, pending single steps), the display switches, the view
// and the path editor. Every edit goes through the core, which may refuse it.

import { showMessage } from "../ui/page";
import { PAPER_UNITS, View } from "../ui/view";
import { CrowdLab, errorText, type CrowdConfig } from "../core/wasm";
import type { Panel } from "./panel";
import { PathEditor } from "./patheditor";
import { CrowdStepper, crowdWorkersWanted } from "./stepper";

export class CrowdSession {
  lab: CrowdLab | null = null;
  playing = true;
  stepsPerFrame = 1;
  /** Single steps asked for while paused (at most one runs per frame). */
  singleSteps = 0;
  showTrace = true;
  showHandles = true;
  /** Something changed that the next frame must draw. */
  dirty = true;
  /** The name of the preset last loaded. */
  preset = "";
  panel: Panel | null = null;
  readonly view = new View(PAPER_UNITS);
  readonly editor: PathEditor;
  /** The crowd stepped in workers (null: never started). */
  stepper: CrowdStepper | null = null;
  /** Workers asked for at the present count (URL or default). */
  workersWanted = 0;
  /** A bad `?workers=` value, reported once. */
  workersProblem: string | null = null;
  /** Test IV density: a count change scales the pathway with it. */
  scaleWithCount = false;

  constructor() {
    this.editor = new PathEditor(
      {
        points: () => this.lab?.pathPoints() ?? new Float32Array(),
        closed: () => this.lab?.pathClosed() ?? true,
        commit: (xy) => {
          if (!this.lab) return "the core is not loaded";
          try {
            this.syncFromWorkers();
            this.lab.setPathPoints(xy);
            this.placeStepping();
            return null;
          } catch (e) {
            return errorText(e);
          }
        },
        report: (m) => showMessage(m),
        changed: () => {
          this.dirty = true;
        },
      },
      this.view,
    );
  }

  /** Runs a setter on the core; shows its message if it refuses. */
  apply(f: (l: CrowdLab) => void): void {
    if (!this.lab) return;
    this.syncFromWorkers();
    try {
      f(this.lab);
      showMessage(null);
    } catch (e) {
      showMessage(errorText(e), "error");
    }
    this.placeStepping();
    this.dirty = true;
  }

  /** Whether workers own the crowd now. */
  get inWorkers(): boolean {
    return this.stepper?.active === true;
  }

  /** Before an edit with workers stepping: the page's CrowdLab takes the
   *  last complete state (the edit applies to what is drawn). */
  syncFromWorkers(): void {
    const st = this.stepper;
    if (this.lab && st?.active && st.state.length === this.lab.count() * 4) this.lab.loadState(st.state, st.time);
  }

  /** After a load or an edit: workers (re)start from the page's CrowdLab
   *  when the count asks for them (`?workers=`, or the default from
   *  AUTO_WORKERS_FROM boids), else the page's thread steps. */
  placeStepping(): void {
    const lab = this.lab;
    if (!lab) return;
    const w = crowdWorkersWanted(lab.count());
    this.workersWanted = w.n;
    if (w.problem && !this.workersProblem) {
      this.workersProblem = w.problem;
      showMessage(w.problem, "error");
    }
    if (w.n === 0 || lab.count() === 0) {
      // Back from workers: the measures restart (they skipped those steps).
      if (this.stepper?.active) lab.resetMetrics();
      this.stepper?.stop();
      lab.setMetricsEnabled(true);
      return;
    }
    if (!this.stepper || this.stepper.workers !== w.n) {
      this.stepper?.terminate();
      this.stepper = new CrowdStepper(w.n);
      this.stepper.onTraced = (x, y) => this.lab?.observeStep(x, y);
      this.stepper.onStep = (state) => {
        const l = this.lab;
        if (!l) return;
        const i = l.tracedBoid();
        l.observeStep(state[2 * i] ?? 0, state[2 * i + 1] ?? 0);
        this.dirty = true;
      };
      this.stepper.traced = () => this.lab?.tracedBoid() ?? 0;
    }
    // Measures need every boid's forces: only on the page's thread.
    lab.setMetricsEnabled(false);
    void this.stepper.start(lab.config(), lab.state(), lab.time());
  }

  /** Fits the pathway (with its radius) in the canvas. */
  fitView(): void {
    if (!this.lab) return;
    const xy = this.lab.pathPoints();
    const r = this.lab.pathRadius();
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i + 1 < xy.length; i += 2) {
      const x = xy[i] ?? 0;
      const y = xy[i + 1] ?? 0;
      x0 = Math.min(x0, x);
      x1 = Math.max(x1, x);
      y0 = Math.min(y0, y);
      y1 = Math.max(y1, y);
    }
    if (!Number.isFinite(x0)) return;
    this.view.fit(x0 - r, y0 - r, x1 + r, y1 + r, 40);
    this.dirty = true;
  }

  /** The panel shows what the core holds. */
  private syncPanel(): void {
    const { lab, panel } = this;
    if (!lab || !panel) return;
    const c = lab.config();
    panel.set({
      seek: c.seek,
      separation: c.separation,
      weight: c.separation_weight,
      boids: lab.count(),
      radius: lab.pathRadius(),
      closed: lab.pathClosed(),
    });
  }

  /** A new CrowdLab for `config` (the old one is kept if the core refuses). */
  load(config: CrowdConfig, fit: boolean): void {
    try {
      const next = new CrowdLab(config);
      this.lab?.free();
      this.lab = next;
      this.editor.selected = null;
      this.preset = config.name ?? "";
      showMessage(null);
    } catch (e) {
      showMessage(errorText(e), "error");
      return;
    }
    this.placeStepping();
    this.syncPanel();
    if (fit) this.fitView();
    this.dirty = true;
  }

  /** Back to step 0 keeping the edits (path, count, seek, separation). */
  reset(): void {
    if (this.lab) this.load(this.lab.config(), false);
  }

  /** One step on the next frame, paused. */
  stepOnce(): void {
    this.setPlaying(false);
    this.singleSteps++;
  }

  /** Called by setPlaying (the transport's button shows it). */
  onPlaying: (playing: boolean) => void = () => {};

  setPlaying(p: boolean): void {
    this.playing = p;
    this.onPlaying(p);
  }
}
