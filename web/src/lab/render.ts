// Drawing only: grid, trails, agents, targets in the paper's mode colours,
// and the overlays (radial direction, η at the target, γ, the nearest η ring,
// the η field, the relaxed arc 𝒜 and α_r). No state, no simulation.

import type { Surface } from "../ui/canvas";
import { FORCE_2D, GL_THRESHOLD, GlSprites, markPath } from "../ui/glsprites";
import { abgr, headingAt, PixelSprites } from "../ui/sprites";
import { vehicleGlyph, type VehicleKind } from "../ui/glyphs";
import type { View } from "../ui/view";
import { FIELD_STRIDE, Mode, StateField } from "../core/wasm";
import { drawObstacles } from "./obstacles";
import { MANOEUVRE_WORDS, MODE_WORDS, modeColour } from "../ui/modes";
import { RIM_MIN_PX } from "./handles";
import type { Trails } from "./trails";

/** The paper's names of the modes, indexed by the core's `Mode` number. */
export const MODE_NAMES = ["End_of_Steering", "Orientation_only", "Position_only", "Funnelling"] as const;

/** Paper 000 §6's shapes (circle = seek, triangle = orientation only,
 *  circle + triangle = funnelling), each mode in its own colour
 *  (src/ui/modes.ts); grey = end of steering. */
export const COLOURS = {
  seek: MODE_WORDS.PositionOnly.colour,
  funnelling: MODE_WORDS.Funnelling.colour,
  orientation: MODE_WORDS.OrientationOnly.colour,
  end: MODE_WORDS.EndOfSteering.colour,
  background: "#fbfaf7",
  grid: "#e6e3dc",
  axis: "#cfcac0",
  vehicle: "#2b2b2b",
  radial: "#222222",
  eta: "#9c27b0",
  gamma: "#138a36",
  ring: "#e08a00",
  ringDark: "#7a4b00",
  field: "#5f7fa8",
  fieldDark: "#1f2f48",
  arc: "#00a3a3",
  trail: "rgba(60, 60, 60, 0.35)",
} as const;

export interface TargetDraw {
  x: number;
  y: number;
  beta: number;
  dTol: number;
  epsTol: number;
  mode: number;
}

/** Samples in the vehicle frame: (distance, α, α+η, reachable 0/1) ×n. */
export interface FieldDraw {
  samples: Float32Array;
  originX: number;
  originY: number;
  theta: number;
  dark: string;
  light: string;
}

export interface Overlay {
  x: number;
  y: number;
  theta: number;
  targetX: number;
  targetY: number;
  /** θ+α+η: predicted final tangential direction (world). */
  etaDir: number | null;
  /** Modulated heading γ (world). */
  gamma: number | null;
  /** Relaxed arc 𝒜 (world angles from the vehicle) on radius `arcR`, and α_r. */
  arc: { r: number; a0: number; a1: number; ar: number } | null;
}

/** A predicted seek path (crate::ghost): x, y pairs (world), and its end. */
export interface GhostDraw {
  points: Float32Array;
  reached: boolean;
  /** Final tangential direction (world), NaN when not reached. */
  finalDir: number;
  /** Drawn at the fallback speed v_dt (the queried speed orbits). */
  slowed: boolean;
}

/** The ghost path: dashed in η's colour, with its final direction as an
 *  arrow (the direction η measures); an orbit ends in a cross. */
export function drawGhost(ctx: CanvasRenderingContext2D, v: View, g: GhostDraw, width = 2): void {
  const n = Math.floor(g.points.length / 2);
  if (n < 2) return;
  ctx.save();
  ctx.strokeStyle = COLOURS.eta;
  ctx.globalAlpha = 0.7;
  ctx.lineWidth = width;
  ctx.setLineDash(g.slowed ? [2, 4] : [7, 5]);
  strokePolyline(ctx, v, g.points, n);
  ctx.setLineDash([]);
  const e = v.toScreen(g.points[2 * n - 2]!, g.points[2 * n - 1]!);
  if (g.reached && Number.isFinite(g.finalDir)) {
    arrow(ctx, e.x, e.y, g.finalDir, 26, 7);
  } else {
    ctx.beginPath();
    ctx.moveTo(e.x - 5, e.y - 5);
    ctx.lineTo(e.x + 5, e.y + 5);
    ctx.moveTo(e.x + 5, e.y - 5);
    ctx.lineTo(e.x - 5, e.y + 5);
    ctx.stroke();
  }
  ctx.restore();
}

