// Agents drawn by the hundred or the ten thousand, the same way on every
// page: oriented triangles (one canvas path for all of them) for small
// crowds, pixel sprites beyond: in software-rasterised Chromium a filled
// path costs far more per agent than writing its few pixels.

import type { Surface } from "./canvas";

/** Adds an oriented triangle to the current path: nose `r` ahead of (x, y)
 *  along the screen direction (ux, uy) (y down), base `back`·r behind it. */
export function triangle(ctx: CanvasRenderingContext2D, x: number, y: number, ux: number, uy: number, r: number, back: number): void {
  ctx.moveTo(x + ux * r, y + uy * r);
  ctx.lineTo(x - ux * r * back - uy * r * 0.55, y - uy * r * back + ux * r * 0.55);
  ctx.lineTo(x - ux * r * back + uy * r * 0.55, y - uy * r * back - ux * r * 0.55);
  ctx.closePath();
}

/** ABGR (little-endian RGBA bytes) of a #rrggbb colour. */
export function abgr(hex: string): number {
  const n = parseInt(hex.slice(1), 16);
  return ((0xff << 24) | ((n & 0xff) << 16) | (n & 0xff00) | ((n >> 16) & 0xff)) >>> 0;
}

/** Headings a sprite's nose can point to: a two-pixel nose shows no finer
 *  step. A table of their unit vectors and rounding by `+ 0.5 | 0` stand
 *  for cos, sin and `Math.round` per agent, which would be most of the
 *  cost of stamping agents by the hundred thousand (the same blocks). */
export const HEADINGS = 256;

/** Screen unit vectors (y down) of the [`HEADINGS`] headings, x then y. */
export const HEADING_UNITS: Float32Array = (() => {
  const t = new Float32Array(2 * HEADINGS);
  for (let j = 0; j < HEADINGS; j++) {
    const a = (j * 2 * Math.PI) / HEADINGS;
    t[2 * j] = Math.cos(a);
    t[2 * j + 1] = -Math.sin(a);
  }
  return t;
})();

/** The offset in [`HEADING_UNITS`] of the nearest table heading to `theta`
 *  (rad, world frame, y up; any turn, wrapped by the mask). */
export function headingAt(theta: number): number {
  return 2 * (((theta * (HEADINGS / (2 * Math.PI)) + 16 * HEADINGS + 0.5) | 0) & (HEADINGS - 1));
}

interface Layer {
  canvas: HTMLCanvasElement;
  ctx: CanvasRenderingContext2D;
  img: ImageData;
  px: Uint32Array;
  /** The layer's width in pixels, read once: `canvas.width` is a DOM call,
   *  and `stamp` runs per agent (up to hundreds of thousands a frame). */
  w: number;
}

/** The (2r+1)² block of `colour` centred on pixel offset `o` of `px`, a
 *  layer `W` pixels wide: the usual 3 × 3 block written out, and the
 *  caller's rounding by `+ 0.5 | 0` (every pixel kept at a positive
 *  index), as this runs per agent on the page's thread, beside the
 *  stepping workers; the same pixels as the general loop. */
function block(px: Uint32Array, W: number, o: number, r: number, colour: number): void {
  if (r === 1) {
    px[o - W - 1] = colour;
    px[o - W] = colour;
    px[o - W + 1] = colour;
    px[o - 1] = colour;
    px[o] = colour;
    px[o + 1] = colour;
    px[o + W - 1] = colour;
    px[o + W] = colour;
    px[o + W + 1] = colour;
  } else {
    for (let dy = -r; dy <= r; dy++) {
      const row = o + dy * W;
      for (let dx = -r; dx <= r; dx++) px[row + dx] = colour;
    }
  }
}

/** An offscreen layer of backing-store pixels: `begin`, `stamp` each agent,
 *  `present` (one putImageData, one drawImage). One per canvas. */
export class PixelSprites {
  private layer: Layer | null = null;
  /** {@link PixelSprites.noses}' last table, its nose length and width. */
  private noseTable = { nose: NaN, w: -1, at: new Int32Array(2 * HEADINGS) };

