// Where the CPU goes per drawn state, and what the ≥ 100,000
// agents (boids) per 16.7 ms frame target would take on this machine.
//
// The frame counts of `perf.mjs` say how far a page is from the target;
// they do not say why. This samples every thread of the browser it launched
// (Linux /proc: user + system ticks per thread, over SAMPLE_MS) while a page
// steps in `--workers` workers (default one per core), and divides by the
// states drawn meanwhile:
// - per drawn state, the CPU ms of the stepping workers, of the page's
//   thread (drawing, Chromium's frame), and of every other thread (the
//   compositor, the GPU process's display compositor, I/O);
// - how busy the machine was (% of one core, of 100 × cores) and so how much
//   it idled (the workers waiting: for each other at the crowd's barrier, or
//   for the page);
// - the CPU that 100,000 per frame needs at those per-state costs: states
//   per second × ms per state, against 100 × cores %. Above it, the target
//   needs cheaper states (the core's update, the drawing), not better
//   scheduling; below it, the idle time is the lever.
// The lab at `--lab-sizes` agents (default 100,000, the page's maximum: 60
// states a second), the crowd at `--crowd-sizes` boids (Test IV density;
// 150,000: 40 a second), `--rounds` rounds each (default 2), one line per
// round. `--base DIR` (repeatable): a previous build's dist measured in the
// same run, the builds in rotating order each round; the summary then gives
// each build's medians and, per base, the paired ratios of this build's
// rounds to the base's (agents per frame, CPU per drawn state, the page's
// thread). `--help` lists the options.
import { existsSync, readdirSync, readFileSync } from "node:fs";
import { cpus, loadavg } from "node:os";
import { serveBuilds, launch, openPage, waitReady, loadCrowd, BASE_OPTION, rotated } from "./harness.mjs";
import { options, whole, wholeList } from "./options.mjs";

const { values } = options(
  `CPU per drawn state per thread group (workers, page, other) in headless Chromium.
Usage: node web/test/budget.mjs [options]   (after \`make web-build-test\`; \`make bench-budget\`)`,
  {
    "lab-sizes": { type: "string", default: "100000", arg: "N,N…", help: "the lab's agent counts (empty: no lab rows)" },
    "crowd-sizes": { type: "string", default: "150000,200000", arg: "N,N…", help: "the crowd's boid counts, Test IV density (empty: no crowd rows)" },
    rounds: { type: "string", default: "2", arg: "N", help: "rounds of every size and build" },
    workers: { type: "string", default: String(cpus().length), arg: "N", help: "workers stepping each page (a worker per core)" },
    dist: { type: "string", arg: "DIR", help: "serve this build from DIR instead of web/dist-test" },
    ...BASE_OPTION,
  },
);

if (!existsSync("/proc/self/task")) {
  console.error("budget.mjs: needs Linux's /proc (per-thread CPU time)");
  process.exit(1);
}
const SAMPLE_MS = 4000;
const TARGET = 100_000;
const labSizes = wholeList(values, "lab-sizes");
const crowdSizes = wholeList(values, "crowd-sizes");
const rounds = whole(values, "rounds", 1);
const workers = whole(values, "workers", 0);
const TICK_MS = 1000 / 100; // USER_HZ: Linux reports ticks of 10 ms

/** The browser's processes: `root` and its descendants (by parent pid). */
function tree(root) {
  const parent = new Map();
  for (const d of readdirSync("/proc")) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const st = readFileSync(`/proc/${d}/stat`, "utf8");
      parent.set(Number(d), Number(st.slice(st.lastIndexOf(")") + 2).split(" ")[1]));
    } catch {
      // The process ended meanwhile.
    }
  }
  const mine = new Set([root]);
  for (let grew = true; grew; ) {
    grew = false;
    for (const [pid, pp] of parent) if (!mine.has(pid) && mine.has(pp)) (mine.add(pid), (grew = true));
  }
  return mine;
}

/** CPU ticks per thread of the browser, keyed by pid/tid, with its group:
 *  the workers, the renderer's main thread (the page), the rest. */
