// The playground's handles by keyboard (ui/keyhandles.ts): the vehicle's
// body and heading knob, the target's centre, β knob, tolerance circle
// (D_tol) and triangle corner (ε_tol), and every obstacle's knobs. Each
// arrow key moves the focused handle by a step (Shift: a larger one)
// through the same sink as a drag, so the world, the sliders and the link
// follow as they do for a pointer.

import { KeyHandles, type KeyHandleSpec } from "../ui/keyhandles";
import type { Vec, View } from "../ui/view";
import type { LabAvoidance } from "./avoidance";
import type { Pose } from "./state";
import { HIT_PX, pick, TOUCH_HIT_PX, type DragSink, type Handles } from "./handles";
import { dragObstacle, obstacleKnobs, OBSTACLE_STRIDE, type ObstacleLimits, type ObstaclePart } from "./obstacles";

const DEG = Math.PI / 180;

/** Steps of a key press: small, and with Shift. */
export const KEY_STEPS = {
  /** Positions, m. */
  move: [0.1, 1],
  /** Headings and β, rad. */
  turn: [5 * DEG, 45 * DEG],
  /** D_tol, m. */
  radius: [0.05, 0.5],
  /** ε_tol, rad. */
  opening: [1 * DEG, 10 * DEG],
} as const;

const MOVE_KEYS = "arrow keys move it 0.1 m, with Shift 1 m";
const TURN_KEYS = "left and up arrows turn it anticlockwise 5°, right and down clockwise (Shift: 45°)";
const SIZE_KEYS = (small: string, big: string): string => `up or right arrow: larger by ${small}, down or left: smaller (Shift: ${big})`;

const m = (v: number): string => `${v.toFixed(2)} m`;
const deg = (a: number): string => `${Math.round(wrapDeg(a / DEG))}°`;
const wrapDeg = (d: number): number => ((((d + 180) % 360) + 360) % 360) - 180;
const at = (p: Vec): string => `x ${m(p.x)}, y ${m(p.y)}`;

/** +1 for left and up (anticlockwise, larger), −1 for right and down. */
const turnSign = (d: Vec): number => (d.x < 0 || d.y > 0 ? 1 : -1);
/** +1 for up and right (larger), −1 for down and left. */
const sizeSign = (d: Vec): number => (d.x > 0 || d.y > 0 ? 1 : -1);

export interface KeyboardParts {
  view: View;
  sink: DragSink;
  /** The focus target's handles on screen, or null (a preset: none). */
  handles(): Handles | null;
  /** The target in force: centre, β, D_tol, ε_tol. */
  target(): { x: number; y: number; beta: number; dTol: number; epsTol: number };
  avoid: LabAvoidance;
  limits: ObstacleLimits;
  /** After an obstacle's change (redraw, link). */
  changed(): void;
}

/** The keyboard handles over the lab's canvas; `update` after the
 *  handles' set may have changed (a rebuild, an obstacle added). */
