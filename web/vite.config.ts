// Vite config: serves web/ and hands the committed η table (../tables/) to
// the page at /tables/*, in dev, in preview and in the built dist/.
import { defineConfig, type Plugin } from "vite";
import { readFileSync, readdirSync, existsSync, statSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { resolve, basename } from "node:path";
import type { IncomingMessage, ServerResponse } from "node:http";

const TABLES = resolve(import.meta.dirname, "../tables");

/** Gzipped tables by file, compressed once (issue 17: 3.2 MB → 1.2 MB on
 *  the wire; 0.54 MB as byte planes, `NAME.planes`). */
const gzipped = new Map<string, { mtimeMs: number; body: Buffer }>();

/** The byte planes of `b`: src/tableplanes.ts's `toPlanes` (the page's
 *  `fromPlanes` rejoins them; the e2e suite loads the table this way). */
function toPlanes(b: Uint8Array): Uint8Array {
  const m = b.length >>> 2;
  const out = new Uint8Array(b.length);
  for (let i = 0; i < m; i++) for (let j = 0; j < 4; j++) out[j * m + i] = b[4 * i + j]!;
  out.set(b.subarray(4 * m), 4 * m);
  return out;
}

/** A table file's bytes as served: `NAME.planes` is `NAME.bin` in byte
 *  planes (issue 17, src/tableplanes.ts: same bytes once rejoined, 2.2×
 *  smaller gzipped). */
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
  res.setHeader("Vary", "Accept-Encoding");
  if (/\bgzip\b/.test(String(req.headers["accept-encoding"] ?? ""))) {
    const mtimeMs = statSync(file).mtimeMs;
    const k = `${file}${planes ? "#planes" : ""}`;
    let z = gzipped.get(k);
    if (!z || z.mtimeMs !== mtimeMs) {
      z = { mtimeMs, body: gzipSync(tableBytes(file, planes), { level: 6 }) };
      gzipped.set(k, z);
    }
    res.setHeader("Content-Encoding", "gzip");
    res.end(z.body);
    return;
  }
  res.end(tableBytes(file, planes));
}

function tables(): Plugin {
  return {
    name: "steering-tables",
    configureServer(server) {
      server.middlewares.use(serveTables);
    },
    configurePreviewServer(server) {
      server.middlewares.use(serveTables);
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

/** Issue 17: the lab's HTML starts compiling the core's SIMD build before
 *  its scripts run (index.html); this puts the built asset's URL (hashed,
 *  the one src/wasm.ts would fetch) in place of `%CORE_SIMD_WASM%`, or the
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

// Cross-origin isolation gives performance.now() 5 µs resolution (instead
// of 100 µs), which the HUD's µs-per-update figure needs.
const ISOLATION = { "Cross-Origin-Opener-Policy": "same-origin", "Cross-Origin-Embedder-Policy": "require-corp" };

export default defineConfig({
  base: "./",
  plugins: [tables(), coreWasmUrl()],
  server: { host: "127.0.0.1", fs: { allow: [".."] }, headers: ISOLATION },
  preview: { host: "127.0.0.1", headers: ISOLATION },
  // The η-table workers (issue 14) import the wasm module: ES workers.
  worker: { format: "es" },
  build: {
    target: "es2022",
    sourcemap: false,
    // The gallery pages (crowd path following, random steering) and the learn
    // page (issue 15) beside the funnelling lab.
    rolldownOptions: {
      input: {
        index: resolve(import.meta.dirname, "index.html"),
        crowd: resolve(import.meta.dirname, "crowd.html"),
        wander: resolve(import.meta.dirname, "wander.html"),
        learn: resolve(import.meta.dirname, "learn.html"),
      },
    },
  },
});
