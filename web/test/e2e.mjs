// Browser end-to-end test: the built page (web/dist) in Debian's headless
// Chromium via playwright-core. Checks: no console errors or warnings; drags
// change the target's mode colouring (hook state AND canvas pixels); tolerance
// and orientation handles; presets; keyboard; the controller section (μ
// bound, gain, seek threshold) reaching the core and the URL; URL state round
// trip and a malformed link; a corrupt table shows a readable message. Screenshots go
// to artifacts/ (gitignored). A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check, shot, waitReady, settle, dragOnLab as drag, artifacts, countPixels, docsDir } from "./harness.mjs";
import { resolve } from "node:path";
import assert from "node:assert/strict";
import { readFileSync, copyFileSync } from "node:fs";

/** The core's funnelling settings as the page sets them (JSON: absent options drop out). */
const CORE_DEFAULT = {
  bound: { kind: "turningRadius", factor: 8 }, gain: 2, seekThreshold: 0.25, aim: "entry", minBoundRadius: 1, terminal: { lookahead: 1, heading: 0.5, range: 1 },
  reachability: "vote", orientationOnly: "stop", tolerance: "latched", lead: true, orbitFree: true, commitTurn: true,
};
const coreFunnel = (page) => page.evaluate(() => JSON.parse(JSON.stringify(window.__lab.funnel())));


/** Canvas-pixel colour census around a CSS-pixel point of the lab canvas. */
const colours = (page, at, radius) =>
  countPixels(page, { selector: "#lab", around: { at, radius } }, {
    red: (r, g, b) => r > 170 && g < 90 && b < 90,
    // funnelling's own colour (src/ui/modes.ts)
    orange: (r, g, b) => r > 190 && g > 80 && g < 140 && b < 60,
    blue: (r, g, b) => b > 160 && r < 90 && g < 140,
    grey: (r, g, b) => Math.abs(r - 138) < 12 && Math.abs(g - 143) < 12 && Math.abs(b - 152) < 12,
  });

