// One gallery panel per wander component (one preset file): a grid of tiles,
// one per variant, and the panel's knobs (seed offset, steps, clamp scale,
// speed, hold scale). A knob edits every variant's JSON configuration and
// rebuilds its WanderLab; a re-run replays the traces growing over ~45 frames.

import { beginFrame, setupCanvas, type Surface } from "../ui/canvas";
import { button, slider } from "../ui/controls";
import { errorText, WanderLab, type WanderConfig, type WanderPreset, type WanderVariant } from "../core/wasm";
import { PAPER_UNITS, View } from "../ui/view";
import { tooDeep } from "./jsontext";
import { drawShares, drawTile, markovNote, OWN_SCALE_FROM, shownSide, traceSpan } from "./render";
import { COMPARE } from "./compare";

/** Frames a re-run takes to draw the traces. */
const RUN_FRAMES = 45;

export interface Knobs {
  seedOffset: number;
  steps: number;
  clampScale: number;
  speedScale: number;
  holdScale: number;
}

/** The variant's configuration with the panel's knobs applied. */
export function edited(base: WanderConfig, k: Knobs): WanderConfig {
  const c: WanderConfig = structuredClone(base);
  c.seed = (c.seed ?? 0) + k.seedOffset;
  const ctl = c.control;
  const scale = (v: number | undefined): number | undefined =>
    v === undefined ? undefined : Math.min(180, v * k.clampScale);
  if (k.clampScale !== 1) {
    const d = scale(ctl.max_displacement_deg);
    const v = scale(ctl.max_velocity_deg);
    const a = scale(ctl.max_acceleration_deg);
    if (d !== undefined) ctl.max_displacement_deg = d;
    if (v !== undefined) ctl.max_velocity_deg = v;
    if (a !== undefined) ctl.max_acceleration_deg = a;
  }
  if (k.speedScale !== 1) {
    c.agent = { ...(c.agent ?? {}), speed: (c.agent?.speed ?? 2) * k.speedScale };
  }
  if (k.holdScale !== 1 && c.hold) {
    const h = c.hold;
    const s = (n: number): number => Math.max(1, Math.round(n * k.holdScale));
    c.hold = h.kind === "fixed" ? { kind: "fixed", every: s(h.every) } : { kind: "random", min: s(h.min), max: Math.max(s(h.min), s(h.max)) };
  }
  c.trace_capacity = Math.max(c.trace_capacity ?? 4096, k.steps + 1);
  return c;
}

interface Tile {
  base: WanderConfig;
  variant: WanderVariant;
  canvas: HTMLCanvasElement;
  surface: Surface | null;
  view: View;
  lab: WanderLab | null;
  error: HTMLElement;
  /** What the tile's drawing needs said: its own scale, its trace's measures. */
  note: HTMLElement;
  /** How many times larger than its row's scale the tile is drawn (1: the row's). */
  zoom: number;
  json: HTMLTextAreaElement;
  /** Steps still to run in the current re-run. */
  pending: number;
  drawn: boolean;
}

export interface PanelStatus {
  name: string;
  tiles: number;
  drawn: number;
  errors: string[];
  running: boolean;
  /** Each tile's grid row (its top, CSS px), drawing scale (px per unit),
   *  zoom over its row's scale (1: the row's) and note. */
  scales: Array<{ top: number; scale: number; zoom: number; note: string }>;
}

export class GalleryPanel {
  readonly tiles: Tile[] = [];
  readonly knobs: Knobs;
  private readonly root: HTMLElement;
  private chunk = 1;

