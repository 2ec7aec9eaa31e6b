// Seeded fuzz of the lab's URL decoder: ≥ 10,000 mutated
// fragments (known and random keys; values such as NaN, Infinity, 1e999,
// 0x10, empty, huge, negative, unicode digits, 5,000 characters, bad
// percent-encoding; duplicated keys) through `decodeState`, bundled from the
// page's own TypeScript (web/src/lab/urlstate.ts) with rolldown. Asserts:
// nothing throws; every accepted state is one the core accepts, checked by
// building it in the *release* wasm package (initSync): the vehicle limits,
// the playground agent and its goal, the funnel and relaxed settings, room
// for the random agents (and, for small counts, spawning them), the η field
// view; every key whose value was not taken has a message naming it; and the
// state re-encodes to a fragment that decodes with no message to the same
// state. The avoidance method (`avoid`) and the obstacles (`obs`)
// too, set in the core with setAvoidance / setObstacles. Prints "urlfuzz: N cases, M refused values, T ms" (node:test).
// `--cases N --seed S` set the run (`--help`).
import { readFileSync, writeFileSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { fileURLToPath, pathToFileURL } from "node:url";
import { dirname, resolve, join } from "node:path";
import assert from "node:assert/strict";
import { test } from "node:test";
import { rolldown } from "rolldown";
import { options, whole } from "./options.mjs";

const { values } = options(
  `Seeded fuzz of the lab's URL decoder against the release wasm package.
Usage: node web/test/urlfuzz.mjs [options]   (after \`make wasm\`; \`make test-urlfuzz\`)`,
  {
    cases: { type: "string", default: "10000", arg: "N", help: "mutated fragments decoded" },
    seed: { type: "string", default: "16", arg: "S", help: "the fuzzer's seed (a 32-bit whole number)" },
  },
);

const here = dirname(fileURLToPath(import.meta.url));
const src = resolve(here, "../src/lab");
const root = resolve(here, "../..");
const CASES = whole(values, "cases", 1);
const SEED = whole(values, "seed");

// The page's decoder, as the page runs it.
const tmp = mkdtempSync(join(tmpdir(), "urlfuzz-"));
const entry = join(tmp, "entry.ts");
writeFileSync(entry, [
  `export { decodeState, encodeState } from ${JSON.stringify(resolve(src, "urlstate.ts"))};`,
  `export { RangeTable, FIELDS, parseDecimal, limitDefaults } from ${JSON.stringify(resolve(src, "fields.ts"))};`,
  `export { funnelConfig, relaxedConfig } from ${JSON.stringify(resolve(src, "funnelsettings.ts"))};`,
  `export { defaultState } from ${JSON.stringify(resolve(src, "state.ts"))};`,
].join("\n"));
const bundle = await rolldown({ input: entry, logLevel: "silent" });
const { output } = await bundle.generate({ format: "esm" });
const out = join(tmp, "decoder.mjs");
writeFileSync(out, output[0].code);
const page = await import(pathToFileURL(out).href);
rmSync(tmp, { recursive: true, force: true });

const pkg = resolve(here, "../pkg");
const core = await import(resolve(pkg, "steering.js"));
core.initSync({ module: readFileSync(resolve(pkg, "steering_bg.wasm")) });
const tableBytes = readFileSync(resolve(root, "tables/eta.bin"));
let lab = new core.Lab(tableBytes);
// The core leaves a zero turning radius and reverse speed out; the page
// counts them as limits (its own limitDefaults, so the two cannot drift).
const defaults = page.limitDefaults(lab.params());
const table = new page.RangeTable(core.ranges(), core.precision());
const PRESETS = ["p000_fig1_seek", "p000_fig7_variety"];

// mulberry32: the same cases on every run.
let state = SEED >>> 0;
const rand = () => {
  state = (state + 0x6d2b79f5) >>> 0;
  let t = state;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
const pick = (xs) => xs[Math.floor(rand() * xs.length)];

const OTHER_KEYS = ["halting", "relaxed", "slow", "bound", "aim", "raim", "lp", "ov", "preset", "zx", "zy", "zs", "avoid", "obs", "cmp"];
const NUM_KEYS = page.FIELDS.map((f) => f.url);
const WEIRD = ["NaN", "Infinity", "-Infinity", "1e999", "-1e999", "0x10", "0b11", "0o7", "", " ", "  3 ", "1e308", "-1e308", "5e-324",
  "-0", "+7", ".5", "5.", "1,5", "1_000", "١٢", "１２", "٣.٥", "½", "∞", "1e", "e3", "--1", "%ZZ", "%", "%E2%82", "null", "undefined",
  "true", "[]", "{}", "1".repeat(5000), "9".repeat(400), "0." + "0".repeat(400) + "1", "\u0000", "ℕ", "💥", "<script>", "1 2"];
const randomKey = () => pick([
  () => Math.random === undefined ? "" : String.fromCharCode(97 + Math.floor(rand() * 26)).repeat(1 + Math.floor(rand() * 4)),
  () => "k" + Math.floor(rand() * 1e6),
  () => "ü🚗" + Math.floor(rand() * 100),
  () => "x".repeat(3000),
  () => "",
  () => "%ZZ",
])();
function numberFor(key) {
  const f = page.FIELDS.find((x) => x.url === key);
  const r = table.get(f.core);
  const lo = r.min * f.scale;
  const hi = r.max * f.scale;
  const eps = Math.max(1e-9, (hi - lo) * 1e-7);
  return pick([
    () => String(lo), () => String(hi), () => String(lo - eps), () => String(hi + eps),
    () => String(lo + rand() * (hi - lo)), () => String(Math.round(lo + rand() * (hi - lo))),
    () => String((rand() - 0.5) * 10), () => String(rand() * 3), () => String(Math.round(rand() * 20)),
    () => (rand() * 1e-3).toExponential(), () => String(-rand() * 100),
  ])();
}
const value = (key) => {
  if (NUM_KEYS.includes(key) && rand() < 0.7) return numberFor(key);
  if (key === "preset") return pick([...PRESETS, "missing", ""]);
  if (key === "ov") return pick(["radial,eta", "", "nope", "radial,,gamma", "trails"]);
  if (key === "bound") return pick(["tr", "sl", "lit", "const", "bogus"]);
  if (key === "aim") return pick(["entry", "centre", "left"]);
  if (key === "raim") return pick(["entry", "paperArc", "x"]);
  if (key === "avoid") return pick(["off", "separation", "orca", "ORCA", "rvo", ""]);
  if (key === "obs" && rand() < 0.7) return obstacles();
  if (["halting", "relaxed", "slow", "lp"].includes(key) && rand() < 0.6) return pick(["0", "1"]);
  return pick(WEIRD);
};
/** Obstacle lists for `obs`: mostly well formed, with values at and past
 *  the core's ranges, zero-length walls, bad kinds and separators, too many. */
function obstacles() {
  const coord = () => pick([() => String((rand() - 0.5) * 40), () => "1000000", () => "-1000000", () => "1000000.5", () => pick(WEIRD)])();
  const coordOk = () => (rand() < 0.9 ? String(Math.round((rand() - 0.5) * 4000) / 100) : coord());
  const radius = () => pick(["0.01", "0.009", "0", "-1", "10000", "10000.1", String(rand() * 3), "NaN"]);
  const one = () => {
    if (rand() < 0.5) return `d:${coordOk()},${coordOk()},${rand() < 0.8 ? String(0.05 + rand() * 3) : radius()}`;
    const x = coordOk();
    const y = coordOk();
    return rand() < 0.1 ? `s:${x},${y},${x},${y}` : `s:${x},${y},${coordOk()},${coordOk()}`;
  };
  const n = rand() < 0.03 ? 65 + Math.floor(rand() * 10) : Math.floor(rand() * 5);
  const items = Array.from({ length: n }, one);
  if (rand() < 0.1) items.push(pick(["x:1,2,3", "d:1,2", "s:1,2,3", "d:1,2,3,4", "", "d:,,"]));
  return items.join(pick([";", ";", ";", ",", "|"]));
}

function fragment() {
  if (rand() < 0.03) return "#" + Array.from({ length: 1 + Math.floor(rand() * 40) }, () => pick(["%", "&", "=", "#", "a", "1", "é", "%2", " "])).join("");
  const pairs = [];
  const n = 1 + Math.floor(rand() * 6);
  for (let i = 0; i < n; i++) {
    const r = rand();
    const key = r < 0.65 ? pick(NUM_KEYS) : r < 0.85 ? pick(OTHER_KEYS) : randomKey();
    const v = value(key);
    const enc = rand() < 0.9 ? encodeURIComponent(v) : v;
    pairs.push(`${rand() < 0.95 ? encodeURIComponent(key) : key}=${enc}`);
    if (rand() < 0.05) pairs.push(`${encodeURIComponent(key)}=${encodeURIComponent(value(key))}`);
  }
  return (rand() < 0.5 ? "#" : "") + pairs.join("&");
}

/** Builds the decoded state in the core; throws the core's error if refused. */
function coreAccepts(st) {
  let at = "clear";
  try {
    coreSteps(st, (s) => { at = s; });
  } catch (e) {
    // A panic poisons the Lab (every later call fails): start a new one.
    if (e instanceof WebAssembly.RuntimeError) lab = new core.Lab(tableBytes);
    throw new Error(`the core refused the decoded state at ${at}: ${e && e.message}`);
  }
}

function coreSteps(st, step) {
  lab.clear();
  step("setParams");
  lab.setParams({ ...defaults, ...st.limits });
  step("addAgent");
  const goal = { x: st.target.x, y: st.target.y, beta: st.target.theta, dTol: st.dTol, epsTol: st.epsTol, speed: st.speed, halting: st.halting, relaxed: st.relaxed };
  lab.addAgent({ x: st.vehicle.x, y: st.vehicle.y, theta: st.vehicle.theta, goals: [goal] });
  step("setFunnel");
  lab.setFunnel(page.funnelConfig(st.funnel));
  lab.setRelaxed(page.relaxedConfig(st.funnel));
  step("setAvoidance");
  if (st.avoidance !== null) lab.setAvoidance(st.avoidance);
  if (st.obstacles !== null) lab.setObstacles(new Float32Array(st.obstacles));
  step("checkRoom");
  lab.checkRoom(st.agents);
  assert.ok(Number.isInteger(st.agents) && Number.isInteger(st.seed) && st.seed >= 0 && st.seed <= 2 ** 32 - 1, `n=${st.agents} seed=${st.seed}`);
  step("spawnRandom");
  if (st.agents <= 20) lab.spawnRandom(st.agents, st.seed, Math.max(10, Math.sqrt(st.agents) * 1.5), st.speed);
  step("etaField");
  const field = lab.etaField(st.field.vC, st.field.omegaC, st.field.vD);
  assert.ok(field.every(Number.isFinite), "η field finite");
  step("step");
  lab.step(1);
  assert.ok(lab.state().every(Number.isFinite), "state finite after a step");
}

test(`${CASES} mutated fragments (seed ${SEED}): decoded without a throw, accepted by the core, refusals named, re-encoded cleanly`, () => {
  const t0 = performance.now();
  let refused = 0;
  let accepted = 0;
  let withObstacles = 0;
  let withAvoid = 0;
  const failures = [];
  for (let c = 0; c < CASES; c++) {
    const frag = fragment();
    try {
      const { state: st, problems } = page.decodeState(frag, PRESETS, table, defaults);
      refused += problems.length;
      assert.ok(problems.every((p) => typeof p === "string" && p.length > 0 && p.length < 400), "messages are short and non-empty");
      coreAccepts(st);
      accepted++;
      if (st.obstacles !== null && st.obstacles.length > 0) withObstacles++;
      if (st.avoidance !== null) withAvoid++;
      // Every numeric key whose (first) value was not taken is named in a message.
      const raw = frag.startsWith("#") ? frag.slice(1) : frag;
      let params = null;
      try { decodeURIComponent(raw); params = new URLSearchParams(raw); } catch { /* the whole link is refused, with a message */ }
      if (raw.trim() === "") assert.deepEqual(problems, [], "a blank fragment is the default state");
      else if (params === null) assert.ok(problems.length > 0, "bad encoding has a message");
      else {
        for (const f of page.FIELDS) {
          const t = params.get(f.url);
          if (t === null) continue;
          const v = page.parseDecimal(t, table.get(f.core).integer);
          const got = f.get(st, defaults) * f.scale;
          const taken = v !== null && Math.abs(got - v) <= 1e-9 * Math.max(1, Math.abs(v));
          if (!taken) assert.ok(problems.some((p) => p.startsWith(`${f.url}=`) || p.startsWith(`${f.url}:`)), `${f.url}="${t.slice(0, 30)}" not taken and not reported: ${JSON.stringify(problems)}`);
        }
        const avoid = params.get("avoid");
        if (avoid !== null && st.avoidance !== avoid) assert.ok(problems.some((p) => p.startsWith("avoid=")), `avoid="${avoid}" not taken and not reported`);
        if (params.get("obs") !== null && st.obstacles === null) assert.ok(problems.some((p) => p.startsWith("obs:")), "obs not taken and not reported");
        for (const k of params.keys()) {
          if (!NUM_KEYS.includes(k) && !OTHER_KEYS.includes(k)) assert.ok(problems.some((p) => p.includes("unknown field")), `unknown ${k.slice(0, 20)} not reported`);
        }
      }
      // What the page writes back decodes, silently, to the same state.
      const again = page.decodeState(page.encodeState(st, table, defaults), PRESETS, table, defaults);
      assert.deepEqual(again.problems, [], "the rewritten URL is clean");
      for (const f of page.FIELDS) {
        const a = f.get(st, defaults) * f.scale;
        const b = f.get(again.state, defaults) * f.scale;
        assert.ok(Math.abs(a - b) <= 1e-4 * Math.max(1, Math.abs(a)) + 1e-4, `${f.url}: ${a} → ${b}`);
      }
      assert.equal(again.state.avoidance, st.avoidance, "avoid round trip");
      assert.equal(again.state.obstacles === null, st.obstacles === null, "obs round trip");
      if (st.obstacles !== null) {
        assert.equal(again.state.obstacles.length, st.obstacles.length, "obs count round trip");
        st.obstacles.forEach((v, i) => assert.ok(Math.abs(v - again.state.obstacles[i]) <= 1e-4 * Math.max(1, Math.abs(v)), `obs[${i}]: ${v} → ${again.state.obstacles[i]}`));
      }
    } catch (e) {
      failures.push(`${JSON.stringify(frag.slice(0, 200))}: ${e && e.message ? e.message.slice(0, 300) : e}`);
    }
  }
  const ms = performance.now() - t0;
  console.log(`# urlfuzz: ${CASES} cases (seed ${SEED}), ${accepted} states built in the core (${withObstacles} with obstacles, ${withAvoid} with a method), ${refused} refused values reported, ${failures.length} failures, ${ms.toFixed(0)} ms`);
  assert.deepEqual(failures.slice(0, 10), []);
});
