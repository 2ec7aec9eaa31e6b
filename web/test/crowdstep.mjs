// Crowd step cost in Node at 30,000 boids (Test IV pathway, Parker 10 %, metrics on, as the
// crowd page's bench), separation on / off, for each wasm package directory given (e.g. a
// baseline built from an older commit and web/pkg): rounds alternate between packages, best of 5.
// Issue 17's anomaly: `node web/test/crowdstep.mjs /path/to/old/pkg web/pkg`.
import { readFileSync } from "node:fs";
import { resolve } from "node:path";
const pkgs = process.argv.slice(2);
const libs = [];
for (const pkg of pkgs) {
  const core = await import(resolve(pkg) + "/steering.js");
  core.initSync({ module: readFileSync(resolve(pkg) + "/steering_bg.wasm") });
  const base = core.CrowdLab.paperPresets().find((p) => p.boids === 300 && p.seek.kind === "parker" && Math.abs(p.seek.fraction - 0.1) < 1e-6);
  const labs = [true, false].map((sep) => { const l = new core.CrowdLab({ ...base, boids: 30000, separation: sep }); l.step(20); return l; });
  libs.push({ pkg, labs, best: [Infinity, Infinity] });
}
for (let r = 0; r < 5; r++) for (const s of libs) s.labs.forEach((l, k) => {
  const t0 = performance.now(); l.step(10); s.best[k] = Math.min(s.best[k], (performance.now() - t0) / 10);
});
for (const s of libs) console.log(`${s.pkg}: 30,000 boids, separation on ${s.best[0].toFixed(2)} ms/step, off ${s.best[1].toFixed(2)} ms/step`);
