// Static obstacles in the lab: discs and wall segments as the
// core lays them out (`Lab.obstacles()` / `setObstacles`, five floats each:
// kind 0 disc `x, y, radius, 0`, kind 1 segment `x1, y1, x2, y2`), their
// text in the URL (`obs=d:x,y,r;s:x1,y1,x2,y2`, checked against the core's
// ranges `obstacle.x`, `obstacle.y`, `obstacle.radius`), which part of one a
// press grabs and what a drag does to the list, and their drawing. Pure: no
// wasm at run time (the URL fuzz runs it in Node).

import type { Vec, View } from "../ui/view";
import { clip, show, type RangeTable } from "./fields";

/** Floats per obstacle. */
export const OBSTACLE_STRIDE = 5;
/** Most obstacles a link may carry (the core takes 1,024; a link stays short). */
export const MAX_URL_OBSTACLES = 64;
/** The shortest wall a link or a drag makes, m (the core refuses 0). */
export const MIN_SEGMENT = 0.05;

/** The obstacles as `n × OBSTACLE_STRIDE` floats. */
export type ObstacleList = number[];

const fmt = (v: number): string => String(Math.round(v * 1e4) / 1e4);

/** The URL text of `list` (4 decimals). */
export function encodeObstacles(list: readonly number[]): string {
  const out: string[] = [];
  for (let o = 0; o + OBSTACLE_STRIDE <= list.length; o += OBSTACLE_STRIDE) {
    const r = list.slice(o + 1, o + 5).map(fmt);
    out.push(list[o] === 0 ? `d:${r.slice(0, 3).join(",")}` : `s:${r.join(",")}`);
  }
  return out.join(";");
}

/** Parses the URL text: the list, or why it is refused (naming the
 *  obstacle and the value; the core's ranges). Empty text = no obstacles. */
export function decodeObstacles(text: string, ranges: RangeTable): { list: ObstacleList } | { error: string } {
  if (text === "") return { list: [] };
  const items = text.split(";");
  if (items.length > MAX_URL_OBSTACLES) return { error: `${items.length} obstacles (a link carries at most ${MAX_URL_OBSTACLES})` };
  const list: ObstacleList = [];
  const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
  for (const [i, item] of items.entries()) {
    const m = /^([ds]):(.*)$/.exec(item);
    const want = m?.[1] === "d" ? 3 : 4;
    const parts = m ? m[2]!.split(",") : [];
    if (!m || parts.length !== want) return { error: `obstacle ${i + 1} "${clip(item)}" is not d:x,y,radius or s:x1,y1,x2,y2` };
    const keys = m[1] === "d" ? ["obstacle.x", "obstacle.y", "obstacle.radius"] : ["obstacle.x", "obstacle.y", "obstacle.x", "obstacle.y"];
    const vals: number[] = [];
    for (const [k, t] of parts.entries()) {
      const r = ranges.get(keys[k]!);
      const v = DECIMAL.test(t.trim()) ? Number(t) : NaN;
      if (!Number.isFinite(v) || v < r.min || v > r.max) {
        return { error: `obstacle ${i + 1}: ${r.key} "${clip(t)}" is not a number in [${show(r.min)}, ${show(r.max)}] ${r.unit}` };
      }
      vals.push(v);
    }
    if (m[1] === "s" && Math.hypot(vals[2]! - vals[0]!, vals[3]! - vals[1]!) < MIN_SEGMENT) {
      return { error: `obstacle ${i + 1}: a wall needs two ends at least ${MIN_SEGMENT} m apart` };
    }
    list.push(m[1] === "d" ? 0 : 1, ...vals, ...(m[1] === "d" ? [0] : []));
  }
  return { list };
}

/** The part of an obstacle a press grabs. */
export type ObstaclePart = "centre" | "rim" | "end1" | "end2" | "body";

export interface ObstacleGrab {
  index: number;
  part: ObstaclePart;
}