function sample(root) {
  const out = new Map();
  for (const pid of tree(root)) {
    let cmd = "";
    try {
      cmd = readFileSync(`/proc/${pid}/cmdline`, "utf8");
    } catch {
      continue;
    }
    if (!/chrom/i.test(cmd.split("\0")[0] ?? "")) continue;
    const renderer = cmd.includes("--type=renderer");
    let tasks = [];
    try {
      tasks = readdirSync(`/proc/${pid}/task`);
    } catch {
      continue;
    }
    for (const t of tasks) {
      try {
        const st = readFileSync(`/proc/${pid}/task/${t}/stat`, "utf8");
        const name = st.slice(st.indexOf("(") + 1, st.lastIndexOf(")"));
        const f = st.slice(st.lastIndexOf(")") + 2).split(" ");
        const group = name.startsWith("DedicatedWorker") ? "workers" : renderer && String(t) === String(pid) ? "page" : "other";
        out.set(`${pid}/${t}`, { group, ticks: Number(f[11]) + Number(f[12]) });
      } catch {
        // The thread ended meanwhile.
      }
    }
  }
  return out;
}

const { builds, close } = await serveBuilds(values.base, values.dist);
const browser = await launch();
// Playwright starts the browser as this process's child: its processes are
// our descendants whose command line names Chromium.
const root = process.pid;
const rows = [];

async function measure(what, n, build, at, round) {
  const base = at.replace(/\/?$/, "/");
  const { page, context, problems } = await openPage(browser, { width: 1280, height: 800 }, 1);
  const hook = what === "lab" ? "__lab" : "__crowd";
  let cores = 0;
  try {
    if (what === "lab") {
      await page.goto(`${base}?workers=${workers}#n=${n}&ov=`);
      const err = await waitReady(page, 120000);
      if (err) throw new Error(err);
    } else {
      await loadCrowd(page, base, workers, n);
    }
    cores = await page.evaluate(() => navigator.hardwareConcurrency);
    await page.waitForFunction((h) => !window[h].workers()?.starting, hook, { timeout: 120000 });
    await page.waitForTimeout(1000);
    const a = sample(root);
    const t0 = performance.now();
    await page.evaluate((h) => window[h].perfReset(), hook);
    await page.waitForTimeout(SAMPLE_MS);
    const b = sample(root);
    const secs = (performance.now() - t0) / 1000;
    const s = await page.evaluate((h) => window[h].perfStats(), hook);
    const info = await page.evaluate((h) => window[h].workers(), hook);
    // The lab counts a drawn state as a stepped frame; the crowd as a drawn frame.
    const states = (what === "lab" ? s.steppedFrames : s.drawnFrames) / (s.spanMs / 1000);
    const pct = { workers: 0, page: 0, other: 0 };
    for (const [id, v] of b) pct[v.group] += ((v.ticks - (a.get(id)?.ticks ?? 0)) * TICK_MS) / (10 * secs);
    const busy = pct.workers + pct.page + pct.other;
    // The groups come from thread names: fail loudly if they stop matching.
    if (info?.workers > 0 && !(pct.workers > 1)) throw new Error(`${what} n=${n}: ${info.workers} workers, but no CPU in threads named DedicatedWorker (/proc)`);
    if (!(pct.page > 1)) throw new Error(`${what} n=${n}: no CPU in the renderer's main thread (/proc)`);
    if (!(states > 0)) throw new Error(`${what} n=${n}: no state drawn in ${SAMPLE_MS} ms`);
    const per = (p) => (p * 10) / states; // ms of CPU per drawn state
    const need = (TARGET * 60) / n; // states a second for 100,000 per frame
    const row = { build, round, what, n, states, perFrame: (states * n) / 60, pct, busy, ms: per(busy), pageMs: per(pct.page), need, needPct: (busy / states) * need, cores, mode: info?.mode, workers: info?.workers };
    rows.push(row);
    console.log(
      `${what}${builds.length > 1 ? ` [${build}]` : ""} n=${n} (${row.mode}, ${row.workers} workers, hardwareConcurrency ${cores}): ${states.toFixed(1)} states drawn/s = ${Math.round(row.perFrame)} per 16.7 ms frame; ` +
        `busy ${busy.toFixed(0)} % of ${100 * cores} (workers ${pct.workers.toFixed(0)}, page ${pct.page.toFixed(0)}, other ${pct.other.toFixed(0)}); ` +
        `CPU ms per drawn state: workers ${per(pct.workers).toFixed(2)}, page ${per(pct.page).toFixed(2)}, other ${per(pct.other).toFixed(2)}, all ${row.ms.toFixed(2)}; ` +
        `${TARGET.toLocaleString("en")} per frame needs ${need.toFixed(1)} states/s = ${row.needPct.toFixed(0)} % of ${100 * cores}; ` +
        `host load ${loadavg()[0].toFixed(2)} (1-min average, other processes included)`,
    );
    if (problems.length) throw new Error(problems.join("\n"));
  } finally {
    await context.close();
  }
}

