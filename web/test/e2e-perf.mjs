// The browser checks of speed (`make test-e2e-perf`), against the test build in
// Debian's headless Chromium: the SIMD build of the core loads where the
// engine has WebAssembly SIMD and the baseline build where it has not (SIMD
// hidden from WebAssembly.validate), and both run the lab, the crowd and the
// learn page without console errors; above 2,000 agents the funnelling and
// crowd pages draw their agents through WebGL2 (the canvas's data-agents
// says which path drew; the agents' pixels are there). Headless Chromium's
// WebGL is software (SwiftShader): there the pages keep the 2D sprites (a
// WebGL layer would be read back every frame), so the GL checks force it
// with `?draw=gl` and allow the one "GPU stall due to ReadPixels" warning
// that software compositing then prints; `?draw=2d` forces the sprites. Screenshots at 1280 and 390 px in artifacts/perf-gl-*.
// A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check, waitReady, shot, settle, unisolated, countPixels } from "./harness.mjs";
import assert from "node:assert/strict";


/** The core's wasm files the page fetched (Vite adds a hash to the name). */
const wasmFetched = (page) =>
  page.evaluate(() => performance.getEntriesByType("resource").map((e) => e.name.split("/").pop()).filter((n) => n.endsWith(".wasm")));

/** Makes WebAssembly.validate refuse modules using SIMD (opcode prefix 0xfd), as an engine without SIMD does. */
const NO_SIMD = () => {
  const validate = WebAssembly.validate.bind(WebAssembly);
  WebAssembly.validate = (bytes) => {
    const b = new Uint8Array(bytes instanceof ArrayBuffer ? bytes : bytes.buffer);
    return b.length < 64 && b.includes(0xfd) ? false : validate(bytes);
  };
};

