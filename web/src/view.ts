// World ↔ screen transform. World: y up, angles CCW from +x. Screen: CSS
// pixels, y down. One View per canvas; its zoom limits suit its units.

export interface Vec {
  x: number;
  y: number;
}

/** How far a view may zoom, CSS pixels per world unit. */
export interface ScaleLimits {
  min: number;
  max: number;
}

/** The funnelling page's worlds: metres, a few to a few hundred across. */
export const METRES: ScaleLimits = { min: 2, max: 2000 };
/** The gallery pages' worlds, measured in paper pixels: a 640 × 400
 *  pathway, or a wander trace thousands of units across in a 200-pixel tile. */
export const PAPER_UNITS: ScaleLimits = { min: 1e-4, max: 1e3 };

export class View {
  /** World point at the centre of the canvas. */
  cx = 0;
  cy = 0;
  /** CSS pixels per world unit. */
  scale = 40;
  width = 1;
  height = 1;

  constructor(readonly limits: ScaleLimits = METRES) {}

  resize(width: number, height: number): void {
    this.width = Math.max(1, width);
    this.height = Math.max(1, height);
  }

  toScreen(x: number, y: number): Vec {
    return {
      x: (x - this.cx) * this.scale + this.width / 2,
      y: this.height / 2 - (y - this.cy) * this.scale,
    };
  }

  toWorld(sx: number, sy: number): Vec {
    return {
      x: (sx - this.width / 2) / this.scale + this.cx,
      y: (this.height / 2 - sy) / this.scale + this.cy,
    };
  }

  private clamp(scale: number): number {
    return Math.min(this.limits.max, Math.max(this.limits.min, scale));
  }

  /** Zooms by `factor` keeping the world point under (sx, sy) fixed. */
  zoomAt(sx: number, sy: number, factor: number): void {
    const before = this.toWorld(sx, sy);
    this.scale = this.clamp(this.scale * factor);
    const after = this.toWorld(sx, sy);
    this.cx += before.x - after.x;
    this.cy += before.y - after.y;
  }

  panBy(dxScreen: number, dyScreen: number): void {
    this.cx -= dxScreen / this.scale;
    this.cy += dyScreen / this.scale;
  }

  /** Fits the world box [x0,x1]×[y0,y1] with a margin in CSS pixels, the
   *  same on every side or per side (room kept for what floats over the
   *  canvas: the lab's HUD above, its legend below). */
  fit(x0: number, y0: number, x1: number, y1: number, margin: number | Insets = 40): void {
    const m = typeof margin === "number" ? { left: margin, right: margin, top: margin, bottom: margin } : margin;
    const w = Math.max(1e-3, x1 - x0);
    const h = Math.max(1e-3, y1 - y0);
    const sx = Math.max(1, this.width - m.left - m.right) / w;
    const sy = Math.max(1, this.height - m.top - m.bottom) / h;
    this.scale = this.clamp(Math.min(sx, sy));
    this.cx = (x0 + x1) / 2 - (m.left - m.right) / 2 / this.scale;
    this.cy = (y0 + y1) / 2 + (m.top - m.bottom) / 2 / this.scale;
  }
}

/** Room per side, CSS pixels. */
export interface Insets {
  left: number;
  right: number;
  top: number;
  bottom: number;
}
