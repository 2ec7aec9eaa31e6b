// <funnel-figure> as a page author uses it: the tarball installed under
// target/npm-user/element, a plain HTML page (npm/example/figures.html:
// one <script type="module"> importing the installed package's
// funnel-figure.js, no bundler, no import map) served from there alone,
// in headless Chromium. In one figure the target is dragged by its handle
// and its `arrive` event read (at the dragged target, inside both
// tolerances); the other's attributes are changed from script and it
// re-plans to the new target; a handle moves with the arrow keys too.
// Screenshots at 1440×900 and 390×844 into artifacts/.
import { test } from "node:test";
import assert from "node:assert/strict";
import { cpSync, mkdirSync } from "node:fs";
import { join } from "node:path";
import { installed, npmDir, repo } from "./install.mjs";
import { launch, serve } from "./browser.mjs";

const artifacts = join(repo, "artifacts");
const DEG = Math.PI / 180;

/** Resolves with the next `arrive` of figure `id` whose detail passes `ok` (read in the page). */
function nextArrival(page, id, since) {
  return page.waitForFunction(([id, since]) => window.arrivals.find((a) => a.id === id && a.n > since) ?? null, [id, since], { timeout: 90_000, polling: 250 }).then((h) => h.jsonValue());
}

test("two <funnel-figure> elements on a plain page: a dragged target arrives, changed attributes re-plan", async (t) => {
  const scratch = installed("element");
  cpSync(join(npmDir, "example", "figures.html"), join(scratch, "index.html"));
  const { server, url } = await serve(scratch);
  t.after(() => server.close());
  const browser = await launch();
  t.after(() => browser.close());
  const page = await browser.newPage({ viewport: { width: 1440, height: 900 } });
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => (m.type() === "error" || m.type() === "warning") && errors.push(m.text()));
  const requests = [];
  page.on("request", (r) => requests.push(new URL(r.url()).pathname));
  // Every event of both figures, numbered, from the first.
  await page.addInitScript(() => {
    window.arrivals = [];
    window.modes = [];
    let n = 0;
    const listen = (f) => {
      f.addEventListener("arrive", (e) => window.arrivals.push({ id: f.id, n: ++n, ...e.detail, tx: +f.getAttribute("tx"), ty: +f.getAttribute("ty"), tb: +f.getAttribute("tb") }));
      f.addEventListener("modechange", (e) => window.modes.push({ id: f.id, n: ++n, ...e.detail }));
    };
    new MutationObserver(() => document.querySelectorAll("funnel-figure:not([data-heard])").forEach((f) => { f.dataset.heard = ""; listen(f); })).observe(document, { childList: true, subtree: true });
  });
  await page.goto(url);
  await page.waitForFunction(() => [...document.querySelectorAll("funnel-figure")].every((f) => f.modeName !== null), null, { timeout: 30_000 });
  mkdirSync(artifacts, { recursive: true });
  await page.screenshot({ path: join(artifacts, "npm-figures-1440.png") });

  // Drag the first figure's target 140 px right and 90 px down.
  const handle = page.locator("#drag [data-handle='target']");
  const box = await handle.boundingBox();
  const [x0, y0] = [box.x + box.width / 2, box.y + box.height / 2];
  const mark = await page.evaluate(() => window.arrivals.length + window.modes.length);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(x0 + 14 * i, y0 + 9 * i);
  await page.mouse.up();
  const dragged = await page.evaluate(() => { const f = document.getElementById("drag"); return { tx: +f.getAttribute("tx"), ty: +f.getAttribute("ty") }; });
  assert.ok(dragged.tx > 3.2 && dragged.ty < 1.3, `the drag moved the target right and down: ${JSON.stringify(dragged)}`);
  const a = await nextArrival(page, "drag", mark);
  assert.ok(Math.abs(a.tx - dragged.tx) < 1e-9 && Math.abs(a.ty - dragged.ty) < 1e-9, `arrived at the dragged target ${JSON.stringify(a)}`);
  assert.ok(a.distance < 0.3 && a.headingError < 10 * DEG, `inside both tolerances: ${JSON.stringify(a)}`);
  assert.ok(Math.hypot(a.x - dragged.tx, a.y - dragged.ty) < 0.3);

  // The second figure's attributes changed from script: a new set-up from its start.
  const before = await page.evaluate(() => window.arrivals.length + window.modes.length);
  await page.evaluate(() => {
    const f = document.getElementById("other");
    f.setAttribute("tx", "-1");
    f.setAttribute("ty", "2.5");
    f.setAttribute("tb", "-90");
  });
  await page.waitForFunction(() => document.getElementById("other").fragment.includes("tx=-1&ty=2.5&tb=-90"), null, { timeout: 10_000 });
  const b = await nextArrival(page, "other", before);
  assert.ok(Math.hypot(b.x + 1, b.y - 2.5) < 0.4, `arrived at the new target (-1, 2.5): ${JSON.stringify(b)}`);
  assert.ok(Math.abs(Math.atan2(Math.sin(b.theta + Math.PI / 2), Math.cos(b.theta + Math.PI / 2))) < 15 * DEG, `facing −90°: ${JSON.stringify(b)}`);
  const modes = await page.evaluate((n) => window.modes.filter((m) => m.id === "other" && m.n > n), before);
  assert.ok(modes.length >= 2 && modes.at(-1).name === "EndOfSteering", `modechange events, the last End_of_Steering: ${JSON.stringify(modes)}`);

  // The heading knob by keyboard: ArrowLeft turns β (the knob, due north of the target, moves west).
  const tb = await page.evaluate(() => document.getElementById("drag").getAttribute("tb"));
  await page.locator("#drag [data-handle='beta']").focus();
  for (let i = 0; i < 2; i++) await page.keyboard.press("Shift+ArrowLeft");
  const tb2 = await page.evaluate(() => document.getElementById("drag").getAttribute("tb"));
  assert.notEqual(tb2, tb, "the arrow keys turned the target");

  await page.screenshot({ path: join(artifacts, "npm-figures-1440-after.png") });
  await page.setViewportSize({ width: 390, height: 844 });
  await page.waitForTimeout(500);
  await page.screenshot({ path: join(artifacts, "npm-figures-390.png"), fullPage: true });
  const widths = await page.evaluate(() => [...document.querySelectorAll("funnel-figure")].map((f) => f.shadowRoot.querySelector("canvas").width));
  assert.ok(widths.every((w) => w > 300 && w < 390 * 3), `the canvases follow their boxes on a phone: ${widths}`);

  assert.deepEqual(errors, []);
  for (const p of requests) {
    assert.ok(p === "/" || p.startsWith("/node_modules/steering-core/"), `only the page and the installed package were fetched: ${p}`);
  }
  for (const p of ["/node_modules/steering-core/funnel-figure.js", "/node_modules/steering-core/pkg/steering_bg.wasm", "/node_modules/steering-core/eta.bin"]) {
    assert.ok(requests.includes(p), `loaded ${p}`);
  }
});
