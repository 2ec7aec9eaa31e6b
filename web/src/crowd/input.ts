// The crowd page's canvas and keys: drag a path point (else pan), hover
// highlights a point, double-click a segment adds a point, the wheel zooms;
// space plays/pauses, s steps, r resets, Delete removes the selected point,
// Escape deselects.

import { wheelZoom, panDrag } from "../ui/panzoom";
import { attachPointer, type Drag } from "../ui/pointer";
import type { Vec } from "../ui/view";
import type { CrowdSession } from "./session";

export function attachCanvas(canvas: HTMLCanvasElement, s: CrowdSession): void {
  const { editor, view } = s;
  const changed = (): void => {
    s.dirty = true;
  };
  attachPointer(
    canvas,
    (p: Vec): Drag | null => {
      if (!s.lab) return null;
      const i = s.showHandles ? editor.hitPoint(p) : null;
      if (i !== null) return editor.drag(i, p);
      editor.selected = null;
      s.dirty = true;
      return panDrag(canvas, view, p, changed);
    },
    (p) => {
      const h = p && s.showHandles ? editor.hitPoint(p) : null;
      if (h !== editor.hover) {
        editor.hover = h;
        canvas.style.cursor = h !== null ? "move" : "";
        s.dirty = true;
      }
    },
  );
  canvas.addEventListener("dblclick", (e) => {
    if (!s.lab || !s.showHandles) return;
    const r = canvas.getBoundingClientRect();
    const p = { x: e.clientX - r.left, y: e.clientY - r.top };
    if (editor.hitPoint(p) !== null) return;
    editor.insertAt(p, Math.max(12, s.lab.pathRadius() * view.scale));
  });
  wheelZoom(canvas, view, changed);
}

export function attachKeys(s: CrowdSession): void {
  window.addEventListener("keydown", (e) => {
    const t = e.target;
    if (t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement) return;
    if (t instanceof HTMLInputElement && (t.type === "number" || t.type === "text")) return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (e.key === " ") {
      e.preventDefault();
      s.setPlaying(!s.playing);
    } else if (e.key === "s") {
      s.stepOnce();
    } else if (e.key === "r") {
      s.reset();
    } else if (e.key === "Delete" || e.key === "Backspace") {
      if (s.editor.selected !== null) {
        e.preventDefault();
        s.editor.removeSelected();
      }
    } else if (e.key === "Escape") {
      s.editor.selected = null;
      s.dirty = true;
    }
  });
}
