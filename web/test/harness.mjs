// Shared by the e2e and perf scripts: serves the test build (web/dist-test,
// `make web-build-test`: the pages with their test hooks) with Vite's
// preview server on 127.0.0.1 and launches Debian's Chromium via
// playwright-core.
import { preview } from "vite";
import { chromium } from "playwright-core";
import { fileURLToPath } from "node:url";
import { dirname, resolve } from "node:path";
import { mkdirSync } from "node:fs";
import { spawn } from "node:child_process";
import { test } from "node:test";
import { options } from "./options.mjs";

export const webDir = resolve(dirname(fileURLToPath(import.meta.url)), "..");
export const artifacts = resolve(webDir, "../artifacts");
/** The build the suites drive: the pages with their test hooks. */
export const testDist = resolve(webDir, "dist-test");
mkdirSync(artifacts, { recursive: true });

/** Where a suite writes the pictures the repository commits (docs/lab.png,
 *  docs/screenshots/): its `--docs DIR` option (test/options.mjs), by
 *  default artifacts/docs, so that a test run leaves a clean checkout clean;
 *  `make screenshots` passes `--docs docs` to refresh the committed ones. */
export function docsDir(usage) {
  const { values } = options(usage, {
    docs: { type: "string", default: "artifacts/docs", arg: "DIR", help: "the folder for the committed pictures (docs to refresh them)" },
  });
  const dir = resolve(webDir, "..", values.docs);
  mkdirSync(resolve(dir, "screenshots"), { recursive: true });
  return dir;
}

export const CHROMIUM_ARGS = [
  "--headless=new",
  "--no-sandbox",
  "--disable-gpu",
  "--disable-dev-shm-usage",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
  "--disable-quic",
  "--no-first-run",
  // The browser's own omnibox popups are WebUI pages, preloaded in a
  // renderer of their own for every window (a context here): seen taking
  // 15–45 % of a core each through a suite, for a UI no test shows.
  "--disable-features=WebUIOmniboxPopup,WebUIOmniboxAimPopup,WebUIOmniboxFullPopup",
];

/** Chromium's flags for WebGPU on a machine without a GPU: Dawn over
 *  SwiftShader's Vulkan (a CPU emulation), the page on http://127.0.0.1
 *  (a secure context). CHROMIUM_ARGS less --disable-gpu. */
export const GPU_ARGS = [
  ...CHROMIUM_ARGS.filter((a) => a !== "--disable-gpu"),
  "--enable-unsafe-webgpu",
  "--enable-features=Vulkan",
  "--use-webgpu-adapter=swiftshader",
  "--use-vulkan=swiftshader",
  // A WebGPU canvas needs the compositor on SwiftShader too (without these
  // two, configuring one fails: "A valid external Instance reference no longer exists").
  "--use-angle=swiftshader",
  "--enable-unsafe-swiftshader",
];

/** Serves web/dist-test, or `outDir` (another build's, e.g. a baseline). */
export async function serve(outDir = testDist) {
  const server = await preview({
    root: webDir,
    configFile: resolve(webDir, "vite.config.ts"),
    logLevel: "warn",
    preview: { host: "127.0.0.1", port: 0, strictPort: false },
    build: { outDir: resolve(outDir) },
  });
  const url = server.resolvedUrls?.local?.[0];
  if (!url) throw new Error("vite preview gave no URL");
  return { server, url };
}

/** The `--base DIR` option of the benches (repeatable; test/options.mjs):
 *  the dists of other builds to measure beside this one in the same run. */
export const BASE_OPTION = {
  base: { type: "string", multiple: true, default: [], arg: "DIR", help: "another build's dist (e.g. main's web/dist-test) measured beside this one, same run" },
};

/** Serves this build (web/dist-test, or `outDir`) and each base dist: `url`,
 *  `bases` ({ dir, url, server }), `builds` ([name, url], "this" first) and
 *  `close()` for every server. The benches' same-run baselines. */
export async function serveBuilds(baseDirs, outDir) {
  const { server, url } = await serve(outDir);
  const bases = [];
  for (const dir of baseDirs) bases.push({ dir, ...(await serve(dir)) });
  const builds = [["this", url], ...bases.map((b) => [b.dir, b.url])];
  const close = async () => {
    await server.close();
    for (const b of bases) await b.server.close();
  };
  return { url, bases, builds, close };
}