function segDistance(p: Vec, a: Vec, b: Vec): number {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.min(1, Math.max(0, ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2)) : 0;
  return Math.hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/** Screen positions of obstacle `i`'s knobs: a disc's centre and its rim
 *  knob (to the right), a wall's two ends. */
export function obstacleKnobs(view: View, list: readonly number[], i: number): Vec[] {
  const o = i * OBSTACLE_STRIDE;
  if (list[o] === 0) {
    const c = view.toScreen(list[o + 1]!, list[o + 2]!);
    return [c, { x: c.x + list[o + 3]! * view.scale, y: c.y }];
  }
  return [view.toScreen(list[o + 1]!, list[o + 2]!), view.toScreen(list[o + 3]!, list[o + 4]!)];
}

/** The obstacle part under the screen point `p` (knobs first, last drawn
 *  on top); `hit`: the playground handles' hit radius (a touch's is larger). */
export function pickObstacle(view: View, list: readonly number[], p: Vec, hit = 12): ObstacleGrab | null {
  const knob = hit - 2;
  const n = Math.floor(list.length / OBSTACLE_STRIDE);
  for (let i = n - 1; i >= 0; i--) {
    const [k1, k2] = obstacleKnobs(view, list, i) as [Vec, Vec];
    const disc = list[i * OBSTACLE_STRIDE] === 0;
    if (Math.hypot(p.x - k2.x, p.y - k2.y) <= knob) return { index: i, part: disc ? "rim" : "end2" };
    if (Math.hypot(p.x - k1.x, p.y - k1.y) <= knob) return { index: i, part: disc ? "centre" : "end1" };
  }
  for (let i = n - 1; i >= 0; i--) {
    const o = i * OBSTACLE_STRIDE;
    const [k1, k2] = obstacleKnobs(view, list, i) as [Vec, Vec];
    if (list[o] === 0) {
      const r = list[o + 3]! * view.scale;
      const d = Math.hypot(p.x - k1.x, p.y - k1.y);
      if (Math.abs(d - r) <= 6) return { index: i, part: "rim" };
      if (d < r) return { index: i, part: "centre" };
    } else if (segDistance(p, k1, k2) <= 7) return { index: i, part: "body" };
  }
  return null;
}

/** Keeps world coordinates inside the core's obstacle ranges. */
export interface ObstacleLimits {
  coord: number;
  minRadius: number;
  maxRadius: number;
}

export function obstacleLimits(ranges: RangeTable): ObstacleLimits {
  const x = ranges.get("obstacle.x");
  const y = ranges.get("obstacle.y");
  const r = ranges.get("obstacle.radius");
  return { coord: Math.min(x.max, -x.min, y.max, -y.min), minRadius: r.min, maxRadius: r.max };
}

/** `list` with `g` dragged: the grabbed part follows the world point `w`,
 *  offset by where the press was (`from`, world) relative to the part's start.
 *  A wall's end stops MIN_SEGMENT short of the other end. */
export function dragObstacle(start: readonly number[], g: ObstacleGrab, from: Vec, w: Vec, lim: ObstacleLimits): ObstacleList {
  const out = [...start];
  const o = g.index * OBSTACLE_STRIDE;
  const c = (v: number): number => Math.min(lim.coord, Math.max(-lim.coord, v));
  const dx = w.x - from.x;
  const dy = w.y - from.y;
  switch (g.part) {
    case "centre":
      out[o + 1] = c(start[o + 1]! + dx);
      out[o + 2] = c(start[o + 2]! + dy);
      break;
    case "rim": {
      const r = Math.hypot(w.x - start[o + 1]!, w.y - start[o + 2]!);
      out[o + 3] = Math.min(lim.maxRadius, Math.max(Math.max(lim.minRadius, 0.05), r));
      break;
    }
    case "body":
      for (const k of [1, 3]) out[o + k] = c(start[o + k]! + dx);
      for (const k of [2, 4]) out[o + k] = c(start[o + k]! + dy);
      break;
    case "end1":
    case "end2": {
      const [me, other] = g.part === "end1" ? [1, 3] : [3, 1];
      let x = c(start[o + me]! + dx);
      let y = c(start[o + me + 1]! + dy);
      const ox = start[o + other]!;
      const oy = start[o + other + 1]!;
      const d = Math.hypot(x - ox, y - oy);
      if (d < MIN_SEGMENT * 2) {
        const ux = d > 1e-9 ? (x - ox) / d : 1;
        const uy = d > 1e-9 ? (y - oy) / d : 0;
        x = c(ox + ux * MIN_SEGMENT * 2);
        y = c(oy + uy * MIN_SEGMENT * 2);
      }
      out[o + me] = x;
      out[o + me + 1] = y;
      break;
    }
  }
  return out;
}

export const OBSTACLE_COLOURS = { fill: "rgba(110, 84, 60, 0.28)", stroke: "#6e543c" } as const;

/** Draws the obstacles; with `knobs`, the draggable knobs too. */
export function drawObstacles(ctx: CanvasRenderingContext2D, view: View, list: readonly number[], knobs: boolean): void {
  const n = Math.floor(list.length / OBSTACLE_STRIDE);
  if (n === 0) return;
  ctx.save();
  ctx.strokeStyle = OBSTACLE_COLOURS.stroke;
  ctx.fillStyle = OBSTACLE_COLOURS.fill;
  for (let i = 0; i < n; i++) {
    const o = i * OBSTACLE_STRIDE;
    const [k1, k2] = obstacleKnobs(view, list, i) as [Vec, Vec];
    ctx.beginPath();
    if (list[o] === 0) {
      ctx.lineWidth = 2;
      ctx.arc(k1.x, k1.y, Math.max(1, list[o + 3]! * view.scale), 0, Math.PI * 2);
      ctx.fill();
      ctx.stroke();
    } else {
      ctx.lineWidth = 4;
      ctx.lineCap = "round";
      ctx.moveTo(k1.x, k1.y);
      ctx.lineTo(k2.x, k2.y);
      ctx.stroke();
    }
  }
  if (knobs) {
    ctx.fillStyle = "#ffffff";
    ctx.lineWidth = 1.5;
    for (let i = 0; i < n; i++) {
      for (const k of obstacleKnobs(view, list, i)) {
        ctx.beginPath();
        ctx.arc(k.x, k.y, 4.5, 0, Math.PI * 2);
        ctx.fill();
        ctx.stroke();
      }
    }
  }
  ctx.restore();
}
