// The boid count's limits on the crowd page: the page's largest count,
// above which a typed count is refused with a message, and the heavy
// count, above which the page asks before it runs.
//
// The heavy counts are where a 2-core machine stops giving 30 new states a
// second (`make bench-web`'s crowd rows measure them):
// - the page's own pathway (its density grows with the count, so does the
//   separation's work per boid): about 15,000 boids; from 20,000 the crowd
//   steps in workers (stepper.ts), the page keeps drawing but new states
//   come slower;
// - Test IV density (the panel's switch scales the pathway with the
//   count): HEAVY_DENSE_BOIDS below.

import { parseDecimal } from "../ui/controls";

/** Largest boid count the page runs (the core allows more: `MAX_BOIDS`). */
export const PAGE_MAX_BOIDS = 200_000;
/** Counts above this give fewer than 30 new states a second (see above): asked for first. */
export const HEAVY_BOIDS = 15_000;
/** The same at Test IV density (pathway scaled with the count). */
export const HEAVY_DENSE_BOIDS = 100_000;

/** What to do with a typed count `text`, the count in force being `current`. */
export type CountDecision =
  | { kind: "run"; n: number }
  | { kind: "refuse"; message: string }
  | { kind: "ask"; n: number; message: string };

const fmt = (n: number): string => n.toLocaleString("en");

/** `dense`: Test IV density is on (the pathway scales with the count). */
export function decideCount(text: string, current: number, dense = false): CountDecision {
  const n = parseDecimal(text, true);
  if (n === null || n < 0 || n > PAGE_MAX_BOIDS) {
    const what = n === null ? `"${text.length > 20 ? `${text.slice(0, 20)}…` : text}" is not a whole number` : `${fmt(n)} is outside`;
    return { kind: "refuse", message: `boid count: ${what} [0, ${fmt(PAGE_MAX_BOIDS)}] (this page's limit); ${fmt(current)} kept` };
  }
  const heavy = dense ? HEAVY_DENSE_BOIDS : HEAVY_BOIDS;
  if (n > heavy && n !== current) {
    return {
      kind: "ask", n,
      message: dense
        ? `${fmt(n)} boids is heavy: above ${fmt(heavy)} at Test IV density new states came at under 30 per second on a 2-core machine. Still ${fmt(current)} boids.`
        : `${fmt(n)} boids is heavy: on this pathway (no Test IV density) above ${fmt(heavy)} the crowd ran below 30 fps on a 2-core machine (20,000: 22 fps; workers keep the page drawing but new states come slower). Still ${fmt(current)} boids.`,
    };
  }
  return { kind: "run", n };
}
