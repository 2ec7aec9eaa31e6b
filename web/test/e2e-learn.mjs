// Browser end-to-end test of the learn page (learn.html): the
// built page in Debian's headless Chromium via playwright-core. Checks:
// every section's canvas draws; one handle per section drags (pointer) and
// changes a number in the prose; handles move with the keyboard; the
// "show in the lab" links open the lab in the figure's state (the lab's
// window.__lab hook); no figure plays on its own, reduced motion or not
// (each waits at the set-up its text describes); the figures agree with
// their paragraphs (§2's η, §3's probe and ghosts, §5's mode order, read
// from each figure's data-shows and the text's live numbers); no console
// errors. Screenshots of every
// section at 1280x800 and 390x844 go to artifacts/learn-*.png.
// A node:test suite (harness.mjs `check`).
import { serve, launch, openPage, check, waitReady, settle, artifacts, countPixels } from "./harness.mjs";
import { resolve } from "node:path";
import assert from "node:assert/strict";


/** Section → [handle to drag, live number it must change, drag offset in CSS px]. */
const DRAGS = {
  seek: ["target", "seek-A", { x: -40, y: -50 }],
  eta: ["target", "eta-sim", { x: -30, y: 45 }],
  table: ["probe", "table-eta", { x: 50, y: -30 }],
  modulation: ["beta", "mod-deta", { x: -50, y: 20 }],
  modes: ["target", "modes-D", { x: 40, y: 30 }],
  moving: ["middle", "moving-chain", { x: 40, y: 40 }],
  region: ["centre", "region-arc", { x: 0, y: -40 }],
  challenges: ["target", "break-D", { x: 40, y: -30 }],
};

async function waitLearn(page) {
  await page.waitForFunction(() => {
    const l = window.__learn;
    return l && (l.error !== null || (l.ready && Object.values(l.frames()).every((n) => n > 0)));
  }, null, { timeout: 30000 });
  return page.evaluate(() => window.__learn.error);
}

/** Pixels of a figure's canvas that differ from the background (#fbfaf7), and those in colour. */
const inked = (page, name) =>
  countPixels(page, { selector: `[data-figure="${name}"] canvas` }, {
    n: (r, g, b) => Math.abs(r - 251) + Math.abs(g - 250) + Math.abs(b - 247) > 30,
    colour: (r, g, b) => Math.max(r, g, b) - Math.min(r, g, b) > 60,
  });

/** Every live number of section `name`: [data-live, text]. */
const liveNumbers = (page, name) =>
  page.$$eval(`#${name} [data-live]`, (els) => els.filter((e) => e.dataset.live !== "none").map((e) => [e.dataset.live, e.textContent]));

/** The checks a figure must pass after playing to its end (each section,
 *  at the page's width `w`): no live number blank ("—", "…") or
 *  "unreachable" for the set-up the page starts in, both while the last
 *  picture holds and after the rewind; every handle at least 24 CSS px. */
async function playedChecks(page, w) {
  for (const name of Object.keys(DRAGS)) {
    await check(`${w}: ${name} after playing to the end shows its quantities, handles ≥ 24 px`, async () => {
      await page.locator(`#${name}`).scrollIntoViewIfNeeded();
      await page.evaluate((n) => window.__learn.finish(n), name);
      await settle(page);
      // ("unreachable" is a blank for η itself; section 3's reachability
      // may say it of the probe, with the v_dt that fixes it.)
      const blank = (nums) => nums.filter(([k, t]) => /—|…/.test(t ?? "") || (k !== "table-reach" && /unreachable/.test(t ?? "")));
      assert.deepEqual(blank(await liveNumbers(page, name)), [], "at the end");
      await page.waitForFunction((n) => document.querySelector(`[data-figure="${n}"] .fig-clock`).textContent === "t 0.0 s", name, { timeout: 5000 });
      assert.deepEqual(blank(await liveNumbers(page, name)), [], "after the rewind");
      for (const box of await page.locator(`[data-figure="${name}"] .handle`).evaluateAll((hs) => hs.map((h) => h.getBoundingClientRect()).map((r) => ({ w: r.width, h: r.height })))) {
        assert.ok(box.w >= 24 && box.h >= 24, `handle ${box.w}×${box.h}`);
      }
    });
  }
}