export interface Scene {
  /** The followed agent's predicted seek path, or null. */
  ghost: GhostDraw | null;
  state: Float32Array;
  stride: number;
  count: number;
  targets: TargetDraw[];
  trails: Trails | null;
  /** Index of the editable agent (handles drawn), or -1. */
  focus: number;
  /** The agent the HUD describes: ringed when there are several. */
  shown: number;
  focusTarget: TargetDraw | null;
  overlay: Overlay | null;
  showRadial: boolean;
  ring: FieldDraw | null;
  field: FieldDraw | null;
  /** Screen length of the orientation/heading handles, CSS px. */
  handlePx: number;
  /** Static obstacles (lab/obstacles.ts layout), drawn with their knobs. */
  obstacles: readonly number[];
  /** Body radius (m) drawn round each agent when avoidance is on, else null. */
  bodyRadius: number | null;
  /** The vehicle's kind (its glyph); a car-like one's manoeuvre has its own colour. */
  kind: VehicleKind;
}

export function arrow(ctx: CanvasRenderingContext2D, x: number, y: number, ang: number, len: number, head = 6): void {
  const ex = x + Math.cos(ang) * len;
  const ey = y - Math.sin(ang) * len;
  ctx.beginPath();
  ctx.moveTo(x, y);
  ctx.lineTo(ex, ey);
  ctx.moveTo(ex, ey);
  ctx.lineTo(ex - Math.cos(ang - 0.45) * head, ey + Math.sin(ang - 0.45) * head);
  ctx.moveTo(ex, ey);
  ctx.lineTo(ex - Math.cos(ang + 0.45) * head, ey + Math.sin(ang + 0.45) * head);
  ctx.stroke();
}

export function grid(s: Surface, v: View): void {
  const { ctx } = s;
  let step = 1;
  while (step * v.scale < 18) step *= 5;
  const a = v.toWorld(0, s.height);
  const b = v.toWorld(s.width, 0);
  ctx.lineWidth = 1;
  ctx.strokeStyle = COLOURS.grid;
  ctx.beginPath();
  for (let x = Math.floor(a.x / step) * step; x <= b.x; x += step) {
    const p = v.toScreen(x, 0);
    ctx.moveTo(Math.round(p.x) + 0.5, 0);
    ctx.lineTo(Math.round(p.x) + 0.5, s.height);
  }
  for (let y = Math.floor(a.y / step) * step; y <= b.y; y += step) {
    const p = v.toScreen(0, y);
    ctx.moveTo(0, Math.round(p.y) + 0.5);
    ctx.lineTo(s.width, Math.round(p.y) + 0.5);
  }
  ctx.stroke();
  ctx.strokeStyle = COLOURS.axis;
  const o = v.toScreen(0, 0);
  ctx.beginPath();
  ctx.moveTo(o.x, 0);
  ctx.lineTo(o.x, s.height);
  ctx.moveTo(0, o.y);
  ctx.lineTo(s.width, o.y);
  ctx.stroke();
}

/** Draws a target in its mode's colours (paper 000 §6); `carLike`: the
 *  vehicle cannot turn on the spot (its manoeuvre's colour, ui/modes.ts). */
