// Frame-time harness: the built page with N extra funnelling agents
// (URL flag n=N, no trails or overlays) in headless Chromium. For each N,
// waits 0.5 s, then samples ~2 s with performance.now(): mean rAF interval,
// mean and p95 work per frame (core step + drawing) and core step time.
// Issue 18: the largest N again with each avoidance method of AVOID
// (default separation,orca; argv[3]), beside the same run's avoidance-off figures.
import { serve, launch, openPage, waitReady, artifacts } from "./harness.mjs";
import { resolve } from "node:path";

const sizes = (process.argv[2] ?? "1000,10000").split(",").map(Number);
const { server, url } = await serve();
const browser = await launch();
let bad = 0;
try {
  const firsts = [];
  const marks = { "lab:core": [], "lab:table": [] };
  for (let k = 0; k < 5; k++) {
    const { page, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
    await page.goto(url);
    const err = await waitReady(page, 60000);
    if (err) throw new Error(err);
    firsts.push(await page.evaluate(() => window.__lab.firstFrameMs));
    for (const m of await page.evaluate(() => performance.getEntriesByType("mark").map((e) => [e.name, e.startTime]))) marks[m[0]]?.push(m[1]);
    await context.close();
  }
  firsts.sort((a, b) => a - b);
  const median = (a) => a.sort((x, y) => x - y)[a.length >> 1]?.toFixed(0) ?? "?";
  console.log(
    `first drawn frame after navigation start: median ${firsts[2].toFixed(0)} ms (min ${firsts[0].toFixed(0)}, max ${firsts[4].toFixed(0)}) over 5 loads; ` +
      `core instantiated at ${median(marks["lab:core"])} ms, table loaded at ${median(marks["lab:table"])} ms (medians)`,
  );
  // Above 2,000 agents also with the WebGL2 layer forced (?draw=gl, issue 17:
  // headless WebGL is software, so the page's own choice is the 2D sprites).
  const runs = sizes.flatMap((n) => (n > 2000 ? [[n, ""], [n, "gl"]] : [[n, ""]]));
  const avoids = (process.argv[3] ?? "separation,orca").split(",").filter((m) => m !== "");
  const largest = Math.max(...sizes);
  for (const m of avoids) runs.push([largest, "", m]);
  for (const [n, draw, avoid] of runs) {
    const { page, problems: all, context } = await openPage(browser, { width: 1280, height: 800 }, 1);
    await page.goto(`${url.replace(/\/?$/, "/")}${draw ? `?draw=${draw}` : ""}#n=${n}&ov=${avoid ? `&avoid=${avoid}` : ""}`);
    const err = await waitReady(page, 60000);
    if (err) throw new Error(err);
    await page.waitForTimeout(500);
    await page.evaluate(() => window.__lab.perfReset());
    await page.waitForTimeout(2000);
    const s = await page.evaluate(() => window.__lab.perfStats());
    await page.screenshot({ path: resolve(artifacts, `perf-${n}${draw ? `-${draw}` : ""}${avoid ? `-${avoid}` : ""}.png`) });
    const how = await page.$eval("#lab", (c) => c.dataset.agents);
    console.log(
      `perf n=${s.agents - 1}+1 agents (${how}${avoid ? `, avoidance ${avoid}` : ""}): ${s.frames} frames in ~2 s, rAF interval ${s.meanIntervalMs.toFixed(2)} ms ` +
        `(${(1000 / s.meanIntervalMs).toFixed(1)} fps), work/frame mean ${s.meanWorkMs.toFixed(2)} ms p95 ${s.p95WorkMs.toFixed(2)} ms, ` +
        `core step/frame ${s.meanStepMs.toFixed(2)} ms, drawing/frame ${s.meanDrawMs.toFixed(2)} ms, ` +
        `core ${s.usPerUpdate.toFixed(2)} µs per agent update`,
    );
    const problems = all.filter((p) => !(draw === "gl" && /GPU stall due to ReadPixels/.test(p)));
    if (problems.length) { bad++; console.log(problems.join("\n")); }
    await context.close();
  }
} finally {
  await browser.close();
  await server.close();
}
process.exit(bad ? 1 : 0);
