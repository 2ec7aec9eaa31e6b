// Vite config: serves web/ and hands the committed η table (../tables/) to
// the page at /tables/*, in dev, in preview and in the built dist/.
import { defineConfig, type Plugin } from "vite";
import { readFileSync, readdirSync, existsSync, statSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { resolve, basename } from "node:path";
import type { IncomingMessage, ServerResponse } from "node:http";
import { pathToFileURL } from "node:url";
import { build as bundle } from "rolldown";
import type { firstFrameData } from "./src/lab/firstdata";
import { toPlanes } from "./src/core/tableplanes.ts";

const TABLES = resolve(import.meta.dirname, "../tables");

/** Gzipped files, compressed once per change: the tables (the byte planes,
 *  `NAME.planes`, gzip to less than half of `NAME.bin`; src/core/tableplanes.ts)
 *  and the built core (its wasm to about two fifths). */
const gzipped = new Map<string, { mtimeMs: number; body: Buffer }>();

/** Sends `bytes()` (the content of `file`, as served under `key`),
 *  gzipped when the client takes gzip. */
function send(req: IncomingMessage, res: ServerResponse, key: string, file: string, bytes: () => Buffer): void {
  res.setHeader("Vary", "Accept-Encoding");
  if (!/\bgzip\b/.test(String(req.headers["accept-encoding"] ?? ""))) {
    res.end(bytes());
    return;
  }
  const mtimeMs = statSync(file).mtimeMs;
  let z = gzipped.get(key);
  if (!z || z.mtimeMs !== mtimeMs) {
    z = { mtimeMs, body: gzipSync(bytes(), { level: 6 }) };
    gzipped.set(key, z);
  }
  res.setHeader("Content-Encoding", "gzip");
  res.end(z.body);
}

/** A table file's bytes as served: `NAME.planes` is `NAME.bin` in byte
 *  planes (the page's `fromPlanes` rejoins them; the e2e suite loads the
 *  table this way). */
function tableBytes(file: string, planes: boolean): Buffer {
  const b = readFileSync(file);
  return planes ? Buffer.from(toPlanes(b)) : b;
}

function serveTables(req: IncomingMessage, res: ServerResponse, next: () => void): void {
  const url = req.url ?? "";
  const m = /^\/tables\/([A-Za-z0-9_.-]+)(\?.*)?$/.exec(url);
  if (!m || m[1] === undefined) return next();
  const planes = m[1].endsWith(".planes");
  const file = resolve(TABLES, basename(planes ? m[1].replace(/\.planes$/, ".bin") : m[1]));
  if (!existsSync(file)) {
    res.statusCode = 404;
    res.end("not found");
    return;
  }
  res.setHeader("Content-Type", "application/octet-stream");
  send(req, res, `${file}${planes ? "#planes" : ""}`, file, () => tableBytes(file, planes));
}

/** The built core's wasm (`assets/*.wasm` of `outDir`), gzipped: Vite's
 *  preview compresses scripts and pages but not wasm, the heaviest file
 *  of every page (the browser inflates it while compiling the stream). */
function serveWasm(outDir: string) {
  return (req: IncomingMessage, res: ServerResponse, next: () => void): void => {
    const m = /^\/assets\/([A-Za-z0-9_.-]+\.wasm)(\?.*)?$/.exec(req.url ?? "");
    const file = m?.[1] === undefined ? undefined : resolve(outDir, "assets", m[1]);
    if (file === undefined || !existsSync(file)) return next();
    res.setHeader("Content-Type", "application/wasm");
    res.setHeader("Cache-Control", "public, max-age=31536000, immutable");
    send(req, res, file, file, () => readFileSync(file));
  };
}

function tables(): Plugin {
  return {
    name: "steering-tables",
    configureServer(server) {
      server.middlewares.use(serveTables);
    },
    configurePreviewServer(server) {
      server.middlewares.use(serveTables);
      server.middlewares.use(serveWasm(resolve(server.config.root, server.config.build.outDir)));
    },
    generateBundle() {
      if (!existsSync(TABLES)) return;
      for (const f of readdirSync(TABLES)) {
        if (!f.endsWith(".bin")) continue;
        const bytes = readFileSync(resolve(TABLES, f));
        this.emitFile({ type: "asset", fileName: `tables/${f}`, source: bytes });
        this.emitFile({ type: "asset", fileName: `tables/${f.replace(/\.bin$/, ".planes")}`, source: toPlanes(bytes) });
      }
    },
  };
}

/** The lab's HTML starts compiling the core's SIMD build before
 *  its scripts run (index.html); this puts the built asset's URL (hashed,
 *  the one src/core/wasm.ts would fetch) in place of `%CORE_SIMD_WASM%`, or the
 *  package's own file in the dev server. */
function coreWasmUrl(): Plugin {
  return {
    name: "steering-core-wasm-url",
    transformIndexHtml: {
      order: "post",
      handler(html, ctx) {
        if (!html.includes("%CORE_SIMD_WASM%")) return html;
        const asset = Object.keys(ctx.bundle ?? {}).find((f) => /(^|\/)steering_simd_bg-[^/]*\.wasm$/.test(f));
        if (ctx.bundle && !asset) throw new Error("the core's SIMD build is not in the bundle");
        return html.replace("%CORE_SIMD_WASM%", asset ? `./${asset}` : "./pkg/steering_simd_bg.wasm");
      },
    },
  };
}

/** `v` as a JavaScript literal: JSON, but NaN and ±Infinity kept (the
 *  core's internals use NaN for "none") and typed arrays as arrays. */
function jsLiteral(v: unknown): string {
  if (typeof v === "number") return Number.isNaN(v) ? "NaN" : !Number.isFinite(v) ? (v > 0 ? "Infinity" : "-Infinity") : Object.is(v, -0) ? "-0" : String(v);
  if (typeof v === "string" || typeof v === "boolean" || v === null || v === undefined) return JSON.stringify(v ?? null);
  if (ArrayBuffer.isView(v)) return jsLiteral(Array.from(v as unknown as ArrayLike<number>));
  if (Array.isArray(v)) return `[${v.map(jsLiteral).join(",")}]`;
  const entries = Object.entries(v as Record<string, unknown>).filter(([, x]) => x !== undefined);
  return `{${entries.map(([k, x]) => `${JSON.stringify(k)}:${jsLiteral(x)}`).join(",")}}`;
}

/** The first drawn frame (src/lab/firstframe.ts): the core, run
 *  here in Node, builds the default playground as src/lab/sim.ts does
 *  (`Lab.withoutTable`, the playground agent, the controller settings) and
 *  its state at t = 0, the agent's internals and predicted seek path go
 *  into the lab's built HTML, with src/lab/first.ts bundled inline to draw
 *  them before any script request or the core is in. */
async function firstFrameScript(): Promise<string> {
  const src = resolve(import.meta.dirname, "src/lab");
  const pkg = resolve(import.meta.dirname, "pkg");
  const bundleTs = (input: string, format: "iife" | "esm") =>
    bundle({
      input, platform: format === "iife" ? "browser" : "node", logLevel: "warn", write: false, output: { format, minify: format === "iife" },
      // The inline script takes the core's enums from its glue, not its classes (no wasm there): their
      // top-level `Symbol.dispose` lines and registries would keep them
      // in the minified script.
      plugins: [{
        name: "glue-enums-only",
        transform: (code: string, id: string) =>
          /pkg[\\/]steering\.js$/.test(id) && format === "iife"
            ? code.replace(/^if \(Symbol\.dispose\) .*$/gm, "").replace(/new (FinalizationRegistry|TextDecoder|TextEncoder)\(/g, "/*#__PURE__*/ new $1(")
            : null,
      }],
    });
  // src/lab/firstdata.ts (bundled, as the config loader does not load the page's modules) on the core's package.
  const maker = (await bundleTs(resolve(src, "firstdata.ts"), "esm")).output[0].code;
  const { firstFrameData: make } = (await import(`data:text/javascript;base64,${Buffer.from(maker).toString("base64")}`)) as { firstFrameData: typeof firstFrameData };
  const core = (await import(pathToFileURL(resolve(pkg, "steering.js")).href)) as typeof import("./pkg/steering.js");
  core.initSync({ module: readFileSync(resolve(pkg, "steering_bg.wasm")) });
  const data = make(core);
  const code = (await bundleTs(resolve(src, "first.ts"), "iife")).output[0].code.replace(/<\/(script)/gi, "<\\/$1");
  return `window.__firstFrameData=${jsLiteral(data)};\n${code}`;
}

function firstFrame(): Plugin {
  return {
    name: "steering-first-frame",
    transformIndexHtml: {
      order: "post",
      async handler(html, ctx) {
        // The built lab page only (the dev server starts as before).
        const bundle = ctx.bundle;
        if (!bundle || !html.includes('<canvas id="lab"')) return html;
        // The stylesheet inline too: a linked one would hold the inline script
        // (and the layout it measures) until its request came back.
        const inlined = html.replace(/<link rel="stylesheet" crossorigin href="\.\/([^"]+\.css)">/g, (link, file: string) => {
          const css = bundle[file];
          return css && css.type === "asset" ? `<style>${String(css.source)}</style>` : link;
        });
        return inlined.replace("</main>", `</main>\n    <script>${await firstFrameScript()}</script>`);
      },
    },
  };
}

