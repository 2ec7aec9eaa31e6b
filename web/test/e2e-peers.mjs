// Side by side with the peers, in headless Chromium, one page run: the
// test build's peers harness (peers.html, src/peers/) runs our wasm core,
// Yuka 0.7.8 (Vehicle + ArriveBehavior, and SeekBehavior) and DetourCrowd
// (@recast-navigation/core 0.43.1) on the same seeded oriented targets and
// the pedestrian's limits, and the circle swaps for the crowd rows; this
// script prints the rows and writes them as figures records
// (records.mjs) for the report's Peers section:
//   web/test/e2e-peers.mjs::peers_web_oriented  (deterministic)
//   web/test/e2e-peers.mjs::peers_web_swap      (deterministic)
//   web/test/e2e-peers.mjs::peers_web_cost      (timed: --full only)
// Figure ids: peers.web.<scenario>.<metric>.<side>, side one of ours,
// yuka-arrive, yuka-seek, detour; the timed rows' sides ours, yuka, detour
// (same page, alternating rounds), <peer>-over-ours (their ratios) and
// ours-workers (the lab page stepped by its Web Workers: another page
// and run, said apart). Then the lab's compare view (index.html#cmp=1): both arrival
// headings read through window.__lab, ours within ε_tol of β, Yuka's
// reported; the switch works from the keyboard; screenshots at 1440×900
// and 390×844 in artifacts/. A node:test suite (harness.mjs `check`).
// The deterministic records must equal the committed ones (docs/figures/,
// which the report's Peers section renders) figure for figure, unless
// `--record` (`make figures`: measuring them anew). The timed record goes
// to target/figures-full (`make figures-full`).
// Run: `make test-e2e-peers` (PEERS_ARGS="--full" for the timed rows).
import assert from "node:assert/strict";
import { serve, launch, openPage, check, waitReady, settle, shot } from "./harness.mjs";
import { options, whole, wholeList } from "./options.mjs";
import { figure, writeRecord, committedFigures } from "./records.mjs";

const { values } = options(
  "Usage: node web/test/suite.mjs web/test/e2e-peers.mjs [options]\nOur core, Yuka and DetourCrowd on the same cases in Chromium; figures records into $FIGURES_DIR (default target/figures).",
  {
    full: { type: "boolean", default: false, help: "also the timed rows: cost per agent update at --sizes" },
    record: { type: "boolean", default: false, help: "write the deterministic records without comparing them with the committed ones (make figures)" },
    seed: { type: "string", default: "2", arg: "S", help: "seed of the oriented targets (report seed; nothing here is tuned)" },
    cases: { type: "string", default: "100", arg: "N", help: "oriented targets" },
    sizes: { type: "string", default: "1000,10000,100000", arg: "N,N,...", help: "agent counts of the timed rows" },
    rounds: { type: "string", default: "3", arg: "R", help: "alternating rounds per size (timed rows)" },
    "round-ms": { type: "string", default: "400", arg: "MS", help: "wall ms per side per round (timed rows)" },
    // Building 100,000 DetourCrowd agents took 25 s and its first update
    // had not ended after 4 minutes (Node, this machine): not a row.
    "detour-max": { type: "string", default: "30000", arg: "N", help: "DetourCrowd's timed rows up to N agents" },
  },
);
const seed = whole(values, "seed");
const nCases = whole(values, "cases", 1);
const SOURCE = "web/test/e2e-peers.mjs";
const COMMAND = `make test-e2e-peers PEERS_ARGS="--seed ${seed} --cases ${nCases}"`;
/** The rows just measured equal the committed record's (the report's
 *  Peers section), at the digits the report prints, unless `--record`. */
function asCommitted(source, figures) {
  if (values.record) return;
  const shown = (f) => [f.id, Number(f.value).toFixed(f.digits)];
  const committed = committedFigures(source);
  assert.ok(committed, `${source}: no committed record in docs/figures/ (make figures writes it)`);
  assert.deepEqual(figures.filter((f) => Number.isFinite(f.value)).map(shown), committed.map(shown), `${source}: the rows differ from the committed record (make figures measures them anew)`);
}
const SIDES = { ours: "ours", yukaArrive: "yuka-arrive", yukaSeek: "yuka-seek", detour: "detour" };

