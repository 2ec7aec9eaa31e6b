// Time to the first frame (`--loads N` fresh loads, 9 by default; with
// `--base DIR` alternating with a previous build's dist, median and p90,
// and where the time went). Then the frame-time harness: the built page with N extra funnelling agents
// (URL flag n=N, no trails or overlays) in headless Chromium. For each N,
// waits 0.5 s, then samples ~2 s with performance.now(): mean rAF interval,
// mean and p95 work per frame (core step + drawing) and core step time.
// Then the largest N again with each avoidance method of AVOID
// (default separation,orca; the second argument), beside the same run's
// avoidance-off figures. Then the lab's agents stepped per frame in workers
// and the crowd's boids per frame (`--help` lists the options).
import { serveBuilds, serveChild, launch, openPage, waitReady, artifacts, loadCrowd, BASE_OPTION, rotated } from "./harness.mjs";
import { options, whole, wholeList, wholeItems, choiceList, oneOf } from "./options.mjs";
import { resolve } from "node:path";
import { loadavg } from "node:os";

const MODES = ["0", "1", "N"];
const { values: opts, positionals } = options(
  `Frame times, first-frame loads, workers and crowd rows in headless Chromium.
Usage: node web/test/perf.mjs [SIZES [AVOID]] [options]   (after \`make web-build-test\`; \`make bench-web\`)
  SIZES  the lab's agent counts for the frame-time rows (default 1000,10000;
         "" runs the first-frame loads alone)
  AVOID  avoidance methods run at the largest size (default separation,orca)
Modes (--worker-modes, --crowd-modes): 0 the page's thread, 1 one worker,
N a worker per core (navigator.hardwareConcurrency).`,
  {
    // Served beside this one: the first-frame loads and the workers' and
    // crowd's rows alternate between the builds, in rotating order.
    ...BASE_OPTION,
    loads: { type: "string", default: "9", arg: "N", help: "fresh loads per build for the time to the first frame" },
    // A user's server does not share the browser driver's event loop: the
    // child-process server (test/serve.mjs) measures without that.
    server: { type: "string", default: "inproc", arg: "inproc|child|both", help: "first-frame loads served in this process, by a child process, or both alternating" },
    "only-workers": { type: "boolean", default: false, help: "the workers' rows alone" },
    "only-crowd": { type: "boolean", default: false, help: "the crowd's rows alone" },
    "worker-sizes": { type: "string", default: "10000,30000,100000", arg: "N,N…", help: "the lab's agent counts in the workers' rows" },
    "worker-rounds": { type: "string", default: "1", arg: "N", help: "rounds of the workers' rows" },
    "worker-modes": { type: "string", default: "0,1,N", arg: "M,M…", help: "the workers' rows' modes" },
    "crowd-sizes": { type: "string", default: "30000,100000,150000,200000", arg: "N,N…", help: "the crowd's boid counts (Test IV density)" },
    "crowd-rounds": { type: "string", default: "3", arg: "N", help: "rounds of the crowd's rows (medians)" },
    "crowd-modes": { type: "string", default: "0,1,N", arg: "M,M…", help: "the crowd's rows' modes" },
  },
  { positionals: 2 },
);
const baseDirs = opts.base;
const LOADS = whole(opts, "loads", 1);
const SERVER = oneOf(opts, "server", ["inproc", "child", "both"]);
// An empty size list ("") runs the first-frame loads alone.
const sizes = wholeItems(positionals[0] ?? "1000,10000", "SIZES");
const onlyFirst = sizes.length === 0;
const onlyWorkers = opts["only-workers"];
const onlyCrowd = opts["only-crowd"];
const workerSizes = wholeList(opts, "worker-sizes");
const workerRounds = whole(opts, "worker-rounds", 1);
const workerModes = choiceList(opts, "worker-modes", MODES);
const crowdSizes = wholeList(opts, "crowd-sizes");
const crowdRounds = whole(opts, "crowd-rounds", 1);
const crowdModes = choiceList(opts, "crowd-modes", MODES);
const { url, bases, builds, close } = await serveBuilds(baseDirs);
const children = [];
if (SERVER !== "inproc" && !onlyWorkers) {
  for (const d of [...baseDirs, ""]) children.push({ dir: d || "this", ...(await serveChild(d || undefined)) });
}
const browser = await launch();
let bad = 0;

