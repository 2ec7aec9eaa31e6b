// Browser end-to-end test of the gallery pages (web/dist, built by
// `make web-build`) in Debian's headless Chromium via playwright-core.
// crowd.html: loads without console errors or warnings, switching seek and
// preset reaches the core, 10,000 boids run, dragging a path point moves it,
// double-click adds a point and Delete removes it, keys; it also measures the
// step cost (boids stepped per 16.7 ms frame) at 300 / 3,000 / 30,000 boids.
// wander.html: loads without console errors, every panel draws every tile
// (non-blank canvases), a knob rebuilds, a bad JSON edit shows the core's
// message. Screenshots go to artifacts/ (gitignored).
// A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check, shot, settle, artifacts, unisolated, countPixels } from "./harness.mjs";
import { resolve } from "node:path";
import { writeFileSync } from "node:fs";
import assert from "node:assert/strict";


async function waitCrowd(page) {
  await page.waitForFunction(() => {
    const c = window.__crowd;
    return c && (c.error !== null || (c.ready && c.frames > 2));
  }, null, { timeout: 20000 });
  return page.evaluate(() => window.__crowd.error);
}

/** Share of a canvas's pixels that are not its background (its top-left pixel's colour). */
async function inked(page, selector, index = 0) {
  const n = await countPixels(page, { selector, index }, {
    ink: (r, g, b, bg) => Math.abs(r - bg[0]) + Math.abs(g - bg[1]) + Math.abs(b - bg[2]) > 30,
  });
  return n.ink / n.total;
}