/** The oriented rows: [metric id, what, summary key, unit, digits]. */
const ORIENTED = [
  ["rest", "runs at rest (≤ 0.01 m/s) inside D_tol over the last ≥ 1 s of 40 s", "restPct", "%", 0],
  ["oriented", "runs at rest inside D_tol standing within ε_tol of β", "orientedPct", "%", 0],
  ["rest_heading_p50", "heading error |θ − β| standing at rest at the end, median", "restHeadingP50", "°", 1],
  ["rest_heading_p95", "heading error |θ − β| standing at rest at the end, p95", "restHeadingP95", "°", 1],
  ["entry_heading_p50", "heading error at the first entry into D_tol, median", "entryHeadingP50", "°", 1],
  ["length_ratio_p50", "path length (to the final rest, else to the first entry into D_tol) over the Dubins shortest at v_d's turning radius, median", "lengthRatioP50", "×", 2],
  ["speed_violation_runs", "runs with a step above v_max", "speedViolationRuns", "runs", 0],
  ["turn_violation_runs", "runs with a step turning faster than ω_max", "turnViolationRuns", "runs", 0],
  ["max_turn_rate", "largest heading rate of any run", "maxTurnRate", "rad/s", 1],
  ["arrive_time_p50", "seconds until the final rest began, median", "arriveTimeP50", "s", 1],
];
const SWAP = [
  ["worst_overlaps", "most body pairs overlapping (closer than 2 r) after one step", "worstOverlaps", "pairs", 0],
  ["overlap_steps", "steps with any overlapping pair", "overlapSteps", "steps", 0],
  ["arrived", "agents at rest inside D_tol over the last ≥ 1 s", "arrived", "agents", 0],
  ["all_arrived_time", "seconds until the last agent came to rest inside D_tol for good", "allArrivedTime", "s", 1],
  ["rest_heading_p50", "heading error standing at rest at the end, median", "restHeadingP50", "°", 1],
];

/** Which way a metric is better ("higher" / "lower"), and why a peer
 *  ahead of ours on it is: the report says so on the peer's row. */
const AHEAD = {
  rest: ["higher", "a holonomic point (Yuka) or disc (Detour) stops anywhere in the disk, with no heading to reach"],
  length_ratio_p50: ["lower", "another model: it turns on the spot and ignores the start and end headings, so its straight path is shorter than any oriented one"],
  arrive_time_p50: ["lower", "less work: no heading to reach, so it drives straight in and stops"],
  arrived: ["higher", "another model: discs with no heading to reach stop wherever they are let through; two of ours stand just outside D_tol, held off by their neighbours"],
  all_arrived_time: ["lower", "less work: discs with no heading to reach drive straight through"],
};

/** `what` with, on a peer's row that is ahead of ours, the report's note why. */
function aheadNote(metric, what, value, ours, side) {
  const a = AHEAD[metric];
  if (side === "ours" || !a || !Number.isFinite(value)) return what;
  // Ours without a value (not every agent arrived): the peer's is ahead.
  const ahead = !Number.isFinite(ours) || (a[0] === "higher" ? value > ours : value < ours);
  return ahead ? `${what}; the peer is ahead of ours here: ${a[1]}` : what;
}

/** One side's settings in words, for a figure's `what`. */
function sideWords(side, s) {
  const v = s.vehicle;
  return {
    ours: `ours: funnelling (standard, the core's defaults), v_d = ${s.goal.speed} m/s, halting`,
    yukaArrive: `${s.yuka} Vehicle + ArriveBehavior (deceleration 3, tolerance 0: defaults), maxSpeed ${v.vMax}, maxTurnRate ${v.omegaMax}, maxForce ${v.accelMax} (mass 1)`,
    yukaSeek: `${s.yuka} Vehicle + SeekBehavior, maxSpeed ${v.vMax}, maxTurnRate ${v.omegaMax}, maxForce ${v.accelMax} (mass 1)`,
    detour: `${s.detour}, radius ${s.detourAgent.radius}, maxSpeed ${s.detourAgent.maxSpeed}, maxAcceleration ${s.detourAgent.maxAcceleration}, flat navmesh, other parameters Detour's defaults`,
  }[side];
}