/** One fresh load of `at`: the first frame, the table in force, and where
 *  the time went (resource timing, marks), ms after navigation start. */
async function startLoad(at) {
  const { page, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
  await page.goto(at);
  const err = await waitReady(page, 60000);
  if (err) throw new Error(err);
  const r = await page.evaluate(() => {
    const nav = performance.getEntriesByType("navigation")[0];
    const res = performance.getEntriesByType("resource");
    const pick = (re, f) => res.filter((e) => re.test(e.name)).map(f);
    const end = (re) => { const a = pick(re, (e) => e.responseEnd); return a.length ? Math.max(...a) : NaN; };
    const start = (re) => { const a = pick(re, (e) => e.startTime); return a.length ? Math.min(...a) : NaN; };
    const mark = (n) => performance.getEntriesByName(n)[0]?.startTime ?? NaN;
    const l = window.__lab;
    return {
      "html": nav.responseEnd,
      "first-frame script runs": mark("lab:firstscript"),
      "scripts in": end(/\.js(\?|$)/),
      "main module runs": mark("lab:main"),
      "DOMContentLoaded": nav.domContentLoadedEventStart,
      "wasm requested": start(/\.wasm(\?|$)/),
      "wasm in": end(/\.wasm(\?|$)/),
      "core instantiated": mark("lab:core"),
      "scene built (first rAF next)": mark("lab:scene"),
      "first-frame script's rAF": mark("lab:firstraf"),
      "first frame": l.firstFrameMs,
      "core's first frame (loop)": mark("lab:loop"),
      "first contentful paint": performance.getEntriesByName("first-contentful-paint")[0]?.startTime ?? NaN,
      "table in": end(/eta\.(bin|planes)/),
      "table loaded (clock runs)": Number.isFinite(l.tableMs) ? l.tableMs : mark("lab:table"),
    };
  });
  await context.close();
  return r;
}

try {
  if (!onlyWorkers && !onlyCrowd) {
  const inproc = [...bases.map((b) => [b.dir, b.url]), ["this", url]];
  const sides = [
    ...(SERVER === "child" ? [] : inproc),
    ...children.map((c) => [SERVER === "both" ? `${c.dir}, child server` : c.dir, c.url]),
  ];
  console.log(`first-frame loads: host load average ${loadavg().map((x) => x.toFixed(2)).join(" ")} (before)`);
  const rows = Object.fromEntries(sides.map(([n]) => [n, []]));
  for (let k = 0; k < LOADS; k++) for (let j = 0; j < sides.length; j++) { const [n, at] = sides[(j + k) % sides.length]; rows[n].push(await startLoad(at)); }
  const q = (a, p) => { const s = a.filter(Number.isFinite).sort((x, y) => x - y); return s.length ? s[Math.min(s.length - 1, Math.floor(p * s.length))] : NaN; };
  const f = (x) => (Number.isFinite(x) ? x.toFixed(0) : "—");
  for (const [n] of sides) {
    const firsts = rows[n].map((r) => r["first frame"]);
    console.log(
      `first drawn frame after navigation start (${n}): median ${f(q(firsts, 0.5))} ms, ` +
        `p90 ${f(q(firsts, 0.9))} ms (min ${f(q(firsts, 0))}, max ${f(q(firsts, 1))}) over ${firsts.length} loads`,
    );
  }
  console.log(`host load average ${loadavg().map((x) => x.toFixed(2)).join(" ")} (after)`);
  const keys = Object.keys(rows[sides[0][0]][0]);
  console.log(`start-up breakdown, medians (ms after navigation start): ${sides.map(([n]) => n).join(" / ")}`);
  for (const key of keys) console.log(`  ${key.padEnd(28)} ${sides.map(([n]) => f(q(rows[n].map((r) => r[key]), 0.5)).padStart(6)).join(" / ")}`);
  }

  // Above 2,000 agents also with the WebGL2 layer forced (?draw=gl:
  // headless WebGL is software, so the page's own choice is the 2D sprites).
  const runs = onlyWorkers || onlyFirst || onlyCrowd ? [] : sizes.flatMap((n) => (n > 2000 ? [[n, ""], [n, "gl"]] : [[n, ""]]));
  const avoids = onlyWorkers || onlyFirst || onlyCrowd ? [] : (positionals[1] ?? "separation,orca").split(",").filter((m) => m !== "");
  const largest = Math.max(...sizes);
  for (const m of avoids) runs.push([largest, "", m]);
  for (const [n, draw, avoid] of runs) {
    const { page, problems: all, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
    await page.goto(`${url.replace(/\/?$/, "/")}${draw ? `?draw=${draw}` : ""}#n=${n}&ov=${avoid ? `&avoid=${avoid}` : ""}`);
    const err = await waitReady(page, 60000);
    if (err) throw new Error(err);
    await page.waitForTimeout(500);
    await page.evaluate(() => window.__lab.perfReset());
    await page.waitForTimeout(2000);
    const s = await page.evaluate(() => window.__lab.perfStats());
    await page.screenshot({ path: resolve(artifacts, `perf-${n}${draw ? `-${draw}` : ""}${avoid ? `-${avoid}` : ""}.png`) });
    const how = await page.$eval("#lab", (c) => c.dataset.agents);
    console.log(
      `perf n=${s.agents - 1}+1 agents (${how}${avoid ? `, avoidance ${avoid}` : ""}): ${s.frames} frames in ~2 s, rAF interval ${s.meanIntervalMs.toFixed(2)} ms ` +
        `(${(1000 / s.meanIntervalMs).toFixed(1)} fps), work/frame mean ${s.meanWorkMs.toFixed(2)} ms p95 ${s.p95WorkMs.toFixed(2)} ms, ` +
        `core step/frame ${s.meanStepMs.toFixed(2)} ms, drawing/frame ${s.meanDrawMs.toFixed(2)} ms, ` +
        `core ${s.usPerUpdate.toFixed(2)} µs per agent update`,
    );
    const problems = all.filter((p) => !(draw === "gl" && /GPU stall due to ReadPixels/.test(p)));
    if (problems.length) { bad++; console.log(problems.join("\n")); }
    await context.close();
  }
  // Funnelling agents stepped per 16.7 ms frame with the
  // world on the page's thread (workers=0), in one worker and in as many as
  // the browser reports cores, same run, alternating by size; ratios to the
  // page's thread and to one worker. Agents stepped per frame = agent
  // updates finished / (sampled wall time / 16.7 ms); every frame draws the
  // last complete state (fps), "states" = frames that drew a new one.
  const wsizes = onlyFirst || onlyCrowd ? [] : workerSizes;
  const rounds = workerRounds;
  let cores = 0;
  const rows = new Map();
  const drawnRows = new Map();
  // With `--base DIR`: every row for each build, this one and the bases,
  // in rotating order (the crowd's rows too; `builds`).
  for (let round = 0; round < rounds; round++) {
    for (const n of wsizes) {
      // Alternating order by round, so a drift in the host's load does not favour one mode.
      for (const w of (round % 2 ? ["N", "1", "0"] : ["0", "1", "N"]).filter((m) => workerModes.includes(m))) {
      for (const [build, at] of rotated(builds, round)) {
        const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
        // "N": as many workers as navigator.hardwareConcurrency (read on the first load).
        const nq = `?workers=${w === "N" ? cores || 2 : w}`;
        await page.goto(`${at.replace(/\/?$/, "/")}${nq}#n=${n}&ov=`);
        const err = await waitReady(page, 120000);
        if (err) throw new Error(err);
        cores = await page.evaluate(() => navigator.hardwareConcurrency);
        await page.waitForFunction(() => !(window.__lab.workers()?.starting), null, { timeout: 120000 });
        await page.waitForTimeout(700);
        await page.evaluate(() => window.__lab.perfReset());
        await page.waitForTimeout(3000);
        const s = await page.evaluate(() => window.__lab.perfStats());
        const info = await page.evaluate(() => window.__lab.workers());
        const perFrame = s.updates / (s.spanMs / (1000 / 60));
        // As the crowd's rows count: the agents of the new states drawn
        // (frames that drew one; the world keeps real time, so a state
        // may hold several steps).
        const drawnPerFrame = (s.steppedFrames * (n + 1)) / (s.spanMs / (1000 / 60));
        const key = `${build}|${n}|${w}`;
        rows.set(key, [...(rows.get(key) ?? []), perFrame]);
        drawnRows.set(key, [...(drawnRows.get(key) ?? []), drawnPerFrame]);
        console.log(
          `workers ${builds.length > 1 ? `[${build}] ` : ""}n=${n} ${w === "N" ? `N=${cores}` : w} (${info ? `${info.mode}, ${info.workers} slices` : "page's thread"}): ` +
            `${Math.round(perFrame)} agents stepped per 16.7 ms (${Math.round(drawnPerFrame)} stepped + drawn), ${(1000 / s.meanIntervalMs).toFixed(1)} fps, ` +
            `${((s.steppedFrames * 1000) / s.spanMs).toFixed(1)} states drawn/s, page's work/frame mean ${s.meanWorkMs.toFixed(2)} ms p95 ${s.p95WorkMs.toFixed(2)} ms ` +
            `(per state drawn ${((s.meanWorkMs * s.frames) / Math.max(1, s.steppedFrames)).toFixed(2)} ms, of which drawing ${((s.meanDrawMs * s.frames) / Math.max(1, s.steppedFrames)).toFixed(2)}), ` +
            (info ? `slowest worker ${info.usPerUpdate.toFixed(3)} µs per agent update of the world, workers started in ${info.startMs.toFixed(0)} ms` : `core ${s.usPerUpdate.toFixed(3)} µs per agent update`),
        );
        if (problems.length) { bad++; console.log(problems.join("\n")); }
        await context.close();
      }
      }
    }
  }
  if (wsizes.length) console.log(`workers: navigator.hardwareConcurrency = ${cores}; agents stepped per 16.7 ms frame (median of ${rounds} round(s)), ratios in the same run:`);
  const med = (a = [NaN]) => [...a].sort((x, y) => x - y)[a.length >> 1];
  for (const [build] of builds) for (const n of wsizes) {
    const [m0, m1, mn] = ["0", "1", "N"].map((w) => med(rows.get(`${build}|${n}|${w}`)));
    const [d0, d1, dn] = ["0", "1", "N"].map((w) => med(drawnRows.get(`${build}|${n}|${w}`)));
    console.log(
      `workers summary ${builds.length > 1 ? `[${build}] ` : ""}n=${n}: page's thread ${Math.round(m0)}, 1 worker ${Math.round(m1)}, ${cores} workers ${Math.round(mn)}; ` +
        `${cores} workers / 1 worker ${(mn / m1).toFixed(2)}×, / page's thread ${(mn / m0).toFixed(2)}×; ` +
        `stepped + drawn (new states' agents): ${Math.round(d0)}, ${Math.round(d1)}, ${Math.round(dn)}`,
    );
  }

  // The crowd: boids stepped + drawn per 16.7 ms frame at
  // Test IV's density (Parker 10 %, separation, pathway scaled by n / 300:
  // `window.__crowd.loadScaled`), the crowd on the page's thread
  // (workers=0), in one worker and in as many as the browser reports cores,
  // same run, alternating order by round; medians of `--crowd-rounds` (3)
  // rounds. Per frame = boids of the states drawn (each a complete new
  // step of every boid) / (sampled wall time / 16.7 ms).
  const csizes = onlyWorkers || (onlyFirst && !onlyCrowd) ? [] : crowdSizes;
  const crounds = crowdRounds;
  // With `--base DIR`: every row for each build too, this one and the
  // bases in rotating order (the same-run baseline of a change; `builds`).
  const crows = new Map();
  if (csizes.length) console.log(`crowd: host load average ${loadavg().map((x) => x.toFixed(2)).join(" ")} (before)`);
  for (let round = 0; round < crounds; round++) {
    for (const n of csizes) {
      for (const w of (round % 2 ? ["N", "1", "0"] : ["0", "1", "N"]).filter((m) => crowdModes.includes(m))) {
      for (const [build, at] of rotated(builds, round)) {
        const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
        await loadCrowd(page, at, w === "N" ? cores || 2 : w, n);
        cores = await page.evaluate(() => navigator.hardwareConcurrency);
        await page.waitForTimeout(700);
        await page.evaluate(() => window.__crowd.perfReset());
        await page.waitForTimeout(3000);
        const s = await page.evaluate(() => window.__crowd.perfStats());
        const info = await page.evaluate(() => window.__crowd.workers());
        const frame = s.spanMs / (1000 / 60);
        const drawn = (s.drawnFrames * n) / frame;
        const key = `${build}|${n}|${w}`;
        crows.set(key, [...(crows.get(key) ?? []), drawn]);
        const how = await page.$eval("#crowd", (c) => c.dataset.agents);
        console.log(
          `crowd ${builds.length > 1 ? `[${build}] ` : ""}n=${n} ${w === "N" ? `N=${cores}` : w} (${info.mode === "main" ? "page's thread" : `${info.mode}, ${info.workers} workers`}, drawn as ${how}): ` +
            `${Math.round(drawn)} boids stepped + drawn per 16.7 ms (${Math.round(s.updates / frame)} stepped), ${(1000 / s.meanIntervalMs).toFixed(1)} fps, ` +
            `${((s.drawnFrames * 1000) / s.spanMs).toFixed(1)} states drawn/s (${s.skippedSteps ?? "—"} steps passed undrawn), page's work/frame mean ${s.meanWorkMs.toFixed(2)} ms p95 ${s.p95WorkMs.toFixed(2)} ms`,
        );
        if (round === 0 && w === "N" && build === "this") await page.screenshot({ path: resolve(artifacts, `perf-crowd-${n}.png`) });
        if (problems.length) { bad++; console.log(problems.join("\n")); }
        await context.close();
      }
      }
    }
  }
  if (csizes.length) console.log(`crowd: host load average ${loadavg().map((x) => x.toFixed(2)).join(" ")} (after); navigator.hardwareConcurrency = ${cores}; boids stepped + drawn per 16.7 ms frame, median of ${crounds} round(s):`);
  for (const [build] of builds) {
    for (const n of csizes) {
      const [m0, m1, mn] = ["0", "1", "N"].map((w) => med(crows.get(`${build}|${n}|${w}`)));
      const runs = ["0", "1", "N"].map((w) => crows.get(`${build}|${n}|${w}`) ?? []);
      const range = (a) => (a.length > 1 ? ` (${Math.round(Math.min(...a))}–${Math.round(Math.max(...a))})` : "");
      console.log(
        `crowd summary ${builds.length > 1 ? `[${build}] ` : ""}n=${n}: page's thread ${Math.round(m0)}${range(runs[0])}, 1 worker ${Math.round(m1)}${range(runs[1])}, ` +
          `${cores} workers ${Math.round(mn)}${range(runs[2])}; ${cores} workers / page's thread ${(mn / m0).toFixed(2)}×`,
      );
    }
  }
} finally {
  await browser.close();
  await close();
  for (const c of children) await c.server.close();
}
process.exit(bad ? 1 : 0);
