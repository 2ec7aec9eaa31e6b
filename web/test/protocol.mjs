// The continuing-jobs protocol (src/threads/continuing.ts) under load, in
// Node: real threads (worker_threads), the real module (its types
// stripped by Vite's `transformWithOxc`), random step and drawing times.
//
// Each worker writes step s into its slice of the step's buffer; the
// "page" raises the target every frame, takes a state (`take`), checks
// that its buffer holds that step (every 61st float, all slices), draws
// for a while, and checks it again: a buffer handed to a later step while drawn would show
// there (the page may take a state DEPTH behind the newest, so the workers
// protect that many more buffers).
// Then: states drawn in order, none skipped at a step per frame (at 1–3
// steps a frame, a faster clock, the page takes a frame's worth on), and
// every worker ending after the same step. The lab's protocol
// (`runIndependent`, 2 and 3 workers) and the crowd's (`runContinuing`,
// its barrier; a worker also checks that the step it reads from is whole).
//
// Usage: node test/protocol.mjs [--frames N]   (about 25 s; node:test,
// exits 1 on a failure; `--help` lists the options)

import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { Worker } from "node:worker_threads";
import { transformWithOxc } from "vite";
import assert from "node:assert/strict";
import { test } from "node:test";
import { options, whole } from "./options.mjs";

const { values } = options(
  `The workers' continuing-jobs protocol (src/threads/continuing.ts) on real threads in Node.
Usage: node test/protocol.mjs [options]   (from web/; \`make test-protocol\`)`,
  { frames: { type: "string", default: "200", arg: "N", help: "page frames per protocol run" } },
);

const here = new URL(".", import.meta.url).pathname;
const dir = mkdtempSync(join(tmpdir(), "protocol-"));
const src = readFileSync(join(here, "../src/threads/continuing.ts"), "utf8");
const { code: js } = await transformWithOxc(src, "continuing.ts", { lang: "ts" });

/** The module as committed (`null`), or with other DEPTH and LEAD. */
function moduleFor(depth, lead) {
  let code = js;
  if (depth !== null) {
    code = code.replace(/export const DEPTH = \d+;/, `export const DEPTH = ${depth};`).replace(/export const LEAD = \d+;/, `export const LEAD = ${lead};`);
    if (!code.includes(`DEPTH = ${depth};`) || !code.includes(`LEAD = ${lead};`)) throw new Error("protocol.mjs: DEPTH / LEAD not found in continuing.ts");
  }
  const path = join(dir, `continuing-${depth ?? "committed"}-${lead ?? ""}.mjs`);
  writeFileSync(path, code);
  return path;
}

const SLICE = 4096;
const FRAMES = whole(values, "frames", 1);

// The worker: its slice of each step's buffer set to the step number, in
// random time (0–3 ms busy); the note keeps the step's buffer.
writeFileSync(
  join(dir, "worker.mjs"),
  `
import { workerData, parentPort } from "node:worker_threads";
const { mod, protocol, ctrl: cb, slots: sb, states, worker, workers, front, seed } = workerData;
const P = await import(mod);
const ctrl = new Int32Array(cb);
const slots = new Int32Array(sb);
const bufs = states.map((b) => new Float64Array(b));
let r = seed >>> 0;
const rand = () => ((r = (Math.imul(r, 1664525) + 1013904223) >>> 0) / 2 ** 32);
const busy = (ms) => { const t = performance.now() + ms; while (performance.now() < t); };
const lo = worker * ${SLICE}, hi = lo + ${SLICE};
let bad = "";
const work = {
  ctrl, worker, workers, front,
  step(from, dst, s) {
    if (from >= 0) {
      // The barrier's protocol: the state stepped from is step s − 1, whole.
      const b = bufs[from];
      for (let i = 0; i < b.length; i += 97) if (b[i] !== s - 1 && !bad) bad = "worker " + worker + " step " + s + " read " + b[i] + " from buffer " + from;
    }
    busy(rand() * 3);
    bufs[dst].fill(s, lo, hi);
  },
  note(s, dst) { slots[(s - 1) % P.SLOT_RING] = dst; },
};
const steps = protocol === "independent" ? P.runIndependent(work) : P.runContinuing(work);
parentPort.postMessage({ steps, bad });
`,
);

function sleep(ms) {
  Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);
}

