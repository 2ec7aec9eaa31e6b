// The package in Node, as a user's script meets it: the tarball installed
// under target/npm-user/node, `createLab()` with no browser (the module
// and the table read from disk), an agent driven to rest and asked
// `done` / `atRest` / `mode`; what a refused agent says; and the cost of
// adding agents, measured in one run: 16,000 single adds must take under
// 20× the time of 1,000 (linear: 16×; a re-plan of the whole world per
// add made it quadratic), and 100,000 agents in one `addAgents` call
// under 150× (linear: 100×); CPU time, the medians of interleaved rounds.
import { test } from "node:test";
import assert from "node:assert/strict";
import { join } from "node:path";
import { pathToFileURL } from "node:url";
import { installed } from "./install.mjs";

const scratch = installed("node");
const core = await import(pathToFileURL(join(scratch, "node_modules/steering-core/index.js")).href);
const { createLab, Lab, Mode, MODE_NAMES } = core;

const DEG = Math.PI / 180;

/** Agent k of a seeded set: a start and an oriented halting goal within 20 m. */
function agent(k) {
  const r = (i) => {
    const x = Math.sin(k * 12.9898 + i * 78.233) * 43758.5453;
    return x - Math.floor(x);
  };
  return { x: 40 * r(1) - 20, y: 40 * r(2) - 20, theta: 2 * Math.PI * r(3) - Math.PI, goals: [{ x: 40 * r(4) - 20, y: 40 * r(5) - 20, beta: 2 * Math.PI * r(6) - Math.PI, dTol: 0.3, epsTol: 10 * DEG, speed: 1.3, halting: true }] };
}

test("createLab() runs in Node: an agent is driven to rest inside both tolerances", async () => {
  const lab = await createLab();
  assert.ok(lab instanceof Lab);
  const i = lab.addAgent({ x: -5, y: -2, theta: 0, goals: [{ x: 5, y: 2, beta: Math.PI / 2, dTol: 0.25, epsTol: 5 * DEG, speed: 1.3, halting: true }] });
  assert.equal(i, 0);
  assert.equal(lab.done(0), false);
  let steps = 0;
  while (!lab.atRest(0) && steps < 60 * 60) {
    lab.step(1);
    steps++;
  }
  assert.ok(lab.atRest(0), `at rest within a minute (${steps} steps)`);
  assert.equal(lab.done(0), true);
  assert.equal(lab.mode(0), Mode.EndOfSteering);
  assert.equal(MODE_NAMES[lab.mode(0)], "EndOfSteering");
  assert.deepEqual([...lab.modes()], [Mode.EndOfSteering]);
  // A second lab shares the instantiated module.
  assert.equal((await createLab()).count(), 0);
});

test("a refused agent is named, and so is its missing field", async () => {
  const lab = await createLab();
  const { theta: _, ...noTheta } = agent(1);
  assert.throws(() => lab.addAgent(noTheta), (e) => /field `theta`: missing/.test(e.message));
  const noTol = agent(2);
  delete noTol.goals[0].dTol;
  assert.throws(() => lab.addAgent(noTol), (e) => /field `goals\[0\]\.dTol`: missing/.test(e.message));
  const bad = [agent(3), agent(4), { ...agent(5), x: Number.NaN }];
  assert.throws(() => lab.addAgents(bad), (e) => /^agents\[2\]/.test(e.message));
  const typo = [agent(3), { ...agent(4), heading: 1 }];
  assert.throws(() => lab.addAgents(typo), (e) => /agents\[1\].*heading/.test(e.message));
  assert.equal(lab.count(), 0, "nothing added when one agent is refused");
  assert.throws(() => lab.done(0), /agent/);
});

/** CPU seconds of this process (every thread: the collector's too) while
 *  `f` runs: less swayed by the other processes of a shared machine than
 *  the wall clock. */
function cpuSeconds(f) {
  const t0 = process.cpuUsage();
  f();
  const d = process.cpuUsage(t0);
  return (d.user + d.system) / 1e6;
}

/** CPU seconds to add `n` agents one call each, to a fresh lab. */
async function singles(n) {
  const lab = await createLab();
  const list = Array.from({ length: n }, (_, k) => agent(k));
  const s = cpuSeconds(() => {
    for (const a of list) lab.addAgent(a);
  });
  assert.equal(lab.count(), n);
  lab.free();
  return s;
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

test("adds cost amortised constant time each, single or batched (one run)", async (t) => {
  await singles(1000); // warm-up: the JIT and the module's memory
  const one = [];
  const sixteen = [];
  // Interleaved rounds, so that a busy spell of the machine falls on both sizes.
  for (let r = 0; r < 3; r++) {
    one.push(await singles(1000));
    sixteen.push(await singles(16000));
  }
  const lab = await createLab();
  const list = Array.from({ length: 100000 }, (_, k) => agent(k));
  let first = -1;
  const batch = cpuSeconds(() => {
    first = lab.addAgents(list);
  });
  assert.equal(first, 0);
  assert.equal(lab.count(), 100000);
  lab.step(1);
  const ratio16 = median(sixteen) / median(one);
  const ratio100 = batch / median(one);
  t.diagnostic(`CPU time: 1,000 single adds ${(median(one) * 1000).toFixed(1)} ms (median of 3); 16,000 ${(median(sixteen) * 1000).toFixed(1)} ms (${ratio16.toFixed(1)}×); 100,000 in one call ${(batch * 1000).toFixed(1)} ms (${ratio100.toFixed(1)}×)`);
  // Bounds at twice the linear ratio: under `make test`'s load one run's
  // ratio moved between 12× and 20× (16,000 against 1,000), while a cost
  // per add that grows with the count (the world copied on each add) gives
  // 256×.
  assert.ok(ratio16 < 32, `16,000 single adds took ${ratio16.toFixed(1)}× the time of 1,000 (linear: 16×)`);
  assert.ok(ratio100 < 200, `100,000 agents in one call took ${ratio100.toFixed(1)}× the time of 1,000 single adds (linear: 100×)`);
});