const table = (title, rows, cols) => {
  console.log(`\n# ${title}`);
  console.log(`# ${"metric".padEnd(22)}${cols.map((c) => c.padStart(13)).join("")}`);
  for (const [name, vals] of rows) console.log(`# ${name.padEnd(22)}${vals.map((v) => (Number.isFinite(v) ? (Math.abs(v) >= 100 ? v.toFixed(0) : v.toFixed(2)) : "—").padStart(13)).join("")}`);
};

/** Ours stepped by the lab's Web Workers at `n` agents (as web/test/perf.mjs
 *  measures its workers' rows): the slowest worker's µs per agent update
 *  and the agents stepped per 16.7 ms frame over 3 s. */
async function labWorkers(n) {
  const { page, context } = await openPage(browser, { width: 1280, height: 800 });
  try {
    await page.goto(`${base}?workers=${await page.evaluate(() => navigator.hardwareConcurrency) || 2}#n=${n}&ov=`);
    const err = await waitReady(page, 120_000);
    if (err) throw new Error(err);
    await page.waitForFunction(() => !(window.__lab.workers()?.starting), null, { timeout: 120_000 });
    await page.waitForTimeout(700);
    await page.evaluate(() => window.__lab.perfReset());
    await page.waitForTimeout(3000);
    const s = await page.evaluate(() => window.__lab.perfStats());
    const info = await page.evaluate(() => window.__lab.workers());
    return { workers: info?.workers ?? 0, mode: info?.mode ?? "main", usPerUpdate: info?.usPerUpdate ?? s.usPerUpdate, perFrame: s.updates / (s.spanMs / (1000 / 60)) };
  } finally {
    await context.close();
  }
}

