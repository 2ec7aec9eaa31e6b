// A vehicle's glyph by its kind, seen from above and pointing along its
// heading, added to the current path (one fill per colour for a few hundred
// agents): a pedestrian's shoulders and nose, a round robot with a
// pointer, a car's body with a pointed bonnet, and a car-like vehicle
// (one that cannot turn on the spot) as that car with its four wheels.
// The subpaths of one glyph never overlap, so a fill with the nonzero rule
// shows them all whatever their winding.

/** The kinds of vehicle the lab draws (scenarios/vehicles/*.json). */
export type VehicleKind = "pedestrian" | "robot" | "car" | "carLike";

/** The kind a set of limits reads as: a minimum turning radius makes it
 *  car-like; else a car's speed (5 m/s and more: the reference car's is 15),
 *  a small fast-turning robot (at most 1 m/s, 3 rad/s and more: the
 *  reference robot's 0.5 m/s, 4 rad/s), or a pedestrian (the core's
 *  default vehicle, 2 m/s). */
export function vehicleKind(p: { vMax: number; omegaMax: number; minTurnRadius?: number | undefined }): VehicleKind {
  if ((p.minTurnRadius ?? 0) > 0) return "carLike";
  if (p.vMax >= 5) return "car";
  if (p.vMax <= 1 && p.omegaMax >= 3) return "robot";
  return "pedestrian";
}

/** Adds the polygon of points (a, b) in the glyph's frame: `a` along the
 *  heading, `b` to its left, in units of `r`. */
function poly(ctx: CanvasRenderingContext2D, x: number, y: number, ux: number, uy: number, r: number, pts: ReadonlyArray<readonly [number, number]>): void {
  // Screen y points down: the left of (ux, uy) is (uy, −ux).
  for (let k = 0; k < pts.length; k++) {
    const [a, b] = pts[k]!;
    const px = x + (ux * a + uy * b) * r;
    const py = y + (uy * a - ux * b) * r;
    if (k === 0) ctx.moveTo(px, py);
    else ctx.lineTo(px, py);
  }
  ctx.closePath();
}

const CAR_BODY = [[-0.95, 0.42], [0.62, 0.42], [1.1, 0.16], [1.1, -0.16], [0.62, -0.42], [-0.95, -0.42]] as const;
const WHEEL = [[-0.2, 0.09], [0.2, 0.09], [0.2, -0.09], [-0.2, -0.09]] as const;

/** Adds kind `kind`'s glyph at (x, y), nose along the screen direction
 *  (ux, uy) (y down), about `r` px from its centre to its nose. */
export function vehicleGlyph(ctx: CanvasRenderingContext2D, kind: VehicleKind, x: number, y: number, ux: number, uy: number, r: number): void {
  switch (kind) {
    case "pedestrian":
      // Shoulders across the heading, a nose ahead of them.
      ctx.moveTo(x + uy * 0.62 * r, y - ux * 0.62 * r);
      ctx.ellipse(x, y, 0.3 * r, 0.62 * r, Math.atan2(uy, ux), -Math.PI / 2, 1.5 * Math.PI);
      ctx.closePath();
      poly(ctx, x, y, ux, uy, r, [[1.05, 0], [0.34, 0.3], [0.34, -0.3]]);
      break;
    case "robot":
      // A round body, a pointer ahead of it.
      ctx.moveTo(x + 0.55 * r, y);
      ctx.arc(x, y, 0.55 * r, 0, 2 * Math.PI);
      ctx.closePath();
      poly(ctx, x, y, ux, uy, r, [[1.1, 0], [0.66, 0.26], [0.66, -0.26]]);
      break;
    case "car":
      poly(ctx, x, y, ux, uy, r, CAR_BODY);
      break;
    case "carLike":
      // The car's body, narrower, with its four wheels beside it.
      poly(ctx, x, y, ux, uy, r, CAR_BODY.map(([a, b]) => [a, b * 0.75] as const));
      for (const [a, b] of [[-0.6, 0.5], [-0.6, -0.5], [0.55, 0.5], [0.55, -0.5]] as const) {
        poly(ctx, x, y, ux, uy, r, WHEEL.map(([c, d]) => [a + c, b + d] as const));
      }
      break;
  }
}
