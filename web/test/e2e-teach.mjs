// The lab as a learner meets it, at 1440×900 and 390×844: the legend names
// every control mode of the core (read from the bindings' `Mode` through
// the test hook, not a copy) in plain words, the HUD's mode chip says the
// same words and links to the learn page's mode list, diagnostics sit
// behind a toggle, presets read as titles grouped by paper, and on a phone
// every handle of the playground has a hit area of at least 24 CSS px, the
// tolerance knob does not share the target's, and vehicle and target are
// on the stage, clear of the HUD and the legend. Screenshots of the four
// pages at both sizes go to DOCS/screenshots/ (`--docs`: artifacts/docs by
// default; `make screenshots` refreshes the committed docs/screenshots/).
// A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check, waitReady, settle, dragOnLab, docsDir } from "./harness.mjs";
import assert from "node:assert/strict";
import { resolve } from "node:path";

const SHOTS = resolve(docsDir("node web/test/e2e-teach.mjs [--docs DIR]: the lab as a learner meets it, and the four pages' screenshots"), "screenshots");
const VIEWPORTS = { desktop: { width: 1440, height: 900 }, phone: { width: 390, height: 844 } };
/** The paper's code names, which the lab's words replace. */
const CODE_NAMES = /Position_only|Orientation_only|End_of_Steering|EndOfSteering|PositionOnly|OrientationOnly/;