const { server, url } = await serve();
const browser = await launch();
try {
  const hashes = {};
  for (const simd of [true, false]) {
    const name = simd ? "simd128" : "baseline";
    await check(`${name} core: the lab and the crowd page load it and run${simd ? "" : ", the lab's 120 steps in the simd128 core's bits"}`, async () => {
      const { page, problems, context } = await openPage(browser);
      if (!simd) await context.addInitScript(NO_SIMD);
      await page.goto(`${url}#n=2000&ov=`);
      assert.equal(await waitReady(page, 60000), null);
      const files = await wasmFetched(page);
      assert.equal(files.length, 1, files.join(", "));
      assert.match(files[0], simd ? /^steering_simd_bg/ : /^steering_bg/);
      const t0 = await page.evaluate(() => window.__lab.frames);
      await page.waitForFunction((f) => window.__lab.frames > f + 5, t0);
      // The same bits from either module in Chromium (web/test/simd-bits.mjs
      // compares them over every preset in Node): 2,000 agents, 120 steps.
      hashes[name] = await page.evaluate(async () => {
        const l = window.__lab;
        l.setPaused(true);
        await l.restart();
        await l.stepN(120);
        return l.stateHash();
      });
      assert.match(hashes[name], /^[0-9a-f]{8,}$/);
      if (!simd) assert.equal(hashes.baseline, hashes.simd128, "the baseline core's state after 120 steps is the simd128 core's");
      await page.goto(url.replace(/\/?$/, "/crowd.html"));
      await page.waitForFunction(() => window.__crowd && (window.__crowd.error !== null || window.__crowd.frames > 2), null, { timeout: 30000 });
      assert.equal(await page.evaluate(() => window.__crowd.error), null);
      assert.match((await wasmFetched(page))[0], simd ? /^steering_simd_bg/ : /^steering_bg/);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }

  /** Pixels of what the page shows over `selector`'s box (every canvas
   *  layer, as composited) within `tol` of one of `colours` ([r, g, b]
   *  each), from one screenshot: a frame of 20,000 agents in software GL
   *  is slow to capture. */
  const colourPixels = async (page, selector, colours, tol = 40) => {
    const near = (rgb) => new Function("r", "g", "b", `return Math.abs(r - ${rgb[0]}) + Math.abs(g - ${rgb[1]}) + Math.abs(b - ${rgb[2]}) < ${tol};`);
    const counts = await countPixels(page, { selector, composited: true }, Object.fromEntries(colours.map((rgb, i) => [`c${i}`, near(rgb)])));
    return colours.reduce((sum, _, i) => sum + counts[`c${i}`], 0);
  };

  /** Problems other than software compositing's ReadPixels notice (forced GL only). */
  const real = (problems) => problems.filter((p) => !/GL Driver Message \(OpenGL, Performance, .*\): GPU stall due to ReadPixels/.test(p));

  await check("software WebGL (headless): 20,000 agents drawn as 2D sprites, no GL warnings", async () => {
    const { page, problems, context } = await openPage(browser);
    await page.goto(`${url}#n=20000&ov=`);
    assert.equal(await waitReady(page, 60000), null);
    await settle(page);
    assert.equal(await page.$eval("#lab", (c) => c.dataset.agents), "sprites");
    assert.deepEqual(problems, []);
    await context.close();
  });

  for (const [w, h] of [[1280, 800], [390, 800]]) {
    await check(`funnelling page, 20,000 agents at ${w} px: drawn through WebGL2, agents on the canvas; ?draw=2d draws sprites`, async () => {
      const { page, problems, context } = await openPage(browser, { width: w, height: h }, w < 500 ? 2 : 1);
      await page.goto(`${url.replace(/\/?$/, "/")}?draw=gl#n=20000&ov=`);
      assert.equal(await waitReady(page, 60000), null);
      await settle(page);
      assert.equal(await page.$eval("#lab", (c) => c.dataset.agents), "webgl2");
      // The agents' dark grey (#2b2b2b) and the mode colours they are
      // filled with (ui/modes.ts): thousands of pixels.
      const painted = await colourPixels(page, "#lab", [[0x2b, 0x2b, 0x2b], [0xd6, 0x27, 0x28], [0xdd, 0x6b, 0x00], [0x1f, 0x5f, 0xd1], [0x8a, 0x8f, 0x98]]);
      assert.ok(painted > 2000, `only ${painted} agent-coloured pixels`);
      await shot(page, `perf-gl-lab-${w}`);
      await page.goto(`${url.replace(/\/?$/, "/")}?draw=2d#n=20000&ov=`);
      assert.equal(await waitReady(page, 60000), null);
      await settle(page);
      assert.equal(await page.$eval("#lab", (c) => c.dataset.agents), "sprites");
      assert.deepEqual(real(problems), []);
      await context.close();
    });
  }
  await check("crowd page, 20,000 boids: drawn through WebGL2, boids on the canvas; 300 boids as triangles", async () => {
    const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
    await page.goto(url.replace(/\/?$/, "/crowd.html?draw=gl"));
    await page.waitForFunction(() => window.__crowd && window.__crowd.frames > 2, null, { timeout: 30000 });
    assert.equal(await page.$eval("#crowd", (c) => c.dataset.agents), "triangles");
    await page.fill("#boids", "20000");
    await page.press("#boids", "Enter");
    await page.click("#boids-confirm"); // above 15,000 the page asks first
    await page.waitForFunction(() => window.__crowd.count() === 20000, null, { timeout: 20000 });
    await settle(page);
    assert.equal(await page.$eval("#crowd", (c) => c.dataset.agents), "webgl2");
    const boid = await colourPixels(page, "#crowd", [[0x2b, 0x4a, 0x7a]]);
    assert.ok(boid > 2000, `only ${boid} boid-coloured pixels`);
    await shot(page, "perf-gl-crowd-1280");
    assert.deepEqual(real(problems), []);
    await context.close();
  });
  // The world stepped in Web Workers (?workers=N).
  const base = url.replace(/\/?$/, "/");
  /** Opens the lab at `query` + `hash`; waits for the workers (if any) to own the world. */
  const openLab = async (query, hash, isolated = true) => {
    const o = await openPage(browser);
    if (!isolated) await unisolated(o.context);
    await o.page.goto(`${base}${query}${hash}`);
    assert.equal(await waitReady(o.page, 120000), null);
    await o.page.waitForFunction(() => !window.__lab.workers()?.starting, null, { timeout: 120000 });
    return o;
  };
  /** Paused, rebuilt at t = 0, `k` steps: the state's hash before and after, and the time. */
  const stepped = (page, k) =>
    page.evaluate(async (k) => {
      const l = window.__lab;
      l.setPaused(true);
      await l.restart();
      const h0 = l.stateHash();
      await l.stepN(k);
      // The shown agent's internals too (workers: noted per step in shared memory).
      return { h0, h: l.stateHash(), count: l.count(), internals: l.internals() };
    }, k);
  const K = 120;
  const oneCore = new Map();
  for (const hash of ["#n=20000&ov=", "#preset=p000_fig6_face_to_face"]) {
    const { page, context } = await openLab("?workers=0", hash);
    assert.equal(await page.evaluate(() => window.__lab.workers()), null);
    oneCore.set(hash, await stepped(page, K));
    await context.close();
  }

  for (const [name, query, hash, isolated, mode, slices] of [
    ["2 workers, shared memory, 20,001 agents", "?workers=2", "#n=20000&ov=", true, "shared", 2],
    ["2 workers, no cross-origin isolation: states by message, 20,001 agents", "?workers=2", "#n=20000&ov=", false, "messages", 2],
    ["3 workers, paper 000 Fig. 6 (agents facing each other stay on one worker)", "?workers=3", "#preset=p000_fig6_face_to_face", true, "shared", 3],
  ]) {
    await check(`${name}: runs, draws, and after ${K} steps equals one core bit for bit`, async () => {
      const { page, problems, context } = await openLab(query, hash, isolated);
      const info = await page.evaluate(() => window.__lab.workers());
      assert.equal(info.mode, mode);
      assert.equal(info.crossOriginIsolated, isolated);
      assert.equal(info.workers, slices, JSON.stringify(info.ranges));
      assert.equal(info.error, null);
      // Running: states arrive and are drawn.
      const f0 = await page.evaluate(() => window.__lab.frames);
      await page.evaluate(() => window.__lab.perfReset());
      await page.waitForFunction((f) => window.__lab.frames > f + 3 && window.__lab.perfStats().updates > 0, f0, { timeout: 30000 });
      if (hash.startsWith("#preset=p000_fig6")) {
        // Fig. 6's pairs (0, 1), (2, 3), …: no worker boundary between a pair.
        for (const [start] of info.ranges) assert.equal(start % 2, 0, JSON.stringify(info.ranges));
      }
      assert.match(await page.$eval("#hud", (e) => e.textContent), new RegExp(`step\\s+${slices} workers, ${mode === "shared" ? "shared memory" : "messages"}`));
      const r = await stepped(page, K);
      assert.notEqual(r.h, r.h0, "the agents moved");
      assert.deepEqual(r, oneCore.get(hash));
      await shot(page, `perf-workers-${mode}-${slices}`);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }

  await check("workers: a drag while paused reaches the worker that owns the agent (same state as one core after it)", async () => {
    const run = async (query) => {
      const { page, problems, context } = await openLab(query, "#n=20000&ov=");
      await page.evaluate(async () => {
        window.__lab.setPaused(true);
        await window.__lab.restart();
      });
      await settle(page);
      const h = await page.evaluate(() => window.__lab.handles());
      const box = await page.locator("#lab").boundingBox();
      await page.mouse.move(box.x + h.vehicle.x, box.y + h.vehicle.y);
      await page.mouse.down();
      await page.mouse.move(box.x + h.vehicle.x - 40, box.y + h.vehicle.y + 30, { steps: 6 });
      await page.mouse.up();
      // The edit goes out with the next job; wait until the drawn state has it.
      await page.waitForFunction((x) => Math.abs(window.__lab.handles().vehicle.x - x) < 2, h.vehicle.x - 40, { timeout: 20000 });
      const moved = await page.evaluate(() => window.__lab.handles().vehicle);
      const out = await page.evaluate(async () => {
        await window.__lab.stepN(60);
        return window.__lab.stateHash();
      });
      assert.deepEqual(problems, []);
      await context.close();
      return { moved, out };
    };
    const one = await run("?workers=0");
    const two = await run("?workers=2");
    assert.deepEqual(two, one);
    assert.ok(Number.isFinite(one.moved.x));
  });

  await check("workers on a table built for other limits (vmax=1.5): the workers get its bytes, same state as one core", async () => {
    const run = async (query) => {
      const { page, problems, context } = await openLab(query, "#n=20000&ov=&vmax=1.5");
      await page.waitForFunction(() => window.__lab.table()?.state === "exact", null, { timeout: 120000 });
      const r = await stepped(page, 60);
      const info = await page.evaluate(() => window.__lab.workers());
      assert.deepEqual(problems, []);
      await context.close();
      return { r, info };
    };
    const one = await run("?workers=0");
    const two = await run("?workers=2");
    assert.equal(one.info, null);
    assert.equal(two.info.workers, 2);
    assert.equal(two.info.error, null);
    assert.deepEqual(two.r, one.r);
  });

  await check("workers by default from 20,000 agents (navigator.hardwareConcurrency of them), none below; a bad ?workers= is reported", async () => {
    let { page, problems, context } = await openLab("", "#n=20000&ov=");
    const info = await page.evaluate(() => window.__lab.workers());
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    assert.equal(info.wanted, Math.min(8, cores));
    assert.notEqual(info.mode, "main");
    assert.deepEqual(problems, []);
    await context.close();
    ({ page, problems, context } = await openLab("", "#n=5000&ov="));
    assert.equal(await page.evaluate(() => window.__lab.workers()), null);
    await context.close();
    ({ page, problems, context } = await openLab("?workers=x", "#n=100&ov="));
    assert.match(await page.$eval("#message", (e) => e.textContent), /workers = x is not a whole number/);
    await context.close();
  });
  await check("workers stop when avoidance is switched on (every agent coupled): the world is rebuilt on the page's core, ORCA in force", async () => {
    const { page, problems, context } = await openLab("?workers=2", "#n=20001&ov=");
    await page.waitForFunction(() => window.__lab.workers()?.mode !== "main" && window.__lab.workers()?.starting === false, null, { timeout: 60000 });
    await page.selectOption("#avoidance", "orca");
    await page.waitForFunction(() => window.__lab.workers()?.mode === "main", null, { timeout: 60000 });
    assert.equal(await page.evaluate(() => window.__lab.avoidance()), "orca");
    const t0 = await page.evaluate(() => window.__lab.simTime());
    await page.waitForFunction((t0) => window.__lab.simTime() > t0, t0, { timeout: 60000 });
    assert.deepEqual(problems, []);
    await context.close();
  });

  // The first drawn frame: the default page draws its scene from
  // the HTML (src/lab/firstframe.ts) before its scripts and core arrive; the
  // core's first frame, the η table held back (the clock at t = 0), must be
  // the same picture, pixel for pixel, from the same state, bit for bit.
  for (const [w, h, dpr] of [[1280, 800, 1], [390, 844, 3]]) {
    await check(`first frame at ${w} px (devicePixelRatio ${dpr}): drawn before the scripts, the core's first frame the same pixels and state`, async () => {
      const { page, problems, context } = await openPage(browser, { width: w, height: h }, dpr);
      const gate = () => {
        let open = () => {};
        const wait = new Promise((r) => { open = r; });
        return { wait, open };
      };
      const scripts = gate();
      const table = gate();
      await page.route(/\.js(\?|$)/, async (r) => { await scripts.wait; await r.continue(); });
      await page.route(/eta\.(bin|planes)/, async (r) => { await table.wait; await r.continue(); });
      const pixels = () => page.evaluate(() => {
        const c = document.getElementById("lab");
        // A PNG of the backing store (getImageData would warn on a canvas not made for readback).
        const d = c.toDataURL("image/png");
        let hsh = 0x811c9dc5;
        for (let i = 0; i < d.length; i++) hsh = Math.imul(hsh ^ d.charCodeAt(i), 0x01000193) >>> 0;
        return { w: c.width, h: c.height, hash: hsh.toString(16) };
      });
      await page.goto(url, { waitUntil: "commit" });
      await page.waitForFunction(() => window.__firstFrame !== undefined, null, { timeout: 30000 });
      assert.equal(await page.evaluate(() => window.__lab), undefined, "the page's modules ran before the first frame");
      const first = await pixels();
      await shot(page, `first-frame-${w}`);
      scripts.open();
      await page.waitForFunction(() => (window.__lab?.frames ?? 0) >= 2, null, { timeout: 60000 });
      assert.equal(await page.evaluate(() => window.__lab.live()), false);
      const core = await pixels();
      await shot(page, `first-frame-core-${w}`);
      assert.deepEqual(core, first, "the core's first frame differs from the HTML's");
      const hashes = await page.evaluate(async () => {
        const u = new Uint32Array(window.__firstFrame.state.buffer);
        let h = 0x811c9dc5;
        for (const x of u) for (let b = 0; b < 32; b += 8) h = Math.imul(h ^ ((x >>> b) & 0xff), 0x01000193) >>> 0;
        return { first: h.toString(16).padStart(8, "0"), core: window.__lab.stateHash(), firstMs: window.__lab.firstFrameMs, ff: window.__firstFrame.ms };
      });
      assert.equal(hashes.first, hashes.core);
      assert.equal(hashes.firstMs, hashes.ff, "window.__lab.firstFrameMs is the HTML's frame");
      table.open();
      assert.equal(await waitReady(page, 60000), null);
      await page.waitForFunction(() => window.__lab.simTime() > 0.5, null, { timeout: 60000 });
      await shot(page, `first-frame-loaded-${w}`);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }
  await check("first frame: a link with a hash or ?workers= is not drawn from the HTML (the core's scene of the link)", async () => {
    for (const at of ["#preset=p000_fig6_face_to_face", "?workers=1"]) {
      const { page, problems, context } = await openPage(browser);
      await page.goto(`${url.replace(/\/?$/, "/")}${at}`);
      assert.equal(await waitReady(page, 60000), null);
      assert.equal(await page.evaluate(() => window.__firstFrame), undefined, at);
      assert.ok(Number.isFinite(await page.evaluate(() => window.__lab.firstFrameMs)), at);
      assert.deepEqual(problems, []);
      await context.close();
    }
  });
} finally {
  await browser.close();
  await server.close();
}
