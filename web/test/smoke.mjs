// Node smoke test of the *release* wasm package (web/pkg, built by
// `make wasm`): instantiates it with initSync, as a broken post-processing
// step (wasm-opt, bindgen mismatch) shows only when the real package loads.
import { readFileSync, readdirSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { dirname, resolve } from "node:path";
import assert from "node:assert/strict";
import { test } from "node:test";

const here = dirname(fileURLToPath(import.meta.url));
const pkg = resolve(here, "../pkg");
const root = resolve(here, "../..");
const core = await import(resolve(pkg, "steering.js"));
core.initSync({ module: readFileSync(resolve(pkg, "steering_bg.wasm")) });

test("version is the crate's", () => {
  const cargo = readFileSync(resolve(root, "Cargo.toml"), "utf8");
  const v = /^version = "([^"]+)"/m.exec(cargo)[1];
  assert.equal(core.version(), v);
});

test("seeded samples are deterministic Float32Arrays", () => {
  const a = core.randomSamples(3, 16);
  assert.ok(a instanceof Float32Array);
  assert.equal(a.length, 16);
  assert.deepEqual(Array.from(a), Array.from(core.randomSamples(3, 16)));
});

const table = readFileSync(resolve(root, "tables/eta.bin"));

test("the committed table loads; a corrupt one throws a readable Error", () => {
  const lab = new core.Lab(new Uint8Array(table));
  const info = lab.tableInfo();
  assert.ok(info.entries > 10000 && info.distances.length > 2 && info.dEta > 0);
  const bad = new Uint8Array(table);
  bad[bad.length >> 1] ^= 0xff;
  assert.throws(() => new core.Lab(bad), (e) => e instanceof Error && /η table/.test(e.message));
  assert.throws(() => new core.Lab(new Uint8Array(10)), (e) => e instanceof Error && /η table/.test(e.message));
});

test("agents step; state() is a Float32Array of stride stateStride()", () => {
  const lab = new core.Lab(new Uint8Array(table));
  const g = { x: 5, y: 2, beta: Math.PI / 2, dTol: 0.3, epsTol: 0.17, speed: 1.3, halting: true, relaxed: false };
  lab.addAgent({ x: -3, y: 0, theta: 0, goals: [g] });
  lab.step(300);
  const s = lab.state();
  assert.ok(s instanceof Float32Array);
  assert.equal(s.length, core.Lab.stateStride());
  assert.ok(Math.hypot(s[0] - -3, s[1]) > 2, `moved: ${s[0]}, ${s[1]}`);
  const i = lab.internals(0);
  assert.ok([0, 1, 2, 3].includes(i.mode));
  assert.throws(() => lab.internals(5), /no agent 5/);
  assert.throws(() => lab.addAgent({ x: 0, y: 0, theta: 0, goals: [{ ...g, dTol: -1 }] }), /dTol/);
  const field = lab.etaField(0.5, 0, 1.3);
  assert.ok(field instanceof Float32Array && field.length % 4 === 0 && field.length > 400);
});

test("every preset scenario loads and runs", () => {
  const lab = new core.Lab(new Uint8Array(table));
  const dir = resolve(root, "scenarios");
  const files = readdirSync(dir).filter((f) => f.endsWith(".json"));
  assert.ok(files.length > 0);
  for (const f of files) {
    const info = lab.loadScenario(readFileSync(resolve(dir, f), "utf8"));
    assert.ok(info.agents > 0, f);
    lab.step(120);
    assert.ok(lab.state().every(Number.isFinite), f);
  }
});