const { server, url } = await serve();
const browser = await launch();
try {
  for (const [tag, viewport] of Object.entries(VIEWPORTS)) {
    const { page, problems, context } = await openPage(browser, viewport);
    await page.goto(`${url}index.html`);
    assert.equal(await waitReady(page), null);
    await page.waitForFunction(() => window.__lab.live());
    await settle(page);

    await check(`${tag}: the legend names each of the core's modes once, in words, and the HUD's chip uses them`, async () => {
      const r = await page.evaluate(() => ({
        core: window.__lab.coreModes(),
        legend: [...document.querySelectorAll(".legend [data-mode]")].map((e) => ({ mode: e.dataset.mode, text: e.textContent.trim() })),
        legendText: document.querySelector(".legend").textContent,
        chip: document.querySelector("#hud .hud-chip")?.textContent,
        chipHref: document.querySelector("#hud .hud-chip")?.getAttribute("href"),
        hud: document.getElementById("hud").textContent,
      }));
      assert.deepEqual([...r.legend.map((l) => l.mode)].sort(), [...r.core].sort(), "one legend entry per core mode");
      const words = r.legend.map((l) => l.text);
      assert.equal(new Set(words).size, words.length, "distinct words");
      for (const w of ["seeking", "funnelling", "turning on the spot", "arrived"]) assert.ok(words.includes(w), `legend says "${w}": ${words}`);
      assert.ok(words.includes(r.chip), `chip "${r.chip}" is a legend word`);
      assert.equal(r.chipHref, "learn.html#modes");
      assert.doesNotMatch(r.legendText, CODE_NAMES);
      assert.doesNotMatch(r.hud, CODE_NAMES);
      console.log(`# ${tag}: core modes ${r.core.join(", ")} → legend ${words.join(", ")}; chip "${r.chip}"`);
    });

    await check(`${tag}: each mode has its own colour on the canvas legend`, async () => {
      const colours = await page.$$eval(".legend [data-mode] .sw", (els) => els.map((e) => getComputedStyle(e).color));
      const perMode = await page.$$eval(".legend [data-mode]", (els) => els.map((e) => getComputedStyle(e.querySelector(".sw")).color));
      assert.equal(new Set(perMode).size, perMode.length, `colours ${perMode}`);
      assert.ok(colours.length >= perMode.length);
    });

    await check(`${tag}: diagnostics (µs/agent, frame, table) are behind a closed toggle`, async () => {
      const d = await page.evaluate(() => {
        const det = document.querySelector("#hud details.hud-diag");
        return { open: det?.open, text: det?.textContent ?? "", visible: det ? det.querySelector("pre").checkVisibility() : null };
      });
      assert.equal(d.open, false);
      assert.match(d.text, /µs\/agent/);
      assert.match(d.text, /table/);
      assert.equal(d.visible, false);
    });

    await check(`${tag}: screenshots of the lab with the η field, learn, crowd and wander`, async () => {
      await page.waitForTimeout(1200);
      await settle(page);
      await page.screenshot({ path: resolve(SHOTS, `lab-${tag}.png`) });
      await page.check("#ov-field");
      await settle(page);
      await page.waitForTimeout(300);
      await page.locator(".stage").screenshot({ path: resolve(SHOTS, `lab-eta-field-${tag}.png`) });
      await page.uncheck("#ov-field");
      for (const [name, file, ready] of [
        ["learn", "learn.html", () => { const l = window.__learn; return l && (l.error !== null || (l.ready && Object.values(l.frames()).every((n) => n > 0))); }],
        ["crowd", "crowd.html", () => { const c = window.__crowd; return c && (c.error !== null || (c.ready && c.frames > 2)); }],
        ["wander", "wander.html", () => { const w = window.__wander; return w && (w.error !== null || (w.ready && !w.busy() && w.frames > 2)); }],
      ]) {
        const p = await context.newPage();
        p.on("pageerror", (e) => problems.push(`pageerror: ${e.message}`));
        p.on("console", (m) => { if (m.type() === "error") problems.push(`console.error: ${m.text()}`); });
        await p.goto(`${url}${file}`);
        await p.waitForFunction(ready, null, { timeout: 60000 });
        await p.waitForTimeout(800);
        await p.screenshot({ path: resolve(SHOTS, `${name}-${tag}.png`) });
        await p.close();
      }
    });

    if (tag === "phone") {
      await check("phone: the HUD starts folded (chip and one line), opens on a tap, and covers little of the stage", async () => {
        const size = () => page.evaluate(() => {
          const h = document.getElementById("hud").getBoundingClientRect();
          const s = document.querySelector(".stage").getBoundingClientRect();
          return { share: (h.width * h.height) / (s.width * s.height), folded: document.getElementById("hud").classList.contains("folded") };
        });
        const folded = await size();
        assert.ok(folded.folded);
        await page.click("#hud .hud-fold");
        const open = await size();
        assert.ok(!open.folded && open.share > folded.share);
        await page.click("#hud .hud-fold");
        console.log(`# phone: the folded HUD covers ${(100 * folded.share).toFixed(1)} % of the stage (open ${(100 * open.share).toFixed(1)} %)`);
        assert.ok(folded.share < 0.12, `${folded.share}`);
      });

      await check("phone: vehicle and target on the stage, clear of the HUD and the legend", async () => {
        // At the start: the vehicle where the playground puts it.
        await page.evaluate(() => window.__lab.setPaused(true));
        await page.evaluate(() => window.__lab.restart());
        await settle(page);
        const r = await page.evaluate(() => {
          const c = document.getElementById("lab").getBoundingClientRect();
          const rel = (e) => { const b = e.getBoundingClientRect(); return { x0: b.left - c.left, y0: b.top - c.top, x1: b.right - c.left, y1: b.bottom - c.top }; };
          const hud = document.getElementById("hud");
          return { h: window.__lab.handles(), w: c.width, hgt: c.height, hud: rel(hud), legend: rel(document.querySelector(".stage .legend")), hudSays: `${hud.classList.contains("folded") ? "folded" : "open"}: ${hud.textContent}` };
        });
        for (const k of ["vehicle", "target", "beta", "heading", "opening", "rim"]) {
          const p = r.h[k];
          assert.ok(p.x > 0 && p.x < r.w && p.y > 0 && p.y < r.hgt, `${k} on the stage: ${JSON.stringify(p)}`);
          for (const [name, b] of [["HUD", r.hud], ["legend", r.legend]]) {
            assert.ok(!(p.x > b.x0 - 4 && p.x < b.x1 + 4 && p.y > b.y0 - 4 && p.y < b.y1 + 4), `${k} under the ${name}: ${JSON.stringify(p)} ${JSON.stringify(b)} (the HUD ${r.hudSays})`);
          }
        }
      });

      await check("phone: every handle has a hit area of at least 24 CSS px; the tolerance knob is not the target's centre", async () => {
        const h = await page.evaluate(() => window.__lab.handles());
        const kinds = ["vehicle", "heading", "target", "rim", "beta", "opening"];
        let minGap = Infinity;
        for (const a of kinds) for (const b of kinds) if (a < b) minGap = Math.min(minGap, Math.hypot(h[a].x - h[b].x, h[a].y - h[b].y));
        // Every point within 12 px of a handle's centre grabs it: a 24 px disc,
        // whole when no other handle's centre is within 24 px.
        const bad = [];
        for (const k of kinds) {
          for (let a = 0; a < 16; a++) {
            const x = h[k].x + 11.5 * Math.cos((a * Math.PI) / 8), y = h[k].y + 11.5 * Math.sin((a * Math.PI) / 8);
            const got = await page.evaluate(([x, y]) => window.__lab.handleKindAt(x, y), [x, y]);
            if (got !== k) bad.push(`${k} at ${a * 22.5}°: ${got}`);
          }
        }
        const rimGap = Math.hypot(h.rim.x - h.target.x, h.rim.y - h.target.y);
        console.log(`# phone: handles at least ${minGap.toFixed(1)} px apart; tolerance knob ${rimGap.toFixed(1)} px from the target's centre; ${bad.length} of ${kinds.length * 16} probe points missed`);
        assert.deepEqual(bad, []);
        assert.ok(minGap >= 24, `closest handles ${minGap} px`);
        assert.ok(rimGap >= 24, `tolerance knob ${rimGap} px from the centre`);
        // Dragging the knob outwards widens D_tol and leaves the target where it is.
        const s0 = await page.evaluate(() => window.__lab.state());
        const dx = h.rim.x - h.target.x, dy = h.rim.y - h.target.y, n = Math.hypot(dx, dy);
        await dragOnLab(page, h.rim, { x: h.rim.x + (dx / n) * 20, y: h.rim.y + (dy / n) * 20 });
        const s1 = await page.evaluate(() => window.__lab.state());
        assert.ok(s1.dTol > s0.dTol + 0.1, `D_tol ${s0.dTol} → ${s1.dTol}`);
        assert.deepEqual([s1.target.x, s1.target.y], [s0.target.x, s0.target.y]);
        await page.evaluate(() => window.__lab.restart());
        await page.evaluate(() => window.__lab.setPaused(false));
      });
    }

    await check(`${tag}: presets read as titles grouped by paper; under a preset the playground's controls are gone and the HUD names its agent`, async () => {
      const menu = await page.$$eval("#preset optgroup", (gs) => gs.map((g) => ({ label: g.label, options: [...g.querySelectorAll("option")].map((o) => o.textContent) })));
      assert.ok(menu.length >= 2 && menu.every((g) => /^Paper 00\d|^Avoidance|^Car-like|^Short range/.test(g.label)), JSON.stringify(menu.map((g) => g.label)));
      for (const g of menu) for (const o of g.options) assert.doesNotMatch(o, /_|^p\d{3}|^avoid_/, `option "${o}"`);
      await page.selectOption("#preset", "p000_fig7_variety");
      await page.waitForFunction(() => window.__lab.count() === 8 && /agent 1 of 8/.test(document.getElementById("hud").textContent));
      const hidden = await page.evaluate(() => ({
        goal: document.querySelector("#beta")?.closest("fieldset")?.hidden,
        note: document.querySelector(".preset-note")?.hidden,
      }));
      assert.deepEqual(hidden, { goal: true, note: false });
      await page.waitForTimeout(1500);
      await settle(page);
      await page.screenshot({ path: resolve(SHOTS, `lab-preset-${tag}.png`) });
      await page.selectOption("#preset", "");
      await page.waitForFunction(() => window.__lab.count() === 1);
      const back = await page.evaluate(() => document.querySelector("#beta")?.closest("fieldset")?.hidden);
      assert.equal(back, false);
    });

    await check(`${tag}: the reading selector puts the papers' controller or ours in force and names it as the core does`, async () => {
      const label = () => page.locator(".controller-label").textContent();
      assert.equal(await label(), "In force: ours standard");
      await page.selectOption("#reading", "paper");
      await page.waitForFunction(() => /paper 000 standard/.test(document.querySelector(".controller-label").textContent));
      const core = await page.evaluate(() => window.__lab.funnel());
      assert.deepEqual([core.bound.kind, core.gain, core.seekThreshold, core.aim, core.terminal ?? null], ["literal", 1, 1, "centre", null]);
      assert.deepEqual([await page.inputValue("#mu-bound"), await page.inputValue("#aim"), await page.inputValue("#pursuit")], ["lit", "centre", "off"]);
      await page.waitForFunction(() => location.hash.includes("rd=paper"), null, { timeout: 3000 });
      await page.locator("#mu-gain").fill("1.5");
      await page.waitForFunction(() => /custom standard/.test(document.querySelector(".controller-label").textContent));
      assert.equal(await page.inputValue("#reading"), "custom");
      await page.selectOption("#preset", "p001_fig6c_relaxed");
      await page.waitForFunction(() => window.__lab.state().preset === "p001_fig6c_relaxed" && window.__lab.count() === 1);
      await page.selectOption("#reading", "paper");
      await page.waitForFunction(() => /paper 001 relaxed/.test(document.querySelector(".controller-label").textContent));
      await page.selectOption("#reading", "ours");
      await page.waitForFunction(() => /ours relaxed/.test(document.querySelector(".controller-label").textContent));
      await page.selectOption("#preset", "");
      await page.waitForFunction(() => window.__lab.count() === 1 && /ours standard/.test(document.querySelector(".controller-label").textContent));
      console.log(`# ${tag}: reading selector: ours standard → paper 000 standard → custom standard; p001 Fig. 6c: paper 001 relaxed → ours relaxed`);
    });

    await check(`${tag}: the β number box shows its whole number`, async () => {
      const fits = await page.$eval(".numbox input", () => {
        const i = document.querySelector("#beta")?.closest(".slider")?.querySelector(".numbox input");
        if (!i) return null;
        const old = i.value;
        i.value = "-179.5";
        const ok = i.scrollWidth <= i.clientWidth;
        i.value = old;
        return ok;
      });
      assert.equal(fits, true);
    });

    await check(`${tag}: learn §3 measures a seek simulation against a table lookup on this machine`, async () => {
      const p = await context.newPage();
      await p.goto(`${url}learn.html`);
      await p.waitForFunction(() => /^\d/.test(document.querySelector('[data-live="table-ratio"]')?.textContent ?? ""), null, { timeout: 30000 });
      const r = await p.evaluate(() => Object.fromEntries(["table-sim-us", "table-lookup-us", "table-ratio", "table-sim-frame", "table-lookup-frame"].map((k) => [k, document.querySelector(`[data-live="${k}"]`).textContent])));
      console.log(`# ${tag}: learn §3 on this host: seek simulation ${r["table-sim-us"]}, lookup ${r["table-lookup-us"]}, ratio ${r["table-ratio"]}; 1,000 agents: ${r["table-sim-frame"]} vs ${r["table-lookup-frame"]} per frame`);
      assert.ok(Number(r["table-ratio"].replace(/,/g, "")) > 10, JSON.stringify(r));
      if (tag === "phone") {
        // As a reader sees it: the cost paragraph scrolled up under the
        // pinned figure, whole, with the page's margin on its left.
        const last = p.locator("#table .prose p").last();
        await last.evaluate((el) => el.scrollIntoView({ block: "end" }));
        await p.waitForTimeout(300);
        const g = await p.evaluate(() => {
          const fig = document.querySelector('[data-figure="table"]').getBoundingClientRect();
          const para = [...document.querySelectorAll("#table .prose p")].at(-1).getBoundingClientRect();
          return { figBottom: fig.bottom, figHeight: fig.height, paraTop: para.top, paraLeft: para.left, vh: window.innerHeight };
        });
        assert.ok(g.figHeight <= 0.45 * g.vh + 1, `pinned figure ${g.figHeight} px of ${g.vh}`);
        assert.ok(g.paraTop >= g.figBottom, `paragraph top ${g.paraTop} under the figure (bottom ${g.figBottom})`);
        assert.ok(g.paraLeft >= 12, `text ${g.paraLeft} px from the left edge`);
        await p.screenshot({ path: resolve(SHOTS, `learn-table-${tag}.png`) });
      } else {
        await p.locator("#table .prose").screenshot({ path: resolve(SHOTS, `learn-table-${tag}.png`) });
      }
      await p.close();
    });

    await check(`${tag}: crowd explains Paper 003 and its tests and has one boid-count control; wander tiles have titles, a line per panel, one scale per row`, async () => {
      const c = await context.newPage();
      await c.goto(`${url}crowd.html`);
      await c.waitForFunction(() => window.__crowd?.ready);
      const crowd = await c.evaluate(() => ({
        text: document.querySelector("#panel").textContent,
        counts: document.querySelectorAll("#boids, #boids-slider, [id^='boids-'][id$='0'], #boids-1").length,
      }));
      assert.match(crowd.text, /Paper 003 is a student report/);
      for (const t of ["Test I", "Test II", "Test III", "Test IV", "What to compare"]) assert.ok(crowd.text.includes(t), t);
      assert.equal(crowd.counts, 1, "one boid-count control");
      await c.close();
      const w = await context.newPage();
      await w.goto(`${url}wander.html`);
      await w.waitForFunction(() => window.__wander?.ready && !window.__wander.busy() && window.__wander.frames > 2, null, { timeout: 60000 });
      const g = await w.evaluate(() => ({
        captions: [...document.querySelectorAll(".tile .label")].map((e) => e.textContent),
        compare: document.querySelectorAll(".wpanel .compare").length,
        panels: window.__wander.panels(),
        height: document.documentElement.scrollHeight,
      }));
      assert.ok(g.captions.every((t) => !/screenshot\d/.test(t)), "no image file names in the titles");
      assert.equal(g.compare, g.panels.length);
      for (const p of g.panels) {
        const rows = new Map();
        // A tile drawn at its own scale says so in its note (the gallery suite checks it); the rest of its row share one.
        for (const s of p.scales.filter((t) => t.zoom === 1)) rows.set(s.top, [...(rows.get(s.top) ?? []), s.scale]);
        for (const [top, scales] of rows) assert.ok(scales.every((x) => Math.abs(x - scales[0]) < 1e-9 * scales[0]), `${p.name} row at ${top}: ${scales}`);
      }
      console.log(`# ${tag}: wander gallery ${g.height} px tall, ${g.captions.length} tiles`);
      await w.close();
    });

    await check(`${tag}: no console errors`, async () => {
      assert.deepEqual(problems.filter((p) => !/warning/.test(p)), []);
    });
    await context.close();
  }
} finally {
  await browser.close();
  await server.close();
}
