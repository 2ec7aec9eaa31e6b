// The npm package as another project uses it: the tarball `make npm` packs
// is installed into a scratch folder (target/npm-user/example), the example page (npm/example) is
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
import { cpSync, mkdirSync } from "node:fs";
import { join } from "node:path";
import { installed, npmDir, repo } from "./install.mjs";
import { launch, serve } from "./browser.mjs";

const artifacts = join(repo, "artifacts");

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
  const scratch = installed("example");
  for (const f of ["index.html", "main.js"]) cpSync(join(npmDir, "example", f), join(scratch, f));

  const { server, url } = await serve(scratch);
  t.after(() => server.close());
  const browser = await launch();
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
