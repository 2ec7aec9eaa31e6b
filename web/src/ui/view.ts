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

  /** The world box a resize keeps in sight, and the margins it keeps
   *  round it: the last fit's, or what the canvas showed after the last
   *  pan, zoom or `show`. A resize fits this box again rather than keeping
   *  the scale, so what was framed stays framed when a window narrows or a
   *  phone turns, and turning back gives the same view. */
  private kept: { x0: number; y0: number; x1: number; y1: number; margin: Margin } | null = null;

  constructor(readonly limits: ScaleLimits = METRES) {}

  /** The canvas's new size in CSS pixels; the kept box is fitted again. */
  resize(width: number, height: number): void {
    const w = Math.max(1, width);
    const h = Math.max(1, height);
    if (w === this.width && h === this.height) return;
    this.width = w;
    this.height = h;
    const k = this.kept;
    if (k) this.place(k.x0, k.y0, k.x1, k.y1, k.margin);
  }

  /** Shows the world point (cx, cy) at the centre, `scale` CSS px per unit
   *  (a view read from a link); what it shows is then the kept box. */
  show(cx: number, cy: number, scale: number): void {
    this.cx = cx;
    this.cy = cy;
    this.scale = this.clamp(scale);
    this.keepVisible();
  }

  /** Keeps what the canvas shows now, edge to edge. */
  private keepVisible(): void {
    const a = this.toWorld(0, this.height);
    const b = this.toWorld(this.width, 0);
    this.kept = { x0: a.x, y0: a.y, x1: b.x, y1: b.y, margin: 0 };
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
    this.keepVisible();
  }

  panBy(dxScreen: number, dyScreen: number): void {
    this.cx -= dxScreen / this.scale;
    this.cy += dyScreen / this.scale;
    this.keepVisible();
  }

  /** Fits the world box [x0,x1]×[y0,y1] with a margin in CSS pixels, the
   *  same on every side or per side (room kept for what floats over the
   *  canvas: the lab's HUD above, its legend below), or a function giving
   *  them for the view's size (room that changes with the layout). The box
   *  is then the one a resize keeps in sight. */
  fit(x0: number, y0: number, x1: number, y1: number, margin: Margin = 40): void {
    this.kept = { x0, y0, x1, y1, margin };
    this.place(x0, y0, x1, y1, margin);
  }

  private place(x0: number, y0: number, x1: number, y1: number, margin: Margin): void {
    const given = typeof margin === "function" ? margin(this) : margin;
    const m = typeof given === "number" ? { left: given, right: given, top: given, bottom: given } : given;
    const w = Math.max(1e-3, x1 - x0);
    const h = Math.max(1e-3, y1 - y0);
    const sx = Math.max(1, this.width - m.left - m.right) / w;
    const sy = Math.max(1, this.height - m.top - m.bottom) / h;
    this.scale = this.clamp(Math.min(sx, sy));
    this.cx = (x0 + x1) / 2 - (m.left - m.right) / 2 / this.scale;
    this.cy = (y0 + y1) / 2 + (m.top - m.bottom) / 2 / this.scale;
  }
}

/** The room a fit keeps round its box: CSS pixels on every side, per
 *  side, or per side for the view's current size. */
export type Margin = number | Insets | ((view: View) => number | Insets);

/** Room per side, CSS pixels. */
export interface Insets {
  left: number;
  right: number;
  top: number;
  bottom: number;
}
