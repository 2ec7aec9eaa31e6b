// Issue 17's browser checks (`make test-e2e-perf`), against web/dist in
// Debian's headless Chromium: the SIMD build of the core loads where the
// engine has WebAssembly SIMD and the baseline build where it has not (SIMD
// hidden from WebAssembly.validate), and both run the lab, the crowd and the
// learn page without console errors. Prints "e2e-perf: N passed, M failed".
import { serve, launch, openPage, checks, waitReady } from "./harness.mjs";
import assert from "node:assert/strict";

const { check, finish } = checks("e2e-perf");

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
  for (const simd of [true, false]) {
    const name = simd ? "simd128" : "baseline";
    await check(`${name} core: the lab and the crowd page load it and run`, async () => {
      const { page, problems, context } = await openPage(browser);
      if (!simd) await context.addInitScript(NO_SIMD);
      await page.goto(`${url}#n=2000&ov=`);
      assert.equal(await waitReady(page, 60000), null);
      const files = await wasmFetched(page);
      assert.equal(files.length, 1, files.join(", "));
      assert.match(files[0], simd ? /^steering_simd_bg/ : /^steering_bg/);
      const t0 = await page.evaluate(() => window.__lab.frames);
      await page.waitForFunction((f) => window.__lab.frames > f + 5, t0);
      await page.goto(url.replace(/\/?$/, "/crowd.html"));
      await page.waitForFunction(() => window.__crowd && (window.__crowd.error !== null || window.__crowd.frames > 2), null, { timeout: 30000 });
      assert.equal(await page.evaluate(() => window.__crowd.error), null);
      assert.match((await wasmFetched(page))[0], simd ? /^steering_simd_bg/ : /^steering_bg/);
      assert.deepEqual(problems, []);
      await context.close();
    });
  }
} finally {
  await browser.close();
  await server.close();
}
finish();
