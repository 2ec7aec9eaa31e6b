// Typings of steering-core's element module: importing it defines
// <funnel-figure> (see the README for its attributes).

/** `modechange`'s detail: the shown agent's control mode (the core's
 *  `Mode` number and name, the lab's word for it) and the time, s. */
export interface ModeChangeDetail {
  mode: number;
  name: "EndOfSteering" | "OrientationOnly" | "PositionOnly" | "Funnelling" | null;
  word: string | null;
  previous: number;
  time: number;
}

/** `arrive`'s detail: every agent done and at rest; the shown agent's
 *  pose (m, rad), its distance (m) and heading error (rad) to its target. */
export interface ArriveDetail {
  time: number;
  x: number;
  y: number;
  theta: number;
  distance: number;
  headingError: number;
}

export declare class FunnelFigure extends HTMLElement {
  static readonly observedAttributes: readonly string[];
  /** Resolves once the first set-up is built. */
  readonly ready: Promise<void>;
  /** The shown agent's control mode (the core's `Mode` name), null before the first build. */
  readonly modeName: string | null;
  /** Simulated seconds since the set-up's start. */
  readonly time: number;
  /** The set-up as the lab's link fragment: `LAB/index.html#` + this. */
  readonly fragment: string;
  /** The shown agent's state: m, rad, m/s. */
  readonly agent: { x: number; y: number; theta: number; v: number } | null;
  setPlaying(on: boolean): void;
  addEventListener<K extends keyof FunnelFigureEventMap>(type: K, listener: (this: FunnelFigure, ev: FunnelFigureEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
}

export interface FunnelFigureEventMap extends HTMLElementEventMap {
  modechange: CustomEvent<ModeChangeDetail>;
  arrive: CustomEvent<ArriveDetail>;
}

declare global {
  interface HTMLElementTagNameMap {
    "funnel-figure": FunnelFigure;
  }
}
