// The shipped simd128 module (web/pkg/steering_simd_bg.wasm, built by
// `make wasm`) gives the baseline module's bits, in Node (V8, Chromium's
// engine): every funnelling preset stepped one step at a time with each
// state hashed, the wander presets' traces, the crowd presets (Parker and
// Reynolds seek), and small η tables of every reference vehicle built
// through the workers' calls. The baseline build is held to the native
// golden hashes in headless Chromium (`make test-wasm`), so equal bits here
// hold the module the pages load on a SIMD engine to them too, without a
// second wasm test build. (Both modules share one JavaScript glue file,
// checked byte for byte by `make wasm`; each is its own instance here, the
// glue imported twice under two URLs.)
import { readFileSync, readdirSync } from "node:fs";
import { fileURLToPath, pathToFileURL } from "node:url";
import { dirname, resolve } from "node:path";
import assert from "node:assert/strict";
import { test } from "node:test";

const here = dirname(fileURLToPath(import.meta.url));
const pkg = resolve(here, "../pkg");
const root = resolve(here, "../..");

/** One instance of the glue with `wasm` as its module. */
async function load(wasm, tag) {
  const core = await import(`${pathToFileURL(resolve(pkg, "steering.js")).href}?${tag}`);
  core.initSync({ module: readFileSync(resolve(pkg, wasm)) });
  return core;
}
const cores = { baseline: await load("steering_bg.wasm", "baseline"), simd128: await load("steering_simd_bg.wasm", "simd128") };
assert.ok(WebAssembly.validate(readFileSync(resolve(pkg, "steering_simd_bg.wasm"))), "this engine has WebAssembly SIMD");

/** FNV-1a (64-bit) over the bit patterns of float arrays, updated in place. */
const FNV_PRIME = 0x100000001b3n;
const MASK = (1n << 64n) - 1n;
function fnv(h, floats) {
  const words = new Uint32Array(floats.buffer, floats.byteOffset, floats.length);
  for (const w of words) h.value = ((h.value ^ BigInt(w)) * FNV_PRIME) & MASK;
}
const hasher = () => ({ value: 0xcbf29ce484222325n });

/** `run(core)` under both modules: the same digest. */
function sameBits(what, run) {
  const base = run(cores.baseline);
  const simd = run(cores.simd128);
  assert.deepEqual(simd, base, `${what}: the simd128 module differs from the baseline`);
  return base;
}

const table = readFileSync(resolve(root, "tables/eta.bin"));
const presets = (dir) => readdirSync(resolve(root, dir)).filter((f) => f.endsWith(".json")).map((f) => [f, readFileSync(resolve(root, dir, f), "utf8")]);

/** Steps `lab` one step at a time, `steps` times, hashing what each of
 *  `reads` returns after every step. */
function everyStep(lab, steps, ...reads) {
  const h = hasher();
  for (let t = 0; t < steps; t++) {
    lab.step(1);
    for (const read of reads) fnv(h, read(lab));
  }
  return h;
}

// The golden hashes' length (tests/funnel_determinism.rs: 1,800 steps).
const STEPS = 1800;

test("every funnelling preset: every state of 1,800 steps, bit for bit", () => {
  for (const [name, json] of presets("scenarios")) {
    sameBits(name, (core) => {
      const lab = new core.Lab(new Uint8Array(table));
      lab.loadScenario(json);
      const h = everyStep(lab, STEPS, (l) => l.state());
      lab.free();
      return h.value;
    });
  }
});

test("every wander preset: every variant's trace, bit for bit", () => {
  for (const [name, json] of presets("scenarios/wander")) {
    sameBits(name, (core) => {
      const preset = core.WanderLab.parsePreset(json);
      const h = hasher();
      for (const v of preset.variants) {
        const lab = new core.WanderLab(v.config);
        lab.run(preset.steps);
        fnv(h, lab.trace());
        lab.free();
      }
      return h.value;
    });
  }
});

test("the crowd presets: positions and velocities every step, and the trace, bit for bit", () => {
  for (const [name, json] of presets("scenarios/crowd")) {
    sameBits(name, (core) => {
      const lab = core.CrowdLab.fromJson(json);
      const h = everyStep(lab, 400, (l) => l.positions(), (l) => l.velocities());
      fnv(h, lab.trace());
      lab.free();
      return h.value;
    });
  }
});

test("small η tables of every reference vehicle, built in three slices, byte for byte", () => {
  const counts = [6, 12, 3, 4, 4];
  const names = cores.baseline.referenceVehicles().map((r) => r.name);
  assert.ok(names.length >= 4, names.join(", "));
  for (const name of names) {
    const bytes = sameBits(name, (core) => {
      const p = core.referenceVehicles().find((r) => r.name === name).vehicle;
      const n = core.tableJob(p, counts).entries;
      const cuts = [0, Math.floor(n / 3), Math.floor(n / 2), n];
      const parts = cuts.slice(1).map((end, i) => core.tableSlice(p, counts, cuts[i], end));
      const data = new Float32Array(parts.reduce((s, a) => s + a.length, 0));
      parts.reduce((at, a) => (data.set(a, at), at + a.length), 0);
      return Array.from(core.assembleTable(p, counts, data));
    });
    assert.ok(bytes.length > 100, `${name}: ${bytes.length} bytes`);
  }
});
