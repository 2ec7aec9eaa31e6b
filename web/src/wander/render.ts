// Draws one gallery tile: the agent's trace fitted to the tile (equal
// aspect), shaded light → dark with time, the generated path under it, a
// start dot, the agent at the end and a scale bar.

import { beginFrame, type Surface } from "../ui/canvas";
import { triangle } from "../ui/sprites";
import type { View } from "../ui/view";

const SHADES = 8;

function shade(k: number): string {
  // Light steel blue → dark navy.
  const t = k / (SHADES - 1);
  const r = Math.round(150 - 130 * t);
  const g = Math.round(180 - 140 * t);
  const b = Math.round(220 - 110 * t);
  return `rgb(${r},${g},${b})`;
}

/** A round number of world units about a fifth of `span`. */
function niceLength(span: number): number {
  const raw = span / 5;
  const p = 10 ** Math.floor(Math.log10(raw));
  const m = raw / p;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}

/** A trace that its row's scale would draw this many times smaller than
 *  its own fit is drawn at its own scale: at the row's it would be a speck
 *  in the tile's middle. */
export const OWN_SCALE_FROM = 3;

/** The world length a tile's side shows for a trace box of side `side`
 *  (the padding drawTile adds). */
export function shownSide(side: number): number {
  return side + 2 * Math.max(4, 0.02 * side);
}

/** A Markov trace measured: the share of steps whose angle (the heading's
 *  displacement from the start heading, what the tables draw) falls in
 *  each of the tables' ranges (0–15°, 15–30°, 30–45°), and the share of
 *  steps on which the angle changes (the two-table variants keep it with a
 *  probability per range). */
export function markovShares(trace: Float32Array): { ranges: [number, number, number]; changes: number } {
  const n = Math.floor(trace.length / 3);
  const bins: [number, number, number] = [0, 0, 0];
  let changes = 0;
  const start = trace[2] ?? 0;
  for (let i = 1; i < n; i++) {
    const d = (trace[3 * i + 2] ?? 0) - start;
    const angle = (Math.abs(Math.atan2(Math.sin(d), Math.cos(d))) * 180) / Math.PI;
    const k = Math.min(2, Math.floor(angle / 15)) as 0 | 1 | 2;
    bins[k] += 1;
    if (i > 1 && Math.abs((trace[3 * i + 2] ?? 0) - (trace[3 * i - 1] ?? 0)) > 1e-6) changes++;
  }
  const steps = Math.max(1, n - 1);
  return { ranges: [bins[0] / steps, bins[1] / steps, bins[2] / steps], changes: changes / Math.max(1, steps - 1) };
}

/** The markov tiles' note in words. */
export function markovNote(trace: Float32Array): string {
  const m = markovShares(trace);
  const pc = (x: number): string => `${Math.round(100 * x)} %`;
  return `This trace: the angle is 0–15° on ${pc(m.ranges[0])} of steps, 15–30° on ${pc(m.ranges[1])}, 30–45° on ${pc(m.ranges[2])}; it changes on ${pc(m.changes)} of steps.`;
}

/** The ranges' colours in a tile's share bar, light to dark (small to large angles). */
const RANGE_COLOURS = ["#f2c14e", "#e07b39", "#9c2f2f"];

/** A Markov tile's picture of its note: a bar in the top-left corner split
 *  by the share of steps in each angle range, so the four tables' walks,
 *  alike at a glance, are told apart by how they spend their steps. */
export function drawShares(s: Surface, trace: Float32Array): void {
  const ctx = s.ctx;
  const m = markovShares(trace);
  const w = Math.min(120, s.width - 16);
  let x = 8;
  m.ranges.forEach((share, k) => {
    ctx.fillStyle = RANGE_COLOURS[k]!;
    ctx.fillRect(x, 8, share * w, 10);
    x += share * w;
  });
  ctx.strokeStyle = "#555";
  ctx.lineWidth = 1;
  ctx.strokeRect(8, 8, w, 10);
  ctx.fillStyle = "#333";
  ctx.font = "10px system-ui, sans-serif";
  ctx.fillText("angle 0–15° · 15–30° · 30–45°", 8, 30);
}

/** The larger side of the box round `trace` and `path` (world units), or 0. */
export function traceSpan(trace: Float32Array, path: Float32Array): number {
  const b = bounds(trace, path);
  return b ? Math.max(b.x1 - b.x0, b.y1 - b.y0) : 0;
}