/** `builds` in round `round`'s order: rotated by one each round, so a drift
 *  in the host's speed favours no build. */
export function rotated(builds, round) {
  return builds.map((_, k) => builds[(k + round) % builds.length]);
}

/** As serve, but from a child process (test/serve.mjs): the server's work
 *  then does not wait on the harness's own (perf.mjs --server child). */
export function serveChild(outDir) {
  const child = spawn(process.execPath, [resolve(webDir, "test/serve.mjs"), outDir ? resolve(outDir) : ""], { stdio: ["ignore", "pipe", "inherit"] });
  return new Promise((ok, fail) => {
    let out = "";
    child.once("exit", (code) => fail(new Error(`the preview server exited (${code})`)));
    child.stdout.on("data", (d) => {
      out += String(d);
      const line = out.split("\n")[0];
      if (out.includes("\n")) ok({ url: line.trim(), server: { close: async () => { child.kill(); } } });
    });
  });
}

/** The exit code of a suite whose browser process died under it (a crash
 *  of Chromium itself, not a failed check): test/suite.mjs runs such a
 *  suite once more. 75 is sysexits' EX_TEMPFAIL. */
export const BROWSER_CRASHED = 75;

/** Chromium from Debian's package, or the binary at $CHROMIUM: where the
 *  browser is installed is a fact of the host, not an option of a run.
 *  A browser that disconnects before the script closes it has crashed:
 *  that is said at once, with where Chromium left its crash dump, and the
 *  script then exits with BROWSER_CRASHED whatever its checks said (the
 *  checks that were running were cut short by the crash, not failed by
 *  the page). `args`: Chromium's flags (the GPU suite's own: WebGPU over
 *  SwiftShader, GPU_ARGS). */
export async function launch(args = CHROMIUM_ARGS) {
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args,
  });
  let closing = false;
  const close = browser.close.bind(browser);
  browser.close = (...a) => { closing = true; return close(...a); };
  browser.on("disconnected", () => {
    if (closing) return;
    console.error(`\n*** Chromium's browser process exited under the suite (a crash; dumps in ~/.config/chromium/Crash Reports/pending). Exit code ${BROWSER_CRASHED}.\n`);
    process.on("exit", () => { process.exitCode = BROWSER_CRASHED; });
  });
  return browser;
}

/** Opens a page that records console errors/warnings and page errors. */
export async function openPage(browser, viewport = { width: 1280, height: 800 }, deviceScaleFactor = 1, extra = {}) {
  const context = await browser.newContext({ viewport, deviceScaleFactor, ...extra });
  const page = await context.newPage();
  const problems = [];
  page.on("console", (m) => {
    if (m.type() === "error" || m.type() === "warning") problems.push(`console.${m.type()}: ${m.text()}`);
  });
  page.on("pageerror", (e) => problems.push(`pageerror: ${e.message}`));
  return { context, page, problems };
}

export async function waitReady(page, timeout = 20000) {
  await page.waitForFunction(() => {
    const l = window.__lab;
    return l && (l.error !== null || (l.ready && l.frames > 1));
  }, null, { timeout });
  return page.evaluate(() => window.__lab.error);
}

/** The crowd page at `at` (a served dist's URL) in `workers` workers
 *  (`?workers=`), loaded with `n` boids at Test IV density, its workers
 *  started (perf.mjs, budget.mjs). */
export async function loadCrowd(page, at, workers, n) {
  await page.goto(`${at.replace(/\/?$/, "/")}crowd.html?workers=${workers}`);
  await page.waitForFunction(() => window.__crowd && (window.__crowd.error !== null || window.__crowd.frames > 2), null, { timeout: 60000 });
  await page.evaluate((k) => window.__crowd.loadScaled(k), n);
  await page.waitForFunction(() => !window.__crowd.workers().starting, null, { timeout: 120000 });
}

/** Resolves after the page has run two animation frames: whatever an input
 *  changed has then been drawn, however slow the host (a fixed sleep is not
 *  enough on a loaded CI machine). */
