// Drawing helpers the learn page's figures share, on top of the lab's
// renderer (same colours, same target and ghost drawing): a vehicle, a
// polyline path, a dashed line, an angle arc with its label, and a wedge.

import { arrow, COLOURS, grid } from "../lab/render";
import { triangle } from "../ui/sprites";
import type { View } from "../ui/view";

export { arrow, COLOURS };
export { drawField, drawGhost, drawTarget, MODE_NAMES } from "../lab/render";

/** The lab's grid under a figure. */
export function backdrop(ctx: CanvasRenderingContext2D, v: View): void {
  grid({ ctx, canvas: ctx.canvas, width: v.width, height: v.height, dpr: 1 }, v);
}

/** Degrees, one decimal, for the prose and the canvas labels. */
export function deg(a: number): string {
  return Number.isFinite(a) ? `${((a * 180) / Math.PI).toFixed(1)}°` : "—";
}

/** A vehicle at (x, y) heading θ (world), as the lab draws agents. */
export function vehicle(ctx: CanvasRenderingContext2D, v: View, x: number, y: number, theta: number, colour: string = COLOURS.vehicle): void {
  const p = v.toScreen(x, y);
  ctx.fillStyle = colour;
  ctx.beginPath();
  triangle(ctx, p.x, p.y, Math.cos(theta), -Math.sin(theta), Math.max(8, Math.min(14, 0.45 * v.scale)), 0.6);
  ctx.fill();
}

/** A position-only target (seek's red circle), drawn at the table's reach
 *  radius, 0.25 m: where the predicted seek path ends. */
export function positionTarget(ctx: CanvasRenderingContext2D, v: View, x: number, y: number): void {
  const p = v.toScreen(x, y);
  ctx.strokeStyle = COLOURS.seek;
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.arc(p.x, p.y, Math.max(4, 0.25 * v.scale), 0, 2 * Math.PI);
  ctx.stroke();
}

/** A polyline through world points (x, y pairs). */
export function path(ctx: CanvasRenderingContext2D, v: View, xy: ArrayLike<number>, colour: string, width = 2, dash: number[] = []): void {
  const n = Math.floor(xy.length / 2);
  if (n < 2) return;
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.beginPath();
  for (let k = 0; k < n; k++) {
    const p = v.toScreen(xy[2 * k]!, xy[2 * k + 1]!);
    if (k === 0) ctx.moveTo(p.x, p.y);
    else ctx.lineTo(p.x, p.y);
  }
  ctx.stroke();
  ctx.restore();
}

/** A straight line between two world points. */
export function line(ctx: CanvasRenderingContext2D, v: View, x0: number, y0: number, x1: number, y1: number, colour: string, width = 1, dash: number[] = []): void {
  path(ctx, v, [x0, y0, x1, y1], colour, width, dash);
}

/** A world-angle arrow of `len` CSS px from a world point. */
export function ray(ctx: CanvasRenderingContext2D, v: View, x: number, y: number, angle: number, len: number, colour: string, width = 2): void {
  const p = v.toScreen(x, y);
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  arrow(ctx, p.x, p.y, angle, len, 7);
}

/** Canvas font of the figures' labels: large enough to read on a phone. */
export const LABEL_FONT = "700 16px system-ui, sans-serif";

/** `text` centred at screen point (x, y), on a halo of the figure's
 *  background so that lines under it do not hide it. */
function haloText(ctx: CanvasRenderingContext2D, text: string, x: number, y: number, colour: string): void {
  ctx.font = LABEL_FONT;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.lineJoin = "round";
  ctx.lineWidth = 4;
  ctx.strokeStyle = COLOURS.background;
  ctx.strokeText(text, x, y);
  ctx.fillStyle = colour;
  ctx.fillText(text, x, y);
}

/** The arc of angle a0 → a1 (world, CCW positive) of radius `r` CSS px
 *  around a world point, labelled at its middle (or at `at`, a fraction
 *  of the way from a0 to a1, so that two labels at one point do not meet). */