export function drawTarget(ctx: CanvasRenderingContext2D, v: View, t: TargetDraw, handlePx: number, handles: boolean, carLike = false): void {
  const c = v.toScreen(t.x, t.y);
  const r = Math.max(2, t.dTol * v.scale);
  const circle = t.mode === Mode.PositionOnly || t.mode === Mode.Funnelling || t.mode === Mode.EndOfSteering;
  const triangle = t.mode === Mode.OrientationOnly || t.mode === Mode.Funnelling || t.mode === Mode.EndOfSteering;
  const colour = modeColour(t.mode, carLike);
  ctx.lineWidth = 2;
  ctx.strokeStyle = colour;
  ctx.fillStyle = colour;
  if (circle) {
    ctx.beginPath();
    ctx.arc(c.x, c.y, r, 0, Math.PI * 2);
    ctx.stroke();
  } else {
    // The tolerance circle stays visible (dashed, faint) for dragging.
    ctx.save();
    ctx.setLineDash([4, 4]);
    ctx.globalAlpha = 0.35;
    ctx.beginPath();
    ctx.arc(c.x, c.y, r, 0, Math.PI * 2);
    ctx.stroke();
    ctx.restore();
  }
  const L = handlePx;
  const a0 = t.beta - t.epsTol;
  const a1 = t.beta + t.epsTol;
  ctx.save();
  if (!triangle) ctx.globalAlpha = 0.3;
  ctx.globalAlpha *= 0.22;
  ctx.beginPath();
  ctx.moveTo(c.x, c.y);
  ctx.lineTo(c.x + Math.cos(a0) * L, c.y - Math.sin(a0) * L);
  ctx.lineTo(c.x + Math.cos(a1) * L, c.y - Math.sin(a1) * L);
  ctx.closePath();
  ctx.fill();
  ctx.globalAlpha /= 0.22;
  if (!triangle) ctx.setLineDash([4, 4]);
  ctx.stroke();
  ctx.restore();
  // The orientation needle β.
  ctx.beginPath();
  ctx.moveTo(c.x, c.y);
  ctx.lineTo(c.x + Math.cos(t.beta) * (L + 24), c.y - Math.sin(t.beta) * (L + 24));
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(c.x, c.y, 3, 0, Math.PI * 2);
  ctx.fill();
  if (handles) {
    ctx.fillStyle = "#ffffff";
    ctx.lineWidth = 1.5;
    const rk = Math.max(r, RIM_MIN_PX);
    // A circle smaller than the knob's distance: a stalk from the rim
    // carries the knob, so that it reads as the rim's.
    if (rk > r + 1) {
      const ux = Math.cos(t.beta + Math.PI / 2);
      const uy = -Math.sin(t.beta + Math.PI / 2);
      ctx.beginPath();
      ctx.moveTo(c.x + ux * r, c.y + uy * r);
      ctx.lineTo(c.x + ux * (rk - 5), c.y + uy * (rk - 5));
      ctx.stroke();
    }
    for (const [hx, hy] of [
      [c.x + Math.cos(t.beta) * (L + 24), c.y - Math.sin(t.beta) * (L + 24)],
      [c.x + Math.cos(a1) * L, c.y - Math.sin(a1) * L],
      [c.x + Math.cos(t.beta + Math.PI / 2) * rk, c.y - Math.sin(t.beta + Math.PI / 2) * rk],
    ] as const) {
      ctx.beginPath();
      ctx.arc(hx, hy, 5, 0, Math.PI * 2);
      ctx.fill();
      ctx.stroke();
    }
  }
}

/** `gapPx` > 0: at most one arrow per `gapPx` square of the screen (the
 *  core samples the field densely near the vehicle; drawn all, the arrows
 *  there are a tangle). */
