// Crowd step cost in Node at 30,000 boids (Test IV pathway, Parker 10 %, metrics on, as the
// crowd page's bench), separation on / off, for each wasm package directory given (e.g. a
// baseline built from an older commit and web/pkg): rounds alternate between packages, best of 5.
// Usage: `node web/test/crowdstep.mjs /path/to/old/pkg web/pkg`; options:
// `--n 100000` boids, `--scaled` (Test IV density: pathway scaled by
// n / 300, as `cargo bench --bench crowd`; separation on, metrics on / off instead of
// separation on / off), `--simd` (the package's steering_simd_bg.wasm); also prints the
// cost of copying positions + velocities out.
import { readFileSync } from "node:fs";
import { resolve } from "node:path";
import { options, whole } from "./options.mjs";
const { values, positionals: pkgs } = options(
  `Crowd step cost in Node for each wasm package directory given, rounds alternating.
Usage: node web/test/crowdstep.mjs PKG_DIR... [options]`,
  {
    n: { type: "string", default: "30000", arg: "N", help: "boids" },
    scaled: { type: "boolean", default: false, help: "Test IV density (pathway scaled by n / 300); metrics on / off instead of separation on / off" },
    simd: { type: "boolean", default: false, help: "the package's steering_simd_bg.wasm" },
  },
  { positionals: true },
);
const N = whole(values, "n", 1);
const { scaled, simd } = values;
const libs = [];
for (const pkg of pkgs) {
  const core = await import(resolve(pkg) + "/steering.js");
  core.initSync({ module: readFileSync(resolve(pkg) + (simd ? "/steering_simd_bg.wasm" : "/steering_bg.wasm")) });
  const base = core.CrowdLab.paperPresets().find((p) => p.boids === 300 && p.seek.kind === "parker" && Math.abs(p.seek.fraction - 0.1) < 1e-6);
  const k = N / 300;
  const path = scaled ? { ...base.path, points: base.path.points.map(([x, y]) => [x * k, y * k]) } : base.path;
  const labs = [true, false].map((on) => {
    const l = new core.CrowdLab({ ...base, boids: N, path, separation: scaled ? true : on });
    if (scaled) l.setMetricsEnabled(on);
    l.step(20);
    return l;
  });
  libs.push({ pkg, labs, best: [Infinity, Infinity], copy: Infinity });
}
for (let r = 0; r < 5; r++) for (const s of libs) s.labs.forEach((l, k) => {
  const t0 = performance.now(); l.step(10); s.best[k] = Math.min(s.best[k], (performance.now() - t0) / 10);
  const t1 = performance.now(); l.positions(); l.velocities(); s.copy = Math.min(s.copy, performance.now() - t1);
});
const what = scaled ? ["metrics on", "off"] : ["separation on", "off"];
for (const s of libs) {
  console.log(`${s.pkg}${simd ? " (simd128)" : ""}: ${N.toLocaleString("en")} boids${scaled ? " at Test IV density" : ""}, ${what[0]} ${s.best[0].toFixed(2)} ms/step (${((s.best[0] * 1e6) / N).toFixed(0)} ns/boid), ${what[1]} ${s.best[1].toFixed(2)} ms/step (${((s.best[1] * 1e6) / N).toFixed(0)} ns/boid); positions + velocities copied out ${s.copy.toFixed(2)} ms`);
}
