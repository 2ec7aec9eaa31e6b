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

export const webDir = resolve(dirname(fileURLToPath(import.meta.url)), "..");
export const artifacts = resolve(webDir, "../artifacts");
/** The build the suites drive: the pages with their test hooks. */
export const testDist = resolve(webDir, "dist-test");
mkdirSync(artifacts, { recursive: true });

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

/** Takes every `--base DIR` (repeatable) out of `args` (in place): the
 *  dists of other builds to measure beside this one in the same run. */
export function takeBases(args) {
  const dirs = [];
  for (let at = args.indexOf("--base"); at >= 0; at = args.indexOf("--base")) dirs.push(args.splice(at, 2)[1]);
  return dirs;
}

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
 *  then does not wait on the harness's own (issue 17, perf.mjs --child). */
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

export async function launch() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    args: CHROMIUM_ARGS,
  });
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

/** Named checks that do not stop the run (CHECK=text: those named with it): each prints `ok - name` or
 *  `not ok - name` with the first lines of the stack; `finish` prints
 *  "`suite`: N passed, M failed" and exits non-zero on any failure. */
export function checks(suite) {
  let passed = 0;
  let failed = 0;
  return {
    async check(name, f) {
      // CHECK=text runs only the checks whose name contains it.
      if (process.env.CHECK && !name.includes(process.env.CHECK)) return;
      try {
        await f();
        passed++;
        console.log(`ok - ${name}`);
      } catch (e) {
        failed++;
        console.log(`not ok - ${name}\n  ${String(e && e.stack ? e.stack : e).split("\n").slice(0, 6).join("\n  ")}`);
      }
    },
    finish() {
      console.log(`${suite}: ${passed} passed, ${failed} failed`);
      process.exit(failed === 0 ? 0 : 1);
    },
  };
}

/** A screenshot of `page` as artifacts/`name`.png. */
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
