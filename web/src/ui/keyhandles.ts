// Keyboard access to a canvas's draggable handles: one focusable button per
// handle laid over the canvas at the handle's place (in the tab order
// after the canvas), arrow keys nudge the focused handle by a step (Shift:
// a larger one), and each change is read out through one polite live
// region. The buttons let pointer events through (the canvas keeps its own
// hit test and drags); they show only as a focus ring. WCAG 2.1.1: every
// drag has a keyboard equivalent.

import type { Vec } from "./view";

/** Arrow keys as a unit direction (screen: right and up positive). */
const ARROWS: Readonly<Record<string, Vec>> = {
  ArrowLeft: { x: -1, y: 0 },
  ArrowRight: { x: 1, y: 0 },
  ArrowUp: { x: 0, y: 1 },
  ArrowDown: { x: 0, y: -1 },
};

export interface KeyHandleSpec {
  /** Stable name (the button's data-handle, for tests and styles). */
  name: string;
  /** What it moves, read by screen readers ("target", "heading knob"). */
  label: string;
  /** How its arrow keys work, read after the label. */
  keys: string;
  /** Its CSS-pixel place on the canvas now, or null when it is not there. */
  at(): Vec | null;
  /** Moves it one step along the arrow `d` (x right, y up), a large step
   *  when `big`; returns what it now is, to be read out. */
  nudge(d: Vec, big: boolean): string;
}

/** The buttons of a set of handles over one canvas. */
export class KeyHandles {
  private readonly buttons = new Map<string, { el: HTMLButtonElement; spec: KeyHandleSpec }>();
  private readonly live: HTMLElement;

  /** `stage`: the canvas's positioned parent; the buttons follow `after`
   *  (the canvas) in the tab order. */
  constructor(private readonly stage: HTMLElement, private readonly after: Element) {
    const live = document.createElement("div");
    live.className = "sr-only";
    live.setAttribute("aria-live", "polite");
    live.setAttribute("role", "status");
    live.dataset["handles"] = "announce";
    stage.append(live);
    this.live = live;
  }

  /** The handles now: buttons made for new names, dropped for gone ones, in this order. */
  set(specs: readonly KeyHandleSpec[]): void {
    const keep = new Set(specs.map((s) => s.name));
    for (const [name, b] of this.buttons) {
      if (keep.has(name)) continue;
      b.el.remove();
      this.buttons.delete(name);
    }
    let prev: Element = this.after;
    for (const spec of specs) {
      let b = this.buttons.get(spec.name);
      if (b) b.spec = spec;
      else {
        b = { el: this.button(spec.name), spec };
        this.buttons.set(spec.name, b);
      }
      b.el.setAttribute("aria-label", `${spec.label}: ${spec.keys}`);
      if (prev.nextElementSibling !== b.el) prev.after(b.el);
      prev = b.el;
    }
    this.place();
  }

  /** Puts every button over its handle (each frame: handles move). */
  place(): void {
    for (const { el, spec } of this.buttons.values()) {
      const p = spec.at();
      const shown = p !== null && Number.isFinite(p.x) && Number.isFinite(p.y);
      if (el.hidden === shown) el.hidden = !shown;
      if (!shown) continue;
      const left = `${p.x.toFixed(1)}px`;
      const top = `${p.y.toFixed(1)}px`;
      if (el.style.left !== left) el.style.left = left;
      if (el.style.top !== top) el.style.top = top;
    }
  }

  /** Moves the focus to handle `name`'s button (a pointer grabbed that
   *  handle: the arrow keys then go on moving it), without scrolling. */
  focus(name: string): void {
    this.buttons.get(name)?.el.focus({ preventScroll: true });
  }

  /** Reads `text` out (the live region). */
  announce(text: string): void {
    // The same text twice in a row is still read: cleared first.
    if (this.live.textContent === text) this.live.textContent = "";
    this.live.textContent = text;
  }

  private button(name: string): HTMLButtonElement {
    const el = document.createElement("button");
    el.type = "button";
    el.className = "keyhandle";
    el.dataset["handle"] = name;
    el.addEventListener("keydown", (e) => {
      const d = ARROWS[e.key];
      const b = this.buttons.get(name);
      if (!d || !b || e.ctrlKey || e.metaKey || e.altKey) return;
      e.preventDefault();
      e.stopPropagation();
      this.announce(b.spec.nudge(d, e.shiftKey));
      this.place();
    });
    this.stage.append(el);
    return el;
  }
}
