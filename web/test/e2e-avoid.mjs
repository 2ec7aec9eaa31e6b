// Playwright for avoidance in the lab, against the built page in
// Debian's headless Chromium. The page's own loop plays the antipodal circle
// swap (32 agents, preset avoid_circle32) while a sampler in the page reads
// the core's overlap count (`Lab.overlaps`, pairs closer than two body
// radii) every animation frame: 0 over the whole swap with ORCA, > 0 with
// avoidance off (so the check can fail). Also: the panel's selector changes
// the core's method and the link; presets bring their own method and
// obstacles; a mouse and a finger drag obstacles (pointer events with
// capture) and the core's obstacles move; added obstacles survive a reload
// through the link; a malformed link is refused field by field. Screenshots
// at desktop and 390 px widths in artifacts/. A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check, shot, waitReady, settle, dragOnLab as mouseDrag } from "./harness.mjs";
import assert from "node:assert/strict";


/** Plays the loaded preset in the page until every agent has finished or
 *  `maxSimS` of simulated time passed (or, with `stopOnOverlap`, the first
 *  overlap); returns the most pairs overlapping in one frame, frames seen,
 *  simulated seconds and agents finished. */
async function play(page, maxSimS, stopOnOverlap = false) {
  return page.evaluate(({ maxSimS, stopOnOverlap }) => new Promise((resolve) => {
    const lab = window.__lab;
    lab.setPaused(false);
    let worst = 0;
    let frames = 0;
    const frame = () => {
      frames++;
      worst = Math.max(worst, lab.overlaps());
      const t = lab.simTime();
      const done = lab.finished() === lab.count();
      if (t >= maxSimS || done || (stopOnOverlap && worst > 0)) {
        lab.setPaused(true);
        resolve({ worst, frames, t, finished: lab.finished(), count: lab.count() });
      } else requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  }), { maxSimS, stopOnOverlap });
}

const { server, url } = await serve();
const browser = await launch();
const allProblems = [];
const base = url.replace(/\/?$/, "/");
try {
  const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
  await page.goto(`${base}#preset=avoid_circle32&ov=`);
  assert.equal(await waitReady(page, 60000), null);

  await check("the circle swap preset brings ORCA: the panel shows it, the core runs it", async () => {
    await page.waitForFunction(() => window.__lab.count() === 32, null, { timeout: 10000 });
    assert.equal(await page.evaluate(() => window.__lab.avoidance()), "orca");
    assert.equal(await page.locator("#avoidance").inputValue(), "orca");
  });

  await check("circle swap N = 32 played in the page with ORCA: 0 overlapping pairs in every frame, every agent arrives", async () => {
    // Paused first: "r" rebuilds at t = 0 and keeps the pause, so the
    // clock cannot run past 0 before the check sees it (play() unpauses).
    await page.evaluate(() => window.__lab.setPaused(true));
    await page.keyboard.press("r");
    // The rebuild is done when the swap starts again (nobody at its target).
    await page.waitForFunction(() => window.__lab.simTime() === 0 && window.__lab.count() === 32 && window.__lab.finished() === 0, null, { timeout: 10000 });
    const r = await play(page, 60);
    console.log(`# ORCA: ${r.frames} frames, ${r.t.toFixed(1)} s simulated, ${r.finished}/${r.count} finished, most overlapping pairs in a frame ${r.worst}`);
    await shot(page, "avoid-01-circle32-orca-end");
    assert.equal(r.worst, 0);
    assert.ok(r.frames > 100, `${r.frames} frames sampled`);
    assert.equal(r.finished, r.count, `${r.finished}/${r.count} finished in ${r.t.toFixed(1)} s`);
  });

  await check("selecting off in the panel changes the core's method and the link; the same swap then overlaps", async () => {
    await page.selectOption("#avoidance", "off");
    assert.equal(await page.evaluate(() => window.__lab.avoidance()), "off");
    await page.waitForFunction(() => location.hash.includes("avoid=off"), null, { timeout: 3000 });
    // Reset keeps the choice (the link's state), and replays the swap.
    // Paused first: "r" rebuilds at t = 0 and keeps the pause, so the
    // clock cannot run past 0 before the check sees it (play() unpauses).
    await page.evaluate(() => window.__lab.setPaused(true));
    await page.keyboard.press("r");
    // The rebuild is done when the swap starts again (nobody at its target).
    await page.waitForFunction(() => window.__lab.simTime() === 0 && window.__lab.count() === 32 && window.__lab.finished() === 0, null, { timeout: 10000 });
    assert.equal(await page.evaluate(() => window.__lab.avoidance()), "off");
    const r = await play(page, 30, true);
    console.log(`# off: overlapping pairs ${r.worst} after ${r.t.toFixed(1)} s simulated`);
    await shot(page, "avoid-02-circle32-off-overlap");
    assert.ok(r.worst > 0, `no overlap in ${r.t} s with avoidance off: the check could not fail`);
  });

  await check("separation and ORCA selected in the panel reach the core", async () => {
    for (const m of ["separation", "orca"]) {
      await page.selectOption("#avoidance", m);
      assert.equal(await page.evaluate(() => window.__lab.avoidance()), m);
      await page.waitForFunction((m) => location.hash.includes(`avoid=${m}`), m, { timeout: 3000 });
    }
  });

  await check("the plans select reaches the core and the link (every step, then back to every 2 steps)", async () => {
    assert.equal(await page.evaluate(() => window.__lab.replanEvery()), 2);
    assert.equal(await page.locator("#avoidance-plan").inputValue(), "2");
    const options = await page.locator("#avoidance-plan option").evaluateAll((os) => os.map((o) => o.value));
    assert.deepEqual(options, ["1", "2", "3", "4"]);
    await page.selectOption("#avoidance-plan", "1");
    assert.equal(await page.evaluate(() => window.__lab.replanEvery()), 1);
    await page.waitForFunction(() => location.hash.includes("plan=1"), null, { timeout: 3000 });
    await page.selectOption("#avoidance-plan", "2");
    assert.equal(await page.evaluate(() => window.__lab.replanEvery()), 2);
    await page.waitForFunction(() => location.hash.includes("plan=2"), null, { timeout: 3000 });
  });

  await check("another preset brings its own method and obstacles (corridor: ORCA, two walls)", async () => {
    await page.selectOption("#preset", "avoid_corridor");
    await page.waitForFunction(() => window.__lab.state().preset === "avoid_corridor" && window.__lab.count() === 24, null, { timeout: 10000 });
    assert.equal(await page.evaluate(() => window.__lab.avoidance()), "orca");
    assert.equal(await page.locator("#avoidance").inputValue(), "orca");
    const obs = await page.evaluate(() => window.__lab.obstacles());
    assert.equal(obs.length, 10);
    assert.deepEqual([obs[0], obs[5]], [1, 1]);
    await page.waitForFunction(() => !location.hash.includes("avoid=") && !location.hash.includes("obs=") && !location.hash.includes("plan="), null, { timeout: 3000 });
    assert.equal(await page.evaluate(() => window.__lab.replanEvery()), 2);
  });

  await check("mouse: dragging a wall's middle moves it in the core; an end moves one end", async () => {
    await page.evaluate(() => window.__lab.setPaused(true));
    const before = await page.evaluate(() => window.__lab.obstacles());
    const scale = await page.evaluate(() => window.__lab.viewScale());
    const [a, b] = await page.evaluate(() => window.__lab.obstacleKnobs(0));
    const mid = { x: (a.x + b.x) / 2 + 0.3 * (b.x - a.x), y: (a.y + b.y) / 2 };
    await mouseDrag(page, mid, { x: mid.x + 40, y: mid.y - 60 });
    const after = await page.evaluate(() => window.__lab.obstacles());
    const dx = 40 / scale;
    const dy = 60 / scale;
    for (const [k, d] of [[1, dx], [2, dy], [3, dx], [4, dy]]) {
      assert.ok(Math.abs(after[k] - before[k] - d) < 0.05, `wall coordinate ${k}: ${before[k]} → ${after[k]} (expected +${d.toFixed(2)})`);
    }
    assert.deepEqual(after.slice(5), before.slice(5), "the other wall stays");
    await page.waitForFunction(() => location.hash.includes("obs=s%3A") || location.hash.includes("obs=s:"), null, { timeout: 3000 });
    const [a2] = await page.evaluate(() => window.__lab.obstacleKnobs(0));
    await mouseDrag(page, a2, { x: a2.x - 30, y: a2.y });
    const end = await page.evaluate(() => window.__lab.obstacles());
    assert.ok(Math.abs(end[1] - after[1] + 30 / scale) < 0.05 && Math.abs(end[3] - after[3]) < 1e-6, JSON.stringify([after.slice(0, 5), end.slice(0, 5)]));
    await shot(page, "avoid-03-corridor-wall-dragged");
  });

  await check("touch: a finger drags a doorway wall (pointer events with capture)", async () => {
    const t = await openPage(browser, { width: 390, height: 844 }, 2, { hasTouch: true, isMobile: true });
    await t.page.goto(`${base}#preset=avoid_doorway&ov=`);
    assert.equal(await waitReady(t.page, 60000), null);
    await t.page.waitForFunction(() => window.__lab.count() > 0 && window.__lab.obstacles().length > 0, null, { timeout: 10000 });
    await t.page.evaluate(() => window.__lab.setPaused(true));
    await settle(t.page);
    await shot(t.page, "avoid-04-doorway-390");
    const before = await t.page.evaluate(() => window.__lab.obstacles());
    const scale = await t.page.evaluate(() => window.__lab.viewScale());
    const n = before.length / 5;
    // The first obstacle whose first knob is on the canvas.
    const box = await t.page.locator("#lab").boundingBox();
    let i = -1;
    let k = null;
    for (let j = 0; j < n && i < 0; j++) {
      const [p] = await t.page.evaluate((j) => window.__lab.obstacleKnobs(j), j);
      if (p.x > 20 && p.y > 20 && p.x < box.width - 40 && p.y < box.height - 40) { i = j; k = p; }
    }
    assert.ok(i >= 0, "an obstacle knob on screen");
    const cdp = await t.context.newCDPSession(t.page);
    const at = (p) => [{ x: box.x + p.x, y: box.y + p.y }];
    await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: at(k) });
    for (let s = 1; s <= 10; s++) await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: at({ x: k.x + 2 * s, y: k.y + 1.5 * s }) });
    await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
    await settle(t.page);
    const after = await t.page.evaluate(() => window.__lab.obstacles());
    const o = i * 5;
    assert.ok(Math.abs(after[o + 1] - before[o + 1] - 20 / scale) < 0.05 && Math.abs(after[o + 2] - before[o + 2] + 15 / scale) < 0.05,
      `obstacle ${i}: ${before.slice(o, o + 5)} → ${after.slice(o, o + 5)}`);
    await shot(t.page, "avoid-05-doorway-390-dragged");
    allProblems.push(...t.problems);
    await t.context.close();
  });

  await check("playground: + disc and + wall add obstacles, the rim knob sizes the disc, the link carries them into a fresh page", async () => {
    await page.selectOption("#preset", "");
    await page.waitForFunction(() => window.__lab.state().preset === "" && window.__lab.count() >= 1, null, { timeout: 10000 });
    assert.equal(await page.evaluate(() => window.__lab.avoidance()), "off");
    assert.equal((await page.evaluate(() => window.__lab.obstacles())).length, 0);
    await page.evaluate(() => window.__lab.setPaused(true));
    await page.click("#add-disc");
    await page.click("#add-wall");
    const obs = await page.evaluate(() => window.__lab.obstacles());
    assert.equal(obs.length, 10);
    const scale = await page.evaluate(() => window.__lab.viewScale());
    const [, rim] = await page.evaluate(() => window.__lab.obstacleKnobs(0));
    await mouseDrag(page, rim, { x: rim.x + 0.5 * scale, y: rim.y });
    const sized = await page.evaluate(() => window.__lab.obstacles());
    assert.ok(Math.abs(sized[3] - (obs[3] + 0.5)) < 0.05, `radius ${obs[3]} → ${sized[3]}`);
    await page.selectOption("#avoidance", "orca");
    await page.evaluate(() => window.__lab.setPaused(false));
    await page.waitForTimeout(800);
    await shot(page, "avoid-06-playground-obstacles-orca");
    await page.click("#copy-link").catch(() => {});
    await page.waitForFunction(() => location.hash.includes("obs=") && location.hash.includes("avoid=orca"), null, { timeout: 3000 });
    const link = await page.evaluate(() => location.href);
    const f = await openPage(browser, { width: 1280, height: 800 }, 1);
    await f.page.goto(link);
    assert.equal(await waitReady(f.page, 60000), null);
    assert.equal(await f.page.evaluate(() => window.__lab.avoidance()), "orca");
    const again = await f.page.evaluate(() => window.__lab.obstacles());
    assert.equal(again.length, 10);
    sized.forEach((v, j) => assert.ok(Math.abs(v - again[j]) < 1e-3, `obstacle float ${j}: ${v} → ${again[j]}`));
    assert.deepEqual(await f.page.evaluate(() => window.__lab.problems), []);
    allProblems.push(...f.problems);
    await f.context.close();
  });

  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    await check(`a malformed avoidance link is refused field by field with a message (${viewport.width} px)`, async () => {
      const p = await openPage(browser, viewport, 2);
      await p.page.goto(`${base}#avoid=rvo&plan=9&obs=d:1,2,0;s:0,0,0,0`);
      assert.equal(await waitReady(p.page, 60000), null);
      const probs = await p.page.evaluate(() => window.__lab.problems);
      assert.ok(probs.some((m) => m.startsWith('avoid="rvo" is not one of off, separation, orca')), JSON.stringify(probs));
      assert.ok(probs.some((m) => m.startsWith("obs: obstacle 1: obstacle.radius")), JSON.stringify(probs));
      assert.ok(probs.some((m) => m.startsWith('plan="9" is not a whole number of steps in [1, 4]')), JSON.stringify(probs));
      assert.equal(await p.page.evaluate(() => window.__lab.replanEvery()), 2);
      assert.equal(await p.page.locator("#message").isVisible(), true);
      assert.equal(await p.page.evaluate(() => window.__lab.avoidance()), "off");
      assert.equal((await p.page.evaluate(() => window.__lab.obstacles())).length, 0);
      await p.page.waitForFunction(() => !location.hash.includes("avoid=") && !location.hash.includes("obs="), null, { timeout: 3000 });
      await shot(p.page, `avoid-07-bad-link-${viewport.width}`);
      allProblems.push(...p.problems);
      await p.context.close();
    });
  }

  await check("desktop and phone screenshots of the corridor with ORCA (bodies, walls, knobs)", async () => {
    for (const [w, h, tag] of [[1280, 800, "desktop"], [390, 844, "phone"]]) {
      const p = await openPage(browser, { width: w, height: h }, 2);
      await p.page.goto(`${base}#preset=avoid_corridor&ov=`);
      assert.equal(await waitReady(p.page, 60000), null);
      await p.page.waitForTimeout(4000);
      await shot(p.page, `avoid-08-corridor-${tag}`);
      await p.page.locator("#panel fieldset:nth-of-type(2)").screenshot({ path: `${(await import("./harness.mjs")).artifacts}/avoid-09-panel-${tag}.png` });
      allProblems.push(...p.problems);
      await p.context.close();
    }
  });

  allProblems.push(...problems);
  await context.close();
  await check("no console errors or warnings", async () => {
    assert.deepEqual(allProblems, []);
  });
} finally {
  await browser.close();
  await server.close();
}