async function run(mod, protocol, workers, seed, speeds) {
  const P = await import(mod);
  const ctrlBuf = new SharedArrayBuffer(P.CTRL_BYTES);
  const slotBuf = new SharedArrayBuffer(4 * P.SLOT_RING);
  const states = Array.from({ length: P.STATES }, () => new SharedArrayBuffer(8 * SLICE * workers));
  const bufs = states.map((b) => new Float64Array(b));
  const ctrl = new Int32Array(ctrlBuf);
  const slots = new Int32Array(slotBuf);
  const jobs = new P.ContinuingJobs(ctrl);
  const front = 0;
  jobs.begin(front, 1);
  const done = Array.from({ length: workers }, (_, worker) => {
    const w = new Worker(join(dir, "worker.mjs"), { workerData: { mod, protocol, ctrl: ctrlBuf, slots: slotBuf, states, worker, workers, front, seed: seed * 31 + worker } });
    return new Promise((res, rej) => {
      w.once("message", (m) => { res(m); void w.terminate(); });
      w.once("error", rej);
    });
  });
  let r = seed >>> 0;
  const rand = () => ((r = (Math.imul(r, 1664525) + 1013904223) >>> 0) / 2 ** 32);
  const errors = [];
  const whole = (buffer, step, when) => {
    const b = bufs[buffer];
    for (let i = 0; i < b.length; i += 61) {
      if (b[i] !== step) {
        errors.push(`${protocol} ×${workers}: step ${step} in buffer ${buffer} held ${b[i]} at float ${i} ${when}`);
        return;
      }
    }
  };
  let drawn = 0;
  let last = 0;
  // Liveness: a quarter of the frames must draw a state. Workers kept off
  // the cores by other work (make test runs two lanes on two cores) step
  // late, so the page goes on for up to four times the frames until they
  // have: what is judged is that the drawer is not starved by the
  // protocol, not how fast a loaded machine steps.
  let frames = 0;
  for (let f = 0; f < FRAMES || (drawn < FRAMES / 4 && f < 4 * FRAMES); f++) {
    frames = f + 1;
    // A frame's worth of steps: 1 in real time, more at a faster clock.
    const k = speeds ? 1 + Math.floor(rand() * 3) : 1;
    jobs.perFrame = k;
    jobs.raise(k, k);
    const picked = jobs.take(false, (k) => slots[(k - 1) % P.SLOT_RING]);
    if (picked) {
      if (picked.step <= last || (!speeds && picked.step !== last + 1)) errors.push(`${protocol} ×${workers}: took step ${picked.step} after ${last}`);
      last = picked.step;
      drawn++;
      whole(picked.buffer, picked.step, "when taken");
      // Drawing: the buffer must hold still meanwhile.
      sleep(rand() * 4);
      whole(picked.buffer, picked.step, "after drawing it");
    }
    // A frame's remaining time, sometimes late (the page kept off its core).
    sleep(rand() < 0.1 ? 6 + rand() * 10 : rand() * 3);
  }
  jobs.end();
  const results = await Promise.all(done);
  const ends = results.map((m) => m.steps);
  for (const m of results) if (m.bad) errors.push(`${protocol} ×${workers}: ${m.bad}`);
  if (new Set(ends).size !== 1) errors.push(`${protocol} ×${workers}: workers ended after steps ${ends.join(", ")}`);
  if (!speeds && jobs.skipped !== 0) errors.push(`${protocol} ×${workers}: ${jobs.skipped} states skipped at a step per frame`);
  if (drawn < FRAMES / 4) errors.push(`${protocol} ×${workers}: only ${drawn} states drawn in ${frames} frames`);
  console.log(`# DEPTH ${P.DEPTH} LEAD ${P.LEAD}, ${protocol} ×${workers}${speeds ? ", 1–3 steps a frame" : ""}: ${drawn} states drawn in order of ${ends[0]} stepped, ${frames} frames; ${errors.length ? "FAILED" : "ok"}`);
  return errors;
}

// The committed DEPTH and LEAD, then others (the protocol is written for any).
for (const [depth, lead] of [[null, null], [1, 1], [2, 2]]) {
  const mod = moduleFor(depth, lead);
  for (const [protocol, workers, seed] of [["independent", 2, 1], ["independent", 3, 2], ["barrier", 2, 3], ["barrier", 3, 4]]) {
    for (const speeds of [false, true]) {
      const name = `DEPTH ${depth ?? "as committed"}${lead === null ? "" : ` LEAD ${lead}`}, ${protocol} ×${workers}${speeds ? ", 1–3 steps a frame" : ", a step a frame"}`;
      await test(name, async () => {
        const errors = await run(mod, protocol, workers, seed, speeds);
        assert.deepEqual(errors.slice(0, 20), []);
      });
    }
  }
}
rmSync(dir, { recursive: true, force: true });
