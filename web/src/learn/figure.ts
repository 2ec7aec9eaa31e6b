// The live figure every section of the learn page uses: a HiDPI canvas
// with draggable handles over it, play / pause / step / reset, a "show in
// the lab" link built from the lab's own URL state format, and a caption.
// The section supplies the simulation (its own Lab, forked from the page's
// one η table), the drawing and the live numbers in its prose.
//
// Motion: a figure plays only when the reader presses Play (or Step): it
// waits at the set-up its prose describes, so the numbers the text quotes
// are the ones on the canvas when the reader gets there. A run that ends
// holds its last picture for a moment, then rewinds to the start state:
// the prose describes the set-up the reader made, so its numbers must not
// stay blank ("—") for the state the run ended in.

import { beginFrame, setupCanvas, type Surface } from "../ui/canvas";
import type { LimitDefaults, RangeTable } from "../lab/fields";
import { COLOURS } from "../lab/render";
import type { LabState } from "../lab/state";
import { encodeState } from "../lab/urlstate";
import { View } from "../ui/view";
import { scaleBar } from "./draw";
import { Handle, type HandleSpec } from "./handle";

export interface FigureSpec {
  /** The section's id (the figure's data-figure). */
  name: string;
  /** What the canvas shows, for screen readers. */
  label: string;
  /** World box to fit, m: [x0, y0, x1, y1] (read again by `LiveFigure.refit`). */
  box(): readonly [number, number, number, number];
  handles: HandleSpec[];
  /** Back to the start state after an edit (a drag, a slider, Reset). */
  reset(): void;
  /** One simulation step of dt; false when the run is over. */
  step(): boolean;
  /** Simulated seconds since the start state. */
  time(): number;
  draw(ctx: CanvasRenderingContext2D, view: View): void;
  /** Writes the live numbers of the prose (called after every change). */
  numbers(): void;
  /** The lab's state that shows this figure's set-up. */
  labState(): LabState;
  /** What the canvas labels show now, by name (mirrored into the figure's
   *  data-shows as JSON after every frame, so a test can hold the picture
   *  against the numbers its paragraph quotes). */
  shows?(): Record<string, string | number | boolean>;
}

/** What the "show in the lab" links are encoded against: the core's ranges
 *  and default limits, as the lab reads them (set once by main.ts). */
let linkContext: { ranges: RangeTable; defaults: LimitDefaults } | null = null;

export function setLinkContext(ranges: RangeTable, defaults: LimitDefaults): void {
  linkContext = { ranges, defaults };
}

/** How long an ended run's last picture stays before the rewind, ms. */
export const REWIND_MS = 1500;

/** The stacked layout of learn.css (phones), where each figure is pinned
 *  above its prose. */
const stacked = window.matchMedia("(max-width: 820px)");
/** Share of the viewport's height a pinned figure is sized to, so that
 *  the paragraph read under it (about 10 lines) stays in view beside it. */
const PINNED_SHARE = 0.45;
/** A figure taller than this share even with the smallest canvas is not
 *  pinned: it would leave too little room for the text. */
const UNPIN_SHARE = 0.5;
/** The canvas's height range on a phone, CSS px: below 150 px the
 *  figures' labels crowd; above 300 px nothing more is seen. */
const STAGE_MIN = 150;
const STAGE_MAX = 300;

/** On a phone, sizes `stage` so that the whole pinned figure `host` (its
 *  buttons, sliders and diagram included) takes at most PINNED_SHARE of
 *  the viewport; a figure over UNPIN_SHARE even at STAGE_MIN is not
 *  pinned (it scrolls away with its section rather than cover the text). */
function fitPinned(host: HTMLElement, stage: HTMLElement): void {
  if (!stacked.matches) {
    stage.style.height = "";
    host.classList.remove("unpinned");
    return;
  }
  const room = PINNED_SHARE * window.innerHeight;
  const chrome = host.offsetHeight - stage.offsetHeight;
  const h = Math.round(Math.min(STAGE_MAX, Math.max(STAGE_MIN, room - chrome)));
  if (stage.style.height !== `${h}px`) stage.style.height = `${h}px`;
  host.classList.toggle("unpinned", chrome + h > UNPIN_SHARE * window.innerHeight);
}

/** Figures currently playing; one animation frame drives them all. */
const playing = new Set<LiveFigure>();
let rafId = 0;
let last = 0;

function tick(now: number): void {
  const dtMs = last === 0 ? 16.7 : Math.min(100, now - last);
  last = now;
  for (const f of playing) f.advance(dtMs);
  rafId = playing.size > 0 ? requestAnimationFrame(tick) : 0;
  if (rafId === 0) last = 0;
}

export class LiveFigure {
  readonly view = new View();
  /** Where a section puts its sliders and choices (under the canvas). */
  readonly controls: HTMLDivElement;
  private readonly surface: Surface;
  private readonly handles: Handle[];
  private readonly playBtn: HTMLButtonElement;
  private readonly clock: HTMLSpanElement;
  private readonly link: HTMLAnchorElement;
  private acc = 0;
  private over = false;
  private rewindTimer = 0;
  /** Frames drawn (tests wait for one). */
  frames = 0;