const liveText = (page, name) => page.locator(`[data-live="${name}"]`).first().textContent();

/** What figure `name`'s canvas labels show now (its data-shows). */
const shows = (page, name) => page.evaluate((n) => JSON.parse(document.querySelector(`[data-figure="${n}"]`).dataset.shows ?? "{}"), name);

/** Degrees in a live text ("12.3°") as a number. */
const degrees = (t) => parseFloat(t);

/** The figures held against the numbers and words of their paragraphs, at
 *  the set-up each waits at and after Play (pictures into artifacts/). */
async function textChecks(page, w) {
  await check(`${w}: §2's arc shows the η the text quotes for the set-up, and the table's η is the quoted error away`, async () => {
    await page.locator("#eta").scrollIntoViewIfNeeded();
    const s = await shows(page, "eta");
    assert.equal(s.t, 0, "the figure waits at its set-up");
    const sim = await liveText(page, "eta-sim");
    assert.equal(s.eta, sim, "the arc's label is the text's simulated η");
    const err = Math.abs(degrees(sim) - degrees(await liveText(page, "eta-table")));
    assert.ok(Math.abs(err - degrees(await liveText(page, "eta-err"))) <= 0.11, `|sim − table| ${err}`);
    assert.equal(await liveText(page, "eta-now"), sim, "the η still to come starts at the set-up's");
    await page.locator("#eta").screenshot({ path: resolve(artifacts, `learn-text-eta-${w}.png`) });
  });

  await check(`${w}: §3's probe starts away from the vehicle; its ghosts are labelled and agree with the text`, async () => {
    await page.locator("#table").scrollIntoViewIfNeeded();
    let s = await shows(page, "table");
    assert.equal(s.t, 0, "the figure waits at its set-up");
    assert.equal(s.D, await liveText(page, "table-D"));
    assert.ok(parseFloat(s.D) > 1, `the probe is ${s.D} from the vehicle at the set-up`);
    assert.equal(s.reach, await liveText(page, "table-reach"));
    // Unreachable: the orbit at v_d and the arrival at the text's v_dt, labelled apart.
    assert.equal(s.reach, "unreachable", "the text's two ghosts are on show at the set-up");
    assert.deepEqual(s.ghosts.split(" | "), ["at the desired speed: orbits", `slowed to ${await liveText(page, "table-vdt")}: arrives`]);
    await page.locator("#table").screenshot({ path: resolve(artifacts, `learn-text-table-setup-${w}.png`) });
    // Away from the vehicle, out of its turning circle (Shift + arrow: 1 m).
    const probe = page.locator('[data-figure="table"] [data-handle="probe"]');
    await probe.focus();
    for (let k = 0; k < 2; k++) await page.keyboard.press("Shift+ArrowUp");
    for (let k = 0; k < 2; k++) await page.keyboard.press("Shift+ArrowRight");
    await settle(page);
    s = await shows(page, "table");
    assert.equal(await liveText(page, "table-reach"), "reachable");
    assert.equal(s.reach, "reachable");
    assert.equal(s.ghosts, "seek at the desired speed: arrives");
    await page.locator("#table").screenshot({ path: resolve(artifacts, `learn-text-table-far-${w}.png`) });
    for (let k = 0; k < 2; k++) await page.keyboard.press("Shift+ArrowDown");
    for (let k = 0; k < 2; k++) await page.keyboard.press("Shift+ArrowLeft");
    await settle(page);
  });

  await check(`${w}: §5's lit box climbs the diagram in the order the text says`, async () => {
    await page.locator("#modes").scrollIntoViewIfNeeded();
    const lit = () => page.$$eval("#modes ol.diagram li", (ls) => ls.map((l) => ({ on: l.classList.contains("on"), order: l.querySelector(".lit-order").textContent, word: l.querySelector("b").textContent })));
    let d = await lit();
    assert.equal(d.length, 4, "the diagram's four boxes");
    assert.equal(d.findIndex((b) => b.on), 3, "the set-up lights the last line");
    assert.equal((await shows(page, "modes")).lit, await liveText(page, "modes-mode"));
    const seq = await liveText(page, "modes-seq");
    const words = seq.split(" → ");
    assert.equal(words[0], d[3].word, "the text's sequence starts on the last line");
    assert.equal(words[words.length - 1], d[0].word, "and ends on the first");
    await page.locator("#modes").screenshot({ path: resolve(artifacts, `learn-text-modes-${w}.png`) });
    // Run to the end and read at once (the last picture holds REWIND_MS only).
    const end = await page.evaluate(() => {
      window.__learn.finish("modes");
      const boxes = [...document.querySelectorAll("#modes ol.diagram li")].map((l) => ({ on: l.classList.contains("on"), order: l.querySelector(".lit-order").textContent, word: l.querySelector("b").textContent }));
      return { shows: JSON.parse(document.querySelector('[data-figure="modes"]').dataset.shows), boxes };
    });
    assert.equal(end.shows.seq, seq, "the run lit what the text says");
    d = end.boxes;
    assert.equal(d.findIndex((b) => b.on), 0, "the run ends on the first line");
    assert.ok(d[0].order.endsWith(String(words.length)), `the first line lit last: ${d[0].order}`);
    assert.ok(d[3].order.startsWith("lit 1"), `the last line lit first: ${d[3].order}`);
    const spot = words.includes(d[1].word);
    assert.equal((await liveText(page, "modes-spot")) !== "", spot, "turning on the spot named only when it happens");
    assert.equal(d[1].order !== "", spot);
  });
}

