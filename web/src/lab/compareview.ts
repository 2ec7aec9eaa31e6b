// The compare view's page side: the panel's switch ("compare with Yuka",
// the link's `cmp=1`), its readout in words, and the ghosts drawn over
// the scene (compare.ts computes them). The ghosts follow the playground:
// they are computed again, at most every 120 ms, whenever the vehicle, the
// target, the limits or the controller settings change; a preset or a
// crowd has no single target to compare on.

import { checkbox, help, section } from "../ui/controls";
import type { Surface } from "../ui/canvas";
import type { View } from "../ui/view";
import { errorText, type Lab } from "../core/wasm";
import { oursGhost, PEER_COLOURS, PEER_NAMES, yukaGhost, type PeerGhost } from "./compare";
import { arrow, strokePolyline } from "./render";
import type { LabSim } from "./sim";

const DEG = 180 / Math.PI;
const RECOMPUTE_MS = 120;

export class PeerCompare {
  /** The ghosts last computed (ours, Yuka arrive, Yuka seek), or none. */
  ghosts: PeerGhost[] = [];
  /** Why there are none (off, a preset, Yuka failed to load). */
  note = "";
  private yuka: typeof import("../peers/yukaside") | null = null;
  private loading = false;
  private key = "";
  private timer = 0;
  private readout: HTMLElement | null = null;

  constructor(private readonly sim: LabSim, private readonly core: Lab) {}

  /** The panel's section: the switch and the readout. */
  section(panel: HTMLElement): void {
    const st = this.sim.st;
    const box = section(panel, "Compare with a peer");
    const sw = checkbox(box, "compare", "compare with Yuka (arrive, seek)", st.compare, (v) => {
      st.compare = v;
      this.sim.dirty = true;
      this.sim.url.save();
    });
    sw.el.title = "Ghost trajectories of Yuka 0.7.8's arrive and seek steering beside ours, for the same vehicle, limits and target";
    const out = document.createElement("output");
    out.id = "compare-readout";
    out.className = "help";
    out.setAttribute("aria-live", "polite");
    box.append(out);
    this.readout = out;
    help(box).textContent = "Yuka (a JavaScript game AI library) steers to the target's position: its arrive slows to a stop there, its seek runs through. Neither knows the target's orientation β; funnelling arrives facing it. Same vehicle: Yuka's top speed = v_max, top turn rate = ω_max, top force = A (its vehicle turns its heading to its velocity at once, so ω_max does not bind it).";
  }

  /** What a frame needs: the ghosts for the state in force (recomputed
   *  when it changed), drawn over the scene. */
  draw(s: Surface, v: View): void {
    this.refresh();
    if (!this.sim.st.compare) return;
    for (const g of this.ghosts) drawPeerGhost(s.ctx, v, g);
    drawLabels(s.ctx, v, this.ghosts, this.sim.st.target);
  }

  private refresh(): void {
    const st = this.sim.st;
    const playground = !st.preset && st.agents === 0;
    if (!st.compare || !playground) {
      this.show([], st.compare ? "The compare view needs the playground (one vehicle, one target)." : "");
      this.key = "";
      return;
    }
    if (!this.core.hasTable()) return this.show([], "Waiting for the η table…");
    if (!this.yuka) return this.load();
    const key = JSON.stringify([st.vehicle, st.target, st.dTol, st.epsTol, st.speed, st.halting, st.relaxed, st.funnel, this.sim.params(), this.core.tableKey()]);
    if (key === this.key || this.timer) return;
    this.timer = window.setTimeout(() => {
      this.timer = 0;
      this.sim.dirty = true;
    }, RECOMPUTE_MS);
    this.key = key;
    try {
      const p = this.sim.params();
      this.show([oursGhost(this.core, st, p), yukaGhost(this.yuka, "arrive", st, p), yukaGhost(this.yuka, "seek", st, p)], "");
    } catch (e) {
      this.show([], `The compare view failed: ${errorText(e)}`);
    }
  }

  private load(): void {
    if (this.loading) return;
    this.loading = true;
    this.show([], "Loading Yuka…");
    import("../peers/yukaside").then(
      (m) => {
        this.yuka = m;
        this.sim.dirty = true;
      },
      (e: unknown) => this.show([], `Yuka did not load: ${errorText(e)}`),
    );
  }

