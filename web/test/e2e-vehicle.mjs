// Browser end-to-end test of η tables for the vehicle in use,
// against the built page (web/dist) in Debian's headless Chromium:
// - a preset with a vehicle limit in the link really runs with it
//   (`#preset=p000_fig1_seek&vmax=0.05`: the core's vMax and the agents'
//   speeds), and its table is built;
// - changing a limit in the playground builds the matching table in Web
//   Workers (the HUD says "approximate — building N %", then "exact"), the
//   page keeps animating meanwhile, the URL carries the limit, the
//   playground is not empty; reloading finds the table in IndexedDB
//   (cached, ≤ 100 ms target) and the cache holds its key;
// - lowering max speed below the desired speed, then Reset: the playground
//   keeps its agent;
// - a build whose workers cannot load the core (wasm requests refused)
//   ends in an error the page shows, not at 0 % for ever;
// - the reference vehicles (select "vehicle"): the car's table built;
// - the car-like vehicle (minimum turning radius): R_min in the link and
//   the menu after a reload, a hand edit shows "custom", an out-of-range
//   radius is a note at its control; the playground car never turns
//   faster than v/R_min and arrives; the car-like parking preset ends at
//   rest inside both tolerances, without console errors, and its car goes
//   with it when another preset is chosen;
// - the reverse gear: the backing-in preset carries `vrev` in the link,
//   the HUD says "reverse" while the car backs, and the car ends at rest
//   in its bay facing out, |ω| ≤ |v|/R_min all the way;
// - no console errors. Prints the build and cache timings; a node:test
//   suite (harness.mjs `check`). Screenshots in artifacts/.
import { serve, launch, openPage, check, shot, waitReady, settle } from "./harness.mjs";
import assert from "node:assert/strict";

const { server, url } = await serve();
const browser = await launch();
const timings = {};

const table = (page) => page.evaluate(() => window.__lab.table());
const waitExact = (page, timeout = 90000) =>
  page.waitForFunction(() => window.__lab.table()?.state === "exact" && window.__lab.table()?.key === window.__lab.table()?.wanted, null, { timeout, polling: 50 });
const hud = (page) => page.locator("#hud").textContent();