/** The lab's pages: their file, title and own stylesheets, and their link
 *  in the navigation every page shows, in this order. */
const PAGES = [
  { file: "index.html", title: "funnelling control", nav: "Funnelling", css: [] },
  { file: "crowd.html", title: "crowded path following", nav: "Crowd path following", css: ["./src/gallery.css"] },
  { file: "wander.html", title: "random steering gallery", nav: "Random steering gallery", css: ["./src/gallery.css"] },
  { file: "learn.html", title: "learn funnelling", nav: "Learn", css: ["./src/learn/learn.css"] },
  // The GPU timing page: linked from the lab's panel, not from every page's navigation.
  { file: "gpu.html", title: "the funnelling kernel on this GPU", nav: null, css: ["./src/gallery.css"] },
] as const;

/** Every page's head and navigation, from PAGES: `<!-- lab:head -->` and
 *  `<!-- lab:nav -->` in a page's HTML, filled in before Vite reads its
 *  stylesheets (dev server and build alike). */
function pageFrame(): Plugin {
  return {
    name: "steering-page-frame",
    transformIndexHtml: {
      order: "pre",
      handler(html, ctx) {
        const file = basename(ctx.filename);
        if (TEST_PAGES.includes(file)) return html;
        const page = PAGES.find((p) => p.file === file);
        if (!page) throw new Error(`${file} is not one of the lab's pages (vite.config.ts, PAGES)`);
        const head = [
          `<meta charset="utf-8" />`,
          `<meta name="viewport" content="width=device-width, initial-scale=1" />`,
          `<link rel="icon" href="data:," />`,
          `<title>The steering lab — ${page.title}</title>`,
          ...["./src/style.css", ...page.css].map((href) => `<link rel="stylesheet" href="${href}" />`),
        ];
        const links = PAGES.filter((p) => p.nav !== null).map((p) => `<a href="./${p.file}"${p === page ? ` aria-current="page"` : ""}>${p.nav}</a>`);
        const nav = [`<h1>The steering lab</h1>`, `<nav class="labnav" aria-label="lab pages">`, ...links.map((a) => `  ${a}`), `</nav>`];
        const fill = (marker: string, lines: string[]) => (text: string) =>
          text.replace(new RegExp(`^( *)<!-- ${marker} -->$`, "m"), (_, indent: string) => lines.map((l) => indent + l).join("\n"));
        const out = fill("lab:nav", nav)(fill("lab:head", head)(html));
        if (out.includes("<!-- lab:")) throw new Error(`${file}: a lab:head or lab:nav marker was not filled`);
        return out;
      },
    },
  };
}