export function drawField(ctx: CanvasRenderingContext2D, v: View, f: FieldDraw, lenPx: number, lineWidth: number, gapPx = 0): void {
  const n = Math.floor(f.samples.length / FIELD_STRIDE);
  const cos = Math.cos(f.theta);
  const sin = Math.sin(f.theta);
  const taken = new Set<number>();
  for (const reach of [1, 0]) {
    ctx.strokeStyle = reach ? f.light : f.dark;
    ctx.lineWidth = lineWidth;
    ctx.beginPath();
    for (let k = 0; k < n; k++) {
      const o = k * FIELD_STRIDE;
      if ((f.samples[o + 3]! > 0.5 ? 1 : 0) !== reach) continue;
      const d = f.samples[o]!;
      const a = f.samples[o + 1]!;
      const dir = f.samples[o + 2]! + f.theta;
      const lx = d * Math.cos(a);
      const ly = d * Math.sin(a);
      const p = v.toScreen(f.originX + lx * cos - ly * sin, f.originY + lx * sin + ly * cos);
      if (gapPx > 0) {
        const cell = Math.floor(p.x / gapPx) * 65536 + Math.floor(p.y / gapPx);
        if (taken.has(cell)) continue;
        taken.add(cell);
      }
      const ex = p.x + Math.cos(dir) * lenPx;
      const ey = p.y - Math.sin(dir) * lenPx;
      ctx.moveTo(p.x, p.y);
      ctx.lineTo(ex, ey);
      ctx.moveTo(ex, ey);
      ctx.lineTo(ex - Math.cos(dir - 0.5) * lenPx * 0.35, ey + Math.sin(dir - 0.5) * lenPx * 0.35);
    }
    ctx.stroke();
  }
}

/** Agents above this count are drawn as pixel sprites (../sprites)
 *  instead of triangles, and without their targets. */
export const CROWD_THRESHOLD = 400;

const sprites = new PixelSprites();
const glSprites = new GlSprites();

function drawCrowd(s: Surface, v: View, sc: Scene): void {
  // Above GL_THRESHOLD one WebGL2 instanced draw straight from the state records.
  if (sc.count > GL_THRESHOLD && !FORCE_2D) {
    const { X, Y, Theta, Mode: M } = StateField;
    const palette = modePalette(sc.kind);
    if (glSprites.draw(s, v, sc.state, null, sc.count, { stride: sc.stride, x: X, y: Y, theta: Theta, colour: M }, palette, 3.5)) {
      markPath(s.canvas, "webgl2");
      return;
    }
  }
  glSprites.hide();
  markPath(s.canvas, "sprites");
  if (!sprites.begin(s)) return;
  const W = s.canvas.width;
  const H = s.canvas.height;
  const k = s.dpr;
  const colour = modePalette(sc.kind).map(abgr);
  const ox = v.width / 2;
  const oy = v.height / 2;
  const r = Math.max(1, Math.round(k));
  const nose = 3 * k;
  const { X, Y, Theta } = StateField;
  const noses = sprites.noses(nose);
  // Rounded by `+ 0.5 | 0`: `Math.round` for every pixel kept (the rest,
  // negative ones included, are left out by the bounds test).
  for (let i = 0; i < sc.count; i++) {
    const o = i * sc.stride;
    const sx = (((sc.state[o + X]! - v.cx) * v.scale + ox) * k + 0.5) | 0;
    const sy = ((oy - (sc.state[o + Y]! - v.cy) * v.scale) * k + 0.5) | 0;
    if (sx < r + 4 * k || sy < r + 4 * k || sx >= W - r - 4 * k || sy >= H - r - 4 * k) continue;
    const c = colour[sc.state[o + StateField.Mode]! | 0] ?? colour[3]!;
    const j = headingAt(sc.state[o + Theta]!);
    sprites.stampNosed(sx, sy, r, c, noses[j]!, noses[j + 1]!);
  }
  sprites.present(s);
}

