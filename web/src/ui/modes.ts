// The control modes in plain words, with one colour each: the lab's
// legend, HUD chip and targets, and the learn page's mode list. Keyed by
// the core's own mode names (the bindings' `Mode`), so a mode added to the
// core fails to compile here until it has words and a colour.

import { Mode } from "../core/wasm";

export type ModeKey = keyof typeof Mode;

export interface ModeWords {
  /** What a learner calls it. */
  word: string;
  /** One line on what the vehicle is doing. */
  meaning: string;
  /** Its colour on the canvas (targets, legend swatches, the HUD chip). */
  colour: string;
  /** The same colour darkened for text (at least 4.5:1 on white, WCAG AA). */
  text: string;
  /** The paper's name (paper 000 Fig. 5), kept in exports and on Learn. */
  paper: string;
}

export const MODE_WORDS: Readonly<Record<ModeKey, ModeWords>> = {
  PositionOnly: {
    word: "seeking",
    meaning: "heading straight for the target (close, or already lined up)",
    colour: "#d62728",
    text: "#b3141c",
    paper: "Position_only",
  },
  Funnelling: {
    word: "funnelling",
    meaning: "bending its path so that it arrives facing the target's heading β",
    colour: "#dd6b00",
    text: "#9a4a00",
    paper: "Funnelling",
  },
  OrientationOnly: {
    word: "turning on the spot",
    meaning: "inside the target circle: turning to face β",
    colour: "#1f5fd1",
    text: "#1f5fd1",
    paper: "Orientation_only",
  },
  EndOfSteering: {
    word: "arrived",
    meaning: "within both tolerances: done",
    colour: "#8a8f98",
    text: "#5f646c",
    paper: "End_of_Steering",
  },
};

/** The core's modes in the order a vehicle usually meets them. */
export const MODE_ORDER: readonly ModeKey[] = ["PositionOnly", "Funnelling", "OrientationOnly", "EndOfSteering"];

/** A car-like vehicle (a minimum turning radius) never turns on the spot:
 *  where a unicycle would, the core reports Orientation_only while the car
 *  drives a forward loop to the goal pose (crate/funnelling/manoeuvre.rs,
 *  docs/DESIGN.md §14). Its own words and colour, so that the picture does
 *  not say "turning on the spot" of a car driving at speed. */
export const MANOEUVRE_WORDS: ModeWords = {
  word: "driving round",
  meaning: "cannot turn on the spot: looping round to arrive facing β",
  colour: "#0f8a7e",
  text: "#0b6e64",
  paper: "Orientation_only (car-like manoeuvre)",
};

/** The words of the core's mode number `m`, or undefined; `carLike`: the
 *  vehicle has a minimum turning radius ({@link MANOEUVRE_WORDS}). */
export function modeWords(m: number, carLike = false): ModeWords | undefined {
  if (carLike && m === Mode.OrientationOnly) return MANOEUVRE_WORDS;
  const key = (Mode as unknown as Record<number, string>)[m];
  return key !== undefined && key in MODE_WORDS ? MODE_WORDS[key as ModeKey] : undefined;
}

/** The canvas colour of mode number `m` (`carLike` as for modeWords). */
export function modeColour(m: number, carLike = false): string {
  return modeWords(m, carLike)?.colour ?? MODE_WORDS.PositionOnly.colour;
}

/** The text colour of mode number `m`. */
export function modeTextColour(m: number): string {
  return modeWords(m)?.text ?? MODE_WORDS.PositionOnly.text;
}