  constructor(parent: HTMLElement, readonly name: string, readonly preset: WanderPreset) {
    this.knobs = { seedOffset: 0, steps: preset.steps, clampScale: 1, speedScale: 1, holdScale: 1 };
    this.root = document.createElement("section");
    this.root.className = "wpanel";
    this.root.id = `panel-${name}`;
    const h = document.createElement("h2");
    h.textContent = `${preset.title} `;
    const sec = document.createElement("span");
    sec.className = "muted";
    sec.textContent = `(${preset.section}, ${preset.variants.length} variants)`;
    h.append(sec);
    this.root.append(h);
    const compare = COMPARE[name];
    if (compare) {
      const p = document.createElement("p");
      p.className = "compare";
      p.textContent = compare;
      this.root.append(p);
    }

    const knobs = document.createElement("div");
    knobs.className = "knobs";
    const rebuild = (): void => this.rebuild();
    slider(knobs, {
      id: `${name}-seed`, label: "seed offset", unit: "", min: 0, max: 99, step: 1, value: 0, digits: 0,
      onInput: (v) => { this.knobs.seedOffset = v; rebuild(); },
    });
    slider(knobs, {
      id: `${name}-steps`, label: "steps", unit: "", min: 100, max: 20000, step: 100, value: preset.steps, digits: 0,
      onInput: (v) => { this.knobs.steps = v; rebuild(); },
    });
    slider(knobs, {
      id: `${name}-clamp`, label: "clamps ×", unit: "", min: 0.25, max: 4, step: 0.05, value: 1, digits: 2,
      onInput: (v) => { this.knobs.clampScale = v; rebuild(); },
    });
    slider(knobs, {
      id: `${name}-speed`, label: "speed ×", unit: "", min: 0.25, max: 4, step: 0.05, value: 1, digits: 2,
      onInput: (v) => { this.knobs.speedScale = v; rebuild(); },
    });
    if (preset.variants.some((v) => v.config.hold)) {
      slider(knobs, {
        id: `${name}-hold`, label: "hold ×", unit: "", min: 0.25, max: 4, step: 0.05, value: 1, digits: 2,
        onInput: (v) => { this.knobs.holdScale = v; rebuild(); },
      });
    }
    button(knobs, `${name}-rerun`, "Re-run", "replay every variant from step 0 (same seeds, same traces)", () => this.rerun());
    this.root.append(knobs);

    const grid = document.createElement("div");
    grid.className = "tiles";
    for (const variant of preset.variants) grid.append(this.makeTile(variant));
    this.root.append(grid);
    parent.append(this.root);
  }

  private makeTile(variant: WanderVariant): HTMLElement {
    const el = document.createElement("figure");
    el.className = "tile";
    el.style.margin = "0";
    const canvas = document.createElement("canvas");
    canvas.setAttribute("aria-label", variant.label);
    const cap = document.createElement("figcaption");
    cap.className = "label";
    cap.textContent = variant.label;
    // The paper's image file name is for finding it in the paper, not a title.
    if (variant.figure) cap.title = `the paper's image: ${variant.figure}`;
    const error = document.createElement("div");
    error.className = "err";
    const note = document.createElement("p");
    note.className = "note";
    const details = document.createElement("details");
    const summary = document.createElement("summary");
    summary.textContent = "JSON";
    const json = document.createElement("textarea");
    json.spellcheck = false;
    json.value = JSON.stringify(variant.config, null, 1);
    const apply = document.createElement("button");
    apply.type = "button";
    apply.textContent = "Apply";
    details.append(summary, json, apply);
    el.append(canvas, cap, note, error, details);
    const tile: Tile = {
      base: variant.config, variant, canvas, surface: null, view: new View(PAPER_UNITS), lab: null, error, note, zoom: 1, json, pending: 0, drawn: false,
    };
    apply.addEventListener("click", () => {
      const deep = tooDeep(json.value);
      if (deep !== null) {
        error.textContent = deep;
        return;
      }
      try {
        // The core parses the text as the native code does (duplicate keys,
        // unknown fields and ranges refused, the field named), then hands
        // back the configuration the knobs edit.
        const checked = WanderLab.fromJson(json.value);
        tile.base = checked.config();
        checked.free();
      } catch (e) {
        error.textContent = errorText(e);
        return;
      }
      this.build(tile);
      this.chunk = Math.ceil(this.knobs.steps / RUN_FRAMES);
    });
    this.tiles.push(tile);
    tile.surface = setupCanvas(canvas, () => this.drawAll());
    return el;
  }

