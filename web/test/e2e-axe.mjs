// Accessibility audit of the four pages (lab, learn, crowd, wander) with
// axe-core, the web/ devDependency (pinned), at 1440×900 and 390×844, in
// Debian's headless Chromium via playwright-core. Each page is audited once
// its figures are drawn (the test hooks say when); the audit must find no
// serious or critical violation. The learn page's weight (bytes fetched)
// and first contentful paint are printed for the record.
// A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check } from "./harness.mjs";
import { createRequire } from "node:module";
import assert from "node:assert/strict";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");

/** Page → [file, the test hook's "ready" predicate (run in the page)]. */
const PAGES = {
  lab: ["index.html", () => { const l = window.__lab; return l && (l.error !== null || (l.ready && l.frames > 1)); }],
  learn: ["learn.html", () => { const l = window.__learn; return l && (l.error !== null || (l.ready && Object.values(l.frames()).every((n) => n > 0))); }],
  crowd: ["crowd.html", () => { const c = window.__crowd; return c && (c.error !== null || (c.ready && c.frames > 2)); }],
  wander: ["wander.html", () => { const w = window.__wander; return w && (w.error !== null || (w.ready && !w.busy() && w.frames > 2)); }],
};

const VIEWPORTS = { desktop: { width: 1440, height: 900 }, phone: { width: 390, height: 844 } };

/** axe's violations on the page as it is now: [{ id, impact, nodes, where }]. */
async function audit(page) {
  await page.addScriptTag({ path: AXE });
  return page.evaluate(async () => {
    // eslint-disable-next-line no-undef
    const r = await axe.run(document, { resultTypes: ["violations"] });
    return r.violations.map((v) => ({ id: v.id, impact: v.impact, nodes: v.nodes.length, where: v.nodes.slice(0, 3).map((n) => n.target.join(" ")) }));
  });
}

const { server, url } = await serve();
const browser = await launch();
try {
  for (const [width, viewport] of Object.entries(VIEWPORTS)) {
    for (const [name, [file, ready]] of Object.entries(PAGES)) {
      const { page, context } = await openPage(browser, viewport, 1, { reducedMotion: "reduce" });
      let bytes = 0;
      page.on("response", async (res) => {
        const len = Number(res.headers()["content-length"] ?? NaN);
        bytes += Number.isFinite(len) ? len : (await res.body().catch(() => Buffer.alloc(0))).length;
      });
      await page.goto(new URL(file, url).href);
      await page.waitForFunction(ready, null, { timeout: 60000 });
      if (name === "learn") {
        const fcp = await page.evaluate(() => performance.getEntriesByName("first-contentful-paint")[0]?.startTime ?? NaN);
        console.log(`# learn page (${width}): ${(bytes / 1024).toFixed(0)} KiB fetched (uncompressed), first contentful paint ${fcp.toFixed(0)} ms`);
      }
      const violations = await audit(page);
      const bad = violations.filter((v) => v.impact === "serious" || v.impact === "critical");
      console.log(`# axe ${name} ${width}: ${violations.length} rules violated, ${bad.reduce((s, v) => s + v.nodes, 0)} serious/critical nodes`);
      for (const v of violations) console.log(`#   ${v.impact} ${v.id} ×${v.nodes}: ${v.where.join(" | ")}`);
      await check(`axe: ${name} at ${viewport.width}×${viewport.height}, no serious or critical violation`, async () => {
        assert.deepEqual(bad.map((v) => `${v.id} ×${v.nodes}: ${v.where.join(" | ")}`), []);
      });
      await context.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
}
