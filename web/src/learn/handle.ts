// A draggable handle of a live figure: a focusable button laid over the
// canvas at a world point. Pointer drags (mouse, pen, touch) with capture;
// arrow keys move it by 0.1 m (Shift: 1 m), so every figure is keyboard
// operable. The figure owns the world ↔ screen view.

import type { Vec, View } from "../ui/view";

export interface HandleSpec {
  /** Stable name (the element's data-handle, for tests). */
  name: string;
  /** What it moves, read by screen readers ("target", "heading knob"). */
  label: string;
  /** The handle's world position now. */
  get(): Vec;
  /** The handle was moved to world point `p` (constrain as needed). */
  set(p: Vec): void;
  /** CSS colour of its ring. */
  colour?: string;
}

export class Handle {
  readonly el: HTMLButtonElement;

  constructor(readonly spec: HandleSpec, stage: HTMLElement, private readonly view: View, changed: () => void) {
    const el = document.createElement("button");
    el.type = "button";
    el.className = "handle";
    el.dataset["handle"] = spec.name;
    el.setAttribute("aria-label", `${spec.label}: drag, or focus and use the arrow keys (Shift: bigger steps)`);
    el.title = spec.label;
    if (spec.colour) el.style.borderColor = spec.colour;
    this.el = el;
    stage.append(el);
    const local = (e: PointerEvent): Vec => {
      const r = stage.getBoundingClientRect();
      return view.toWorld(e.clientX - r.left, e.clientY - r.top);
    };
    let dragging: number | null = null;
    el.addEventListener("pointerdown", (e) => {
      if (e.button !== 0) return;
      e.preventDefault();
      el.focus();
      el.setPointerCapture(e.pointerId);
      dragging = e.pointerId;
    });
    el.addEventListener("pointermove", (e) => {
      if (dragging !== e.pointerId) return;
      e.preventDefault();
      spec.set(local(e));
      changed();
    });
    const end = (e: PointerEvent): void => {
      if (dragging !== e.pointerId) return;
      dragging = null;
      if (el.hasPointerCapture(e.pointerId)) el.releasePointerCapture(e.pointerId);
    };
    el.addEventListener("pointerup", end);
    el.addEventListener("pointercancel", end);
    el.addEventListener("keydown", (e) => {
      const step = e.shiftKey ? 1 : 0.1;
      const d: Record<string, Vec> = {
        ArrowLeft: { x: -step, y: 0 }, ArrowRight: { x: step, y: 0 },
        ArrowUp: { x: 0, y: step }, ArrowDown: { x: 0, y: -step },
      };
      const m = d[e.key];
      if (!m) return;
      e.preventDefault();
      const p = spec.get();
      spec.set({ x: p.x + m.x, y: p.y + m.y });
      changed();
    });
  }

  /** Puts the button over its world point. */
  place(): void {
    const p = this.view.toScreen(this.spec.get().x, this.spec.get().y);
    this.el.style.left = `${p.x}px`;
    this.el.style.top = `${p.y}px`;
  }
}