function drawAgents(ctx: CanvasRenderingContext2D, v: View, sc: Scene): void {
  glSprites.hide();
  markPath(ctx.canvas, "triangles");
  const size = Math.max(5, Math.min(14, 0.45 * v.scale));
  const { X, Y, Theta } = StateField;
  if (sc.bodyRadius !== null && sc.bodyRadius * v.scale >= 3) {
    // The bodies avoidance keeps apart.
    const r = sc.bodyRadius * v.scale;
    ctx.save();
    ctx.strokeStyle = "rgba(43, 43, 43, 0.35)";
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (let i = 0; i < sc.count; i++) {
      const p = v.toScreen(sc.state[i * sc.stride + X]!, sc.state[i * sc.stride + Y]!);
      if (p.x < -r || p.y < -r || p.x > v.width + r || p.y > v.height + r) continue;
      ctx.moveTo(p.x + r, p.y);
      ctx.arc(p.x, p.y, r, 0, Math.PI * 2);
    }
    ctx.stroke();
    ctx.restore();
  }
  // One path per mode colour: cheap enough for 10⁴ agents. Each glyph is
  // filled in the colour of the mode in force, outlined dark on the paper.
  const carLike = sc.kind === "carLike";
  // A car's glyph is longer than a walker's: a third larger, so that its
  // wheels and bonnet read at the small scale a car's loops are fitted at.
  const glyph = sc.kind === "car" || carLike ? Math.max(8, 1.35 * size) : size;
  ctx.save();
  ctx.strokeStyle = COLOURS.vehicle;
  ctx.lineWidth = 1;
  ctx.lineJoin = "round";
  for (const mode of [Mode.EndOfSteering, Mode.OrientationOnly, Mode.PositionOnly, Mode.Funnelling]) {
    ctx.fillStyle = modeColour(mode, carLike);
    ctx.beginPath();
    for (let i = 0; i < sc.count; i++) {
      const o = i * sc.stride;
      if (sc.state[o + StateField.Mode] !== mode) continue;
      const p = v.toScreen(sc.state[o + X]!, sc.state[o + Y]!);
      if (p.x < -20 || p.y < -20 || p.x > v.width + 20 || p.y > v.height + 20) continue;
      const th = sc.state[o + Theta]!;
      vehicleGlyph(ctx, sc.kind, p.x, p.y, Math.cos(th), -Math.sin(th), glyph);
    }
    ctx.fill();
    ctx.stroke();
  }
  ctx.restore();
}

/** The sprites' colours by the core's mode number (end, orientation,
 *  seek, funnelling): each mode's own, a car-like vehicle's manoeuvre its own. */
function modePalette(kind: VehicleKind): string[] {
  return [COLOURS.end, kind === "carLike" ? MANOEUVRE_WORDS.colour : COLOURS.orientation, COLOURS.seek, COLOURS.funnelling];
}

/** Faint lines from each vehicle to its own target, and a ring round the
 *  agent the HUD describes (presets with several agents). */
function drawLinks(ctx: CanvasRenderingContext2D, v: View, sc: Scene): void {
  const { X, Y, GoalX, GoalY } = StateField;
  ctx.save();
  ctx.strokeStyle = "rgba(43, 43, 43, 0.16)";
  ctx.lineWidth = 1;
  ctx.setLineDash([3, 4]);
  ctx.beginPath();
  for (let i = 0; i < sc.count; i++) {
    const o = i * sc.stride;
    const p = v.toScreen(sc.state[o + X]!, sc.state[o + Y]!);
    const t = v.toScreen(sc.state[o + GoalX]!, sc.state[o + GoalY]!);
    ctx.moveTo(p.x, p.y);
    ctx.lineTo(t.x, t.y);
  }
  ctx.stroke();
  ctx.setLineDash([]);
  if (sc.shown >= 0 && sc.shown < sc.count) {
    const o = sc.shown * sc.stride;
    const p = v.toScreen(sc.state[o + X]!, sc.state[o + Y]!);
    const t = v.toScreen(sc.state[o + GoalX]!, sc.state[o + GoalY]!);
    ctx.strokeStyle = "rgba(20, 20, 20, 0.55)";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(p.x, p.y);
    ctx.lineTo(t.x, t.y);
    ctx.stroke();
    ctx.strokeStyle = "#111111";
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.arc(p.x, p.y, 15, 0, Math.PI * 2);
    ctx.stroke();
  }
  ctx.restore();
}