  /** Clears the layer, sized to `s`'s backing store; false when the browser gives no 2D context. */
  begin(s: Surface): boolean {
    const W = s.canvas.width;
    const H = s.canvas.height;
    if (!this.layer || this.layer.canvas.width !== W || this.layer.canvas.height !== H) {
      const canvas = document.createElement("canvas");
      canvas.width = W;
      canvas.height = H;
      // A layer only the CPU writes (`willReadFrequently`: a bitmap in
      // memory, not a GPU texture): putImageData is a copy, and the one
      // upload is drawImage's. With a GPU-backed layer every putImageData
      // is an upload of its own, and the page's frames (and the workers'
      // core) pay for it; the visible canvas made software too is slower
      // still (`make bench-web`'s crowd rows compare them).
      const ctx = canvas.getContext("2d", { willReadFrequently: true });
      if (!ctx) return false;
      const img = ctx.createImageData(W, H);
      this.layer = { canvas, ctx, img, px: new Uint32Array(img.data.buffer), w: W };
    }
    this.layer.px.fill(0);
    return true;
  }

  /** A (2r+1)² block centred on backing-store pixel (sx, sy), plus a
   *  two-pixel nose `nose` pixels along (ux, uy) (y down; none if both are 0).
   *  The caller keeps the block and nose inside the layer. */
  stamp(sx: number, sy: number, r: number, colour: number, ux: number, uy: number, nose: number): void {
    const l = this.layer;
    if (!l) return;
    const px = l.px;
    const W = l.w;
    block(px, W, sy * W + sx, r, colour);
    if (ux === 0 && uy === 0) return;
    const nx = (sx + ux * nose + 0.5) | 0;
    const ny = (sy + uy * nose + 0.5) | 0;
    px[ny * W + nx] = colour;
    px[(((sy + ny) / 2 + 0.5) | 0) * W + (((sx + nx) / 2 + 0.5) | 0)] = colour;
  }

  /** Per table heading (indexed as [`HEADING_UNITS`], by [`headingAt`]):
   *  the offsets from a sprite's centre pixel, in this layer's rows, of the
   *  two nose pixels `stamp` writes for that heading and `nose`: the tip,
   *  then the midpoint: the nose's float arithmetic per agent would be
   *  about a third of stamping them. A sprite at integer (sx, sy) has its tip at
   *  sx + ⌊ux·nose + ½⌋ (likewise y), the midpoint at sx + ⌊(dx + 1) / 2⌋.
   *  `stamp` rounds sx + ux·nose + ½ as one sum, which can round the other
   *  way within an ulp of an integer: 54 of 12 million (heading, nose,
   *  position) cases checked, a nose pixel one over. Kept until the width
   *  or `nose` changes. Call after `begin`. */
  noses(nose: number): Int32Array {
    const t = this.noseTable;
    const w = this.layer?.w ?? 0;
    if (t.nose !== nose || t.w !== w) {
      for (let j = 0; j < 2 * HEADINGS; j += 2) {
        const dx = Math.floor(HEADING_UNITS[j]! * nose + 0.5);
        const dy = Math.floor(HEADING_UNITS[j + 1]! * nose + 0.5);
        t.at[j] = dy * w + dx;
        t.at[j + 1] = Math.floor((dy + 1) / 2) * w + Math.floor((dx + 1) / 2);
      }
      t.nose = nose;
      t.w = w;
    }
    return t.at;
  }

  /** `stamp` with the nose given as the two pixel offsets of [`noses`]
   *  (`tip`, `mid`): the same pixels, no float arithmetic. */
  stampNosed(sx: number, sy: number, r: number, colour: number, tip: number, mid: number): void {
    const l = this.layer;
    if (!l) return;
    const px = l.px;
    const W = l.w;
    const o = sy * W + sx;
    block(px, W, o, r, colour);
    px[o + tip] = colour;
    px[o + mid] = colour;
  }

  /** Puts the layer on `s` (CSS-pixel transform in force). */
  present(s: Surface): void {
    const l = this.layer;
    if (!l) return;
    l.ctx.putImageData(l.img, 0, 0);
    s.ctx.drawImage(l.canvas, 0, 0, s.width, s.height);
  }
}
