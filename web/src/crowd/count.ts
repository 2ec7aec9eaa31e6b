// The boid count's two limits on the crowd page (issue 16): the page's
// largest count, above which a typed count is refused with a message (it
// used to be clamped to 200,000 without a word), and the heavy count, above
// which the page asks before it runs (200,000 boids ran at 0.4–1 fps with
// the main thread blocked ~1.3 s per frame).
//
// HEAVY_BOIDS is measured: Test IV (Parker 10 %, separation) at one step
// per frame in headless Chromium on the 2-core CI machine ran 10,000 boids
// at 54 fps (step 8.9 ms + draw 3.2 ms) and 20,000 at 22 fps (30.5 + 7.2
// ms): 15,000 is about the most that keeps 30 fps.

import { parseDecimal } from "../controls";

/** Largest boid count the page runs (the core allows more: `MAX_BOIDS`). */
export const PAGE_MAX_BOIDS = 200_000;
/** Counts above this ran below 30 fps here (see above): asked for first. */
export const HEAVY_BOIDS = 15_000;

/** What to do with a typed count `text`, the count in force being `current`. */
export type CountDecision =
  | { kind: "run"; n: number }
  | { kind: "refuse"; message: string }
  | { kind: "ask"; n: number; message: string };

const fmt = (n: number): string => n.toLocaleString("en");

export function decideCount(text: string, current: number): CountDecision {
  const n = parseDecimal(text, true);
  if (n === null || n < 0 || n > PAGE_MAX_BOIDS) {
    const what = n === null ? `"${text.length > 20 ? `${text.slice(0, 20)}…` : text}" is not a whole number` : `${fmt(n)} is outside`;
    return { kind: "refuse", message: `boid count: ${what} [0, ${fmt(PAGE_MAX_BOIDS)}] (this page's limit); ${fmt(current)} kept` };
  }
  if (n > HEAVY_BOIDS && n !== current) {
    return {
      kind: "ask", n,
      message: `${fmt(n)} boids is heavy: above ${fmt(HEAVY_BOIDS)} the page ran below 30 fps on a 2-core machine (20,000: 22 fps), and the page may stall. Still ${fmt(current)} boids.`,
    };
  }
  return { kind: "run", n };
}
