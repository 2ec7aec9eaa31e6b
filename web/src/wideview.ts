// A View for worlds measured in paper pixels (the crowd and wander pages):
// the same transform as ./view, with zoom limits wide enough for a
// 640 × 400 pathway or a wander trace thousands of units across in a
// 200-pixel tile (View's limits suit metres).

import { View } from "./view";

const MIN_SCALE = 1e-4;
const MAX_SCALE = 1e3;

export class WideView extends View {
  override zoomAt(sx: number, sy: number, factor: number): void {
    const before = this.toWorld(sx, sy);
    this.scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, this.scale * factor));
    const after = this.toWorld(sx, sy);
    this.cx += before.x - after.x;
    this.cy += before.y - after.y;
  }

  override fit(x0: number, y0: number, x1: number, y1: number, margin = 40): void {
    const w = Math.max(1e-3, x1 - x0);
    const h = Math.max(1e-3, y1 - y0);
    this.cx = (x0 + x1) / 2;
    this.cy = (y0 + y1) / 2;
    const sx = Math.max(1, this.width - 2 * margin) / w;
    const sy = Math.max(1, this.height - 2 * margin) / h;
    this.scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, Math.min(sx, sy)));
  }
}
