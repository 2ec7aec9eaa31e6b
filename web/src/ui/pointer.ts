// Dragging with pointer events (mouse, pen and touch alike) and pointer
// capture, so a drag keeps going when the pointer leaves the canvas.

import type { Vec } from "./view";

/** What a press grabbed: called with CSS-pixel canvas coordinates. */
export interface Drag {
  move(p: Vec): void;
  end?(): void;
}

/** Returns the drag for a press at `p`, or null when nothing is there. */
export type HitTest = (p: Vec, e: PointerEvent) => Drag | null;

export function attachPointer(
  el: HTMLElement,
  hit: HitTest,
  hover?: (p: Vec | null) => void,
): void {
  const active = new Map<number, Drag>();
  const local = (e: PointerEvent): Vec => {
    const r = el.getBoundingClientRect();
    return { x: e.clientX - r.left, y: e.clientY - r.top };
  };
  el.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    const d = hit(local(e), e);
    if (!d) return;
    e.preventDefault();
    el.setPointerCapture(e.pointerId);
    active.set(e.pointerId, d);
  });
  el.addEventListener("pointermove", (e) => {
    const d = active.get(e.pointerId);
    if (d) {
      e.preventDefault();
      d.move(local(e));
    } else if (hover && e.pointerType === "mouse") {
      hover(local(e));
    }
  });
  const finish = (e: PointerEvent): void => {
    const d = active.get(e.pointerId);
    if (!d) return;
    active.delete(e.pointerId);
    if (el.hasPointerCapture(e.pointerId)) el.releasePointerCapture(e.pointerId);
    d.end?.();
  };
  el.addEventListener("pointerup", finish);
  el.addEventListener("pointercancel", finish);
  el.addEventListener("lostpointercapture", finish);
  el.addEventListener("pointerleave", () => hover?.(null));
}
