// Editing the pathway's points on the canvas: drag a point (pointer events
// with capture, via ../pointer), double-click a segment to insert a point
// there, select a point and press Delete (or the button) to remove it. The
// core validates every edit (no repeated points, enough points); a rejected
// edit leaves the path as it was and reports the core's message.

import type { Drag } from "../ui/pointer";
import type { Vec, View } from "../ui/view";

export interface PathHost {
  /** The path's points as the core holds them, flat [x0, y0, ...]. */
  points(): Float32Array;
  closed(): boolean;
  /** Hands new points to the core; returns the core's message on rejection, else null. */
  commit(xy: Float32Array): string | null;
  /** Shown when an edit was rejected (null clears). */
  report(message: string | null): void;
  /** Something changed that needs a redraw. */
  changed(): void;
}

/** Pick radius around a point, CSS pixels. */
const PICK = 11;

export interface SegmentHit {
  /** The segment from point `index` to point `index + 1` (wrapping when closed). */
  index: number;
  /** Closest point on it, world units. */
  at: Vec;
  /** Screen distance, CSS pixels. */
  dist: number;
}

export class PathEditor {
  selected: number | null = null;
  hover: number | null = null;

  constructor(private readonly host: PathHost, private readonly view: View) {}

  count(): number {
    return this.host.points().length >> 1;
  }

  /** The point under screen position `p`, or null. */
  hitPoint(p: Vec): number | null {
    const xy = this.host.points();
    let best: number | null = null;
    let bestD = PICK;
    for (let i = 0; 2 * i + 1 < xy.length; i++) {
      const s = this.view.toScreen(xy[2 * i] ?? 0, xy[2 * i + 1] ?? 0);
      const d = Math.hypot(s.x - p.x, s.y - p.y);
      if (d <= bestD) {
        bestD = d;
        best = i;
      }
    }
    return best;
  }

  /** The segment nearest to screen position `p`. */
  nearestSegment(p: Vec): SegmentHit | null {
    const xy = this.host.points();
    const n = xy.length >> 1;
    const segs = this.host.closed() ? n : n - 1;
    let best: SegmentHit | null = null;
    for (let i = 0; i < segs; i++) {
      const j = (i + 1) % n;
      const a = this.view.toScreen(xy[2 * i] ?? 0, xy[2 * i + 1] ?? 0);
      const b = this.view.toScreen(xy[2 * j] ?? 0, xy[2 * j + 1] ?? 0);
      const dx = b.x - a.x;
      const dy = b.y - a.y;
      const l2 = dx * dx + dy * dy;
      const t = l2 > 0 ? Math.min(1, Math.max(0, ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2)) : 0;
      const cx = a.x + t * dx;
      const cy = a.y + t * dy;
      const dist = Math.hypot(p.x - cx, p.y - cy);
      if (!best || dist < best.dist) best = { index: i, at: this.view.toWorld(cx, cy), dist };
    }
    return best;
  }

  private apply(xy: Float32Array): boolean {
    const err = this.host.commit(xy);
    this.host.report(err);
    this.host.changed();
    return err === null;
  }

  /** Inserts a point on the segment nearest to `p` if it is within `maxDist` CSS pixels. */
  insertAt(p: Vec, maxDist: number): boolean {
    const hit = this.nearestSegment(p);
    if (!hit || hit.dist > maxDist) return false;
    return this.insertAfter(hit.index, hit.at);
  }

  /** Inserts `at` after point `index`. */
  insertAfter(index: number, at: Vec): boolean {
    const xy = Array.from(this.host.points());
    xy.splice(2 * (index + 1), 0, at.x, at.y);
    if (!this.apply(Float32Array.from(xy))) return false;
    this.selected = index + 1;
    return true;
  }

  /** The "add point" button: splits the segment after the selected point, or the longest one. */
  insertMidpoint(): boolean {
    const xy = this.host.points();
    const n = xy.length >> 1;
    if (n < 2) return false;
    const segs = this.host.closed() ? n : n - 1;
    let index = this.selected !== null && this.selected < segs ? this.selected : -1;
    if (index < 0) {
      let longest = -1;
      for (let i = 0; i < segs; i++) {
        const j = (i + 1) % n;
        const l = Math.hypot((xy[2 * j] ?? 0) - (xy[2 * i] ?? 0), (xy[2 * j + 1] ?? 0) - (xy[2 * i + 1] ?? 0));
        if (l > longest) {
          longest = l;
          index = i;
        }
      }
    }
    const j = (index + 1) % n;
    const at = {
      x: ((xy[2 * index] ?? 0) + (xy[2 * j] ?? 0)) / 2,
      y: ((xy[2 * index + 1] ?? 0) + (xy[2 * j + 1] ?? 0)) / 2,
    };
    return this.insertAfter(index, at);
  }

  /** Removes the selected point (the core refuses to go below its minimum). */
  removeSelected(): boolean {
    const i = this.selected;
    if (i === null) {
      this.host.report("select a path point first (click it), then remove it");
      return false;
    }
    const xy = Array.from(this.host.points());
    xy.splice(2 * i, 2);
    if (!this.apply(Float32Array.from(xy))) return false;
    this.selected = null;
    return true;
  }

  /** A drag of point `i` (the grab offset is kept, so the point does not jump). */
  drag(i: number, grab: Vec): Drag {
    this.selected = i;
    const xy0 = this.host.points();
    const start = this.view.toWorld(grab.x, grab.y);
    const off = { x: (xy0[2 * i] ?? 0) - start.x, y: (xy0[2 * i + 1] ?? 0) - start.y };
    this.host.changed();
    return {
      move: (p) => {
        const w = this.view.toWorld(p.x, p.y);
        const xy = Float32Array.from(this.host.points());
        xy[2 * i] = w.x + off.x;
        xy[2 * i + 1] = w.y + off.y;
        this.apply(xy);
      },
    };
  }
}
