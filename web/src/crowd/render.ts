// Draws the crowd: the pathway band (its radius), the centre line, the
// path's editable points, the highlighted boid's lap and the boids. Boids are
// oriented triangles up to TRIANGLE_LIMIT, beyond that 2×2-pixel squares; in
// both cases one path and one fill for all boids, not one per boid.

import { beginFrame, type Surface } from "../ui/canvas";
import { FORCE_2D, GL_THRESHOLD, GlSprites, markPath } from "../ui/glsprites";
import { abgr, PixelSprites, triangle } from "../ui/sprites";
import type { View } from "../ui/view";

export const COLOURS = {
  background: "#f4f3ee",
  band: "#dfe6d8",
  bandEdge: "#b9c7ae",
  centre: "#8aa07a",
  boid: "#2b4a7a",
  traced: "#d62728",
  lap: "#d62728",
  handle: "#b06000",
  selected: "#ffb000",
} as const;

/** Above this many boids they are drawn as pixel sprites (../sprites). */
export const TRIANGLE_LIMIT = 400;

const sprites = new PixelSprites();
const glSprites = new GlSprites();

/** Each boid a (2k+1)² block of backing-store pixels plus a two-pixel nose along its velocity. */
function drawSprites(s: Surface, view: View, pos: Float32Array, vel: Float32Array): void {
  if (!sprites.begin(s)) return;
  const W = s.canvas.width;
  const H = s.canvas.height;
  const c = abgr(COLOURS.boid);
  const k = s.dpr;
  const sc = view.scale * k;
  const ox = (view.width / 2 - view.cx * view.scale) * k;
  const oy = (view.height / 2 + view.cy * view.scale) * k;
  const r = Math.max(1, Math.round(k * 0.75));
  const nose = 3 * k;
  const m = r + Math.ceil(nose) + 1;
  const n = pos.length >> 1;
  // Per boid, by the hundred thousand: rounding by `| 0` after a float
  // range test (no Math.round, no overflow), sqrt not hypot.
  for (let i = 0; i < n; i++) {
    const fx = ox + (pos[2 * i] ?? 0) * sc;
    const fy = oy - (pos[2 * i + 1] ?? 0) * sc;
    if (!(fx >= m && fy >= m && fx < W - m && fy < H - m)) continue;
    const sx = (fx + 0.5) | 0;
    const sy = (fy + 0.5) | 0;
    const vx = vel[2 * i] ?? 0;
    const vy = vel[2 * i + 1] ?? 0;
    const len = Math.sqrt(vx * vx + vy * vy);
    // A boid at rest has no nose.
    sprites.stamp(sx, sy, r, c, len > 0 ? vx / len : 0, len > 0 ? -(vy / len) : 0, nose);
  }
  sprites.present(s);
}

export interface CrowdScene {
  path: Float32Array;
  radius: number;
  closed: boolean;
  positions: Float32Array;
  velocities: Float32Array;
  trace: Float32Array;
  traced: number;
  boidRadius: number;
  showTrace: boolean;
  showHandles: boolean;
  selected: number | null;
  hover: number | null;
}

function polyline(ctx: CanvasRenderingContext2D, view: View, xy: Float32Array, closed: boolean): void {
  ctx.beginPath();
  for (let i = 0; i + 1 < xy.length; i += 2) {
    const p = view.toScreen(xy[i] ?? 0, xy[i + 1] ?? 0);
    if (i === 0) ctx.moveTo(p.x, p.y);
    else ctx.lineTo(p.x, p.y);
  }
  if (closed) ctx.closePath();
}

export function drawCrowd(s: Surface, view: View, sc: CrowdScene): void {
  const ctx = s.ctx;
  beginFrame(s, COLOURS.background);
  ctx.lineJoin = "round";
  ctx.lineCap = "round";

  // Pathway band: a line 2 × radius wide, its edge a slightly wider one below.
  const w = 2 * sc.radius * view.scale;
  polyline(ctx, view, sc.path, sc.closed);
  ctx.strokeStyle = COLOURS.bandEdge;
  ctx.lineWidth = w + 2;
  ctx.stroke();
  ctx.strokeStyle = COLOURS.band;
  ctx.lineWidth = w;
  ctx.stroke();
  ctx.setLineDash([6, 5]);
  ctx.strokeStyle = COLOURS.centre;
  ctx.lineWidth = 1;
  ctx.stroke();
  ctx.setLineDash([]);

  // Boids: triangles (one path) for small crowds, pixel sprites beyond.
  const pos = sc.positions;
  const vel = sc.velocities;
  const n = pos.length >> 1;
  if (n > GL_THRESHOLD && !FORCE_2D && glSprites.draw(s, view, pos, vel, n, { stride: 2, x: 0, y: 1, theta: null, colour: null }, [COLOURS.boid], 3)) {
    // One WebGL2 instanced draw, headings from the velocities.
    markPath(s.canvas, "webgl2");
  } else if (n <= TRIANGLE_LIMIT) {
    glSprites.hide();
    markPath(s.canvas, "triangles");
    ctx.beginPath();
    const r = Math.max(2.5, sc.boidRadius * view.scale);
    for (let i = 0; i < n; i++) {
      const p = view.toScreen(pos[2 * i] ?? 0, pos[2 * i + 1] ?? 0);
      const vx = vel[2 * i] ?? 0;
      const vy = vel[2 * i + 1] ?? 0;
      const len = Math.hypot(vx, vy) || 1;
      // Screen y is down: flip the world direction's y.
      triangle(ctx, p.x, p.y, vx / len, -vy / len, r, 0.7);
    }
    ctx.fillStyle = COLOURS.boid;
    ctx.fill();
  } else {
    glSprites.hide();
    markPath(s.canvas, "sprites");
    drawSprites(s, view, pos, vel);
  }

  // The highlighted boid's lap, and the boid itself.
  if (sc.showTrace && sc.trace.length >= 4) {
    polyline(ctx, view, sc.trace, false);
    ctx.strokeStyle = COLOURS.lap;
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }
  if (sc.traced < n) {
    const p = view.toScreen(pos[2 * sc.traced] ?? 0, pos[2 * sc.traced + 1] ?? 0);
    ctx.beginPath();
    ctx.arc(p.x, p.y, Math.max(3.5, sc.boidRadius * view.scale), 0, 2 * Math.PI);
    ctx.strokeStyle = COLOURS.traced;
    ctx.lineWidth = 2;
    ctx.stroke();
  }

  // Editable points.
  if (sc.showHandles) {
    for (let i = 0; 2 * i + 1 < sc.path.length; i++) {
      const p = view.toScreen(sc.path[2 * i] ?? 0, sc.path[2 * i + 1] ?? 0);
      ctx.beginPath();
      ctx.arc(p.x, p.y, i === sc.hover || i === sc.selected ? 8 : 6, 0, 2 * Math.PI);
      ctx.fillStyle = i === sc.selected ? COLOURS.selected : "#ffffff";
      ctx.fill();
      ctx.strokeStyle = COLOURS.handle;
      ctx.lineWidth = 2;
      ctx.stroke();
      if (i === 0) {
        ctx.fillStyle = COLOURS.handle;
        ctx.font = "11px system-ui, sans-serif";
        ctx.fillText("start", p.x + 9, p.y - 8);
      }
    }
  }
}