  constructor(private readonly host: HTMLElement, readonly spec: FigureSpec, private readonly dt: number) {
    host.classList.add("figure");
    host.dataset["figure"] = spec.name;
    const stage = document.createElement("div");
    stage.className = "fig-stage";
    const canvas = document.createElement("canvas");
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", spec.label);
    stage.append(canvas);
    const bar = document.createElement("div");
    bar.className = "fig-bar";
    this.playBtn = this.button(bar, "play", "Play", () => this.setPlaying(!playing.has(this)));
    this.button(bar, "step", "Step", () => { this.setPlaying(false); this.stepOnce(); });
    this.button(bar, "reset", "Reset", () => { this.setPlaying(false); this.changed(); });
    this.clock = document.createElement("span");
    this.clock.className = "fig-clock";
    this.link = document.createElement("a");
    this.link.className = "tolab";
    this.link.textContent = "Show in the lab ↗";
    this.link.target = "_blank";
    this.link.rel = "noopener";
    bar.append(this.clock, this.link);
    this.controls = document.createElement("div");
    this.controls.className = "fig-controls";
    host.append(stage, bar, this.controls);
    this.surface = setupCanvas(canvas, (s) => {
      this.view.resize(s.width, s.height);
      this.refit();
    });
    this.handles = spec.handles.map((h) => new Handle(h, stage, this.view, () => this.changed()));
    const fit = (): void => fitPinned(host, stage);
    new ResizeObserver(fit).observe(host);
    window.addEventListener("resize", fit);
    stacked.addEventListener("change", fit);
    this.changed();
    this.refit();
  }

  private button(bar: HTMLElement, role: string, text: string, onClick: () => void): HTMLButtonElement {
    const b = document.createElement("button");
    b.type = "button";
    b.dataset["role"] = role;
    b.textContent = text;
    b.addEventListener("click", onClick);
    bar.append(b);
    return b;
  }

  /** An edit: back to the start state, numbers, link and picture updated. */
  changed(): void {
    this.cancelRewind();
    this.spec.reset();
    this.over = false;
    this.acc = 0;
    this.spec.numbers();
    if (linkContext) this.link.href = `./index.html#${encodeState(this.spec.labState(), linkContext.ranges, linkContext.defaults)}`;
    this.redraw();
  }

  /** Fits the view to the spec's box (a new set-up; never during a drag). */
  refit(): void {
    const [x0, y0, x1, y1] = this.spec.box();
    this.view.fit(x0, y0, x1, y1, 16);
    this.redraw();
  }

  setPlaying(on: boolean): void {
    if (on) {
      this.cancelRewind();
      if (this.over) this.changed();
      playing.add(this);
      if (rafId === 0) rafId = requestAnimationFrame(tick);
    } else {
      playing.delete(this);
    }
    this.playBtn.textContent = on ? "Pause" : "Play";
    this.playBtn.setAttribute("aria-pressed", String(on));
  }

  private stepOnce(): void {
    if (this.over) this.changed();
    this.cancelRewind();
    this.over = !this.spec.step();
    if (this.over) this.ended();
    this.spec.numbers();
    this.redraw();
  }

  /** Runs to the end at once, as Play would (the test build's hook). */
  finish(): void {
    this.setPlaying(false);
    if (this.over) this.changed();
    while (!this.over) this.over = !this.spec.step();
    this.ended();
    this.spec.numbers();
    this.redraw();
  }

  /** The run is over: hold its last picture, then rewind. */
  private ended(): void {
    this.cancelRewind();
    this.rewindTimer = window.setTimeout(() => {
      this.rewindTimer = 0;
      this.changed();
    }, REWIND_MS);
  }

  private cancelRewind(): void {
    if (this.rewindTimer !== 0) window.clearTimeout(this.rewindTimer);
    this.rewindTimer = 0;
  }

  /** Runs the steps `ms` of wall time is worth (called by the shared frame). */
  advance(ms: number): void {
    this.acc += ms / 1000;
    let k = Math.min(4, Math.floor(this.acc / this.dt));
    this.acc -= k * this.dt;
    if (k === 4) this.acc = 0;
    while (k-- > 0 && !this.over) this.over = !this.spec.step();
    if (this.over) {
      this.setPlaying(false);
      this.ended();
    }
    this.spec.numbers();
    this.redraw();
  }

  redraw(): void {
    const s = this.surface;
    if (!s) return;
    beginFrame(s, COLOURS.background);
    this.spec.draw(s.ctx, this.view);
    scaleBar(s.ctx, this.view);
    for (const h of this.handles ?? []) h.place();
    this.clock.textContent = `t ${this.spec.time().toFixed(1)} s`;
    if (this.spec.shows) this.host.dataset["shows"] = JSON.stringify(this.spec.shows());
    this.frames++;
  }
}