export function settle(page) {
  return page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r()))));
}

/** One test of a suite, on node:test (its runner prints each result and,
 *  at the end, the suite's pass / fail counts; a failure sets the exit
 *  code): awaited in turn, so a suite's tests share its browser and run in
 *  order. To run some of a suite's tests, the runner's own filter:
 *  `node --test-name-pattern=REGEX web/test/e2e.mjs` (the rest are reported
 *  skipped; `make test-e2e NODE_TEST_ARGS=--test-name-pattern=REGEX`). */
export function check(name, f) {
  return test(name, () => f());
}

/** Counts the pixels of the canvas `selector` (`index`: which match) per
 *  class: `classes` maps a name to a test `(r, g, b, first) => boolean`
 *  (run in the page; `first`: the top-left pixel's [r, g, b], the
 *  background). `around`: only the square of CSS-pixel half-side `radius`
 *  about `at`. `composited`: what the page shows over the canvas's box (a
 *  screenshot: every layer, WebGL included) instead of the canvas's own
 *  pixels. The canvas is read from a copy: repeated getImageData on the
 *  page's own context makes Chromium warn about readbacks. Returns the
 *  count per class and `total`, the pixels looked at. */
export async function countPixels(page, { selector, index = 0, around = null, composited = false }, classes) {
  const tests = Object.entries(classes).map(([k, f]) => [k, String(f)]);
  const png = composited ? (await page.screenshot({ clip: await page.locator(selector).nth(index).boundingBox() })).toString("base64") : null;
  return page.evaluate(async ({ selector, index, around, png, tests }) => {
    const c = document.querySelectorAll(selector)[index];
    const src = png ? await createImageBitmap(new Blob([Uint8Array.from(atob(png), (ch) => ch.charCodeAt(0))], { type: "image/png" })) : c;
    const copy = document.createElement("canvas");
    copy.width = src.width;
    copy.height = src.height;
    const ctx = copy.getContext("2d", { willReadFrequently: true });
    ctx.drawImage(src, 0, 0);
    let [x0, y0, w, h] = [0, 0, copy.width, copy.height];
    if (around) {
      const k = copy.width / c.getBoundingClientRect().width;
      x0 = Math.max(0, Math.round((around.at.x - around.radius) * k));
      y0 = Math.max(0, Math.round((around.at.y - around.radius) * k));
      w = Math.min(copy.width - x0, Math.round(2 * around.radius * k));
      h = Math.min(copy.height - y0, Math.round(2 * around.radius * k));
    }
    const d = ctx.getImageData(x0, y0, w, h).data;
    const first = [d[0], d[1], d[2]];
    const fs = tests.map(([k, text]) => [k, (0, eval)(`(${text})`)]);
    const counts = Object.fromEntries(tests.map(([k]) => [k, 0]));
    for (let i = 0; i < d.length; i += 4) for (const [k, f] of fs) if (f(d[i], d[i + 1], d[i + 2], first)) counts[k]++;
    return { ...counts, total: d.length / 4 };
  }, { selector, index, around, png, tests });
}

/** Strips COOP/COEP from every response of `context`: its pages are not
 *  cross-origin isolated (no SharedArrayBuffer; workers fall back to messages). */
export const unisolated = (context) =>
  context.route("**/*", async (route) => {
    const res = await route.fetch();
    const headers = { ...res.headers() };
    delete headers["cross-origin-opener-policy"];
    delete headers["cross-origin-embedder-policy"];
    await route.fulfill({ response: res, headers });
  });

/** A screenshot of `page` as artifacts/`name`.png. */
export const shot = (page, name) => page.screenshot({ path: resolve(artifacts, `${name}.png`) });

/** A mouse drag on the lab's canvas from `from` to `to` (CSS pixels in the
 *  canvas), `steps` moves, then the page settles. */
export async function dragOnLab(page, from, to, steps = 12) {
  const box = await page.locator("#lab").boundingBox();
  await page.mouse.move(box.x + from.x, box.y + from.y);
  await page.mouse.down();
  await page.mouse.move(box.x + to.x, box.y + to.y, { steps });
  await page.mouse.up();
  await settle(page);
}