try {
  for (let r = 0; r < rounds; r++) {
    for (const n of labSizes) for (const [b, at] of rotated(builds, r)) await measure("lab", n, b, at, r);
    for (const n of crowdSizes) for (const [b, at] of rotated(builds, r)) await measure("crowd", n, b, at, r);
  }
  const med = (xs) => {
    const a = [...xs].sort((x, y) => x - y);
    return (a[(a.length - 1) >> 1] + a[a.length >> 1]) / 2;
  };
  console.log(`budget summary (medians of ${rounds} round(s); CPU as % of one core):`);
  for (const [what, sizes] of [["lab", labSizes], ["crowd", crowdSizes]]) {
    for (const n of sizes) {
      for (const [build] of builds) {
        const rs = rows.filter((x) => x.what === what && x.n === n && x.build === build);
        if (!rs.length) continue;
        const cap = 100 * rs[0].cores;
        const need = med(rs.map((x) => x.needPct));
        console.log(
          `budget ${what}${builds.length > 1 ? ` [${build}]` : ""} n=${n}: ${Math.round(med(rs.map((x) => x.perFrame)))} per frame, ${med(rs.map((x) => x.ms)).toFixed(2)} CPU ms per drawn state (page's thread ${med(rs.map((x) => x.pageMs)).toFixed(2)}), busy ${med(rs.map((x) => x.busy)).toFixed(0)} % of ${cap}; ` +
            (n < TARGET
              ? `below ${TARGET.toLocaleString("en")} the world (at most a state per 60 Hz frame) cannot give ${TARGET.toLocaleString("en")} per frame`
              : `${TARGET.toLocaleString("en")} per frame needs ${need.toFixed(0)} % of ${cap}: ${need > cap ? "more than the machine has (cheaper states needed)" : "within the machine (the idle time is the lever)"}`),
        );
      }
      // This build against each base, round by round (the same minutes).
      for (const [build] of builds.slice(1)) {
        const pairs = [];
        for (let r = 0; r < rounds; r++) {
          const at = (b) => rows.find((x) => x.what === what && x.n === n && x.build === b && x.round === r);
          const [a, b] = [at("this"), at(build)];
          if (a && b) pairs.push({ frame: a.perFrame / b.perFrame, cpu: a.ms / b.ms, page: a.pageMs - b.pageMs });
        }
        if (!pairs.length) continue;
        // Ahead or behind by more than half a per cent (a state in 200).
        const ahead = pairs.filter((p) => p.frame > 1.005).length;
        const behind = pairs.filter((p) => p.frame < 0.995).length;
        console.log(
          `budget ${what} n=${n} this / [${build}], ${pairs.length} paired round(s), medians: per frame ${med(pairs.map((p) => p.frame)).toFixed(3)}× (this ahead in ${ahead}, behind in ${behind}), ` +
            `CPU per drawn state ${med(pairs.map((p) => p.cpu)).toFixed(3)}×, page's thread ${med(pairs.map((p) => p.page)) >= 0 ? "+" : ""}${med(pairs.map((p) => p.page)).toFixed(2)} ms per drawn state`,
        );
      }
    }
  }
} finally {
  await browser.close();
  await close();
}
process.exit(0);