export function angleArc(ctx: CanvasRenderingContext2D, v: View, x: number, y: number, r: number, a0: number, a1: number, colour: string, label: string, at = 0.5): void {
  const p = v.toScreen(x, y);
  let d = a1 - a0;
  while (d > Math.PI) d -= 2 * Math.PI;
  while (d < -Math.PI) d += 2 * Math.PI;
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2.5;
  ctx.beginPath();
  // Canvas angles are clockwise (y down): negate.
  ctx.arc(p.x, p.y, r, -a0, -(a0 + d), d > 0);
  ctx.stroke();
  // An arrowhead at a1: the angle's sense.
  const e = a0 + d;
  const ex = p.x + Math.cos(e) * r;
  const ey = p.y - Math.sin(e) * r;
  const tang = e + (d > 0 ? Math.PI / 2 : -Math.PI / 2);
  const tx = Math.cos(tang);
  const ty = -Math.sin(tang);
  if (Math.abs(d) * r > 14) {
    ctx.fillStyle = colour;
    ctx.beginPath();
    ctx.moveTo(ex + tx * 2, ey + ty * 2);
    ctx.lineTo(ex - tx * 8 - ty * 4, ey - ty * 8 + tx * 4);
    ctx.lineTo(ex - tx * 8 + ty * 4, ey - ty * 8 - tx * 4);
    ctx.closePath();
    ctx.fill();
  }
  const m = a0 + d * at;
  haloText(ctx, label, p.x + Math.cos(m) * (r + 14), p.y - Math.sin(m) * (r + 14), colour);
  ctx.restore();
}

/** `text` at `dist` CSS px from a world point along world angle `angle`
 *  (names an arrow at its tip). */
export function tipLabel(ctx: CanvasRenderingContext2D, v: View, x: number, y: number, angle: number, dist: number, text: string, colour: string): void {
  const p = v.toScreen(x, y);
  ctx.save();
  haloText(ctx, text, p.x + Math.cos(angle) * dist, p.y - Math.sin(angle) * dist, colour);
  ctx.restore();
}

/** A scale bar in the bottom-left corner: a round length (0.5, 1, 2 or 5 m)
 *  near 80 CSS px long. */
export function scaleBar(ctx: CanvasRenderingContext2D, v: View): void {
  if (!(v.scale > 0)) return;
  const metres = [0.5, 1, 2, 5, 10].find((m) => m * v.scale >= 60) ?? 10;
  const w = metres * v.scale;
  const x = 12;
  const y = v.height - 14;
  ctx.save();
  ctx.strokeStyle = "#333";
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x, y - 5);
  ctx.lineTo(x, y);
  ctx.lineTo(x + w, y);
  ctx.lineTo(x + w, y - 5);
  ctx.stroke();
  ctx.font = "600 13px system-ui, sans-serif";
  ctx.textAlign = "left";
  ctx.textBaseline = "bottom";
  ctx.lineWidth = 3;
  ctx.strokeStyle = COLOURS.background;
  const text = `${metres} m`;
  ctx.strokeText(text, x + w + 6, y + 4);
  ctx.fillStyle = "#333";
  ctx.fillText(text, x + w + 6, y + 4);
  ctx.restore();
}

/** A filled wedge a0 → a1 (world, a1 > a0 CCW) of radius `r` CSS px. */
export function wedge(ctx: CanvasRenderingContext2D, v: View, x: number, y: number, r: number, a0: number, a1: number, colour: string, alpha = 0.25): void {
  const p = v.toScreen(x, y);
  ctx.save();
  ctx.globalAlpha = alpha;
  ctx.fillStyle = colour;
  ctx.beginPath();
  ctx.moveTo(p.x, p.y);
  ctx.arc(p.x, p.y, r, -a1, -a0);
  ctx.closePath();
  ctx.fill();
  ctx.globalAlpha = 1;
  ctx.strokeStyle = colour;
  ctx.lineWidth = 1.5;
  ctx.stroke();
  ctx.restore();
}

/** A text label at a world point, offset in CSS px. */
export function label(ctx: CanvasRenderingContext2D, v: View, x: number, y: number, text: string, colour: string, dx = 8, dy = -8): void {
  const p = v.toScreen(x, y);
  ctx.save();
  ctx.font = LABEL_FONT;
  ctx.lineJoin = "round";
  ctx.lineWidth = 4;
  ctx.strokeStyle = COLOURS.background;
  ctx.textBaseline = "middle";
  ctx.strokeText(text, p.x + dx, p.y + dy);
  ctx.fillStyle = colour;
  ctx.fillText(text, p.x + dx, p.y + dy);
  ctx.restore();
}