function bounds(trace: Float32Array, path: Float32Array): { x0: number; y0: number; x1: number; y1: number } | null {
  const n = Math.floor(trace.length / 3);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  const grow = (x: number, y: number): void => {
    x0 = Math.min(x0, x);
    x1 = Math.max(x1, x);
    y0 = Math.min(y0, y);
    y1 = Math.max(y1, y);
  };
  for (let i = 0; i < n; i++) grow(trace[3 * i] ?? 0, trace[3 * i + 1] ?? 0);
  for (let i = 0; i + 1 < path.length; i += 2) grow(path[i] ?? 0, path[i + 1] ?? 0);
  return Number.isFinite(x0) ? { x0, y0, x1, y1 } : null;
}

/** `trace` is flat [x, y, θ, ...]; `path` flat [x, y, ...] (may be empty).
 *  `span`: the world length the tile's side shows (the largest trace of
 *  its row, so that a row's tiles share one scale), centred on this trace;
 *  0 fits the trace alone. `zoom` > 1: the tile is drawn at its own scale,
 *  that many times its row's, and says so in its corner. */
export function drawTile(s: Surface, view: View, trace: Float32Array, path: Float32Array, span = 0, zoom = 1): void {
  const ctx = s.ctx;
  beginFrame(s, "#ffffff");
  const n = Math.floor(trace.length / 3);
  const box = bounds(trace, path);
  if (!box) return;
  const { x0, y0, x1, y1 } = box;
  const raw = Math.max(span, x1 - x0, y1 - y0);
  const side = shownSide(raw);
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  view.resize(s.width, s.height);
  view.fit(cx - side / 2, cy - side / 2, cx + side / 2, cy + side / 2, 8);

  ctx.lineJoin = "round";
  ctx.lineCap = "round";
  if (path.length >= 4) {
    ctx.beginPath();
    for (let i = 0; i + 1 < path.length; i += 2) {
      const p = view.toScreen(path[i] ?? 0, path[i + 1] ?? 0);
      if (i === 0) ctx.moveTo(p.x, p.y);
      else ctx.lineTo(p.x, p.y);
    }
    ctx.strokeStyle = "#c9c9c9";
    ctx.lineWidth = 3;
    ctx.stroke();
  }

  // The trace in SHADES stretches of time, each one path.
  ctx.lineWidth = 1;
  for (let k = 0; k < SHADES; k++) {
    const a = Math.floor((k * (n - 1)) / SHADES);
    const b = Math.floor(((k + 1) * (n - 1)) / SHADES);
    if (b <= a) continue;
    ctx.beginPath();
    for (let i = a; i <= b; i++) {
      const p = view.toScreen(trace[3 * i] ?? 0, trace[3 * i + 1] ?? 0);
      if (i === a) ctx.moveTo(p.x, p.y);
      else ctx.lineTo(p.x, p.y);
    }
    ctx.strokeStyle = shade(k);
    ctx.stroke();
  }

  // Start and end.
  if (n > 0) {
    const s0 = view.toScreen(trace[0] ?? 0, trace[1] ?? 0);
    ctx.beginPath();
    ctx.arc(s0.x, s0.y, 3.5, 0, 2 * Math.PI);
    ctx.fillStyle = "#2ca02c";
    ctx.fill();
    const e = 3 * (n - 1);
    const p = view.toScreen(trace[e] ?? 0, trace[e + 1] ?? 0);
    const th = trace[e + 2] ?? 0;
    ctx.beginPath();
    triangle(ctx, p.x, p.y, Math.cos(th), -Math.sin(th), 6, 0.7);
    ctx.fillStyle = "#d62728";
    ctx.fill();
  }

  // Scale bar.
  const len = niceLength(raw);
  const px = len * view.scale;
  ctx.strokeStyle = "#555";
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.moveTo(8, s.height - 8);
  ctx.lineTo(8 + px, s.height - 8);
  ctx.stroke();
  ctx.fillStyle = "#555";
  ctx.font = "10px system-ui, sans-serif";
  ctx.fillText(`${len} u`, 10, s.height - 12);
  // A tile at its own scale says so on the drawing too.
  if (zoom > 1) {
    ctx.font = "600 11px system-ui, sans-serif";
    ctx.fillStyle = "#8a4b00";
    ctx.fillText(`own scale, ×${zoom.toFixed(0)}`, 8, 14);
  }
}
