// The state buffers of a stepper that runs a world in workers (the
// lab's ../lab/stepping.ts and the crowd's ../crowd/stepper.ts): a front array the page
// draws and a back one the workers fill. With cross-origin isolation they
// view SharedArrayBuffers (the workers write into the back one); without,
// they are plain arrays and states come by message.

/** The buffers: `sab` (null without shared memory) holds `states` buffers
 *  of `length` floats, then one of each byte size in `extra`; `state` and
 *  `back` view the first two (or are plain arrays). */
export interface StateBuffers {
  sab: SharedArrayBuffer[] | null;
  state: Float32Array;
  back: Float32Array;
}

/** Buffers for `length` floats per state, holding `initial` in front. */
export function stateBuffers(initial: Float32Array, shared: boolean, states = 2, extra: number[] = []): StateBuffers {
  const length = initial.length;
  const sab = shared
    ? [...Array.from({ length: states }, () => new SharedArrayBuffer(length * 4)), ...extra.map((b) => new SharedArrayBuffer(b))]
    : null;
  const state = sab ? new Float32Array(sab[0] as SharedArrayBuffer) : new Float32Array(length);
  const back = sab ? new Float32Array(sab[1] as SharedArrayBuffer) : new Float32Array(length);
  state.set(initial);
  return { sab, state, back };
}