/** Pages of the test build only (`--mode test`), outside the lab's
 *  navigation: the peers harness (src/peers/main.ts, web/test/e2e-peers.mjs). */
const TEST_PAGES: readonly string[] = ["peers.html"];

// Cross-origin isolation gives performance.now() 5 µs resolution (instead
// of 100 µs), which the HUD's µs-per-update figure needs.
const ISOLATION = { "Cross-Origin-Opener-Policy": "same-origin", "Cross-Origin-Embedder-Policy": "require-corp" };

/** The e2e suites' and the benches' build (`vite build --mode test`):
 *  the pages with their test hooks (`import.meta.env.MODE === "test"`),
 *  beside the shipped dist/, which holds none of them. */
const TEST_MODE = "test";

export default defineConfig(({ mode }) => ({
  base: "./",
  plugins: [pageFrame(), tables(), coreWasmUrl(), firstFrame()],
  server: { host: "127.0.0.1", fs: { allow: [".."] }, headers: ISOLATION },
  preview: { host: "127.0.0.1", headers: ISOLATION },
  // The η-table workers import the wasm module: ES workers.
  worker: { format: "es" },
  build: {
    outDir: mode === TEST_MODE ? "dist-test" : "dist",
    target: "es2022",
    sourcemap: false,
    // The test build's peers harness carries Recast/Detour with its wasm
    // inlined (@recast-navigation/wasm's default build, 0.7 MB): expected there.
    ...(mode === TEST_MODE ? { chunkSizeWarningLimit: 800 } : {}),
    // The gallery pages (crowd path following, random steering) and the
    // learn page beside the funnelling lab.
    rolldownOptions: {
      // The code the pages share in one chunk (not one copy beside each
      // page's own): fewer requests before the lab's core takes over. The
      // peers' code (src/peers/: Yuka, which the lab loads only for its
      // compare view, and the test build's harness) stays out of it.
      output: { codeSplitting: { groups: [{ name: "shared", test: /[\\/](src[\\/](?!peers[\\/])|pkg[\\/])|preload-helper|modulepreload-polyfill/, minShareCount: 2 }] } },
      input: {
        index: resolve(import.meta.dirname, "index.html"),
        crowd: resolve(import.meta.dirname, "crowd.html"),
        wander: resolve(import.meta.dirname, "wander.html"),
        learn: resolve(import.meta.dirname, "learn.html"),
        gpu: resolve(import.meta.dirname, "gpu.html"),
        ...(mode === TEST_MODE ? { peers: resolve(import.meta.dirname, "peers.html") } : {}),
      },
    },
  },
}));
