// Dubins shortest path length (Dubins 1957; Shkel & Lumelsky 2001): the
// same six words and formulas as the core's crate/base/dubins.rs, in
// float64 here, for the peers' "path length over the Dubins shortest"
// (the core does not export its Dubins solver to the page).

const TAU = 2 * Math.PI;
const m2pi = (x: number): number => ((x % TAU) + TAU) % TAU;

/** Normalised (t, p, q) of each word from heading `a` at the origin to
 *  heading `b` at (d, 0), unit radius; null where the word has none. */
function words(a: number, b: number, d: number): Array<[number, number, number] | null> {
  const [sa, ca, sb, cb] = [Math.sin(a), Math.cos(a), Math.sin(b), Math.cos(b)];
  const cab = Math.cos(a - b);
  const lsl = (): [number, number, number] | null => {
    const p2 = 2 + d * d - 2 * cab + 2 * d * (sa - sb);
    if (p2 < 0) return null;
    const th = Math.atan2(cb - ca, d + sa - sb);
    return [m2pi(th - a), Math.sqrt(p2), m2pi(b - th)];
  };
  const rsr = (): [number, number, number] | null => {
    const p2 = 2 + d * d - 2 * cab + 2 * d * (sb - sa);
    if (p2 < 0) return null;
    const th = Math.atan2(ca - cb, d - sa + sb);
    return [m2pi(a - th), Math.sqrt(p2), m2pi(th - b)];
  };
  const lsr = (): [number, number, number] | null => {
    const p2 = -2 + d * d + 2 * cab + 2 * d * (sa + sb);
    if (p2 < 0) return null;
    const p = Math.sqrt(p2);
    const th = Math.atan2(-ca - cb, d + sa + sb) - Math.atan2(-2, p);
    return [m2pi(th - a), p, m2pi(th - b)];
  };
  const rsl = (): [number, number, number] | null => {
    const p2 = d * d - 2 + 2 * cab - 2 * d * (sa + sb);
    if (p2 < 0) return null;
    const p = Math.sqrt(p2);
    const th = Math.atan2(ca + cb, d - sa - sb) - Math.atan2(2, p);
    return [m2pi(a - th), p, m2pi(b - th)];
  };
  const rlr = (): [number, number, number] | null => {
    const tmp = (6 - d * d + 2 * cab + 2 * d * (sa - sb)) / 8;
    if (Math.abs(tmp) > 1) return null;
    const p = m2pi(TAU - Math.acos(tmp));
    const t = m2pi(a - Math.atan2(ca - cb, d - sa + sb) + p / 2);
    return [t, p, m2pi(a - b - t + p)];
  };
  const lrl = (): [number, number, number] | null => {
    const tmp = (6 - d * d + 2 * cab + 2 * d * (sb - sa)) / 8;
    if (Math.abs(tmp) > 1) return null;
    const p = m2pi(TAU - Math.acos(tmp));
    const t = m2pi(-a - Math.atan2(ca - cb, d + sa - sb) + p / 2);
    return [t, p, m2pi(b - a - t + p)];
  };
  return [lsl(), rsr(), lsr(), rsl(), rlr(), lrl()];
}

/** Length of the shortest Dubins path from `(x0, y0, θ0)` to `(x1, y1, θ1)`
 *  with minimum turning radius `rho` > 0, in the input's units. */
export function dubinsLength(x0: number, y0: number, th0: number, x1: number, y1: number, th1: number, rho: number): number {
  const r = Math.max(rho, 1e-6);
  const dx = x1 - x0;
  const dy = y1 - y0;
  const d = Math.hypot(dx, dy) / r;
  const phi = d > 0 ? Math.atan2(dy, dx) : 0;
  let best = Infinity;
  for (const w of words(m2pi(th0 - phi), m2pi(th1 - phi), d)) if (w) best = Math.min(best, w[0] + w[1] + w[2]);
  return best * r;
}

/** The minimum turning radius when cruising at `v` (the core's
 *  `VehicleParams::min_turn_radius`): v / min(ω_max, A_n/v). */
export function minTurnRadius(v: number, omegaMax: number, normalAccelMax: number): number {
  return v / Math.min(omegaMax, normalAccelMax / v);
}
