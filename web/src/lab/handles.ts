// The playground's draggable handles: where they are on screen and which
// one a press grabs. Vehicle body (position) and heading knob; target
// centre, β knob, tolerance circle rim (D_tol) and triangle corner (ε_tol).
// Empty space pans the view.

import { panDrag, wheelZoom } from "../panzoom";
import { attachPointer, type Drag } from "../pointer";
import type { Vec, View } from "../view";
import type { LabState, Pose } from "./state";

const DEG = Math.PI / 180;

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
    rim: { x: c.x + Math.cos(b + Math.PI / 2) * r, y: c.y - Math.sin(b + Math.PI / 2) * r },
    beta: { x: c.x + Math.cos(b) * (handlePx + 12), y: c.y - Math.sin(b) * (handlePx + 12) },
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
  /** The focus vehicle's current pose (a body drag starts from it). */
  vehiclePose(): Pose;
  redraw(): void;
}

type Kind = "beta" | "opening" | "heading" | "vehicle" | "target" | "rim";

const near = (a: Vec, b: Vec, r: number): boolean => Math.hypot(a.x - b.x, a.y - b.y) <= r;
/** World angle (CCW) of the screen direction from `from` to `p`. */
const screenAngle = (from: Vec, p: Vec): number => Math.atan2(-(p.y - from.y), p.x - from.x);

/** The handle under `p`, in priority order (small knobs first). */
export function pick(p: Vec, h: Handles): Kind | null {
  if (near(p, h.beta, 10)) return "beta";
  if (near(p, h.opening, 10)) return "opening";
  if (near(p, h.heading, 10)) return "heading";
  if (near(p, h.vehicle, 14)) return "vehicle";
  if (near(p, h.target, 10)) return "target";
  const rimR = Math.hypot(h.rim.x - h.target.x, h.rim.y - h.target.y);
  if (Math.abs(Math.hypot(p.x - h.target.x, p.y - h.target.y) - rimR) <= 7) return "rim";
  return null;
}

/** `extra`: other draggable things (the obstacles), tried after the
 *  playground's handles and before panning. */
export function attachDrags(canvas: HTMLCanvasElement, view: View, handles: () => Handles | null, sink: DragSink, extra?: (p: Vec) => Drag | null): void {
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
      case "rim":
        return {
          move: (q) => {
            const c = handles()?.target ?? h.target;
            sink.dTol(Math.min(20, Math.max(0.02, Math.hypot(q.x - c.x, q.y - c.y) / view.scale)));
          },
        };
    }
  };
  attachPointer(
    canvas,
    (p): Drag => {
      const h = handles();
      const kind = h ? pick(p, h) : null;
      if (h && kind) return grab(p, h, kind);
      const other = extra?.(p);
      if (other) return other;
      return panDrag(canvas, view, p, () => sink.redraw());
    },
    (p) => {
      const h = handles();
      const over = p !== null && ((h !== null && pick(p, h) !== null) || (extra !== undefined && extra(p) !== null));
      canvas.style.cursor = over ? "grab" : "";
    },
  );
  wheelZoom(canvas, view, () => sink.redraw());
}