async function dragHandle(page, section, handle, by) {
  const h = page.locator(`[data-figure="${section}"] [data-handle="${handle}"]`);
  await h.scrollIntoViewIfNeeded();
  const box = await h.boundingBox();
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + by.x, y + by.y, { steps: 8 });
  await page.mouse.up();
  await settle(page);
}

const { server, url } = await serve();
const browser = await launch();
const allProblems = [];
try {
  // ------------------------------------------------------------ desktop, reduced motion
  const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 }, 1, { reducedMotion: "reduce" });
  await page.goto(`${url}learn.html`);
  const err = await waitLearn(page);
  await check("the learn page loads the core and the table, eight figures", async () => {
    assert.equal(err, null);
    const hrefs = await page.$$eval("nav.labnav a", (as) => as.map((a) => a.getAttribute("href")));
    assert.deepEqual(hrefs, ["./index.html", "./crowd.html", "./wander.html", "./learn.html"]);
    const figs = await page.evaluate(() => window.__learn.figures);
    assert.deepEqual(figs, Object.keys(DRAGS));
    assert.equal(await page.locator("#message").isHidden(), true);
  });

  for (const name of Object.keys(DRAGS)) {
    await check(`${name}: the canvas draws (non-blank, coloured)`, async () => {
      await page.locator(`#${name}`).scrollIntoViewIfNeeded();
      await settle(page);
      const p = await inked(page, name);
      assert.ok(p.n > 0.02 * p.total && p.colour > 200, JSON.stringify(p));
    });
  }

  await check("reduced motion: nothing plays on its own", async () => {
    await page.locator("#modes").scrollIntoViewIfNeeded();
    await page.waitForTimeout(600);
    const clocks = await page.locator(".fig-clock").allTextContents();
    assert.ok(clocks.every((c) => c === "t 0.0 s"), clocks.join(", "));
  });

  for (const [name, [handle, live, by]] of Object.entries(DRAGS)) {
    await check(`${name}: dragging the ${handle} changes ${live} in the text`, async () => {
      const before = await liveText(page, live);
      await dragHandle(page, name, handle, by);
      const after = await liveText(page, live);
      assert.ok(before && after && before !== "…", `${live}: ${before}`);
      assert.notEqual(after, before, `${live} stayed ${before}`);
    });
  }

  await check("keyboard: a focused handle moves with the arrow keys", async () => {
    const before = await liveText(page, "eta-sim");
    await page.locator('[data-figure="eta"] [data-handle="target"]').focus();
    for (let k = 0; k < 5; k++) await page.keyboard.press("ArrowUp");
    await settle(page);
    assert.notEqual(await liveText(page, "eta-sim"), before);
  });

  await check("play, pause and step run the figure's simulation", async () => {
    const fig = page.locator('[data-figure="modes"]');
    await fig.locator('[data-role="step"]').click();
    assert.equal(await fig.locator(".fig-clock").textContent(), "t 0.0 s");
    await fig.locator('[data-role="play"]').click();
    await page.waitForTimeout(800);
    await fig.locator('[data-role="play"]').click();
    const t = parseFloat((await fig.locator(".fig-clock").textContent()).slice(2));
    assert.ok(t > 0.2, `clock ${t}`);
    await fig.locator('[data-role="reset"]').click();
    assert.equal(await fig.locator(".fig-clock").textContent(), "t 0.0 s");
  });

  await check("challenges: each set-up runs and explains itself", async () => {
    for (const key of ["tiny", "close", "behind"]) {
      await page.locator(`[data-challenge-button="${key}"]`).click();
      await settle(page);
      assert.equal(await page.locator(`[data-challenge="${key}"]`).isVisible(), true);
      const t = await liveText(page, "break-time");
      assert.ok(/s$/.test(t), `${key}: ${t}`);
    }
  });

  // Screenshots of every section (desktop).
  for (const name of Object.keys(DRAGS)) {
    await page.locator(`#${name}`).screenshot({ path: resolve(artifacts, `learn-${name}-1280.png`) });
  }

  await check("the 'show in the lab' links open the lab in the figure's state", async () => {
    for (const name of Object.keys(DRAGS)) {
      const href = await page.locator(`[data-figure="${name}"] a.tolab`).getAttribute("href");
      const want = new URLSearchParams(href.slice(href.indexOf("#") + 1));
      const lab = await context.newPage();
      lab.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") problems.push(`lab from ${name}: ${m.text()}`); });
      await lab.goto(new URL(href, `${url}learn.html`).toString());
      assert.equal(await waitReady(lab), null);
      const st = await lab.evaluate(() => window.__lab.state());
      const probs = await lab.evaluate(() => window.__lab.problems);
      assert.deepEqual(probs, [], `${name}: ${probs.join("; ")}`);
      if (want.get("preset")) {
        assert.equal(st.preset, want.get("preset"));
        assert.ok((await lab.evaluate(() => window.__lab.count())) >= 2);
      } else {
        const near = (a, b, what) => assert.ok(Math.abs(a - Number(b)) < 1e-3, `${name} ${what}: ${a} vs ${b}`);
        near(st.target.x, want.get("tx"), "target x");
        near(st.target.y, want.get("ty"), "target y");
        near(st.vehicle.x, want.get("vx"), "vehicle x");
        near(st.vehicle.y, want.get("vy"), "vehicle y");
        // The lab's agent sits where the figure's vehicle starts, with the figure's target.
        const h = await lab.evaluate(() => window.__lab.internals());
        assert.ok(h && Number.isFinite(h.d), `${name}: internals`);
        assert.equal(st.overlays.ghost, true, `${name}: the lab's ghost overlay`);
      }
      await lab.close();
    }
    // The dragged target of section 2 is the one the lab opens with.
    const href = await page.locator('[data-figure="eta"] a.tolab').getAttribute("href");
    assert.notEqual(new URLSearchParams(href.split("#")[1]).get("tx"), "3");
  });

  await check("no console errors or warnings (learn page and the labs it opened)", async () => {
    assert.deepEqual(problems, []);
  });
  allProblems.push(...problems);
  await context.close();

  // ------------------------------------------------------------ desktop: played to the end
  {
    const { page, problems, context } = await openPage(browser, { width: 1440, height: 900 }, 1, { reducedMotion: "reduce" });
    await page.goto(`${url}learn.html`);
    assert.equal(await waitLearn(page), null);
    await textChecks(page, "desktop");
    await playedChecks(page, "desktop");
    await check("desktop, played: no console errors", async () => assert.deepEqual(problems, []));
    allProblems.push(...problems);
    await context.close();
  }

  // ------------------------------------------------------------ autoplay without reduced motion
  {
    const { page, problems, context } = await openPage(browser, { width: 1280, height: 800 });
    await page.goto(`${url}learn.html`);
    await waitLearn(page);
    await check("without reduced motion no figure plays on its own: each waits at its set-up until Play", async () => {
      for (const name of Object.keys(DRAGS)) {
        await page.locator(`[data-figure="${name}"] canvas`).scrollIntoViewIfNeeded();
        await page.waitForTimeout(150);
      }
      await page.waitForTimeout(600);
      const clocks = await page.locator(".fig-clock").allTextContents();
      assert.ok(clocks.every((c) => c === "t 0.0 s"), clocks.join(", "));
      const fig = page.locator('[data-figure="modes"]');
      await fig.locator('[data-role="play"]').click();
      await page.waitForFunction(() => document.querySelector('[data-figure="modes"] .fig-clock').textContent !== "t 0.0 s", null, { timeout: 5000 });
      await fig.locator('[data-role="play"]').click();
    });
    await check("motion context: no console errors", async () => assert.deepEqual(problems, []));
    await context.close();
  }

  // ------------------------------------------------------------ phone
  {
    const { page, problems, context } = await openPage(browser, { width: 390, height: 844 }, 2, { reducedMotion: "reduce", hasTouch: true, isMobile: true });
    await page.goto(`${url}learn.html`);
    await check("phone: loads, no horizontal scrolling", async () => {
      assert.equal(await waitLearn(page), null);
      const w = await page.evaluate(() => document.documentElement.scrollWidth);
      assert.ok(w <= 392, `page is ${w} px wide`);
    });
    for (const name of Object.keys(DRAGS)) {
      await check(`phone: ${name} draws and fits`, async () => {
        await page.locator(`#${name}`).scrollIntoViewIfNeeded();
        await settle(page);
        const p = await inked(page, name);
        assert.ok(p.n > 0.02 * p.total, JSON.stringify(p));
        const box = await page.locator(`[data-figure="${name}"] canvas`).boundingBox();
        assert.ok(box.width <= 390 && box.width > 300, `canvas ${box.width} px`);
        await page.locator(`#${name}`).screenshot({ path: resolve(artifacts, `learn-${name}-390.png`) });
      });
    }
    await check("phone: the figure stays in view while its paragraphs are read", async () => {
      for (const name of Object.keys(DRAGS)) {
        const paras = page.locator(`#${name} .prose p`);
        for (let k = 0; k < await paras.count(); k++) {
          await paras.nth(k).evaluate((p) => p.scrollIntoView({ block: "end" }));
          await settle(page);
          const fig = await page.locator(`[data-figure="${name}"] canvas`).boundingBox();
          assert.ok(fig.y >= -1 && fig.y + fig.height <= 844, `${name} paragraph ${k + 1}: canvas at ${fig.y}..${fig.y + fig.height}`);
          if (k === 1) await page.screenshot({ path: resolve(artifacts, `learn-${name}-390-reading.png`) });
        }
      }
    });
    await check("phone: a tap on a symbol shows its definition inside the screen, a tap elsewhere hides it", async () => {
      // A later use of η: not focusable, so only the tap handler can open it.
      const sym = page.locator("#table .prose .sym:not([tabindex])").first();
      await sym.scrollIntoViewIfNeeded();
      await sym.tap();
      const def = sym.locator(".def");
      assert.ok(await def.isVisible(), "definition shown on tap");
      const box = await def.boundingBox();
      assert.ok(box.x >= 0 && box.x + box.width <= 390, `definition at ${box.x}..${box.x + box.width}`);
      await page.locator("#table h2").tap();
      assert.ok(!(await def.isVisible()), "definition hidden after a tap elsewhere");
    });
    await textChecks(page, "phone");
    await playedChecks(page, "phone");
    await check("phone: no console errors", async () => assert.deepEqual(problems, []));
    allProblems.push(...problems);
    await context.close();
  }
} finally {
  await browser.close();
  await server.close();
}
if (allProblems.length) console.log(`# console problems:\n${allProblems.join("\n")}`);
