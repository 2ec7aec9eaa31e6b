// Wasm / native per funnelling agent update, in one run. The same
// workload — the lab's performance world (spawnRandom: N agents, seed 1,
// extent √N·1.5 m, 1.3 m/s, 16 goals each), warmed up, then rounds of
// STEPS steps — natively (`diagnostics/world_bench.rs`, release) and in Node on
// the release wasm package: both its builds (web/pkg/steering_bg.wasm and
// the SIMD one, steering_simd_bg.wasm), or those of each `--pkg DIR` given
// (e.g. web/pkg and a package built from another commit). Native and wasm rounds alternate, ROUNDS times, so a busy
// machine slows both alike; the figure per side is its fastest round, in
// wall time and in process CPU time (not counting time preempted). The
// states' hash after the run must be equal on both sides (same work, same
// bits). Usage: node web/test/wasmnative.mjs [N] [--pkg DIR]... [--native BIN]
import { readFileSync } from "node:fs";
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { dirname, resolve } from "node:path";
import { existsSync } from "node:fs";
import { pathToFileURL } from "node:url";
import { options } from "./options.mjs";

const here = dirname(fileURLToPath(import.meta.url));
const root = resolve(here, "../..");
const { values, positionals: pos } = options(
  `Wasm / native per funnelling agent update, alternating rounds in one run.
Usage: node web/test/wasmnative.mjs [N] [options]   (N agents, default 10000; \`make bench-wasm-native\`)`,
  {
    pkg: { type: "string", multiple: true, default: [], arg: "DIR", help: "a wasm package directory (default web/pkg)" },
    native: { type: "string", default: resolve(root, "target/release/examples/world_bench"), arg: "BIN", help: "the native world_bench binary" },
  },
  { positionals: 1 },
);
const pkgs = values.pkg.map((d) => resolve(d));
const native = resolve(values.native);
if (!pkgs.length) pkgs.push(resolve(here, "../pkg"));
const builds = pkgs.flatMap((dir) =>
  ["steering_bg.wasm", "steering_simd_bg.wasm"].filter((f) => existsSync(resolve(dir, f))).map((f) => ({ dir, wasm: resolve(dir, f) })),
);
const N = Number(pos[0] ?? 10000);
const STEPS = 20;
const ROUNDS = 5;
const table = readFileSync(resolve(root, "tables/eta.bin"));

function fnv(state, stride) {
  let h = 0x811c9dc5;
  const bytes = new Uint8Array(new Float32Array(state).buffer);
  for (let a = 0; a < state.length / stride; a++) {
    const o = a * stride * 4;
    for (let b = o; b < o + 20; b++) h = Math.imul(h ^ bytes[b], 0x01000193) >>> 0;
  }
  return h.toString(16).padStart(8, "0");
}

const sides = [];
for (const [k, { dir, wasm }] of builds.entries()) {
  // A query string makes each build its own module instance.
  const core = await import(`${pathToFileURL(resolve(dir, "steering.js")).href}?build=${k}`);
  core.initSync({ module: readFileSync(wasm) });
  const lab = new core.Lab(table);
  lab.spawnRandom(N, 1, Math.max(10, Math.sqrt(N) * 1.5), 1.3);
  lab.step(STEPS);
  sides.push({ dir: wasm, core, lab, best: Infinity, cpu: Infinity, rounds: 0 });
}
let nativeBest = Infinity;
let nativeCpu = Infinity;
let nativeHash = "";
for (let r = 0; r < ROUNDS; r++) {
  // Native: its own process (warm-up + 1 timed round each time).
  const out = execFileSync(native, [String(N), String(STEPS), "1"], { encoding: "utf8" });
  for (const m of out.matchAll(/ns_per_update ([\d.]+) cpu ([\d.]+)/g)) {
    nativeBest = Math.min(nativeBest, Number(m[1]));
    nativeCpu = Math.min(nativeCpu, Number(m[2]));
  }
  nativeHash = /hash (\w+)/.exec(out)[1];
  for (const s of sides) {
    const c0 = process.cpuUsage();
    const t0 = performance.now();
    s.lab.step(STEPS);
    const ns = ((performance.now() - t0) * 1e6) / (STEPS * N);
    const c = process.cpuUsage(c0);
    s.best = Math.min(s.best, ns);
    s.cpu = Math.min(s.cpu, ((c.user + c.system) * 1e3) / (STEPS * N));
    s.rounds++;
  }
}
let bad = 0;
console.log(`wasm/native, ${N.toLocaleString("en")} funnelling agents, ${STEPS} steps per round, best of ${ROUNDS} alternating rounds:`);
console.log(`  native (${native.replace(root + "/", "")}): ${nativeBest.toFixed(1)} ns per agent update (CPU time ${nativeCpu.toFixed(1)} ns)`);
for (const s of sides) {
  // Same work as natively: after warm-up + 1 round, the native states' hash.
  const check = new s.core.Lab(table);
  check.spawnRandom(N, 1, Math.max(10, Math.sqrt(N) * 1.5), 1.3);
  check.step(2 * STEPS);
  const h = fnv(check.state(), s.core.Lab.stateStride());
  check.free();
  const same = h === nativeHash;
  if (!same) bad++;
  console.log(
    `  wasm (${s.dir.replace(root + "/", "")}): ${s.best.toFixed(1)} ns per agent update (CPU time ${s.cpu.toFixed(1)} ns) → ` +
      `wasm/native ${(s.best / nativeBest).toFixed(2)}× (CPU time ${(s.cpu / nativeCpu).toFixed(2)}×) ` +
      `(state hash ${h} ${same ? "= native" : `≠ native ${nativeHash}`})`,
  );
  s.lab.free();
}
process.exit(bad ? 1 : 0);
