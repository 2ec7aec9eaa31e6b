// Downloads of the recorded trajectories, as CSV or JSON.

import { download } from "../ui/download";
import { MODE_NAMES } from "./render";
import type { Trails } from "./trails";

export function trajectoriesCsv(trails: Trails): string {
  const lines = ["agent,t_s,x_m,y_m,theta_rad,v_mps,omega_radps,mode"];
  for (let i = 0; i < trails.agents; i++) {
    for (const s of trails.samples(i)) {
      lines.push(
        [i, s.t.toFixed(4), s.x.toFixed(5), s.y.toFixed(5), s.theta.toFixed(5), s.v.toFixed(5), s.omega.toFixed(5),
          MODE_NAMES[s.mode] ?? String(s.mode)].join(","),
      );
    }
  }
  return lines.join("\n") + "\n";
}

export function trajectoriesJson(trails: Trails, meta: Record<string, unknown>): string {
  const agents = [];
  for (let i = 0; i < trails.agents; i++) {
    const ss = trails.samples(i);
    agents.push({
      agent: i,
      t: ss.map((s) => s.t),
      x: ss.map((s) => s.x),
      y: ss.map((s) => s.y),
      theta: ss.map((s) => s.theta),
      v: ss.map((s) => s.v),
      omega: ss.map((s) => s.omega),
      mode: ss.map((s) => MODE_NAMES[s.mode] ?? String(s.mode)),
    });
  }
  return JSON.stringify({ units: { t: "s", x: "m", y: "m", theta: "rad", v: "m/s", omega: "rad/s" }, ...meta, agents });
}

export function downloadCsv(trails: Trails): void {
  download("trajectories.csv", new Blob([trajectoriesCsv(trails)], { type: "text/csv" }));
}

export function downloadJson(trails: Trails, meta: Record<string, unknown>): void {
  download("trajectories.json", new Blob([trajectoriesJson(trails, meta)], { type: "application/json" }));
}
