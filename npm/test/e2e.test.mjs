// The npm package as another project uses it: the tarball `make npm` packs
// is installed into a scratch folder, the example page (npm/example) is
// served from there by a plain static server, and headless Chromium runs
// it. The agent must arrive at the oriented target at rest, then again
// after the target is dragged to a new place and turned by its arrow.
// Nothing of the repository is served: only the example's two files and
// what `npm install` put in node_modules.
//
// Run: `make test-npm` (builds the tarball first), or
// `node --test npm/test/` with STEERING_CORE_TGZ naming a tarball.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { createServer } from "node:http";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import { dirname, extname, join, resolve, sep } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const npmDir = resolve(here, "..");
const repo = resolve(npmDir, "..");
const { name, version } = JSON.parse(readFileSync(join(npmDir, "package.json"), "utf8"));
const tarball = resolve(process.env.STEERING_CORE_TGZ ?? join(repo, "target/npm", `${name}-${version}.tgz`));
const artifacts = join(repo, "artifacts");

// One pinned playwright-core for the repository: the front end's (web/).
const requireFromWeb = createRequire(join(repo, "web/package.json"));
const playwright = await import(pathToFileURL(requireFromWeb.resolve("playwright-core")).href);
const chromium = playwright.chromium ?? playwright.default.chromium;

const CHROMIUM_ARGS = ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-quic", "--no-first-run"];
const TYPES = { ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm", ".bin": "application/octet-stream", ".json": "application/json" };

/** Serves `root` (files only, nothing outside it) on 127.0.0.1. */
function serve(root) {
  const server = createServer((req, res) => {
    const path = decodeURIComponent(new URL(req.url, "http://x").pathname);
    const file = resolve(root, "." + (path.endsWith("/") ? path + "index.html" : path));
    try {
      if (!file.startsWith(root + sep)) throw new Error("outside the root");
      const body = readFileSync(file);
      res.writeHead(200, { "content-type": TYPES[extname(file)] ?? "application/octet-stream" });
      res.end(body);
    } catch {
      res.writeHead(404).end();
    }
  });
  return new Promise((ok) => server.listen(0, "127.0.0.1", () => ok({ server, url: `http://127.0.0.1:${server.address().port}/` })));
}

/** The page's status line, read into numbers. */
function parse(text) {
  const m = text.match(/^(\w+) · target \((-?[\d.]+), (-?[\d.]+)\) facing (-?[\d.]+)° · ([\d.]+) m from it · heading off by (-?[\d.]+)° · ([\d.]+) m\/s$/);
  if (!m) return null;
  const [, mode, x, y, beta, d, off, v] = m;
  return { mode, x: +x, y: +y, beta: +beta, d: +d, off: +off, v: +v };
}

/** Waits until the agent rests inside both tolerances (0.25 m, 5°). */
async function arrival(page, what) {
  let last = "";
  const deadline = Date.now() + 90_000;
  while (Date.now() < deadline) {
    last = await page.locator("#status").textContent();
    const s = parse(last);
    if (s && s.mode === "EndOfSteering" && s.v === 0 && s.d < 0.25 && Math.abs(s.off) < 5) return s;
    await page.waitForTimeout(250);
  }
  assert.fail(`${what}: no arrival at rest within 90 s; the page says "${last}"`);
}

test("the example page, from the installed tarball alone, steers its agent to the oriented target", async (t) => {
  const scratch = mkdtempSync(join(tmpdir(), "steering-core-user-"));
  t.after(() => rmSync(scratch, { recursive: true, force: true }));
  writeFileSync(join(scratch, "package.json"), JSON.stringify({ name: "steering-core-user", private: true, type: "module" }));
  execFileSync("npm", ["install", "--no-audit", "--no-fund", "--loglevel=error", tarball], { cwd: scratch, stdio: "inherit" });
  for (const f of ["index.html", "main.js"]) cpSync(join(npmDir, "example", f), join(scratch, f));

  const { server, url } = await serve(scratch);
  t.after(() => server.close());
  const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args: CHROMIUM_ARGS });
  t.after(() => browser.close());
  const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => m.type() === "error" && errors.push(m.text()));
  const requests = [];
  page.on("request", (r) => requests.push(new URL(r.url()).pathname));
  await page.goto(url);

  const first = await arrival(page, "the first target");
  assert.deepEqual([first.x, first.y, first.beta], [5, 2, 90]);
  mkdirSync(artifacts, { recursive: true });
  await page.screenshot({ path: join(artifacts, "npm-example.png") });

  // Drag the target from (5, 2) to (-3, 3), then its arrow's tip (1 m
  // ahead, now pointing +y) round to point −x: β 180°.
  const box = await page.locator("#view").boundingBox();
  const k = Math.min(box.width, box.height) / 16;
  const at = (x, y) => [box.x + box.width / 2 + x * k, box.y + box.height / 2 - y * k];
  const dragTo = async (from, to) => {
    await page.mouse.move(...at(...from));
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(...at(from[0] + ((to[0] - from[0]) * i) / 10, from[1] + ((to[1] - from[1]) * i) / 10));
    await page.mouse.up();
  };
  await dragTo([5, 2], [-3, 3]);
  await dragTo([-3, 4], [-4, 3]);
  const second = await arrival(page, "the dragged target");
  assert.ok(Math.hypot(second.x + 3, second.y - 3) < 0.1, `target moved to (-3, 3): ${JSON.stringify(second)}`);
  assert.ok(Math.abs(Math.abs(second.beta) - 180) < 3, `target turned to face −x: ${JSON.stringify(second)}`);
  await page.screenshot({ path: join(artifacts, "npm-example-dragged.png") });

  assert.deepEqual(errors, []);
  const served = new Set(requests);
  for (const p of ["/node_modules/steering-core/index.js", "/node_modules/steering-core/pkg/steering_bg.wasm", "/node_modules/steering-core/eta.bin"]) {
    assert.ok(served.has(p), `the page loaded ${p} from the installed package (${[...served].join(", ")})`);
  }
});
