// Node smoke test of the *release* wasm package (web/pkg, built by
// `make wasm`): instantiates it with initSync, as a broken post-processing
// step (wasm-opt, bindgen mismatch) shows only when the real package loads.
import { readFileSync, existsSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { dirname, resolve } from "node:path";
import assert from "node:assert/strict";

const here = dirname(fileURLToPath(import.meta.url));
const pkg = resolve(here, "../pkg");
const root = resolve(here, "../..");
const core = await import(resolve(pkg, "steering.js"));
core.initSync({ module: readFileSync(resolve(pkg, "steering_bg.wasm")) });

let passed = 0;
let failed = 0;
function check(name, f) {
  try {
    f();
    passed++;
    console.log(`ok - ${name}`);
  } catch (e) {
    failed++;
    console.log(`not ok - ${name}\n  ${e && e.stack ? e.stack : e}`);
  }
}

check("version is the crate's", () => {
  const cargo = readFileSync(resolve(root, "Cargo.toml"), "utf8");
  const v = /^version = "([^"]+)"/m.exec(cargo)[1];
  assert.equal(core.version(), v);
});

check("seeded samples are deterministic Float32Arrays", () => {
  const a = core.randomSamples(3, 16);
  assert.ok(a instanceof Float32Array);
  assert.equal(a.length, 16);
  assert.deepEqual(Array.from(a), Array.from(core.randomSamples(3, 16)));
});

const LAB_TESTS = resolve(here, "smoke_lab.mjs");
if (existsSync(LAB_TESTS)) {
  const { labChecks } = await import(LAB_TESTS);
  labChecks(core, check, { root });
}

console.log(`smoke: ${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
