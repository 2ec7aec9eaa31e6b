// HiDPI canvas that follows its container's size. The backing store is
// devicePixelRatio × CSS size; drawing code works in CSS pixels.

export interface Surface {
  canvas: HTMLCanvasElement;
  ctx: CanvasRenderingContext2D;
  /** CSS pixels. */
  width: number;
  height: number;
  dpr: number;
}

export function setupCanvas(canvas: HTMLCanvasElement, onResize: (s: Surface) => void): Surface {
  const ctx = canvas.getContext("2d", { alpha: false });
  if (!ctx) throw new Error("this browser gives no 2D canvas context");
  const surface: Surface = { canvas, ctx, width: 1, height: 1, dpr: 1 };
  const apply = (): void => {
    fitSurface(surface);
    onResize(surface);
  };
  new ResizeObserver(apply).observe(canvas);
  // devicePixelRatio changes (browser zoom, moving between screens).
  const watchDpr = (): void => {
    const mq = window.matchMedia(`(resolution: ${window.devicePixelRatio}dppx)`);
    mq.addEventListener("change", () => {
      apply();
      watchDpr();
    }, { once: true });
  };
  watchDpr();
  apply();
  return surface;
}

/** Sets `s` to its canvas's CSS size and devicePixelRatio, and the backing
 *  store to match (once, no observers: the lab's first frame drawn from the
 *  HTML sizes its canvas exactly as the page will). */
export function fitSurface(s: Surface): void {
  const rect = s.canvas.getBoundingClientRect();
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(1, Math.round(rect.width));
  const h = Math.max(1, Math.round(rect.height));
  const bw = Math.round(w * dpr);
  const bh = Math.round(h * dpr);
  if (s.canvas.width !== bw || s.canvas.height !== bh) {
    s.canvas.width = bw;
    s.canvas.height = bh;
  }
  s.width = w;
  s.height = h;
  s.dpr = dpr;
}

/** Resets the transform so that drawing is in CSS pixels. */
export function beginFrame(s: Surface, background: string): void {
  s.ctx.setTransform(s.dpr, 0, 0, s.dpr, 0, 0);
  s.ctx.fillStyle = background;
  s.ctx.fillRect(0, 0, s.width, s.height);
}