const DOCS = docsDir("node web/test/e2e.mjs [--docs DIR]: the lab end to end, and the README's picture of it (DIR/lab.png)");
const { server, url } = await serve();
const browser = await launch();
const allProblems = [];
try {
  // ---------------------------------------------------------------- playground
  const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 2);
  const t0 = Date.now();
  await page.goto(url);
  const err = await waitReady(page);
  const first = await page.evaluate(() => window.__lab.firstFrameMs);
  console.log(`# first drawn frame ${first.toFixed(0)} ms after navigation start (wall ${Date.now() - t0} ms)`);
  await check("page loads with the table and draws", async () => {
    assert.equal(err, null);
    assert.ok((await page.evaluate(() => window.__lab.count())) >= 1);
    assert.equal(await page.locator("#message").isHidden(), true);
  });
  await check("HiDPI: the backing store is devicePixelRatio × CSS size", async () => {
    const r = await page.evaluate(() => {
      const c = document.getElementById("lab");
      return { w: c.width, cw: c.getBoundingClientRect().width, dpr: devicePixelRatio };
    });
    assert.equal(r.dpr, 2);
    assert.ok(Math.abs(r.w - r.cw * 2) <= 2, JSON.stringify(r));
  });
  await page.waitForTimeout(1500);
  await shot(page, "01-playground-running");

  await check("keyboard: space pauses, s steps, r resets", async () => {
    await page.locator("#lab").click({ position: { x: 5, y: 5 } });
    await page.keyboard.press("Space");
    assert.equal(await page.locator("#play").getAttribute("aria-pressed"), "true");
    const before = await page.evaluate(() => window.__lab.internals()?.d);
    await page.keyboard.press("s");
    const after = await page.evaluate(() => window.__lab.internals()?.d);
    assert.notEqual(before, after);
    await page.keyboard.press("r");
    await settle(page);
    const st = await page.evaluate(() => window.__lab.state());
    const h = await page.evaluate(() => window.__lab.handles());
    assert.ok(h && Math.abs(h.vehicle.x - h.target.x) > 10);
    assert.ok(st.vehicle);
  });

  await check("the HUD: running numbers rewritten at most 15 times a second, a pause at once, a step within 1/15 s", async () => {
    await page.evaluate(() => window.__lab.setPaused(false));
    const seen = await page.evaluate(
      () =>
        new Promise((done) => {
          const el = document.getElementById("hud");
          let writes = 0;
          let frames = 0;
          // One rewrite of the HUD touches several of its parts: one batch of records.
          const mo = new MutationObserver(() => (writes += 1));
          mo.observe(el, { childList: true, characterData: true, subtree: true });
          const t0 = performance.now();
          const tick = () => {
            frames++;
            if (performance.now() - t0 < 1000) requestAnimationFrame(tick);
            else (mo.disconnect(), done({ writes, frames }));
          };
          requestAnimationFrame(tick);
        }),
    );
    assert.ok(seen.writes >= 4 && seen.writes <= 16, `HUD writes in 1 s: ${JSON.stringify(seen)}`);
    await page.evaluate(() => window.__lab.setPaused(true));
    await settle(page);
    assert.match(await page.locator("#hud").textContent(), /paused/);
    const t = (text) => Number(/t (\d+\.\d+) s/.exec(text)[1]);
    const before = t(await page.locator("#hud").textContent());
    await page.locator("#lab").click({ position: { x: 5, y: 5 } });
    await page.keyboard.press("s");
    await page.waitForFunction((b) => Number(/t (\d+\.\d+) s/.exec(document.getElementById("hud").textContent)[1]) > b, before, { timeout: 1000 });
    assert.ok(t(await page.locator("#hud").textContent()) > before);
    // As the keyboard check left it: paused, reset.
    await page.keyboard.press("r");
    await settle(page);
  });

  await check("dragging the target onto the vehicle turns it blue (turning on the spot), out again red or orange (seeking, funnelling)", async () => {
    await page.evaluate(() => window.__lab.setPaused(true));
    let h = await page.evaluate(() => window.__lab.handles());
    const outMode = await page.evaluate(() => window.__lab.mode());
    assert.ok(outMode === 2 || outMode === 3, `outside mode ${outMode}`);
    await drag(page, h.target, h.vehicle);
    h = await page.evaluate(() => window.__lab.handles());
    const inMode = await page.evaluate(() => window.__lab.mode());
    assert.ok(inMode === 1 || inMode === 0, `inside mode ${inMode}`);
    const cin = await colours(page, h.target, 70);
    await shot(page, "02-target-on-vehicle-orientation-only");
    assert.ok(cin.blue > 50 || cin.grey > 50, `blue/grey pixels near target: ${JSON.stringify(cin)}`);
    const far = { x: h.target.x + 300, y: h.target.y - 150 };
    await drag(page, h.target, far);
    h = await page.evaluate(() => window.__lab.handles());
    const outMode2 = await page.evaluate(() => window.__lab.mode());
    assert.ok(outMode2 === 2 || outMode2 === 3, `outside again mode ${outMode2}`);
    const cout = await colours(page, h.target, 70);
    await shot(page, "03-target-away-funnelling");
    assert.ok(cout.red + cout.orange > 50 && cout.blue < cin.blue, `red or orange pixels near target: ${JSON.stringify(cout)}`);
  });

  await check("tolerance circle rim and triangle corner and β handle drag", async () => {
    let h = await page.evaluate(() => window.__lab.handles());
    const s0 = await page.evaluate(() => window.__lab.state());
    const dx = h.rim.x - h.target.x, dy = h.rim.y - h.target.y, n = Math.hypot(dx, dy);
    await drag(page, h.rim, { x: h.rim.x + (dx / n) * 40, y: h.rim.y + (dy / n) * 40 });
    const s1 = await page.evaluate(() => window.__lab.state());
    assert.ok(s1.dTol > s0.dTol + 0.2, `dTol ${s0.dTol} -> ${s1.dTol}`);
    h = await page.evaluate(() => window.__lab.handles());
    await drag(page, h.opening, { x: h.target.x + (h.opening.x - h.target.x) * 0.2 + (h.target.y - h.opening.y) * -0.8, y: h.target.y + (h.opening.y - h.target.y) * 0.2 + (h.opening.x - h.target.x) * 0.8 });
    const s2 = await page.evaluate(() => window.__lab.state());
    assert.ok(Math.abs(s2.epsTol - s1.epsTol) > 0.1, `epsTol ${s1.epsTol} -> ${s2.epsTol}`);
    h = await page.evaluate(() => window.__lab.handles());
    await drag(page, h.beta, { x: h.target.x, y: h.target.y + 80 });
    const s3 = await page.evaluate(() => window.__lab.state());
    assert.ok(Math.abs(s3.target.theta - -Math.PI / 2) < 0.05, `beta ${s3.target.theta}`);
    h = await page.evaluate(() => window.__lab.handles());
    await drag(page, h.heading, { x: h.vehicle.x, y: h.vehicle.y - 80 });
    const s4 = await page.evaluate(() => window.__lab.state());
    assert.ok(Math.abs(s4.vehicle.theta - Math.PI / 2) < 0.05, `vehicle heading ${s4.vehicle.theta}`);
    await shot(page, "04-handles-dragged");
  });

  await check("overlays and the η field view draw", async () => {
    await page.locator("#ov-ring").check();
    await page.locator("#ov-field").check();
    await page.evaluate(() => window.__lab.setPaused(false));
    await page.waitForTimeout(800);
    await page.evaluate(() => window.__lab.setPaused(true));
    await shot(page, "05-eta-field-and-ring");
    await page.locator("#ov-field").uncheck();
    await page.locator("#ov-ring").uncheck();
  });

  await check("exports: trajectories as CSV and JSON, the canvas as PNG", async () => {
    await page.evaluate(() => window.__lab.setPaused(false));
    await page.waitForTimeout(500);
    const grab = async (id, name) => {
      const [dl] = await Promise.all([page.waitForEvent("download"), page.click(`#${id}`)]);
      const dest = resolve(artifacts, name);
      copyFileSync(await dl.path(), dest);
      assert.equal(dl.suggestedFilename(), name);
      return readFileSync(dest);
    };
    const csv = (await grab("csv", "trajectories.csv")).toString("utf8").split("\n");
    assert.equal(csv[0], "agent,t_s,x_m,y_m,theta_rad,v_mps,omega_radps,mode");
    assert.ok(csv.length > 10, `${csv.length} CSV lines`);
    assert.match(csv[5], /^0,[0-9.]+,-?[0-9.]+,-?[0-9.]+,-?[0-9.]+,[0-9.]+,-?[0-9.]+,(Funnelling|Position_only|Orientation_only|End_of_Steering)$/);
    const json = JSON.parse((await grab("json", "trajectories.json")).toString("utf8"));
    assert.equal(json.agents.length, 1);
    assert.ok(json.agents[0].x.length > 5 && json.units.theta === "rad");
    const png = await grab("png", "steering-lab.png");
    assert.deepEqual([...png.subarray(0, 4)], [0x89, 0x50, 0x4e, 0x47]);
    await page.evaluate(() => window.__lab.setPaused(true));
  });

  await check("the canvas follows the window size (HiDPI kept), and what the view framed stays in sight", async () => {
    const size = () => page.evaluate(() => {
      const c = document.getElementById("lab");
      const r = c.getBoundingClientRect();
      return { w: c.width, h: c.height, cw: r.width, ch: r.height };
    });
    const resize = async (width, height) => {
      await page.setViewportSize({ width, height });
      await page.waitForTimeout(200);
      await settle(page);
    };
    const a = await size();
    const scale0 = await page.evaluate(() => window.__lab.viewScale());
    await resize(900, 640);
    const b = await size();
    assert.ok(b.w < a.w && b.h < a.h, `${JSON.stringify(a)} -> ${JSON.stringify(b)}`);
    assert.ok(Math.abs(b.w - b.cw * 2) <= 2);
    await shot(page, "09-resized-900x640");
    // A phone's width, then a turned phone: the vehicle and the target are
    // still on the canvas, not cut off by a scale kept from the wide window.
    for (const [w, h] of [[900, 640], [390, 844], [844, 390]]) {
      await resize(w, h);
      const c = await size();
      const hs = await page.evaluate(() => window.__lab.handles());
      for (const k of ["vehicle", "target"]) {
        const q = hs[k];
        assert.ok(q.x >= 0 && q.x <= c.cw && q.y >= 0 && q.y <= c.ch, `${w}×${h}: the ${k} at ${q.x.toFixed(0)}, ${q.y.toFixed(0)} on a ${c.cw}×${c.ch} canvas`);
      }
    }
    await resize(1280, 800);
    const scale1 = await page.evaluate(() => window.__lab.viewScale());
    assert.ok(Math.abs(scale1 / scale0 - 1) < 1e-9, `back at 1280×800 the scale is ${scale1}, was ${scale0}`);
  });

  // A phone upright and on its side: what floats over the stage (the HUD,
  // folded there, and the legend) covers none of the playground's handles.
  for (const [w, h] of [[390, 844], [844, 390]]) {
    await check(`phone ${w}×${h}: the HUD and the legend leave every handle of the playground free`, async () => {
      const ph = await openPage(browser, { width: w, height: h }, 2, { hasTouch: true, isMobile: true });
      await ph.page.goto(url);
      assert.equal(await waitReady(ph.page), null);
      await settle(ph.page);
      const seen = await ph.page.evaluate(() => {
        const lab = document.getElementById("lab").getBoundingClientRect();
        const box = (q) => {
          const r = document.querySelector(q).getBoundingClientRect();
          return { x: r.x - lab.x, y: r.y - lab.y, w: r.width, h: r.height };
        };
        return { hud: box("#hud"), legend: box(".legend"), folded: document.getElementById("hud").classList.contains("folded"), handles: window.__lab.handles() };
      });
      assert.equal(seen.folded, true, "the HUD starts folded");
      for (const [k, q] of Object.entries(seen.handles)) {
        for (const name of ["hud", "legend"]) {
          const b = seen[name];
          const under = q.x >= b.x && q.x <= b.x + b.w && q.y >= b.y && q.y <= b.y + b.h;
          assert.ok(!under, `the ${k} handle at ${q.x.toFixed(0)}, ${q.y.toFixed(0)} under the ${name} ${JSON.stringify(b)}`);
        }
      }
      await shot(ph.page, `09-phone-${w}x${h}`);
      assert.deepEqual(ph.problems, []);
      await ph.context.close();
    });
  }

  await check("controller section: μ bound select, gain and threshold sliders reach the core and the URL", async () => {
    for (const id of ["mu-bound", "mu-gain", "seek-th"]) assert.equal(await page.locator(`#${id}`).count(), 1, `#${id}`);
    const opts = await page.locator("#mu-bound option").allTextContents();
    assert.deepEqual(opts, ["turning radius ×8 (default)", "6 × literal", "literal (paper)", "constant π/2"]);
    for (const id of ["aim", "pursuit", "relaxed-aim"]) assert.equal(await page.locator(`#${id}`).count(), 1, `#${id}`);
    // The page's defaults are the core's.
    assert.deepEqual(await coreFunnel(page), CORE_DEFAULT);
    assert.deepEqual(await page.evaluate(() => window.__lab.state().funnel), { reading: "ours", bound: "tr", aim: "entry", pursuit: true, relaxedAim: "entry", gain: 2, threshold: 0.25 });
    assert.equal(await page.inputValue("#mu-gain"), "2");
    assert.equal(await page.inputValue("#seek-th"), "0.25");
    const n = await page.evaluate(() => window.__lab.count());
    await page.evaluate(() => window.__lab.setPaused(false));
    await page.selectOption("#mu-bound", "lit");
    await page.locator("#mu-gain").fill("3");
    await page.locator("#seek-th").fill("0.5");
    assert.deepEqual(await coreFunnel(page), { ...CORE_DEFAULT, bound: { kind: "literal" }, gain: 3, seekThreshold: 0.5 });
    const st = await page.evaluate(() => window.__lab.state());
    assert.equal(st.funnel.bound, "lit");
    assert.ok(Math.abs(st.funnel.gain - 3) < 1e-9 && Math.abs(st.funnel.threshold - 0.5) < 1e-9, JSON.stringify(st.funnel));
    assert.equal(await page.evaluate(() => window.__lab.count()), n, "the agents keep running (no rebuild)");
    // The paper's aim and last stretch are one click away, and back.
    await page.selectOption("#aim", "centre");
    await page.selectOption("#pursuit", "off");
    const paper = await coreFunnel(page);
    assert.equal(paper.aim, "centre");
    assert.equal(paper.terminal ?? null, null);
    await page.waitForFunction(() => location.hash.includes("aim=centre") && location.hash.includes("lp=0"), null, { timeout: 2000 });
    await page.selectOption("#aim", "entry");
    await page.selectOption("#pursuit", "on");
    assert.deepEqual(await coreFunnel(page), { ...CORE_DEFAULT, bound: { kind: "literal" }, gain: 3, seekThreshold: 0.5 });
    await page.waitForFunction(() => location.hash.includes("bound=lit"), null, { timeout: 2000 });
    const hash = new URLSearchParams(new URL(page.url()).hash.slice(1));
    assert.equal(hash.get("bound"), "lit");
    assert.equal(Number(hash.get("gain")), 3);
    assert.equal(Number(hash.get("th")), 0.5);
    assert.match(await page.locator("#hud").textContent(), /μ_max /);
    await shot(page, "10-controller-literal");
  });

  await check("the URL state round-trips into a fresh page", async () => {
    await page.waitForTimeout(400);
    const href = page.url();
    assert.ok(href.includes("#"), href);
    const want = await page.evaluate(() => window.__lab.state());
    const p2 = await openPage(browser);
    await p2.page.goto(href);
    assert.equal(await waitReady(p2.page), null);
    const got = await p2.page.evaluate(() => window.__lab.state());
    for (const k of ["dTol", "epsTol", "speed"]) assert.ok(Math.abs(got[k] - want[k]) < 1e-3, `${k}: ${got[k]} vs ${want[k]}`);
    for (const k of ["x", "y", "theta"]) {
      assert.ok(Math.abs(got.target[k] - want.target[k]) < 1e-3, `target.${k}`);
      assert.ok(Math.abs(got.vehicle[k] - want.vehicle[k]) < 1e-3, `vehicle.${k}`);
    }
    assert.deepEqual(got.overlays, want.overlays);
    assert.deepEqual(got.funnel, want.funnel);
    assert.equal(await p2.page.inputValue("#mu-bound"), want.funnel.bound);
    assert.deepEqual(await p2.page.evaluate(() => window.__lab.funnel().bound), { kind: "literal" });
    assert.ok(want.view && got.view, "the view is in the link");
    for (const k of ["cx", "cy", "scale"]) assert.ok(Math.abs(got.view[k] - want.view[k]) < 1e-3, `view.${k}: ${got.view[k]} vs ${want.view[k]}`);
    allProblems.push(...p2.problems);
    await p2.context.close();
  });

  await check("controller settings apply to presets too; back to the defaults", async () => {
    await page.selectOption("#preset", "p000_fig3_funnel");
    await page.waitForFunction(() => window.__lab.state().preset === "p000_fig3_funnel" && window.__lab.count() > 0, null, { timeout: 5000 });
    assert.deepEqual(await coreFunnel(page), { ...CORE_DEFAULT, bound: { kind: "literal" }, gain: 3, seekThreshold: 0.5 });
    await page.selectOption("#mu-bound", "tr");
    await page.locator("#mu-gain").fill("2");
    await page.locator("#seek-th").fill("0.25");
    assert.deepEqual(await coreFunnel(page), CORE_DEFAULT);
    await page.selectOption("#preset", "");
    await page.waitForFunction(() => window.__lab.state().preset === "" && window.__lab.count() === 1, null, { timeout: 5000 });
  });

  await check("a malformed link falls back to defaults with a visible message", async () => {
    const p3 = await openPage(browser);
    await p3.page.goto(`${url}#vx=abc&dtol=-4&bogus=1&ov=radial,nope&preset=missing`);
    assert.equal(await waitReady(p3.page), null);
    const msg = p3.page.locator("#message");
    assert.equal(await msg.isVisible(), true);
    const text = await msg.textContent();
    assert.match(text, /vx="abc"/);
    assert.match(text, /bogus/);
    const st = await p3.page.evaluate(() => window.__lab.state());
    assert.equal(st.vehicle.x, -4);
    assert.equal(st.preset, "");
    await shot(p3.page, "06-malformed-link-message");
    allProblems.push(...p3.problems);
    await p3.context.close();
  });

  await check("a bad controller link (bound=bogus, gain, th) falls back to the defaults with a visible message", async () => {
    const p5 = await openPage(browser);
    await p5.page.goto(`${url}#bound=bogus&gain=nan&th=2&aim=left&lp=2`);
    assert.equal(await waitReady(p5.page), null);
    const msg = p5.page.locator("#message");
    assert.equal(await msg.isVisible(), true);
    const text = await msg.textContent();
    assert.match(text, /bound="bogus"/);
    assert.match(text, /gain="nan"/);
    assert.match(text, /th="2"/);
    assert.match(text, /aim="left"/);
    assert.match(text, /lp="2"/);
    assert.deepEqual(await p5.page.evaluate(() => window.__lab.state().funnel), { reading: "ours", bound: "tr", aim: "entry", pursuit: true, relaxedAim: "entry", gain: 2, threshold: 0.25 });
    assert.deepEqual(await coreFunnel(p5.page), CORE_DEFAULT);
    assert.equal(await p5.page.inputValue("#mu-bound"), "tr");
    await shot(p5.page, "11-bad-controller-link-message");
    allProblems.push(...p5.problems);
    await p5.context.close();
  });

  // The first frame does not wait for the η table. The table's
  // response is held back: the scene at t = 0 is drawn (seek steering, the
  // "loading" badge), a drag made meanwhile is kept, and when the table is
  // let through the same scene funnels from t = 0 with the link's state.
  for (const [w, h, name] of [[1280, 800, "desktop"], [390, 844, "phone"]]) {
    await check(`first frame before the η table (${name} ${w} px): seek view, then funnelling, nothing lost`, async () => {
      const pl = await openPage(browser, { width: w, height: h }, 2);
      let release;
      const held = new Promise((r) => { release = r; });
      await pl.page.route("**/tables/eta.planes", async (r) => { await held; await r.continue(); });
      const frag = "#tx=6&ty=2&tb=90&vx=-4&vy=-1&vth=10&dtol=0.5&etol=8&n=12&seed=4";
      await pl.page.goto(`${url}${frag}`);
      await pl.page.waitForFunction(() => Number.isFinite(window.__lab.firstFrameMs) && window.__lab.frames > 1, null, { timeout: 20000 });
      const before = await pl.page.evaluate(() => ({ live: window.__lab.live(), ready: window.__lab.ready, count: window.__lab.count(), mode: window.__lab.mode(), hud: document.getElementById("hud").textContent, badge: document.querySelector(".table-badge")?.textContent ?? null }));
      assert.equal(before.live, false);
      assert.equal(before.ready, false);
      assert.equal(before.count, 13);
      // The core's provisional plan (Funnelling towards the centre, no η) is
      // shown as seek steering until the table is in.
      assert.equal(before.mode, 3, "the provisional plan");
      assert.match(before.hud, /^seeking/, "the HUD's chip");
      assert.match(before.hud, /η\s+—/);
      assert.match(before.badge ?? "", /loading η table/);
      assert.match(before.hud, /table\s+loading/);
      assert.match(before.hud, /t 0\.00 s/);
      // The badge covers none of the HUD (its chip and buttons).
      const [badge, hud] = await Promise.all([".table-badge", "#hud"].map((q) => pl.page.locator(q).boundingBox()));
      const apart = badge.x >= hud.x + hud.width || hud.x >= badge.x + badge.width || badge.y >= hud.y + hud.height || hud.y >= badge.y + badge.height;
      assert.ok(apart, `the badge ${JSON.stringify(badge)} over the HUD ${JSON.stringify(hud)}`);
      const hs = await pl.page.evaluate(() => window.__lab.handles());
      const reds = await colours(pl.page, hs.target, 40);
      assert.ok(reds.red > 30, `the target drawn in seek red: ${JSON.stringify(reds)}`);
      await shot(pl.page, `14-first-frame-loading-${name}`);
      // A drag while loading: the vehicle moves, and stays moved.
      await drag(pl.page, hs.vehicle, { x: hs.vehicle.x - 30, y: hs.vehicle.y + 20 });
      const st0 = await pl.page.evaluate(() => window.__lab.state());
      assert.ok(Math.abs(st0.vehicle.x - -4) > 0.05, `dragged: ${JSON.stringify(st0.vehicle)}`);
      await pl.page.waitForTimeout(300);
      assert.equal(await pl.page.evaluate(() => window.__lab.live()), false, "still held");
      release();
      await waitReady(pl.page);
      const after = await pl.page.evaluate(() => ({ live: window.__lab.live(), st: window.__lab.state(), mode: window.__lab.mode(), table: window.__lab.table(), hash: location.hash }));
      assert.equal(after.live, true);
      assert.deepEqual(after.st.vehicle, st0.vehicle, "the drag survived the table's arrival");
      assert.deepEqual(after.st.target, st0.target);
      assert.equal(after.table.state, "exact");
      const hudAfter = await pl.page.locator("#hud").textContent();
      assert.match(hudAfter, /^funnelling/, "the HUD's chip");
      // The committed table was fetched, not built: the HUD says so.
      assert.match(hudAfter, /table\s+exact for these limits \(fetched, \d+ ms\)/);
      assert.match(after.hash, /n=12/);
      assert.match(after.hash, /seed=4/);
      await pl.page.waitForTimeout(900);
      assert.equal(await pl.page.locator(".table-badge").count(), 0, "the badge is gone");
      await shot(pl.page, `15-after-table-funnelling-${name}`);
      allProblems.push(...pl.problems);
      await pl.context.close();
    });
  }

  await check("a corrupt table shows a readable message on the page", async () => {
    const p4 = await openPage(browser);
    await p4.page.route("**/tables/eta.planes", (r) => r.fulfill({ status: 200, contentType: "application/octet-stream", body: Buffer.from("this is not an eta table at all") }));
    await p4.page.goto(url);
    const e = await waitReady(p4.page);
    assert.ok(e && /η table/.test(e), String(e));
    const text = await p4.page.locator("#message").textContent();
    assert.match(text, /η table .* rejected/);
    // The scene drawn before the table stays, held at t = 0.
    await p4.page.waitForFunction(() => /table\s+none/.test(document.getElementById("hud").textContent));
    assert.equal(await p4.page.evaluate(() => window.__lab.live()), false);
    await shot(p4.page, "07-corrupt-table-message");
    allProblems.push(...p4.problems);
    await p4.context.close();
  });

  // ------------------------------------------- values the core would refuse
  /** Opens `frag`; returns the page, its message, state and a few measures. */
  const openLink = async (frag, viewport = { width: 1280, height: 800 }) => {
    const p = await openPage(browser, viewport);
    await p.page.goto(`${url}${frag}`);
    assert.equal(await waitReady(p.page), null);
    await p.page.waitForTimeout(600);
    const m = await p.page.evaluate(() => {
      const msg = document.getElementById("message");
      const c = document.getElementById("lab").getBoundingClientRect();
      return { hidden: msg.hidden, text: msg.textContent, msgHeight: msg.getBoundingClientRect().height, canvasHeight: c.height, count: window.__lab.count(), st: window.__lab.state(), hash: location.hash, hud: document.getElementById("hud").textContent };
    });
    return { ...p, ...m };
  };
  const refusedLinks = [
    ["#vd=50", /vd="50": desired speed v_d: 50 is not a number in \[0\.01, 2\] m\/s \(at most max speed\); default kept/, (st) => st.speed === 1.3],
    ["#vmax=0.05", /vd: desired speed v_d 1\.3 m\/s set to 0\.05 m\/s: max speed is 0\.05 m\/s/, (st) => st.speed === 0.05 && st.limits.vMax === 0.05],
    ["#vd=0", /vd="0": desired speed v_d: 0 is not a number in \[0\.01, 2\]/, (st) => st.speed === 1.3],
    ["#n=0x10", /n="0x10": random agents: "0x10" is not a whole number in \[0, 100000\]/, (st) => st.agents === 0],
    ["#vmax=0.05&vd=1", /vd="1": desired speed v_d: 1 is not a number in \[0\.01, 0\.05\] m\/s \(at most max speed\)/, (st) => st.speed === 0.05],
  ];
  for (const [frag, want, stateOk] of refusedLinks) {
    await check(`link ${frag}: refused at the field with a message, playground running, URL rewritten`, async () => {
      const p = await openLink(frag);
      assert.equal(p.hidden, false, "message shown");
      assert.match(p.text, want);
      assert.equal(p.count, 1, "the playground has its agent");
      assert.ok(stateOk(p.st), JSON.stringify({ speed: p.st.speed, limits: p.st.limits, agents: p.st.agents }));
      assert.ok(p.canvasHeight > 200, `canvas ${p.canvasHeight} px`);
      // The address bar holds the state in force: it decodes without a word.
      const again = await openLink(p.hash);
      assert.ok(again.hidden || !/ignored/.test(again.text), again.text);
      assert.equal(again.st.speed, p.st.speed);
      // The agent moves.
      const moved = await p.page.evaluate(() => window.__lab.internals().d);
      assert.ok(Number.isFinite(moved) && moved > 0.3, `D ${moved}`);
      await again.context.close();
      allProblems.push(...p.problems, ...again.problems);
      await p.context.close();
    });
  }
  await check("link #dtol=20: the HUD shows the real distance, not 0 m unreachable", async () => {
    const p = await openLink("#dtol=20");
    assert.equal(p.hidden, true, p.text);
    assert.equal(p.count, 1);
    await p.page.waitForFunction(() => window.__lab.mode() === 0, null, { timeout: 10000 });
    const hud = await p.page.locator("#hud").textContent();
    const d = Number(/D\s+([\d.]+) m/.exec(hud)?.[1]);
    assert.ok(d > 5 && d < 10, hud);
    assert.doesNotMatch(hud, /unreachable/);
    allProblems.push(...p.problems);
    await p.context.close();
  });
  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    await check(`10,000 unknown link keys: the message is capped, the canvas keeps its height (${viewport.width}×${viewport.height})`, async () => {
      const keys = Array.from({ length: 10000 }, (_, i) => `junk${i}=1`).join("&");
      const p = await openLink(`#${keys}&vd=50`, viewport);
      assert.equal(p.hidden, false);
      assert.match(p.text, /… and 9,993 more$/);
      assert.ok(p.msgHeight < viewport.height * 0.31, `message ${p.msgHeight} px`);
      assert.ok(p.canvasHeight > 200, `canvas ${p.canvasHeight} px`);
      assert.equal(p.count, 1);
      assert.ok(p.hash.length < 1000 && !p.hash.includes("junk"), "URL rewritten");
      await shot(p.page, `12-message-cap-${viewport.width}`);
      allProblems.push(...p.problems);
      await p.context.close();
    });
  }
  for (const viewport of [{ width: 1280, height: 800 }, { width: 390, height: 844 }]) {
    await check(`panel: a refused number is reported at its field and the value kept; a lower max speed clamps the desired speed (${viewport.width}×${viewport.height})`, async () => {
      const p = await openLink("", viewport);
      await p.page.fill("#speed-num", "50");
      await p.page.press("#speed-num", "Enter");
      const msg = p.page.locator("#speed-msg");
      assert.equal(await msg.isVisible(), true);
      assert.match(await msg.textContent(), /desired speed v_d: 50 is not a number in \[0\.01, 2\] m\/s \(at most max speed\); 1\.3 m\/s kept/);
      assert.equal(await p.page.evaluate(() => window.__lab.state().speed), 1.3);
      assert.equal(await p.page.inputValue("#speed-num"), "1.3");
      await p.page.locator("#speed-msg").scrollIntoViewIfNeeded();
      await shot(p.page, `13-refused-value-${viewport.width}`);
      // The max speed below the desired speed: clamped, said at the field.
      await p.page.fill("#vmax-num", "0.5");
      await p.page.press("#vmax-num", "Enter");
      assert.equal(await p.page.evaluate(() => window.__lab.state().speed), 0.5);
      assert.match(await msg.textContent(), /desired speed v_d 1\.3 m\/s set to 0\.5 m\/s: max speed is 0\.5 m\/s/);
      assert.equal(await p.page.getAttribute("#speed", "max"), "0.5", "the slider's end follows the max speed");
      await p.page.click("#reset");
      await settle(p.page);
      assert.equal(await p.page.evaluate(() => window.__lab.count()), 1, "Reset keeps the playground");
      await p.page.waitForFunction(() => location.hash.includes("vmax=0.5") && location.hash.includes("vd=0.5"), null, { timeout: 3000 });
      allProblems.push(...p.problems);
      await p.context.close();
    });
  }

  await check("touch: a finger drags the target (pointer events with capture)", async () => {
    const t = await openPage(browser, { width: 800, height: 600 }, 1, { hasTouch: true, isMobile: false });
    await t.page.goto(url);
    assert.equal(await waitReady(t.page), null);
    await t.page.evaluate(() => window.__lab.setPaused(true));
    const h = await t.page.evaluate(() => window.__lab.handles());
    const box = await t.page.locator("#lab").boundingBox();
    const cdp = await t.context.newCDPSession(t.page);
    const at = (p) => [{ x: box.x + p.x, y: box.y + p.y }];
    await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: at(h.target) });
    for (let i = 1; i <= 10; i++) {
      await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: at({ x: h.target.x - 12 * i, y: h.target.y + 8 * i }) });
    }
    await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
    await settle(t.page);
    const h2 = await t.page.evaluate(() => window.__lab.handles());
    assert.ok(Math.abs(h2.target.x - (h.target.x - 120)) < 3 && Math.abs(h2.target.y - (h.target.y + 80)) < 3, `${JSON.stringify(h.target)} -> ${JSON.stringify(h2.target)}`);
    allProblems.push(...t.problems);
    await t.context.close();
  });

  const presets = await page.evaluate(() => window.__lab.presets());
  console.log(`# presets: ${presets.join(", ") || "(none)"}`);
  for (const name of presets) {
    await check(`preset ${name} loads from the selector and runs`, async () => {
      await page.selectOption("#preset", name);
      await page.waitForFunction((n) => window.__lab.state().preset === n && window.__lab.count() > 0, name, { timeout: 5000 });
      assert.equal(await page.locator("#message").isHidden(), true, await page.locator("#message").textContent());
      await page.evaluate(() => window.__lab.setPaused(false));
      // Thirty frames drawn: half a second at 60 Hz, however busy the machine.
      const f0 = await page.evaluate(() => window.__lab.frames);
      await page.waitForFunction((f) => window.__lab.frames >= f + 30, f0);
      await shot(page, `08-preset-${name}`);
      assert.ok(page.url().includes(`preset=${encodeURIComponent(name)}`) || page.url().includes(`preset=${name}`));
      // Every paper preset states its claim and our measurement.
      if (/^p\d{3}_fig/.test(name)) {
        assert.match(await page.locator("#caption .claim").textContent(), /^Paper: ./);
        assert.match(await page.locator("#caption .measured").textContent(), /^Ours: ./);
      }
    });
  }

  await check("the preset menu groups presets by paper and figure", async () => {
    const groups = await page.locator("#preset optgroup").evaluateAll((gs) => gs.map((g) => g.label));
    assert.ok(groups.some((g) => g.startsWith("Paper 000")) && groups.some((g) => g.startsWith("Paper 001")), groups.join(" | "));
    const inFig11 = await page.locator('#preset optgroup[label^="Paper 001"] option').evaluateAll((os) => os.filter((o) => o.textContent.startsWith("Fig. 11 ")).length);
    assert.equal(inFig11, 8);
    for (const [w, h, tag] of [[1280, 800, "desktop"], [390, 844, "phone"]]) {
      await page.setViewportSize({ width: w, height: h });
      await page.selectOption("#preset", "p001_fig11_tol45_relaxed");
      await page.waitForFunction(() => window.__lab.state().preset === "p001_fig11_tol45_relaxed" && window.__lab.count() > 0, null, { timeout: 5000 });
      await page.locator("#caption").scrollIntoViewIfNeeded();
      await page.locator("#caption").screenshot({ path: `${artifacts}/09-fidelity-caption-${tag}.png` });
    }
    await page.setViewportSize({ width: 1280, height: 800 });
    await page.selectOption("#preset", "");
    await page.waitForFunction(() => window.__lab.state().preset === "" && window.__lab.count() === 1, null, { timeout: 5000 });
  });

  // The README's picture of the lab, made here so it shows the lab as it is:
  // a paper-figure preset playing, side panel and caption in view.
  await check("the README's screenshot (lab.png): a paper-figure preset playing", async () => {
    await page.selectOption("#preset", "p001_fig10_beta45_relaxed");
    await page.waitForFunction(() => window.__lab.state().preset === "p001_fig10_beta45_relaxed" && window.__lab.count() > 0, null, { timeout: 5000 });
    if ((await page.locator("#play").getAttribute("aria-pressed")) === "true") await page.locator("#play").click();
    await page.waitForTimeout(5000);
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.screenshot({ path: resolve(DOCS, "lab.png"), scale: "css" });
    await page.selectOption("#preset", "");
    await page.waitForFunction(() => window.__lab.state().preset === "" && window.__lab.count() === 1, null, { timeout: 5000 });
  });

  allProblems.push(...problems);
  await check("no console errors or warnings on any page", async () => {
    assert.deepEqual(allProblems, []);
  });
  await context.close();
} finally {
  await browser.close();
  await server.close();
}