const { server, url } = await serve();
const browser = await launch();
const base = url.replace(/\/?$/, "/");
try {
  const { page, problems } = await openPage(browser, { width: 800, height: 600 });
  page.setDefaultTimeout(600_000);
  await page.goto(`${base}peers.html`);
  await page.waitForFunction(() => window.__peers && (window.__peers.ready || window.__peers.error), null, { timeout: 120_000 });
  const settings = await page.evaluate(() => window.__peers.settings?.() ?? null);

  await check("the peers harness loads our core, Yuka and DetourCrowd", async () => {
    assert.equal(await page.evaluate(() => window.__peers.error), null);
    assert.ok(settings, "the harness gives its settings");
  });

  await check(`oriented targets (${nCases}, seed ${seed}): ours arrives oriented within the limits; the peers' rows recorded`, async () => {
    const r = await page.evaluate(([s, n]) => window.__peers.oriented(s, n), [seed, nCases]);
    const keys = Object.keys(SIDES);
    table(`oriented targets: ${nCases} seeded cases (seed ${seed}), pedestrian, D_tol ${settings.goal.dTol} m, ε_tol ${(settings.goal.epsTol * 180 / Math.PI).toFixed(0)}°`, ORIENTED.map(([id, , k]) => [id, keys.map((s) => r[s][k])]), keys.map((k) => SIDES[k]));
    const figures = ORIENTED.flatMap(([id, what, k, unit, digits]) =>
      keys.map((s) => figure(`peers.web.oriented.${id}.${SIDES[s]}`, aheadNote(id, `${what}; ${nCases} seeded oriented targets 3–10 m away (seed ${seed}), pedestrian limits; ${sideWords(s, settings)}`, r[s][k], r.ours[k], s), r[s][k], unit, digits)));
    console.log(`# record: ${writeRecord({ source: `${SOURCE}::peers_web_oriented`, command: COMMAND, kind: "deterministic", seeds: { tuning: [], report: [seed] }, figures })}`);
    asCommitted(`${SOURCE}::peers_web_oriented`, figures);
    assert.ok(r.ours.orientedPct >= 90, `ours arrives oriented in ${r.ours.orientedPct}% of the runs`);
    assert.equal(r.ours.speedViolationRuns, 0, "ours never exceeds v_max");
    assert.equal(r.ours.turnViolationRuns, 0, "ours never turns faster than ω_max");
  });

  await check("circle swaps (8, 32): ours with ORCA overlaps nowhere; the rows of both recorded", async () => {
    const figures = [];
    for (const name of ["avoid_circle8", "avoid_circle32"]) {
      const r = await page.evaluate((n) => window.__peers.swap(n), name);
      table(`${name}: ours (ORCA, the scenario's settings) and DetourCrowd`, SWAP.map(([id, , k]) => [id, [r.ours[k], r.detour[k]]]), ["ours", "detour"]);
      for (const s of ["ours", "detour"]) for (const u of r[s].unsettled) console.log(`# ${name} ${s}: agent ${u.i} not at rest at the end: ${u.d.toFixed(3)} m from its goal at ${u.v.toFixed(4)} m/s`);
      for (const [id, what, k, unit, digits] of SWAP) {
        figures.push(figure(`peers.web.${name}.${id}.ours`, `${what}; ${name} (scenarios/${name}.json), ${r.ours.agents} agents; ours: funnelling + ORCA, the scenario's settings`, r.ours[k], unit, digits));
        figures.push(figure(`peers.web.${name}.${id}.detour`, aheadNote(id, `${what}; ${name}, ${r.detour.agents} agents; ${settings.detour}, the scenario's radius, maxSpeed = the goal's speed, maxAcceleration ${settings.vehicle.accelMax}, other parameters Detour's defaults`, r.detour[k], r.ours[k], "detour"), r.detour[k], unit, digits));
      }
      assert.equal(r.ours.worstOverlaps, 0, `${name}: ours overlapped`);
    }
    console.log(`# record: ${writeRecord({ source: `${SOURCE}::peers_web_swap`, command: COMMAND, kind: "deterministic", figures })}`);
    asCommitted(`${SOURCE}::peers_web_swap`, figures);
  });

  if (values.full) {
    await check("cost per agent update, same run: ours (one thread), Yuka, DetourCrowd", async () => {
      const rounds = whole(values, "rounds", 1);
      const roundMs = whole(values, "round-ms", 1);
      const figures = [];
      for (const n of wholeList(values, "sizes")) {
        const c = await page.evaluate(([n, r, ms, s, dm]) => window.__peers.costs(n, r, ms, s, dm), [n, rounds, roundMs, seed, whole(values, "detour-max", 0)]);
        table(`${n} agents: µs per agent update and agents stepped per 16.7 ms frame (median of ${rounds} alternating rounds)`, [["us_per_update", ["ours", "yuka", "detour"].map((s) => c[s].usPerUpdate)], ["per_frame", ["ours", "yuka", "detour"].map((s) => c[s].perFrame)]], ["ours", "yuka", "detour"]);
        for (const [s, name] of [["ours", "ours (funnelling, Lab.spawnRandom, one thread)"], ["yuka", `${settings.yuka} arrive`], ["detour", `${settings.detour}, default flags`]]) {
          if (c[s].error) {
            console.log(`# ${s} at ${n}: ${c[s].error}`);
            continue;
          }
          figures.push(figure(`peers.web.cost.n${n}.us_per_update.${s}`, `µs per agent update, ${n} agents to random targets, ${name}`, c[s].usPerUpdate, "µs", 3));
          figures.push(figure(`peers.web.cost.n${n}.per_frame.${s}`, `agents stepped per 16.7 ms frame, ${n} agents, ${name}`, c[s].perFrame, "agents", 0));
          if (s !== "ours") figures.push(figure(`peers.web.cost.n${n}.${s}-over-ours`, `${name}'s cost per agent update over ours, same run, ${n} agents; ${s === "yuka" ? "below 1, the peer is ahead: less work, one steering force and one Euler step an agent, no η lookup, no heading to reach" : "above 1, ours is ahead: the peer's crowd step plans a corridor on the navmesh and avoids locally for every agent"}`, c[s].usPerUpdate / c.ours.usPerUpdate, "×", 2));
        }
      }
      // Ours with the lab's workers, said apart: the lab page itself
      // (`?workers=N`, N = the browser's cores; its real-time loop, at
      // most 4 steps a frame), not this page's same-run rounds.
      for (const n of wholeList(values, "sizes")) {
        const w = await labWorkers(n);
        console.log(`# ours in the lab with ${w.workers} workers (${w.mode}), ${n} agents: slowest worker ${w.usPerUpdate.toFixed(3)} µs per agent update of the world; ${Math.round(w.perFrame)} agents stepped per 16.7 ms frame (the loop's real time)`);
        figures.push(figure(`peers.web.cost.n${n}.us_per_update.ours-workers`, `µs per agent update, ${n} agents, ours in the lab page with ${w.workers} Web Workers (${w.mode}; the slowest worker's stepping time over the world's updates); another page and run than the rows beside it`, w.usPerUpdate, "µs", 3));
        figures.push(figure(`peers.web.cost.n${n}.per_frame.ours-workers`, `agents stepped per 16.7 ms frame, ${n} agents, ours in the lab page with ${w.workers} Web Workers (its real-time loop: at most 4 steps a frame); another page and run than the rows beside it`, w.perFrame, "agents", 0));
      }
      console.log(`# record: ${writeRecord({ source: `${SOURCE}::peers_web_cost`, command: `${COMMAND.replace(/"$/, "")} --full"`, kind: "timed", figures })}`);
    });
  }
  assert.deepEqual(problems, [], "no console error on the harness page");
  await page.context().close();

  await check("the lab's compare view: both arrival headings; ours within ε_tol of β, Yuka's reported", async () => {
    const { page, problems } = await openPage(browser, { width: 1440, height: 900 });
    await page.goto(`${base}index.html#cmp=1`);
    assert.equal(await waitReady(page, 60_000), null);
    await page.waitForFunction(() => (window.__lab.peerGhosts()?.ghosts.length ?? 0) === 3, null, { timeout: 30_000 });
    const { ghosts } = await page.evaluate(() => window.__lab.peerGhosts());
    const st = await page.evaluate(() => window.__lab.state());
    const deg = (a) => (a * 180) / Math.PI;
    for (const g of ghosts) console.log(`# compare view: ${g.side}: ${g.arrived ? "at rest" : "no rest"}, ${g.mark ? `${deg(g.mark.headingErr).toFixed(1)}° off β` : "never inside D_tol"} (${g.time.toFixed(1)} s)`);
    const [ours, arrive, seek] = ghosts;
    assert.equal(ours.side, "ours");
    assert.ok(ours.arrived && ours.mark.headingErr <= st.epsTol, `ours ends ${deg(ours.mark?.headingErr ?? NaN)}° off β (ε_tol ${deg(st.epsTol)}°)`);
    assert.ok(arrive.mark && seek.mark, "both Yuka ghosts reach D_tol");
    assert.match(await page.locator("#compare-readout").textContent(), /Yuka 0\.7\.8 arrive: at rest in [\d.]+ s, [\d.]+° off β/);
    await shot(page, "peers-compare-1440");
    // The switch from the keyboard: off (the link drops cmp), on again.
    await page.locator("#compare").focus();
    await page.keyboard.press("Space");
    await settle(page);
    await page.waitForFunction(() => !location.hash.includes("cmp=1"), null, { timeout: 5000 });
    assert.equal((await page.evaluate(() => window.__lab.peerGhosts())).ghosts.length, 0);
    await page.keyboard.press("Space");
    await page.waitForFunction(() => location.hash.includes("cmp=1") && window.__lab.peerGhosts().ghosts.length === 3, null, { timeout: 5000 });
    await page.setViewportSize({ width: 390, height: 844 });
    await settle(page);
    await shot(page, "peers-compare-390");
    assert.deepEqual(problems, []);
  });
} finally {
  await browser.close();
  await server.close();
}