export function labKeyboard(canvas: HTMLCanvasElement, p: KeyboardParts): { update(): void; place(): void } {
  const stage = canvas.parentElement ?? document.body;
  const keys = new KeyHandles(stage, canvas);
  const { sink } = p;
  const on = (k: keyof Handles) => (): Vec | null => p.handles()?.[k] ?? null;
  // The vehicle a key moves is the one drawn; a key pressed again before the
  // world has drawn the last one's pose builds on that pose.
  let placed: { drawn: Pose; to: Pose } | null = null;
  const same = (a: Pose, b: Pose): boolean => a.x === b.x && a.y === b.y && a.theta === b.theta;
  const pose = (): Pose => {
    const drawn = sink.vehiclePose();
    return placed && same(drawn, placed.drawn) ? placed.to : drawn;
  };
  const place = (to: Pose): void => {
    placed = { drawn: sink.vehiclePose(), to };
    sink.vehicle(to);
  };
  const playground: KeyHandleSpec[] = [
    {
      name: "vehicle", label: "vehicle", keys: MOVE_KEYS, at: on("vehicle"),
      nudge: (d, big) => {
        const s = KEY_STEPS.move[big ? 1 : 0];
        const v = pose();
        const to = { x: v.x + d.x * s, y: v.y + d.y * s, theta: v.theta };
        place(to);
        return `vehicle at ${at(to)}`;
      },
    },
    {
      name: "heading", label: "vehicle heading knob", keys: TURN_KEYS, at: on("heading"),
      nudge: (d, big) => {
        const v = pose();
        const to = { ...v, theta: v.theta + turnSign(d) * KEY_STEPS.turn[big ? 1 : 0] };
        place(to);
        return `vehicle heading ${deg(to.theta)}`;
      },
    },
    {
      name: "target", label: "target", keys: MOVE_KEYS, at: on("target"),
      nudge: (d, big) => {
        const s = KEY_STEPS.move[big ? 1 : 0];
        const t = p.target();
        sink.target(t.x + d.x * s, t.y + d.y * s);
        return `target at ${at(p.target())}`;
      },
    },
    {
      name: "beta", label: "target orientation β knob", keys: TURN_KEYS, at: on("beta"),
      nudge: (d, big) => {
        const b = p.target().beta + turnSign(d) * KEY_STEPS.turn[big ? 1 : 0];
        sink.beta(Math.atan2(Math.sin(b), Math.cos(b)));
        return `orientation β ${deg(p.target().beta)}`;
      },
    },
    {
      name: "rim", label: "position tolerance D_tol (the circle's knob)", keys: SIZE_KEYS("0.05 m", "0.5 m"), at: on("rim"),
      nudge: (d, big) => {
        const r = p.target().dTol + sizeSign(d) * KEY_STEPS.radius[big ? 1 : 0];
        sink.dTol(Math.min(20, Math.max(0.02, r)));
        return `position tolerance D_tol ${m(p.target().dTol)}`;
      },
    },
    {
      name: "opening", label: "orientation tolerance ε_tol (the triangle's corner)", keys: SIZE_KEYS("1°", "10°"), at: on("opening"),
      nudge: (d, big) => {
        const e = p.target().epsTol + sizeSign(d) * KEY_STEPS.opening[big ? 1 : 0];
        sink.epsTol(Math.min(90 * DEG, Math.max(0.5 * DEG, e)));
        return `orientation tolerance ε_tol ${(p.target().epsTol / DEG).toFixed(1)}°`;
      },
    },
  ];
  for (const s of playground) {
    const nudge = s.nudge;
    s.nudge = (d, big) => {
      const said = nudge(d, big);
      sink.redraw();
      return said;
    };
  }
  // A press on the canvas takes the focus from whatever control had it
  // (its arrow keys would go on changing it): to the handle pressed, else
  // to nothing.
  canvas.addEventListener("pointerdown", (e) => {
    const r = canvas.getBoundingClientRect();
    const h = p.handles();
    const at = { x: e.clientX - r.left, y: e.clientY - r.top };
    const kind = h ? pick(at, h, p.target().dTol * p.view.scale, e.pointerType === "touch" ? TOUCH_HIT_PX : HIT_PX) : null;
    if (kind) {
      update();
      keys.focus(kind);
    } else if (document.activeElement instanceof HTMLElement && document.activeElement !== document.body) document.activeElement.blur();
  });
  let shown = "";
  const update = (): void => {
    const l = p.avoid.obstacles;
    const n = Math.floor(l.length / OBSTACLE_STRIDE);
    // The set: whether the playground's handles are there, and each obstacle's kind.
    let want = p.handles() ? "p" : "-";
    for (let i = 0; i < n; i++) want += l[i * OBSTACLE_STRIDE] === 0 ? "d" : "w";
    if (want === shown) return;
    shown = want;
    keys.set([...(p.handles() ? playground : []), ...obstacleSpecs(p, n)]);
  };
  return {
    update,
    place: () => {
      update();
      keys.place();
    },
  };
}

/** Each obstacle's knobs: a disc's centre and rim, a wall's middle and ends. */
function obstacleSpecs(p: KeyboardParts, n: number): KeyHandleSpec[] {
  const out: KeyHandleSpec[] = [];
  const list = (): number[] => p.avoid.obstacles;
  for (let i = 0; i < n; i++) {
    const disc = (): boolean => list()[i * OBSTACLE_STRIDE] === 0;
    const knob = (k: number) => (): Vec | null => (i * OBSTACLE_STRIDE < list().length ? (obstacleKnobs(p.view, list(), i)[k] ?? null) : null);
    const move = (part: ObstaclePart, what: string): KeyHandleSpec["nudge"] => (d, big) => {
      const s = KEY_STEPS.move[big ? 1 : 0];
      const o = i * OBSTACLE_STRIDE;
      const l = list();
      let w: Vec = { x: d.x * s, y: d.y * s };
      // A disc's radius: the rim follows the point at the new radius.
      if (part === "rim") w = { x: l[o + 1]! + Math.max(0, l[o + 3]! + sizeSign(d) * s), y: l[o + 2]! };
      p.avoid.setObstacles(dragObstacle(l, { index: i, part }, { x: 0, y: 0 }, w, p.limits));
      p.changed();
      const q = list();
      if (part === "rim") return `obstacle ${i + 1} radius ${m(q[o + 3]!)}`;
      const k = part === "end2" ? 3 : 1;
      return `obstacle ${i + 1} ${what} at ${at({ x: q[o + k]!, y: q[o + k + 1]! })}`;
    };
    const first = (): Vec | null => knob(0)();
    const mid = (): Vec | null => {
      const a = knob(0)();
      const b = knob(1)();
      return a && b ? { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 } : null;
    };
    // The kind of obstacle i is read when the set is made (an added one makes a new set).
    if (disc()) {
      out.push(
        { name: `obstacle-${i}-centre`, label: `obstacle ${i + 1} (disc)`, keys: MOVE_KEYS, at: first, nudge: move("centre", "centre") },
        { name: `obstacle-${i}-rim`, label: `obstacle ${i + 1} radius knob`, keys: SIZE_KEYS("0.1 m", "1 m"), at: knob(1), nudge: move("rim", "radius") },
      );
    } else {
      out.push(
        { name: `obstacle-${i}-body`, label: `obstacle ${i + 1} (wall)`, keys: MOVE_KEYS, at: mid, nudge: move("body", "first end") },
        { name: `obstacle-${i}-end1`, label: `obstacle ${i + 1} first end`, keys: MOVE_KEYS, at: first, nudge: move("end1", "first end") },
        { name: `obstacle-${i}-end2`, label: `obstacle ${i + 1} second end`, keys: MOVE_KEYS, at: knob(1), nudge: move("end2", "second end") },
      );
    }
  }
  return out;
}