  /** (Re)builds a tile's wanderer from its edited configuration; the trace restarts. */
  private build(tile: Tile): void {
    tile.lab?.free();
    tile.lab = null;
    tile.drawn = false;
    try {
      tile.lab = new WanderLab(edited(tile.base, this.knobs));
      tile.error.textContent = "";
      tile.pending = this.knobs.steps;
    } catch (e) {
      tile.error.textContent = errorText(e);
      tile.pending = 0;
      this.drawAll();
    }
  }

  /** Knob changed: rebuild every variant and run it at once. */
  rebuild(): void {
    for (const t of this.tiles) {
      this.build(t);
      if (t.lab) {
        t.lab.run(t.pending);
        t.pending = 0;
      }
    }
    this.drawAll();
  }

  /** Replays from step 0, the traces growing over RUN_FRAMES frames. */
  rerun(): void {
    for (const t of this.tiles) this.build(t);
    this.chunk = Math.ceil(this.knobs.steps / RUN_FRAMES);
  }

  /** True while a re-run still has steps to replay (read from the tiles, so a
   *  re-run started by this panel's own button counts before the next frame). */
  busy(): boolean {
    return this.tiles.some((t) => t.lab !== null && t.pending > 0);
  }

  /** One animation frame: replays the next chunk of every pending tile. */
  tick(): void {
    let ran = false;
    for (const t of this.tiles) {
      if (!t.lab || t.pending <= 0) continue;
      const n = Math.min(t.pending, this.chunk);
      t.lab.run(n);
      t.pending -= n;
      ran = true;
    }
    if (ran) this.drawAll();
  }

  /** Draws every tile, the tiles of one grid row at one scale (the
   *  row's largest trace), so that a row compares like with like; a trace
   *  that scale would draw OWN_SCALE_FROM or more times smaller than its
   *  own fit (a walk that stays near its start) is drawn at its own scale
   *  instead, and the tile says so. */
  private drawAll(): void {
    const traces = this.tiles.map((t) => (t.lab ? { trace: t.lab.trace(), path: t.lab.pathPoints() } : null));
    const rowOf = this.tiles.map((t) => Math.round(t.canvas.getBoundingClientRect().top));
    const own = traces.map((tr) => (tr ? traceSpan(tr.trace, tr.path) : 0));
    const span = new Map<number, number>();
    this.tiles.forEach((_, i) => {
      if (traces[i]) span.set(rowOf[i]!, Math.max(span.get(rowOf[i]!) ?? 0, own[i]!));
    });
    this.tiles.forEach((t, i) => {
      const s = t.surface;
      if (!s) return;
      const tr = traces[i];
      if (!t.lab || !tr) {
        beginFrame(s, "#fbeaea");
        return;
      }
      const row = span.get(rowOf[i]!) ?? 0;
      const zoom = shownSide(row) / shownSide(own[i]!);
      t.zoom = zoom >= OWN_SCALE_FROM ? zoom : 1;
      drawTile(s, t.view, tr.trace, tr.path, t.zoom > 1 ? 0 : row, t.zoom);
      if (this.name === "markov") drawShares(s, tr.trace);
      const notes = [
        t.zoom > 1 ? `Drawn at its own scale, ${t.zoom.toFixed(0)}× the row's: at the row's it would be a speck.` : "",
        this.name === "markov" ? markovNote(tr.trace) : "",
      ].filter((x) => x !== "").join(" ");
      if (t.note.textContent !== notes) t.note.textContent = notes;
      t.drawn = t.lab.traceLen() > 1;
    });
  }

  status(): PanelStatus {
    return {
      name: this.name,
      tiles: this.tiles.length,
      drawn: this.tiles.filter((t) => t.drawn).length,
      errors: this.tiles.map((t) => t.error.textContent ?? "").filter((e) => e !== ""),
      running: this.tiles.some((t) => t.pending > 0),
      scales: this.tiles.map((t) => ({ top: Math.round(t.canvas.getBoundingClientRect().top), scale: t.view.scale, zoom: t.zoom, note: t.note.textContent ?? "" })),
    };
  }
}
