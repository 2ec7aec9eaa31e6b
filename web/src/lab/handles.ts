// The playground's draggable handles: where they are on screen and which
// one a press grabs. Vehicle body (position) and heading knob; target
// centre, β knob, tolerance circle rim (D_tol) and triangle corner (ε_tol).
// Empty space pans the view.

import { panDrag, wheelZoom } from "../ui/panzoom";
import { attachPointer, type Drag } from "../ui/pointer";
import type { Vec, View } from "../ui/view";
import type { LabState, Pose } from "./state";

const DEG = Math.PI / 180;

/** Half the side of every handle's hit area, CSS px: at least 24 px
 *  across (WCAG 2.5.8's target size). */
export const HIT_PX = 12;
/** The same for a finger, CSS px: 44 px across, the touch target size
 *  platform guidelines ask for (a fingertip covers about 10 mm). */
export const TOUCH_HIT_PX = 22;
/** The tolerance circle's knob sits on the rim, and at least this far from
 *  the target's centre, CSS px: on a small stage the circle itself may be a
 *  few pixels wide, and its knob would otherwise share the centre's hit
 *  area (a stalk from the rim then carries it, render.ts). Below this
 *  radius the rim itself is not grabbed either. */
export const RIM_MIN_PX = 2 * HIT_PX + 2;

/** CSS-pixel canvas positions of every handle. */
export interface Handles {
  target: Vec;
  rim: Vec;
  beta: Vec;
  opening: Vec;
  vehicle: Vec;
  heading: Vec;
}

export function handlePositions(view: View, st: LabState, vehicle: Pose, handlePx: number): Handles {
  const c = view.toScreen(st.target.x, st.target.y);
  const b = st.target.theta;
  const r = st.dTol * view.scale;
  const vs = view.toScreen(vehicle.x, vehicle.y);
  const a1 = b + st.epsTol;
  return {
    target: c,
    rim: { x: c.x + Math.cos(b + Math.PI / 2) * Math.max(r, RIM_MIN_PX), y: c.y - Math.sin(b + Math.PI / 2) * Math.max(r, RIM_MIN_PX) },
    beta: { x: c.x + Math.cos(b) * (handlePx + 24), y: c.y - Math.sin(b) * (handlePx + 24) },
    opening: { x: c.x + Math.cos(a1) * handlePx, y: c.y - Math.sin(a1) * handlePx },
    vehicle: vs,
    heading: { x: vs.x + Math.cos(vehicle.theta) * handlePx * 0.7, y: vs.y - Math.sin(vehicle.theta) * handlePx * 0.7 },
  };
}

/** What a drag changes (world units, radians). */
export interface DragSink {
  target(x: number, y: number): void;
  beta(beta: number): void;
  epsTol(eps: number): void;
  dTol(d: number): void;
  vehicle(pose: Pose): void;
  /** The target's tolerance radius D_tol in force, m. */
  dTolNow(): number;
  /** The focus vehicle's current pose (a body drag starts from it). */
  vehiclePose(): Pose;
  redraw(): void;
}

type Kind = "beta" | "opening" | "heading" | "vehicle" | "target" | "rim";

/** World angle (CCW) of the screen direction from `from` to `p`. */
const screenAngle = (from: Vec, p: Vec): number => Math.atan2(-(p.y - from.y), p.x - from.x);

const KINDS: readonly Kind[] = ["beta", "opening", "heading", "vehicle", "target", "rim"];

/** The handle under `p`: the nearest whose hit area (radius {@link HIT_PX},
 *  the vehicle's body a little more) holds it; else the tolerance circle
 *  itself, when it is drawn larger than its knob's place. */
export function pick(p: Vec, h: Handles, ring = 0, hit = HIT_PX): Kind | null {
  let best: Kind | null = null;
  let bestD = Infinity;
  for (const k of KINDS) {
    const d = Math.hypot(p.x - h[k].x, p.y - h[k].y);
    if (d <= (k === "vehicle" ? hit + 2 : hit) && d < bestD) {
      best = k;
      bestD = d;
    }
  }
  if (best) return best;
  if (ring >= RIM_MIN_PX && Math.abs(Math.hypot(p.x - h.target.x, p.y - h.target.y) - ring) <= (hit * 7) / HIT_PX) return "rim";
  return null;
}

/** `extra`: other draggable things (the obstacles), tried after the
 *  playground's handles and before panning, with the hit radius. A touch
 *  gets the larger hit areas ({@link TOUCH_HIT_PX}). */
export function attachDrags(canvas: HTMLCanvasElement, view: View, handles: () => Handles | null, sink: DragSink, extra?: (p: Vec, hit: number) => Drag | null): void {
  /** The tolerance circle's radius on screen, CSS px. */
  const ring = (): number => sink.dTolNow() * view.scale;
  const grab = (p: Vec, h: Handles, kind: Kind): Drag => {
    switch (kind) {
      case "beta":
        return { move: (q) => sink.beta(screenAngle(handles()?.target ?? h.target, q)) };
      case "opening":
        return {
          move: (q) => {
            const c = handles()?.target ?? h.target;
            const beta = screenAngle(c, handles()?.beta ?? h.beta);
            const a = screenAngle(c, q) - beta;
            const d = Math.abs(Math.atan2(Math.sin(a), Math.cos(a)));
            sink.epsTol(Math.min(90 * DEG, Math.max(0.5 * DEG, d)));
          },
        };
      case "heading":
        return {
          move: (q) => {
            const pose = sink.vehiclePose();
            sink.vehicle({ ...pose, theta: screenAngle(view.toScreen(pose.x, pose.y), q) });
          },
        };
      case "vehicle": {
        const pose = sink.vehiclePose();
        const w0 = view.toWorld(p.x, p.y);
        const off = { x: pose.x - w0.x, y: pose.y - w0.y };
        return {
          move: (q) => {
            const w = view.toWorld(q.x, q.y);
            sink.vehicle({ x: w.x + off.x, y: w.y + off.y, theta: pose.theta });
          },
        };
      }
      case "target": {
        const w0 = view.toWorld(p.x, p.y);
        const t0 = view.toWorld(h.target.x, h.target.y);
        const off = { x: t0.x - w0.x, y: t0.y - w0.y };
        return {
          move: (q) => {
            const w = view.toWorld(q.x, q.y);
            sink.target(w.x + off.x, w.y + off.y);
          },
        };
      }
      case "rim": {
        // Relative: the knob may sit outside a small circle (RIM_MIN_PX).
        const d0 = Math.hypot(p.x - h.target.x, p.y - h.target.y);
        const tol0 = ring() / view.scale;
        return {
          move: (q) => {
            const c = handles()?.target ?? h.target;
            sink.dTol(Math.min(20, Math.max(0.02, tol0 + (Math.hypot(q.x - c.x, q.y - c.y) - d0) / view.scale)));
          },
        };
      }
    }
  };
  attachPointer(
    canvas,
    (p, e): Drag => {
      const hit = e.pointerType === "touch" ? TOUCH_HIT_PX : HIT_PX;
      const h = handles();
      const kind = h ? pick(p, h, ring(), hit) : null;
      if (h && kind) return grab(p, h, kind);
      const other = extra?.(p, hit);
      if (other) return other;
      return panDrag(canvas, view, p, () => sink.redraw());
    },
    (p) => {
      const h = handles();
      const over = p !== null && ((h !== null && pick(p, h, ring()) !== null) || (extra !== undefined && extra(p, HIT_PX) !== null));
      canvas.style.cursor = over ? "grab" : "";
    },
  );
  wheelZoom(canvas, view, () => sink.redraw());
}