const { server, url } = await serve();
const browser = await launch();
const allProblems = [];
const report = {};
try {
  // ------------------------------------------------------------------ crowd
  {
    const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 2);
    await page.goto(new URL("crowd.html", url).href);
    const err = await waitCrowd(page);
    await check("crowd: page loads, the core steps the default preset (Test IV, Parker 10 %)", async () => {
      assert.equal(err, null);
      assert.equal(await page.evaluate(() => window.__crowd.count()), 300);
      const t0 = await page.evaluate(() => window.__crowd.time());
      await page.waitForTimeout(300);
      assert.ok((await page.evaluate(() => window.__crowd.time())) > t0);
      assert.equal(await page.locator("#message").isHidden(), true);
      assert.ok((await inked(page, "#crowd")) > 0.05, "canvas drawn");
    });
    await check("crowd: nav bar links the four pages", async () => {
      const hrefs = await page.$$eval("nav.labnav a", (as) => as.map((a) => a.getAttribute("href")));
      assert.deepEqual(hrefs, ["./index.html", "./crowd.html", "./wander.html", "./learn.html"]);
    });
    await check("crowd: HiDPI backing store", async () => {
      const r = await page.evaluate(() => {
        const c = document.getElementById("crowd");
        return { w: c.width, cw: c.getBoundingClientRect().width };
      });
      assert.equal(r.w, Math.round(r.cw * 2));
    });
    await page.waitForTimeout(1200);
    await shot(page, "crowd-test4-parker10");

    await check("crowd: seek menu switches the core's seek", async () => {
      await page.selectOption("#seek", "reynolds");
      assert.deepEqual(await page.evaluate(() => window.__crowd.seek()), { kind: "reynolds" });
      await page.selectOption("#seek", "parker0.1");
      const s = await page.evaluate(() => window.__crowd.seek());
      assert.equal(s.kind, "parker");
      assert.ok(Math.abs(s.fraction - 0.001) < 1e-6);
    });
    await check("crowd: separation switch", async () => {
      const before = await page.evaluate(() => window.__crowd.separation());
      await page.click("#separation");
      assert.equal(await page.evaluate(() => window.__crowd.separation()), !before);
      await page.click("#separation");
    });
    await check("crowd: preset menu loads Test II Reynolds (10 boids, no separation)", async () => {
      const value = await page.$eval("#preset", (sel) => {
        const o = [...sel.options].find((o) => o.text === "Test II — Reynolds");
        return o ? o.value : null;
      });
      assert.notEqual(value, null);
      await page.selectOption("#preset", value);
      assert.equal(await page.evaluate(() => window.__crowd.count()), 10);
      assert.equal(await page.evaluate(() => window.__crowd.separation()), false);
      assert.equal(await page.$eval("#seek", (s) => s.value), "reynolds");
      assert.equal(await page.$eval("#boids", (s) => s.value), "10");
      await page.waitForTimeout(1500);
      await shot(page, "crowd-test2-reynolds");
    });
    await check("crowd: dragging a path point moves it (mouse, pointer capture)", async () => {
      const before = await page.evaluate(() => window.__crowd.pathPoints());
      const p = await page.evaluate(([x, y]) => window.__crowd.toScreen(x, y), before.slice(0, 2));
      const box = await page.locator("#crowd").boundingBox();
      await page.mouse.move(box.x + p.x, box.y + p.y);
      await page.mouse.down();
      await page.mouse.move(box.x + p.x - 60, box.y + p.y - 40, { steps: 10 });
      await page.mouse.up();
      const after = await page.evaluate(() => window.__crowd.pathPoints());
      const k = await page.evaluate(() => {
        const a = window.__crowd.toScreen(0, 0);
        const b = window.__crowd.toScreen(1, 0);
        return b.x - a.x;
      });
      assert.ok(Math.abs(after[0] - (before[0] - 60 / k)) < 1.5 / k + 0.5, `x ${before[0]} → ${after[0]}`);
      assert.ok(Math.abs(after[1] - (before[1] + 40 / k)) < 1.5 / k + 0.5, `y ${before[1]} → ${after[1]}`);
      assert.deepEqual(after.slice(2), before.slice(2));
      assert.equal(await page.evaluate(() => window.__crowd.selected()), 0);
    });
    await check("crowd: a finger drags a path point too (touch → pointer events with capture)", async () => {
      const context = await browser.newContext({ viewport: { width: 900, height: 700 }, deviceScaleFactor: 1, hasTouch: true });
      const t = await context.newPage();
      const tproblems = [];
      t.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") tproblems.push(m.text()); });
      t.on("pageerror", (e) => tproblems.push(e.message));
      await t.goto(new URL("crowd.html", url).href);
      assert.equal(await waitCrowd(t), null);
      const before = await t.evaluate(() => window.__crowd.pathPoints());
      const p = await t.evaluate(([x, y]) => window.__crowd.toScreen(x, y), before.slice(4, 6));
      const box = await t.locator("#crowd").boundingBox();
      const cdp = await context.newCDPSession(t);
      const at = (dx, dy) => [{ x: box.x + p.x + dx, y: box.y + p.y + dy }];
      await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: at(0, 0) });
      for (let i = 1; i <= 10; i++) {
        await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: at(-4 * i, 3 * i) });
      }
      await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
      await settle(t);
      const after = await t.evaluate(() => window.__crowd.pathPoints());
      assert.ok(after[4] < before[4] - 1 && after[5] < before[5] - 1, `${before.slice(4, 6)} → ${after.slice(4, 6)}`);
      assert.deepEqual(tproblems, []);
      await context.close();
    });
    await check("crowd and gallery at 390 px: no horizontal scrolling (the one-line HUD wraps)", async () => {
      const context = await browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, hasTouch: true, isMobile: true });
      const t = await context.newPage();
      for (const name of ["crowd.html", "wander.html"]) {
        await t.goto(new URL(name, url).href);
        if (name === "crowd.html") {
          assert.equal(await waitCrowd(t), null);
          await t.waitForFunction(() => document.getElementById("hud")?.textContent?.includes("fps"));
        } else {
          await t.waitForTimeout(500);
        }
        const w = await t.evaluate(() => document.documentElement.scrollWidth);
        assert.ok(w <= 390, `${name}: page ${w} px wide at a 390 px viewport`);
      }
      await context.close();
    });
    await check("crowd: a SIMD core that does not load falls back to the baseline build", async () => {
      const context = await browser.newContext({ viewport: { width: 900, height: 700 } });
      const t = await context.newPage();
      await t.route(/steering_simd_bg.*\.wasm/, (route) => route.abort());
      await t.goto(new URL("crowd.html", url).href);
      assert.equal(await waitCrowd(t), null);
      const t0 = await t.evaluate(() => window.__crowd.time());
      await t.waitForFunction((t0) => window.__crowd.time() > t0, t0);
      await context.close();
    });
    await check("crowd: double-click a segment adds a point; Delete removes the selected one", async () => {
      const before = await page.evaluate(() => window.__crowd.pathPoints());
      // Midpoint of the segment from point 1 to point 2.
      const mid = [(before[2] + before[4]) / 2, (before[3] + before[5]) / 2];
      const p = await page.evaluate(([x, y]) => window.__crowd.toScreen(x, y), mid);
      const box = await page.locator("#crowd").boundingBox();
      await page.mouse.dblclick(box.x + p.x, box.y + p.y);
      const added = await page.evaluate(() => window.__crowd.pathPoints());
      assert.equal(added.length, before.length + 2);
      assert.equal(await page.evaluate(() => window.__crowd.selected()), 2);
      await page.keyboard.press("Delete");
      const removed = await page.evaluate(() => window.__crowd.pathPoints());
      assert.deepEqual(removed, before);
      // Add / remove buttons.
      await page.click("#add-point");
      assert.equal((await page.evaluate(() => window.__crowd.pathPoints())).length, before.length + 2);
      await page.click("#remove-point");
      assert.deepEqual(await page.evaluate(() => window.__crowd.pathPoints()), before);
    });
    await check("crowd: radius slider", async () => {
      await page.$eval("#radius", (el) => {
        el.value = "60";
        el.dispatchEvent(new Event("input", { bubbles: true }));
      });
      assert.equal(await page.evaluate(() => window.__crowd.pathRadius()), 60);
    });
    await check("crowd: keys space (pause), s (step), r (reset)", async () => {
      await page.locator("#crowd").click({ position: { x: 5, y: 5 } });
      await page.keyboard.press(" ");
      assert.equal(await page.evaluate(() => window.__crowd.playing), false);
      const t = await page.evaluate(() => window.__crowd.time());
      await page.keyboard.press("s");
      await page.waitForTimeout(100);
      assert.equal(await page.evaluate(() => window.__crowd.time()), t + 1);
      await page.keyboard.press("r");
      assert.equal(await page.evaluate(() => window.__crowd.time()), 0);
      await page.keyboard.press(" ");
      assert.equal(await page.evaluate(() => window.__crowd.playing), true);
    });
    await check("crowd: 10,000 boids run (Test IV, Parker 10 %, separation)", async () => {
      const value = await page.$eval("#preset", (sel) => [...sel.options].find((o) => o.text === "Test IV — Parker 10 %").value);
      await page.selectOption("#preset", value);
      await page.fill("#boids", "10000");
      await page.press("#boids", "Enter");
      assert.equal(await page.evaluate(() => window.__crowd.count()), 10000);
      const t0 = await page.evaluate(() => window.__crowd.time());
      await page.waitForTimeout(2200);
      const s = await page.evaluate(() => ({ t: window.__crowd.time(), fps: window.__crowd.fps, step: window.__crowd.stepMs, draw: window.__crowd.drawMs, m: window.__crowd.metrics() }));
      assert.ok(s.t > t0 + 10, `steps ${t0} → ${s.t}`);
      assert.ok(s.m.mean_distance !== null);
      report.page10k = s;
      console.log(`# 10,000 boids on the page: ${s.fps.toFixed(0)} fps, step ${s.step.toFixed(2)} ms, draw ${s.draw.toFixed(2)} ms per frame`);
      await shot(page, "crowd-10000");
    });
    await check("crowd: a count above the page's limit is refused with a message; a heavy count asks first", async () => {
      const n0 = await page.evaluate(() => window.__crowd.count());
      for (const bad of ["1000000", "0x10", "1e4", "-5", ""]) {
        await page.fill("#boids", bad);
        await page.press("#boids", "Enter");
        const msg = page.locator("#boids-msg");
        assert.equal(await msg.isVisible(), true, bad);
        assert.match(await msg.textContent(), /boid count: .* \[0, 200,000\] \(this page's limit\); 10,000 kept/, bad);
        assert.equal(await page.evaluate(() => window.__crowd.count()), n0, bad);
        assert.equal(await page.$eval("#boids", (el) => el.value), String(n0));
      }
      await shot(page, "crowd-count-refused");
      await page.fill("#boids", "50000");
      await page.press("#boids", "Enter");
      assert.match(await page.locator("#boids-msg").textContent(), /50,000 boids is heavy: .*above 15,000/);
      assert.equal(await page.evaluate(() => window.__crowd.count()), n0, "not run before asked");
      await shot(page, "crowd-count-heavy");
      await page.click("#boids-confirm");
      assert.equal(await page.evaluate(() => window.__crowd.count()), 50000);
      assert.equal(await page.locator("#boids-msg").isHidden(), true);
      await page.fill("#boids", "10000");
      await page.press("#boids", "Enter");
      assert.equal(await page.evaluate(() => window.__crowd.count()), 10000);
    });
    await check("crowd: a bad edit shows the core's message and changes nothing", async () => {
      await page.fill("#boids", "300");
      await page.press("#boids", "Enter");
      const before = await page.evaluate(() => window.__crowd.pathPoints());
      // Drag point 1 exactly onto point 0: a zero-length segment.
      const a = await page.evaluate(([x, y]) => window.__crowd.toScreen(x, y), before.slice(0, 2));
      const b = await page.evaluate(([x, y]) => window.__crowd.toScreen(x, y), before.slice(2, 4));
      const box = await page.locator("#crowd").boundingBox();
      await page.mouse.move(box.x + b.x, box.y + b.y);
      await page.mouse.down();
      await page.mouse.move(box.x + a.x, box.y + a.y, { steps: 4 });
      await page.mouse.move(box.x + b.x, box.y + b.y, { steps: 4 });
      await page.mouse.up();
      const after = await page.evaluate(() => window.__crowd.pathPoints());
      assert.equal(after.length, before.length);
      // Remove below the minimum: a closed path keeps three points.
      for (let i = 0; i < 3; i++) {
        await page.evaluate(() => 0);
        await page.click("#remove-point");
      }
      assert.equal(await page.locator("#message").isVisible(), true);
    });
    await check("crowd: laps are timed; the lap trace and metrics panel (Test IV, Reynolds, 20 steps / frame)", async () => {
      const value = await page.$eval("#preset", (sel) => [...sel.options].find((o) => o.text === "Test IV — Reynolds").value);
      await page.selectOption("#preset", value);
      await page.$eval("#speed", (el) => {
        el.value = "20";
        el.dispatchEvent(new Event("input", { bubbles: true }));
      });
      await page.waitForFunction(() => window.__crowd.metrics().laps > 20, null, { timeout: 30000 });
      const m = await page.evaluate(() => window.__crowd.metrics());
      assert.ok(m.mean_lap_steps > 300 && m.mean_lap_steps < 3000, `mean lap ${m.mean_lap_steps}`);
      assert.ok(m.trace_spread !== null);
      await page.waitForTimeout(300);
      await shot(page, "crowd-test4-reynolds-lap");
      await page.locator("#metrics").screenshot({ path: resolve(artifacts, "crowd-metrics.png") });
      await page.$eval("#speed", (el) => {
        el.value = "1";
        el.dispatchEvent(new Event("input", { bubbles: true }));
      });
    });
    await check("crowd: step cost per boid count (performance.now in the page)", async () => {
      const rows = await page.evaluate(() => window.__crowd.bench([300, 3000, 30000], 600));
      report.bench = rows;
      for (const r of rows) {
        console.log(`# ${String(r.boids).padStart(6)} boids, ${r.setup.padEnd(6)}: ${r.msPerStep.toFixed(3)} ms/step → ${r.boidsPerFrame.toLocaleString("en")} boids per 16.7 ms frame (${r.steps} steps timed)`);
      }
      assert.equal(rows.length, 9);
      assert.ok(rows.every((r) => r.msPerStep > 0));
    });
    await check("crowd: no console errors or warnings", async () => {
      assert.deepEqual(problems, []);
    });
    allProblems.push(...problems);
    await context.close();
  }

  // ------------------------------------------------- crowd in workers
  {
    const owned = (page) => page.waitForFunction(() => { const w = window.__crowd.workers(); return !w.starting && window.__crowd.idle(); }, null, { timeout: 60000 });
    const pause = async (page) => {
      if (await page.evaluate(() => window.__crowd.playing)) await page.click("#play");
      await owned(page);
    };
    /** Paused: the workers' state after `steps` steps against one core's from the same snapshot (and `edit`). */
    const sameAsOneCore = async (page, snap, edit, steps) => {
      await owned(page);
      return page.evaluate(async ([snap, edit, steps]) => {
        const h = window.__crowd;
        const ref = h.reference(snap, edit, steps);
        await h.runSteps(steps);
        return { ref, got: h.stateHash(), info: h.workers() };
      }, [snap, edit, steps]);
    };
    const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
    await page.goto(new URL("crowd.html?workers=2", url).href);
    assert.equal(await waitCrowd(page), null);
    await check("crowd in 2 workers (shared memory, 40,000 boids at Test IV density): runs, draws, its strips rebalanced by speed, its state equals one core's after 30 steps from step 0 and 24 more", async () => {
      await pause(page);
      await page.evaluate(() => window.__crowd.loadScaled(40000));
      await owned(page);
      const snap0 = await page.evaluate(() => window.__crowd.snapshot());
      assert.equal(snap0.time, 0);
      let r = await sameAsOneCore(page, snap0, {}, 30);
      assert.equal(r.info.mode, "shared");
      assert.equal(r.info.workers, 2);
      assert.equal(r.got, r.ref, "after 30 steps from step 0");
      // The strips were rebalanced by the workers' speeds (their cuts
      // moved step by step) and the state is still one core's.
      const shares = r.info.shares;
      assert.equal(shares.length, 2, `shares ${shares}`);
      assert.ok(Math.abs(shares[0] + shares[1] - 1) < 1e-5 && shares.every((f) => f >= 0.05), `shares ${shares}`);
      const skipped0 = await page.evaluate(() => window.__crowd.skippedSteps());
      await page.click("#play");
      const t0 = await page.evaluate(() => window.__crowd.time());
      await page.waitForFunction((t0) => window.__crowd.time() > t0 + 5, t0, { timeout: 30000 });
      await page.waitForTimeout(300);
      // The page's thread held up 100 ms, five times: meanwhile the workers
      // reach the target (two steps beyond the drawn state) and wait.
      for (let k = 0; k < 5; k++) {
        await page.evaluate(() => { const t = performance.now(); while (performance.now() - t < 100); });
        await page.waitForTimeout(150);
      }
      // One step per frame: every state drawn, in order (the page draws the
      // oldest new one; drawing only the newest passed one after each hold).
      const played = (await page.evaluate(() => window.__crowd.time())) - t0;
      assert.ok(played > 5, `played ${played}`);
      assert.equal(await page.evaluate(() => window.__crowd.skippedSteps()), skipped0, `steps passed undrawn in ${played} steps`);
      assert.ok((await inked(page, "#crowd")) > 0.01, "canvas drawn");
      const w = await page.evaluate(() => window.__crowd.workers());
      assert.equal(w.owned.length, 2);
      assert.ok(w.owned.every((k) => k > 10000), `strips ${w.owned}`);
      assert.match(await page.$eval("#metrics", (e) => e.textContent), /off while 2 workers step/);
      await pause(page);
      const snap = await page.evaluate(() => window.__crowd.snapshot());
      r = await sameAsOneCore(page, snap, {}, 24);
      assert.equal(r.got, r.ref, "24 more steps");
      await shot(page, "crowd-workers-40000");
    });
    await check("crowd in workers: a count change and a path drag reach the workers (same state as one core with the same edit)", async () => {
      await pause(page);
      let snap = await page.evaluate(() => window.__crowd.snapshot());
      await page.fill("#boids", "45000");
      await page.press("#boids", "Enter");
      if (await page.locator("#boids-confirm").isVisible()) await page.click("#boids-confirm");
      assert.equal(await page.evaluate(() => window.__crowd.count()), 45000);
      let r = await sameAsOneCore(page, snap, { boids: 45000 }, 12);
      assert.equal(r.info.mode, "shared");
      assert.equal(r.got, r.ref, "count change");
      snap = await page.evaluate(() => window.__crowd.snapshot());
      const before = await page.evaluate(() => window.__crowd.pathPoints());
      const p = await page.evaluate(([x, y]) => window.__crowd.toScreen(x, y), before.slice(0, 2));
      const box = await page.locator("#crowd").boundingBox();
      await page.mouse.move(box.x + p.x, box.y + p.y);
      await page.mouse.down();
      await page.mouse.move(box.x + p.x + 40, box.y + p.y - 30, { steps: 6 });
      await page.mouse.up();
      const after = await page.evaluate(() => window.__crowd.pathPoints());
      assert.ok(after[0] > before[0] + 1, `${before.slice(0, 2)} → ${after.slice(0, 2)}`);
      r = await sameAsOneCore(page, snap, { path: after }, 12);
      assert.equal(r.got, r.ref, "path drag");
    });
    await check("crowd: the Test IV density switch scales the pathway with the count (→ 90,000: by 90,000 / n about its centroid)", async () => {
      const before = await page.evaluate(() => window.__crowd.pathPoints());
      const k = 90000 / (await page.evaluate(() => window.__crowd.count()));
      await page.click("#density");
      await page.fill("#boids", "90000");
      await page.press("#boids", "Enter");
      assert.equal(await page.locator("#boids-msg").isHidden(), true, "90,000 at Test IV density does not ask");
      assert.equal(await page.evaluate(() => window.__crowd.count()), 90000);
      const after = await page.evaluate(() => window.__crowd.pathPoints());
      const m = before.length / 2;
      const c = [0, 1].map((k) => before.filter((_, j) => j % 2 === k).reduce((a, b) => a + b, 0) / m);
      after.forEach((v, j) => assert.ok(Math.abs(v - (c[j % 2] + k * (before[j] - c[j % 2]))) < 1e-3 * Math.abs(v) + 1e-2, `coordinate ${j}: ${before[j]} → ${v}`));
      await owned(page);
    });
    await check("crowd in workers: no console errors or warnings", async () => {
      assert.deepEqual(problems, []);
    });
    allProblems.push(...problems);
    await context.close();

    /** 30,000 boids at Test IV density in `workers` workers, shared memory or (`isolated` false) by message: 12 steps equal one core's. */
    const workersEqualOneCore = async (workers, isolated) => {
      const { page: t, problems: tp, context: c } = await openPage(browser, { width: 900, height: 700 }, 1);
      if (!isolated) await unisolated(c);
      await t.goto(new URL(`crowd.html?workers=${workers}`, url).href);
      assert.equal(await waitCrowd(t), null);
      await pause(t);
      await t.evaluate(() => window.__crowd.loadScaled(30000));
      const snap = await t.evaluate(() => window.__crowd.snapshot());
      const r = await sameAsOneCore(t, snap, {}, 12);
      assert.equal(r.info.mode, isolated ? "shared" : "messages");
      assert.equal(r.info.workers, workers);
      assert.equal(r.info.crossOriginIsolated, isolated);
      assert.equal(r.got, r.ref);
      assert.deepEqual(tp, []);
      await c.close();
    };
    await check("crowd in 1 worker (shared memory, every boid owned: the two bulk copies out of the core's memory): its state equals one core's", () => workersEqualOneCore(1, true));
    await check("crowd in 2 workers without cross-origin isolation (by message): its state equals one core's", () => workersEqualOneCore(2, false));
    await check("crowd: 100,000 boids at Test IV density in workers by default, at 1280 and 390 px (screenshots)", async () => {
      for (const [name, vp, dpr] of [["1280", { width: 1280, height: 800 }, 1], ["390", { width: 390, height: 844 }, 3]]) {
        const { page: t, problems: tp, context: c } = await openPage(browser, vp, dpr);
        await t.goto(new URL("crowd.html", url).href);
        assert.equal(await waitCrowd(t), null);
        await t.evaluate(() => window.__crowd.loadScaled(100000));
        await t.waitForFunction(() => !window.__crowd.workers().starting, null, { timeout: 60000 });
        const t0 = await t.evaluate(() => window.__crowd.time());
        await t.waitForFunction((t0) => window.__crowd.time() > t0 + 10, t0, { timeout: 60000 });
        const info = await t.evaluate(() => window.__crowd.workers());
        assert.equal(info.mode, "shared");
        assert.equal(info.workers, await t.evaluate(() => Math.max(1, Math.min(8, navigator.hardwareConcurrency - 1))));
        assert.ok((await inked(t, "#crowd")) > 0.005, "canvas drawn");
        await t.waitForTimeout(1500);
        assert.match(await t.$eval("#hud", (e) => e.textContent), /100,000 boids .* in \d+ workers?/);
        await shot(t, `crowd-100000-${name}`);
        const w = await t.evaluate(() => document.documentElement.scrollWidth);
        assert.ok(w <= vp.width, `page ${w} px wide`);
        assert.deepEqual(tp, []);
        await c.close();
      }
    });
  }

  // ----------------------------------------------------------------- wander
  {
    const { page, problems, context } = await openPage(browser, { width: 1280, height: 900 }, 1);
    await page.goto(new URL("wander.html", url).href);
    await page.waitForFunction(() => {
      const w = window.__wander;
      return w && (w.error !== null || (w.ready && !w.busy() && w.frames > 2));
    }, null, { timeout: 30000 });
    const status = await page.evaluate(() => ({ error: window.__wander.error, panels: window.__wander.panels() }));
    await check("wander: page loads, eight panels, every tile drawn, no errors", async () => {
      assert.equal(status.error, null);
      assert.deepEqual(status.panels.map((p) => p.name),
        ["control", "distributions", "fields", "time-functions", "timed", "markov", "paths", "composed"]);
      for (const p of status.panels) {
        assert.ok(p.tiles > 0, p.name);
        assert.equal(p.drawn, p.tiles, `${p.name}: ${p.drawn}/${p.tiles} drawn`);
        assert.deepEqual(p.errors, [], p.name);
      }
    });
    await check("wander: every canvas has ink (non-blank)", async () => {
      const n = await page.locator(".tile canvas").count();
      assert.equal(n, status.panels.reduce((s, p) => s + p.tiles, 0));
      for (let i = 0; i < n; i++) {
        const ink = await inked(page, ".tile canvas", i);
        assert.ok(ink > 0.003, `tile ${i}: ink ${ink}`);
      }
    });
    await check("wander: a walk its row's scale would draw as a speck is drawn at its own scale and says so; the Markov tiles measure apart", async () => {
      const tiles = status.panels.flatMap((p) => p.scales.map((t, i) => ({ panel: p.name, i, ...t })));
      const own = tiles.filter((t) => t.zoom > 1);
      // At 1280 px: the unlimited random displacement and the discrete distributions at least.
      assert.ok(own.some((t) => t.panel === "control" && t.i === 0), JSON.stringify(own.map((t) => [t.panel, t.i])));
      assert.ok(own.filter((t) => t.panel === "distributions").length >= 3);
      for (const t of own) assert.match(t.note, /^Drawn at its own scale, \d+× the row's/, `${t.panel} ${t.i}`);
      for (const t of tiles.filter((x) => x.zoom === 1 && x.panel !== "markov")) assert.equal(t.note, "", `${t.panel} ${t.i}`);
      const markov = tiles.filter((t) => t.panel === "markov").map((t) => t.note);
      assert.equal(markov.length, 4);
      assert.equal(new Set(markov).size, 4, markov.join("\n"));
      for (const n of markov) assert.match(n, /^This trace: the angle is 0–15° on \d+ %/);
    });
    await shot(page, "wander-top");
    for (const name of ["control", "fields", "time-functions", "paths"]) {
      await page.locator(`#panel-${name}`).screenshot({ path: resolve(artifacts, `wander-${name}.png`) });
    }
    await check("wander: a knob rebuilds the variants (clamps ×), re-run replays the same traces", async () => {
      const sig = () => page.evaluate(() => {
        const c = document.querySelector("#panel-control .tile canvas");
        return c.toDataURL().length;
      });
      const a = await sig();
      await page.$eval("#control-clamp", (el) => {
        el.value = "0.5";
        el.dispatchEvent(new Event("input", { bubbles: true }));
      });
      const b = await sig();
      assert.notEqual(a, b);
      await page.$eval("#control-clamp", (el) => {
        el.value = "1";
        el.dispatchEvent(new Event("input", { bubbles: true }));
      });
      await page.click("#control-rerun");
      // busy() must see the panel's own re-run at once (it once lagged a frame).
      assert.equal(await page.evaluate(() => window.__wander.busy()), true);
      await page.waitForFunction(() => !window.__wander.busy());
      assert.equal(await sig(), a);
    });
    await check("wander: a bad JSON edit shows the core's message on the tile", async () => {
      const tile = page.locator("#panel-timed .tile").first();
      await tile.locator("summary").click();
      const ta = tile.locator("textarea");
      const text = await ta.inputValue();
      await ta.fill(text.replace(/"mode": "displacement"/, '"mode": "sideways"'));
      await tile.locator("details button").click();
      const err = await tile.locator(".err").textContent();
      assert.match(err, /wander configuration/);
      await ta.fill(text);
      await tile.locator("details button").click();
      assert.equal(await tile.locator(".err").textContent(), "");
    });
    await check("wander: 5,000-deep JSON and duplicate keys are refused with a message, the tile unchanged", async () => {
      const tile = page.locator("#panel-timed .tile").first();
      const ta = tile.locator("textarea");
      const text = await ta.inputValue();
      await ta.fill(`${"[".repeat(5000)}${"]".repeat(5000)}`);
      await tile.locator("details button").click();
      assert.match(await tile.locator(".err").textContent(), /nested more than 32 levels deep/);
      await ta.fill(`{"seed": 1, ${text.trim().slice(1)}`);
      await tile.locator("details button").click();
      assert.match(await tile.locator(".err").textContent(), /seed: given twice/);
      await shot(page, "wander-duplicate-key");
      await ta.fill(text);
      await tile.locator("details button").click();
      assert.equal(await tile.locator(".err").textContent(), "");
    });
    await check("wander: no console errors or warnings", async () => {
      assert.deepEqual(problems, []);
    });
    allProblems.push(...problems);
    await context.close();
  }
} finally {
  await browser.close();
  await server.close();
}
writeFileSync(resolve(artifacts, "gallery-perf.json"), JSON.stringify(report, null, 2));
if (allProblems.length) console.log(allProblems.join("\n"));