export function drawScene(s: Surface, v: View, sc: Scene): void {
  const { ctx } = s;
  grid(s, v);
  drawObstacles(ctx, v, sc.obstacles, true);
  if (sc.field) drawField(ctx, v, sc.field, 12, 1.25, 26);
  if (sc.trails) {
    ctx.strokeStyle = COLOURS.trail;
    ctx.lineWidth = 1.25;
    for (let i = 0; i < sc.trails.agents; i++) {
      ctx.beginPath();
      sc.trails.forEachPoint(i, (x, y, k) => {
        const p = v.toScreen(x, y);
        if (k === 0) ctx.moveTo(p.x, p.y);
        else ctx.lineTo(p.x, p.y);
      });
      ctx.stroke();
    }
  }
  const drawn = new Set<string>();
  for (const t of sc.targets) {
    const key = `${t.x.toFixed(2)},${t.y.toFixed(2)},${t.beta.toFixed(2)},${t.mode}`;
    if (drawn.has(key)) continue;
    drawn.add(key);
    drawTarget(ctx, v, t, Math.min(sc.handlePx, 0.9 * sc.handlePx), false, sc.kind === "carLike");
  }
  if (sc.focusTarget) drawTarget(ctx, v, sc.focusTarget, sc.handlePx, true, sc.kind === "carLike");
  if (sc.ghost) drawGhost(ctx, v, sc.ghost);
  const o = sc.overlay;
  if (o) {
    const p = v.toScreen(o.x, o.y);
    const t = v.toScreen(o.targetX, o.targetY);
    if (sc.showRadial) {
      ctx.strokeStyle = COLOURS.radial;
      ctx.lineWidth = 1;
      ctx.setLineDash([6, 4]);
      ctx.beginPath();
      ctx.moveTo(p.x, p.y);
      ctx.lineTo(t.x, t.y);
      ctx.stroke();
      ctx.setLineDash([]);
    }
    if (o.etaDir !== null) {
      ctx.strokeStyle = COLOURS.eta;
      ctx.lineWidth = 2;
      arrow(ctx, t.x, t.y, o.etaDir, 50, 8);
    }
    if (o.gamma !== null) {
      ctx.strokeStyle = COLOURS.gamma;
      ctx.lineWidth = 2;
      arrow(ctx, p.x, p.y, o.gamma, 55, 8);
    }
    if (o.arc) {
      const r = o.arc.r * v.scale;
      ctx.strokeStyle = COLOURS.arc;
      ctx.lineWidth = 4;
      ctx.beginPath();
      ctx.arc(p.x, p.y, r, -o.arc.a1, -o.arc.a0);
      ctx.stroke();
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(p.x, p.y);
      ctx.lineTo(p.x + Math.cos(o.arc.ar) * r, p.y - Math.sin(o.arc.ar) * r);
      ctx.stroke();
    }
  }
  if (sc.ring) drawField(ctx, v, sc.ring, 22, 1.5);
  if (sc.count > 1 && sc.count <= CROWD_THRESHOLD) drawLinks(ctx, v, sc);
  if (sc.count > CROWD_THRESHOLD) drawCrowd(s, v, sc);
  else drawAgents(ctx, v, sc);
  if (sc.focus >= 0 && sc.focus < sc.count) {
    const q = sc.focus * sc.stride;
    const p = v.toScreen(sc.state[q + StateField.X]!, sc.state[q + StateField.Y]!);
    const th = sc.state[q + StateField.Theta]!;
    ctx.strokeStyle = COLOURS.vehicle;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(p.x, p.y);
    const hx = p.x + Math.cos(th) * sc.handlePx * 0.7;
    const hy = p.y - Math.sin(th) * sc.handlePx * 0.7;
    ctx.lineTo(hx, hy);
    ctx.stroke();
    ctx.fillStyle = "#ffffff";
    ctx.beginPath();
    ctx.arc(hx, hy, 5, 0, Math.PI * 2);
    ctx.fill();
    ctx.stroke();
  }
}

/** Strokes the first `n` points of `points` (x, y pairs in world metres)
 *  as one path in the current style: the ghosts' and the peers' paths. */
export function strokePolyline(ctx: CanvasRenderingContext2D, v: View, points: ArrayLike<number>, n: number): void {
  ctx.beginPath();
  for (let k = 0; k < n; k++) {
    const p = v.toScreen(points[2 * k]!, points[2 * k + 1]!);
    if (k === 0) ctx.moveTo(p.x, p.y);
    else ctx.lineTo(p.x, p.y);
  }
  ctx.stroke();
}