try {
  await check("a preset runs with the link's vehicle limit (vmax=0.05) and gets its table", async () => {
    const { context, page, problems } = await openPage(browser);
    await page.goto(`${url}index.html#preset=p000_fig1_seek&vmax=0.05`);
    assert.equal(await waitReady(page), null);
    const p = await page.evaluate(() => window.__lab.params());
    assert.ok(Math.abs(p.vMax - 0.05) < 1e-6, `core vMax ${p.vMax}`);
    await waitExact(page);
    await page.waitForTimeout(1500);
    const text = await hud(page);
    const m = /speed\s+([\d.]+) m\/s/.exec(text);
    assert.ok(m && Number(m[1]) <= 0.0501, `HUD speed: ${text}`);
    assert.match(text, /table\s+exact/);
    assert.deepEqual(problems, []);
    await context.close();
  });

  await check("a table build whose workers cannot load the core says so (HUD and message), not 0 % for ever", async () => {
    const { context, page } = await openPage(browser);
    await page.goto(`${url}index.html`);
    assert.equal(await waitReady(page), null);
    // The page's own core is in; from now on every wasm request fails, so
    // the table workers cannot instantiate theirs.
    let blocked = 0;
    await context.route(/\.wasm(\?|$)/, (r) => {
      blocked++;
      return r.abort();
    });
    await page.locator("#vmax-num").fill("1.1");
    await page.locator("#vmax-num").press("Enter");
    await page.waitForFunction(() => window.__lab.table()?.state === "error", null, { timeout: 15000, polling: 50 });
    assert.ok(blocked > 0, "the workers asked for the core");
    const msg = (await page.locator("#message").textContent()) ?? "";
    assert.match(msg, /could not be built/);
    assert.match(await hud(page), /table/);
    await shot(page, "vehicle-build-failed");
    await context.close();
  });

  let context, page, problems;
  await check("changing a limit builds the table in workers; HUD, URL, animation", async () => {
    ({ context, page, problems } = await openPage(browser));
    await page.goto(`${url}index.html`);
    assert.equal(await waitReady(page), null);
    const t0 = await table(page);
    assert.equal(t0.state, "exact");
    const frames0 = await page.evaluate(() => window.__lab.frames);
    await page.locator("#vmax-num").fill("1.2");
    await page.locator("#vmax-num").press("Enter");
    await page.waitForFunction(() => window.__lab.table()?.state !== "exact", null, { timeout: 5000, polling: 10 }).catch(() => {});
    const during = await hud(page);
    const start = Date.now();
    await waitExact(page);
    const wall = Date.now() - start;
    const t = await table(page);
    timings.buildMs = t.ms;
    timings.workers = t.workers;
    assert.equal(t.cached, false);
    assert.ok(/approximate — building|exact/.test(during), during);
    const frames1 = await page.evaluate(() => window.__lab.frames);
    assert.ok(frames1 - frames0 > 10, `the page kept animating: ${frames1 - frames0} frames in ${wall} ms`);
    assert.match(await hud(page), /table\s+exact for these limits \(built/);
    assert.match(page.url(), /vmax=1\.2/);
    assert.ok((await page.evaluate(() => window.__lab.count())) >= 1, "the playground has its agent");
    assert.ok(Math.abs((await page.evaluate(() => window.__lab.params())).vMax - 1.2) < 1e-6);
    // The table is stored in the background once in force.
    await page.waitForFunction((k) => window.__lab.cachedTables().then((ks) => ks.includes(k)), t.key, { timeout: 10000, polling: 50 });
    await shot(page, "vehicle-built");
  });

  await check("reloading finds the table in the browser's cache", async () => {
    const key = (await table(page)).key;
    await page.reload();
    assert.equal(await waitReady(page), null);
    await waitExact(page, 10000);
    const t = await table(page);
    timings.cacheMs = t.ms;
    assert.equal(t.key, key);
    assert.equal(t.cached, true);
    assert.match(await hud(page), /table\s+exact for these limits \(cache/);
  });

  await check("max speed below the desired speed, then Reset: the playground keeps its agent", async () => {
    await page.locator("#vmax-num").fill("0.3");
    await page.locator("#vmax-num").press("Enter");
    await settle(page);
    const st = await page.evaluate(() => window.__lab.state());
    assert.ok(st.speed <= 0.3 + 1e-9, `desired speed ${st.speed}`);
    await page.keyboard.press("r");
    await settle(page);
    assert.ok((await page.evaluate(() => window.__lab.count())) >= 1);
    await waitExact(page);
    assert.match(page.url(), /vmax=0\.3/);
  });

  await check("reference vehicles: the car's table is built and its limits are in the URL", async () => {
    await page.selectOption("#vehicle", "car");
    const start = Date.now();
    await waitExact(page, 120000);
    timings.carMs = (await table(page)).ms;
    timings.carWall = Date.now() - start;
    const p = await page.evaluate(() => window.__lab.params());
    assert.deepEqual([p.vMax, p.accelMax, p.omegaMax, p.omegaAccelMax, p.normalAccelMax], [15, 3, 0.8, 2, 4].map(Math.fround));
    assert.equal(await page.inputValue("#vehicle"), "car");
    assert.match(page.url(), /vmax=15/);
    await page.setViewportSize({ width: 390, height: 844 });
    await settle(page);
    await shot(page, "vehicle-car-phone");
    assert.deepEqual(problems, []);
    await context.close();
  });

  /** Runs the paused world from t = 0 one step at a time (at most `limit`
   *  steps) until agent 0 rests in End_of_Steering: the largest excess of
   *  |ω| over v/R_min, the steps taken and the last record. */
  const runCar = (page, limit) =>
    page.evaluate(async (limit) => {
      const l = window.__lab;
      l.setPaused(true);
      await l.restart();
      const R = l.params().minTurnRadius;
      let excess = -Infinity;
      let steps = 0;
      let a = l.agentRecord(0);
      for (; steps < limit && !(a.mode === 0 && a.v === 0); steps++) {
        await l.stepN(1);
        a = l.agentRecord(0);
        excess = Math.max(excess, Math.abs(a.omega) - a.v / R);
      }
      return { R, excess, steps, last: a };
    }, limit);

  await check("the car-like vehicle: R_min in the link and the menu after a reload; |ω| ≤ v/R_min and it arrives", async () => {
    ({ context, page, problems } = await openPage(browser, { width: 1440, height: 900 }));
    await page.goto(`${url}index.html`);
    assert.equal(await waitReady(page), null);
    await page.selectOption("#vehicle", "car_like");
    await waitExact(page);
    assert.equal(Number(await page.inputValue("#rmin-num")), 5);
    await page.waitForFunction(() => /[#&]rmin=5(&|$)/.test(location.hash), null, { timeout: 5000 });
    await page.reload();
    assert.equal(await waitReady(page), null);
    assert.equal(await page.inputValue("#vehicle"), "car_like");
    await waitExact(page, 10000);
    const p = await page.evaluate(() => window.__lab.params());
    assert.equal(p.minTurnRadius, 5);
    const r = await runCar(page, 60 * 60);
    assert.ok(r.excess <= 1e-4, `|ω| − v/R_min reached ${r.excess} rad/s`);
    assert.equal(r.last.mode, 0, `arrived within 60 s: ${JSON.stringify(r)}`);
    const st = await page.evaluate(() => window.__lab.state());
    assert.ok(Math.hypot(r.last.x - st.target.x, r.last.y - st.target.y) <= st.dTol, JSON.stringify(r.last));
    await settle(page);
    await shot(page, "vehicle-car-like");
    // On a phone the playground is fitted for the car's loop when the car is chosen (its table from the cache).
    const phone = await context.newPage();
    await phone.setViewportSize({ width: 390, height: 844 });
    await phone.goto(`${url}index.html`);
    assert.equal(await waitReady(phone), null);
    await phone.selectOption("#vehicle", "car_like");
    await waitExact(phone, 10000);
    assert.equal((await runCar(phone, 60 * 60)).last.mode, 0);
    await settle(phone);
    await shot(phone, "vehicle-car-like-phone");
    await phone.close();
  });

  await check("the car-like vehicle: a hand edit of R_min shows custom; a radius out of range is a note", async () => {
    await page.locator("#rmin-num").fill("3");
    await page.locator("#rmin-num").press("Enter");
    assert.equal(await page.inputValue("#vehicle"), "custom");
    await page.waitForFunction(() => /[#&]rmin=3(&|$)/.test(location.hash), null, { timeout: 5000 });
    await page.locator("#rmin-num").fill("-1");
    await page.locator("#rmin-num").press("Enter");
    assert.match(await page.locator("#rmin-msg").textContent(), /turning radius.*not a number in \[0, 1000\] m/);
    assert.equal((await page.evaluate(() => window.__lab.params())).minTurnRadius, 3);
    assert.deepEqual(problems, []);
  });

  await check("the car-like parking preset: its own vehicle and table, at rest inside both tolerances, no console errors", async () => {
    const opened = await openPage(browser, { width: 1440, height: 900 });
    await opened.page.goto(`${url}index.html#preset=car_like_parking`);
    assert.equal(await waitReady(opened.page), null);
    assert.equal(await opened.page.inputValue("#vehicle"), "car_like");
    await waitExact(opened.page);
    const r = await runCar(opened.page, 60 * 40);
    assert.equal(r.R, 5);
    assert.ok(r.excess <= 1e-4, `|ω| − v/R_min reached ${r.excess} rad/s`);
    const { x, y, theta, v } = r.last;
    assert.equal(v, 0, JSON.stringify(r));
    assert.ok(Math.hypot(x, y - 4) <= 0.5, `at (${x}, ${y}), the bay at (0, 4) ± 0.5 m`);
    const off = Math.abs(Math.atan2(Math.sin(theta - Math.PI), Math.cos(theta - Math.PI)));
    assert.ok(off <= (5 * Math.PI) / 180, `heading off by ${(off * 180) / Math.PI}°`);
    await settle(opened.page);
    await shot(opened.page, "preset-car-like-parking");
    // The car goes with its preset: Fig. 1's walkers turn on the spot again.
    await opened.page.selectOption("#preset", "p000_fig1_seek");
    await opened.page.waitForFunction(() => window.__lab.state().preset === "p000_fig1_seek" && window.__lab.count() > 0, null, { timeout: 5000 });
    assert.equal((await opened.page.evaluate(() => window.__lab.params())).minTurnRadius ?? 0, 0);
    assert.equal(await opened.page.inputValue("#vehicle"), "pedestrian");
    assert.equal(await opened.page.locator("#message").isHidden(), true, await opened.page.locator("#message").textContent());
    // The phone's view is fitted on loading: a fresh page (its table from the context's cache).
    const phone = await opened.context.newPage();
    await phone.setViewportSize({ width: 390, height: 844 });
    await phone.goto(`${url}index.html#preset=car_like_parking`);
    assert.equal(await waitReady(phone), null);
    await waitExact(phone, 10000);
    await phone.evaluate(() => window.__lab.stepN(600));
    await settle(phone);
    await shot(phone, "preset-car-like-parking-phone");
    assert.deepEqual(opened.problems, []);
    await opened.context.close();
    await context.close();
  });
  await check("the reverse gear: the backing-in preset shows vrev in the link and reverse in the HUD, and parks facing out", async () => {
    const opened = await openPage(browser, { width: 1440, height: 900 });
    const page = opened.page;
    await page.goto(`${url}index.html#preset=car_like_reverse_parking`);
    assert.equal(await waitReady(page), null);
    await waitExact(page);
    assert.equal(Number(await page.inputValue("#vrev-num")), 5);
    await page.waitForFunction(() => /[#&]vrev=5(&|$)/.test(location.hash), null, { timeout: 5000 });
    const r = await page.evaluate(async () => {
      const l = window.__lab;
      l.setPaused(true);
      await l.restart();
      const R = l.params().minTurnRadius;
      let excess = -Infinity;
      let backing = 0;
      let a = l.agentRecord(0);
      for (let steps = 0; steps < 60 * 40 && !(a.mode === 0 && a.v === 0); steps++) {
        await l.stepN(1);
        a = l.agentRecord(0);
        excess = Math.max(excess, Math.abs(a.omega) - Math.abs(a.v) / R);
        if (a.v < 0) backing++;
      }
      return { R, excess, backing, last: a };
    });
    assert.ok(r.excess <= 1e-4, `|ω| − |v|/R_min reached ${r.excess} rad/s`);
    assert.ok(r.backing > 60, `backed ${r.backing} steps`);
    const { x, y, theta, v } = r.last;
    // At rest after backing: −0 (the speed braked up to 0 from below).
    assert.ok(v === 0, JSON.stringify(r));
    assert.ok(Math.hypot(x + 6, y + 9) <= 0.5, `at (${x}, ${y}), the bay at (-6, -9) ± 0.5 m`);
    const off = Math.abs(Math.atan2(Math.sin(theta - Math.PI / 2), Math.cos(theta - Math.PI / 2)));
    assert.ok(off <= (5 * Math.PI) / 180, `heading off by ${(off * 180) / Math.PI}°`);
    // While it backs, the HUD says so in words.
    await page.evaluate(async () => { await window.__lab.restart(); await window.__lab.stepN(120); });
    await page.waitForFunction(() => /reverse/.test(document.querySelector("#hud")?.textContent ?? ""), null, { timeout: 5000 });
    await settle(page);
    await shot(page, "preset-car-like-reverse-parking");
    assert.deepEqual(opened.problems, []);
    await opened.context.close();
  });
} finally {
  console.log(`e2e-vehicle timings: ${JSON.stringify(timings)}`);
  await browser.close();
  await server.close();
}
