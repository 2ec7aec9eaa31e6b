// Panning and zooming a View with the pointer: a drag on empty canvas pans
// (grabbing cursor while it lasts), the wheel zooms about the pointer. Every
// page with a movable view uses these two, so the feel is the same.

import type { Drag } from "./pointer";
import type { Vec, View } from "./view";

/** The drag for a press at `start` on empty space: pans `view`. */
export function panDrag(canvas: HTMLCanvasElement, view: View, start: Vec, changed: () => void): Drag {
  let last = start;
  canvas.style.cursor = "grabbing";
  return {
    move: (q) => {
      view.panBy(q.x - last.x, q.y - last.y);
      last = q;
      changed();
    },
    end: () => {
      canvas.style.cursor = "";
    },
  };
}

/** Wheel zoom about the pointer (the page does not scroll under the canvas). */
export function wheelZoom(canvas: HTMLCanvasElement, view: View, changed: () => void): void {
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    const r = canvas.getBoundingClientRect();
    view.zoomAt(e.clientX - r.left, e.clientY - r.top, Math.exp(-e.deltaY * 0.0015));
    changed();
  }, { passive: false });
}
