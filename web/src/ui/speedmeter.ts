// How fast a page really runs, from what it completed: frames drawn and
// simulation time advanced over the last second or so of wall time. The
// pages' readouts ("52 fps · 0.85× real time") come from here, never from
// the display's refresh rate or a step that did not happen.

/** A reading over the meter's window. */
export interface Speed {
  /** Frames drawn per second of wall time. */
  fps: number;
  /** Simulation time advanced per second of wall time (1: real time). */
  ratio: number;
  /** Steps completed per second of wall time. */
  stepsPerSecond: number;
  /** Wall time the reading spans, ms (0: no reading yet). */
  spanMs: number;
}

/** Samples kept, at most one per {@link SAMPLE_MS}: 12.8 s. */
const KEEP = 256;
/** The shortest time between two kept samples, ms (a later tick within it
 *  updates the newest sample). */
const SAMPLE_MS = 50;
/** The longest span a reading looks back for its steps, ms. */
const LONGEST_MS = 12_000;

export class SpeedMeter {
  private readonly at = new Float64Array(KEEP);
  private readonly sim = new Float64Array(KEEP);
  private readonly drawn = new Float64Array(KEEP);
  private readonly steps = new Float64Array(KEEP);
  private n = 0;
  private frames = 0;
  private stepCount = 0;

  /** `windowMs`: the span a reading covers (at least). */
  constructor(private readonly windowMs = 1000) {}

  /** A frame at `now` (ms): `drawn` whether it drew, `simTime` the
   *  simulation's clock now (any unit: the ratio is per that unit per
   *  second), `steps` the steps completed since the last call. */
  tick(now: number, drawn: boolean, simTime: number, steps: number): void {
    if (drawn) this.frames++;
    this.stepCount += steps;
    // Within SAMPLE_MS of the one before, the newest sample is brought up to date.
    const fresh = this.n < 2 || now - this.at[(this.n - 2) % KEEP]! >= SAMPLE_MS;
    if (!fresh) this.n--;
    const i = this.n % KEEP;
    this.at[i] = now;
    this.sim[i] = simTime;
    this.drawn[i] = this.frames;
    this.steps[i] = this.stepCount;
    this.n++;
  }

  /** Forgets the past (a new world: its clock starts again). */
  reset(): void {
    this.n = 0;
  }

  /** The reading over the last window (back to the first sample at least
   *  the window old, or the oldest kept); `minSteps`: further back, up to
   *  {@link LONGEST_MS}, until it spans that many steps (a slow world's
   *  rate is then not 0 or 1 step in a second). */
  read(minSteps = 0): Speed {
    if (this.n < 2) return { fps: 0, ratio: 0, stepsPerSecond: 0, spanMs: 0 };
    const last = (this.n - 1) % KEEP;
    const now = this.at[last]!;
    let j = last;
    const oldest = Math.max(0, this.n - KEEP);
    const steps = this.steps[last]!;
    for (let k = this.n - 2; k >= oldest; k--) {
      j = k % KEEP;
      const span = now - this.at[j]!;
      if (span >= this.windowMs && (steps - this.steps[j]! >= minSteps || span >= LONGEST_MS)) break;
    }
    const span = now - this.at[j]!;
    // Not yet a window's worth since the start (or a reset): no reading.
    if (span < 0.9 * this.windowMs) return { fps: 0, ratio: 0, stepsPerSecond: 0, spanMs: 0 };
    const per = 1000 / span;
    return {
      fps: (this.drawn[last]! - this.drawn[j]!) * per,
      ratio: Math.max(0, this.sim[last]! - this.sim[j]!) * per,
      stepsPerSecond: (this.steps[last]! - this.steps[j]!) * per,
      spanMs: span,
    };
  }
}

/** "0.85× real time", and whether that is plainly slower than `aim`
 *  (1: real time; ¼ in slow motion): below 95 % of it. */
export function realTime(ratio: number, aim = 1): { text: string; slower: boolean } {
  const digits = ratio >= 10 ? 0 : ratio >= 0.1 ? 2 : 3;
  return { text: `${ratio.toFixed(digits)}× real time`, slower: ratio < 0.95 * aim };
}
