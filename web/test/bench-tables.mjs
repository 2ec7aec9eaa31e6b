// `make bench-tables`: the η table build in headless Chromium
// (Web Workers, the page animating) and the cached reload, per reference
// vehicle, over several fresh browser contexts (empty IndexedDB each).
// Prints every run, median and max per vehicle and the host load
// (1-minute load average before and after), as the README quotes them.
// The pedestrian's own table is the committed one, so its build is timed
// at v_max 1.2 m/s (the e2e test's limit change). `--reps N` sets the runs.
import { serve, launch, openPage, waitReady } from "./harness.mjs";
import { options, whole } from "./options.mjs";
import { loadavg } from "node:os";

const { values } = options(
  `The η table build in Chromium's Web Workers and the cached reload, per reference vehicle.
Usage: node web/test/bench-tables.mjs [options]   (after \`make web-build-test\`; \`make bench-tables\`)`,
  { reps: { type: "string", default: "5", arg: "N", help: "fresh browser contexts per vehicle (median, max)" } },
);
const REPS = whole(values, "reps", 1);
const VEHICLES = {
  "pedestrian (vmax 1.2)": ["vmax=1.2", "1.19"],
  car: ["vmax=15&amax=3&wmax=0.8&awmax=2&anmax=4", "14.9"],
  robot: ["vmax=0.5&wmax=4&awmax=16&kp=108&kd=18", "0.49"],
};

const waitExact = (page, timeout = 120000) =>
  page.waitForFunction(
    () => window.__lab.table()?.state === "exact" && window.__lab.table()?.key === window.__lab.table()?.wanted && window.__lab.table()?.ms > 0,
    null,
    { timeout, polling: 20 },
  );
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const fmt = (xs) => xs.map((x) => x.toFixed(0)).join(", ");

const { server, url } = await serve();
const browser = await launch();
const load0 = loadavg()[0];
const rows = [];
let failed = false;
try {
  for (const [name, [hash, vmax2]] of Object.entries(VEHICLES)) {
    const build = [];
    const cached = [];
    const warm = [];
    for (let r = 0; r < REPS; r++) {
      const { context, page, problems } = await openPage(browser);
      await page.goto(`${url}index.html#${hash}`);
      const err = await waitReady(page);
      if (err !== null) throw new Error(err);
      await waitExact(page);
      const t = await page.evaluate(() => window.__lab.table());
      if (t.cached) throw new Error(`${name}: first load found the table cached`);
      build.push(t.ms);
      // The table is stored in the background once in force.
      await page.waitForFunction((k) => window.__lab.cachedTables().then((ks) => ks.includes(k)), t.key, { timeout: 10000, polling: 50 });
      await page.reload();
      await waitReady(page);
      await waitExact(page);
      const c = await page.evaluate(() => window.__lab.table());
      if (!c.cached) throw new Error(`${name}: reload did not find the table cached`);
      cached.push(c.ms);
      // A second limit on the same page: the workers are already running.
      await page.locator("#vmax-num").fill(vmax2);
      await page.locator("#vmax-num").press("Enter");
      await page.waitForFunction((k) => window.__lab.table()?.wanted !== k, c.key, { timeout: 10000, polling: 20 });
      await waitExact(page);
      const w = await page.evaluate(() => window.__lab.table());
      if (w.cached) throw new Error(`${name}: vmax ${vmax2} found cached`);
      warm.push(w.ms);
      if (problems.length) {
        failed = true;
        console.log(`${name}: console problems: ${problems.join("; ")}`);
      }
      const ph = (x) => Object.entries(x.phases ?? {}).map(([k, v]) => `${k} ${v.toFixed(1)}`).join(", ");
      console.log(`${name} run ${r + 1}: build ${t.ms.toFixed(0)} ms (${t.workers} workers; ${ph(t)}), cached reload ${c.ms.toFixed(1)} ms (${ph(c)}), second build (workers running) ${w.ms.toFixed(0)} ms, load ${loadavg()[0].toFixed(2)}`);
      await context.close();
    }
    rows.push({ name, build, cached, warm });
  }
} finally {
  await browser.close();
  await server.close();
}
console.log(`bench-tables: ${REPS} runs per vehicle; 1-min load average ${load0.toFixed(2)} before, ${loadavg()[0].toFixed(2)} after`);
for (const { name, build, cached, warm } of rows) {
  console.log(
    `  ${name}: build median ${median(build).toFixed(0)} ms, max ${Math.max(...build).toFixed(0)} ms (${fmt(build)}); ` +
      `second build median ${median(warm).toFixed(0)} ms, max ${Math.max(...warm).toFixed(0)} ms; ` +
      `cached reload median ${median(cached).toFixed(1)} ms, max ${Math.max(...cached).toFixed(1)} ms (${fmt(cached)})`,
  );
}
process.exit(failed ? 1 : 0);
