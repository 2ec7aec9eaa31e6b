// Accessibility audit of the four pages (lab, learn, crowd, wander) with
// axe-core, the web/ devDependency (pinned), at 1440×900 and 390×844, in
// Debian's headless Chromium via playwright-core. Each page is audited once
// its figures are drawn (the test hooks say when); the audit must find no
// serious or critical violation. The learn page's weight (bytes fetched)
// and first contentful paint are printed for the record.
// Plain words (test/words.mjs): the visible text of each page, and of the
// lab under a paper preset (its caption), holds no code word (an
// identifier, a file path or name, a flag); nor do the presets' captions
// and the gallery's labels as files. The scan is first shown to bite: an
// identifier planted in the page (and one hidden, which must not count).
// A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check } from "./harness.mjs";
import { createRequire } from "node:module";
import assert from "node:assert/strict";
import { readdirSync, readFileSync } from "node:fs";
import { resolve } from "node:path";
import { webDir } from "./harness.mjs";
import { codeWords, visibleText } from "./words.mjs";

const AXE = createRequire(import.meta.url).resolve("axe-core/axe.min.js");

/** Page → [file, the test hook's "ready" predicate (run in the page)]. */
const PAGES = {
  lab: ["index.html", () => { const l = window.__lab; return l && (l.error !== null || (l.ready && l.frames > 1)); }],
  learn: ["learn.html", () => { const l = window.__learn; return l && (l.error !== null || (l.ready && Object.values(l.frames()).every((n) => n > 0))); }],
  crowd: ["crowd.html", () => { const c = window.__crowd; return c && (c.error !== null || (c.ready && c.frames > 2)); }],
  wander: ["wander.html", () => { const w = window.__wander; return w && (w.error !== null || (w.ready && !w.busy() && w.frames > 2)); }],
};
/** A lab preset whose caption is long (claim and measurement): scanned for words only. */
const WORDS_ONLY = { "lab preset": ["index.html#preset=p001_fig10_beta45_relaxed", PAGES.lab[1]] };

/** The code words of the page's visible text, as lines for an assertion. */
const pageWords = async (page) => codeWords(await page.evaluate(visibleText)).map((w) => `${w.kind} “${w.word}” in “…${w.context}…”`);

/** What the files show once chosen: the presets' captions (the lab's
 *  panel), the crowd presets' descriptions, the gallery's titles and labels. */
function fileTexts() {
  const root = resolve(webDir, "..", "scenarios");
  const json = (dir) => readdirSync(dir).filter((f) => f.endsWith(".json")).map((f) => [`${dir.slice(root.length + 1) || "scenarios"}/${f}`, JSON.parse(readFileSync(resolve(dir, f), "utf8"))]);
  const out = [];
  for (const [f, sc] of [...json(root), ...json(resolve(root, "crowd"))]) {
    for (const k of ["description", "source", "claim", "measured", "title"]) if (typeof sc[k] === "string") out.push([`${f} ${k}`, sc[k]]);
  }
  for (const [f, w] of json(resolve(root, "wander"))) {
    out.push([`${f} title`, `${w.title} ${w.section}`]);
    for (const v of w.variants) out.push([`${f} label`, v.label]);
  }
  return out;
}

await check("plain words: the presets' captions and the gallery's labels hold no code word", async () => {
  const texts = fileTexts();
  assert.ok(texts.length > 100, `${texts.length} texts`);
  assert.deepEqual(texts.flatMap(([where, t]) => codeWords(t).map((w) => `${where}: ${w.kind} “${w.word}”`)), []);
});

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
      if (name === "lab" && width === "desktop") {
        await check("plain words: the scan finds a planted identifier, path, flag and command, and not a hidden one", async () => {
          await page.evaluate(() => {
            const p = document.createElement("p");
            p.textContent = "planted: minTurnRadius in scenarios/car_like_parking.json, run steer envelope --vehicle car.json, then cargo test, epsTol 10 deg +/- 5";
            const hidden = document.createElement("p");
            hidden.hidden = true;
            hidden.textContent = "hiddenIdentifier";
            document.body.append(p, hidden);
          });
          const planted = await pageWords(page);
          await page.evaluate(() => { for (const p of [...document.body.children].slice(-2)) p.remove(); });
          const found = planted.join("\n");
          for (const w of ["camelCase “minTurnRadius”", "file path “scenarios/car_like_parking.json”", "flag “--vehicle”", "file name “car.json”", "command “cargo test”", "camelCase “epsTol”", "unit “10 deg”", "unit “+/-”"]) {
            assert.ok(found.includes(w), `the scan missed ${w}:\n${found}`);
          }
          assert.ok(!found.includes("hiddenIdentifier"), "a hidden element's text counted");
          assert.deepEqual(await pageWords(page), [], "the page after the plant is removed");
        });
      }
      await check(`plain words: ${name} at ${viewport.width}×${viewport.height}, no code word in the visible text`, async () => {
        assert.deepEqual(await pageWords(page), []);
      });
      const violations = await audit(page);
      const bad = violations.filter((v) => v.impact === "serious" || v.impact === "critical");
      console.log(`# axe ${name} ${width}: ${violations.length} rules violated, ${bad.reduce((s, v) => s + v.nodes, 0)} serious/critical nodes`);
      for (const v of violations) console.log(`#   ${v.impact} ${v.id} ×${v.nodes}: ${v.where.join(" | ")}`);
      await check(`axe: ${name} at ${viewport.width}×${viewport.height}, no serious or critical violation`, async () => {
        assert.deepEqual(bad.map((v) => `${v.id} ×${v.nodes}: ${v.where.join(" | ")}`), []);
      });
      await context.close();
    }
    for (const [name, [file, ready]] of Object.entries(WORDS_ONLY)) {
      const { page, context } = await openPage(browser, viewport, 1, { reducedMotion: "reduce" });
      await page.goto(new URL(file, url).href);
      await page.waitForFunction(ready, null, { timeout: 60000 });
      await check(`plain words: ${name} at ${viewport.width}×${viewport.height}, no code word in the visible text`, async () => {
        assert.ok((await page.locator(".fidelity.measured").count()) > 0, "the preset's caption is shown");
        assert.deepEqual(await pageWords(page), []);
      });
      await context.close();
    }
  }
} finally {
  await browser.close();
  await server.close();
}