  private show(ghosts: PeerGhost[], note: string): void {
    this.ghosts = ghosts;
    this.note = note;
    const text = note || ghosts.map(sentence).join(" ");
    if (this.readout && this.readout.textContent !== text) this.readout.textContent = text;
  }
}

/** One ghost in words (the readout). */
function sentence(g: PeerGhost): string {
  const name = PEER_NAMES[g.side];
  if (!g.mark) return `${name}: never inside D_tol in ${g.time.toFixed(0)} s.`;
  const off = `${(g.mark.headingErr * DEG).toFixed(1)}° off β`;
  return g.arrived ? `${name}: at rest in ${g.time.toFixed(1)} s, ${off}.` : `${name}: enters D_tol at ${g.time.toFixed(1)} s ${off}, never at rest.`;
}

/** The ghost's path, dashed in its colour, and its arrival heading as an arrow. */
function drawPeerGhost(ctx: CanvasRenderingContext2D, v: View, g: PeerGhost): void {
  const n = g.points.length / 2;
  if (n < 2) return;
  ctx.save();
  ctx.strokeStyle = PEER_COLOURS[g.side];
  ctx.globalAlpha = 0.85;
  ctx.lineWidth = 2.5;
  ctx.setLineDash(g.side === "ours" ? [] : g.side === "arrive" ? [9, 5] : [3, 4]);
  strokePolyline(ctx, v, g.points, n);
  ctx.setLineDash([]);
  if (g.mark) {
    const p = v.toScreen(g.mark.x, g.mark.y);
    // A pale halo under the arrow: the three arrows meet at the target.
    ctx.strokeStyle = "rgba(255, 255, 255, 0.9)";
    ctx.lineWidth = 6;
    arrow(ctx, p.x, p.y, g.mark.heading, 46, 10);
    ctx.strokeStyle = PEER_COLOURS[g.side];
    ctx.lineWidth = 3;
    arrow(ctx, p.x, p.y, g.mark.heading, 46, 10);
    ctx.fillStyle = PEER_COLOURS[g.side];
    ctx.beginPath();
    ctx.arc(p.x, p.y, 3.5, 0, 2 * Math.PI);
    ctx.fill();
  }
  ctx.restore();
}

/** The ghosts' names and arrival headings beside the target, one line each. */
function drawLabels(ctx: CanvasRenderingContext2D, v: View, ghosts: PeerGhost[], target: { x: number; y: number }): void {
  if (ghosts.length === 0) return;
  const t = v.toScreen(target.x, target.y);
  ctx.save();
  ctx.font = "600 12px system-ui, sans-serif";
  ctx.textBaseline = "middle";
  const lines = ghosts.map((g) => ({ g, text: `${PEER_NAMES[g.side]}: ${g.mark ? `${(g.mark.headingErr * DEG).toFixed(0)}° off β${g.arrived ? "" : ", no rest"}` : "never in D_tol"}` }));
  const w = Math.max(...lines.map((l) => ctx.measureText(l.text).width)) + 26;
  // Beside the target: on its right where there is room, else on its left
  // (a phone's narrow stage), kept on the canvas.
  const room = ctx.canvas.clientWidth - 6;
  const x = t.x + 56 + w <= room ? t.x + 56 : Math.max(6, Math.min(t.x - 56 - w, room - w));
  const y0 = Math.max(8, t.y - 64);
  ctx.fillStyle = "rgba(251, 250, 247, 0.88)";
  ctx.fillRect(x - 4, y0 - 4, w + 8, lines.length * 17 + 8);
  lines.forEach(({ g, text }, i) => {
    const y = y0 + 8 + i * 17;
    ctx.strokeStyle = PEER_COLOURS[g.side];
    ctx.lineWidth = 3;
    ctx.setLineDash(g.side === "ours" ? [] : g.side === "arrive" ? [6, 3] : [2, 3]);
    ctx.beginPath();
    ctx.moveTo(x, y);
    ctx.lineTo(x + 18, y);
    ctx.stroke();
    ctx.fillStyle = "#222";
    ctx.fillText(text, x + 24, y);
  });
  ctx.restore();
}
