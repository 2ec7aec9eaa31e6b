// The web sources' house rules, checked as tests/layers.rs checks the
// crate's: no function in web/src longer than MAX_LINES lines (parsed with
// rolldown's TypeScript parser, so a function is what the language says it
// is); no comment in web/src, web/test or the pages that names an issue or
// a stop (history goes in git log; a comment gives today's reason); and
// web/src's folder order. The folders of web/src, bottom to top (LAYERS;
// docs/DESIGN.md §3 says why):
//
//   core/     the one seam to the core's wasm package (wasm.ts) and the
//             η table's byte planes
//   threads/  what a page and its workers share to split work: the worker
//             pool, the job queue, the continuing jobs, the state buffers
//   world/    the worlds as plain data and the calls on them, for the page
//             and the workers alike: the lab's recipe, edits, stepping
//             tasks and shared memory; the crowd's strip tasks
//   workers/  the worker entries (*.worker.ts, and only those): what each
//             computes, from core/, threads/ and world/
//   gpu/      the funnelling kernel on WebGPU (its WGSL, the device, the
//             draw from its buffers, its parity with the core), for pages
//   ui/       what the pages draw and handle with (canvas, view, sprites,
//             controls, pointer, …)
//   lab/ crowd/ learn/ wander/ gpubench/ element/   the pages (element/:
//             the npm package's <funnel-figure>); one may use another in
//             one direction only (learn → lab, element → lab and learn)
//
// A file imports from its own folder or one below; every reference counts
// (import, export … from, import(), a type's import("…"), new
// Worker(new URL(…)), `?worker`); no cycle among folders nor among files;
// only core/ reaches ../pkg; a worker is started from a file of workers/.
// A failure names the file and line. The last test plants workers/ → lab/
// references (one of each kind) in memory and asserts the check reports
// each, so every run shows that the check bites.
// Usage: node test/source.mjs   (node:test; `make test-tsc`)
import { test } from "node:test";
import assert from "node:assert/strict";
import { readdirSync, readFileSync, statSync } from "node:fs";
import { dirname, join, relative, resolve, sep } from "node:path";
import { parseAst } from "rolldown/parseAst";
import { webDir } from "./harness.mjs";

const MAX_LINES = 150;

/** web/src's folders by layer, bottom to top (the comment above). */
const LAYERS = [["core"], ["threads"], ["world"], ["workers"], ["gpu"], ["ui"], ["lab", "crowd", "learn", "wander", "peers", "gpubench", "element"]];

/** Files under `dir` whose name matches `re`, recursively. */
function files(dir, re) {
  return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? files(join(dir, e.name), re) : re.test(e.name) ? [join(dir, e.name)] : [],
  );
}

const FUNCTIONS = new Set(["FunctionDeclaration", "FunctionExpression", "ArrowFunctionExpression"]);

/** Every function of `text` (TypeScript) as [first line, line count]. */
function functions(text) {
  const line = (offset) => text.slice(0, offset).split("\n").length;
  const out = [];
  const visit = (n) => {
    if (Array.isArray(n)) return n.forEach(visit);
    if (!n || typeof n !== "object") return;
    if (FUNCTIONS.has(n.type) && n.body) out.push([line(n.start), line(n.end) - line(n.start) + 1]);
    for (const v of Object.values(n)) if (v && typeof v === "object") visit(v);
  };
  visit(parseAst(text, { lang: "ts" }).body);
  return out;
}

test(`no function in web/src is longer than ${MAX_LINES} lines`, () => {
  const long = [];
  let longest = 0;
  for (const f of files(resolve(webDir, "src"), /\.ts$/)) {
    for (const [at, n] of functions(readFileSync(f, "utf8"))) {
      longest = Math.max(longest, n);
      if (n > MAX_LINES) long.push(`${relative(webDir, f)}:${at}: ${n} lines`);
    }
  }
  assert.ok(longest > 50, `the parser found functions (longest ${longest} lines)`);
  assert.deepEqual(long, []);
});

test("no comment names an issue or a stop", () => {
  const roots = [resolve(webDir, "src"), resolve(webDir, "test")];
  const all = [
    ...roots.flatMap((d) => files(d, /\.(ts|mjs|css)$/)),
    ...readdirSync(webDir).filter((f) => f.endsWith(".html")).map((f) => resolve(webDir, f)),
    resolve(webDir, "vite.config.ts"),
  ];
  const history = /(\/\/|\/\*|^\s*\*|<!--).*\b(issue|stop)s? #?[0-9]+/i;
  const found = [];
  for (const f of all) {
    readFileSync(f, "utf8").split("\n").forEach((l, i) => {
      if (history.test(l)) found.push(`${relative(webDir, f)}:${i + 1}: ${l.trim()}`);
    });
  }
  assert.deepEqual(found, []);
});

// ---- The folder order -------------------------------------------------

const SRC = resolve(webDir, "src");
const RANK = new Map(LAYERS.flatMap((folders, rank) => folders.map((f) => [f, rank])));

/** The folder of `rel` (a path under web/src with `/`): its first segment. */
const folderOf = (rel) => rel.split("/")[0];

const isFile = (p) => statSync(p, { throwIfNoEntry: false })?.isFile() ?? false;

/** `new URL("…", import.meta.url)`'s path, else null. */
function urlLiteral(n) {
  if (n?.type !== "NewExpression" || n.callee.type !== "Identifier" || n.callee.name !== "URL") return null;
  const [path, base] = n.arguments;
  const metaUrl = base?.type === "MemberExpression" && base.object.type === "MetaProperty" && base.property.name === "url";
  return metaUrl && path?.type === "Literal" && typeof path.value === "string" ? path.value : null;
}

const MODULE_REFS = new Set(["ImportDeclaration", "ExportNamedDeclaration", "ExportAllDeclaration", "ImportExpression", "TSImportType"]);
const WORKERS = new Set(["Worker", "SharedWorker"]);

/** Every reference of `text` (TypeScript) to another file, as
 *  { spec, line, kind }: import / export-from / import() / a type's
 *  import("…"), `new URL("…", import.meta.url)` ("url"), and a worker
 *  started from one or imported with `?worker` ("worker"). A reference
 *  whose path is computed has spec null: the check cannot follow it. */
function references(text) {
  const starts = [0];
  for (let i = text.indexOf("\n"); i >= 0; i = text.indexOf("\n", i + 1)) starts.push(i + 1);
  const line = (offset) => starts.findLastIndex((s) => s <= offset) + 1;
  const out = [];
  const visit = (n, parent) => {
    if (Array.isArray(n)) return n.forEach((c) => visit(c, parent));
    if (!n || typeof n !== "object") return;
    if (MODULE_REFS.has(n.type) && n.source) {
      const spec = n.source.type === "Literal" && typeof n.source.value === "string" ? n.source.value : null;
      out.push({ spec, line: line(n.start), kind: spec?.includes("?worker") ? "worker" : n.type === "ImportExpression" ? "import()" : "import" });
    }
    const url = urlLiteral(n);
    const started = parent?.type === "NewExpression" && WORKERS.has(parent.callee.name) && parent.arguments[0] === n;
    if (url !== null) out.push({ spec: url, line: line(n.start), kind: started ? "worker" : "url" });
    else if (n.type === "NewExpression" && WORKERS.has(n.callee.name) && urlLiteral(n.arguments[0]) === null) {
      out.push({ spec: null, line: line(n.start), kind: "worker" });
    }
    for (const v of Object.values(n)) if (v && typeof v === "object") visit(v, n);
  };
  visit(parseAst(text, { lang: "ts" }).body, null);
  return out;
}

/** The import graph of web/src: its files and edges { from, to, line,
 *  kind } (paths relative to web/src with `/`; `to` outside it starts with
 *  `../`), and the references that do not resolve. `read` gives a file's
 *  text (the self-test plants an import through it). */
function importGraph(read = (f) => readFileSync(f, "utf8")) {
  const rel = (p) => relative(SRC, p).split(sep).join("/");
  const all = files(SRC, /\.ts$/).sort();
  const edges = [];
  const problems = [];
  for (const f of all) {
    for (const { spec, line, kind } of references(read(f))) {
      const at = `${rel(f)}:${line}`;
      if (spec === null) problems.push(`${at}: a ${kind} reference with a computed path (the order check cannot follow it)`);
      if (spec === null || !spec.startsWith(".")) continue;
      const path = resolve(dirname(f), spec.replace(/\?.*$/, ""));
      // Outside web/src (the core's package, built by `make wasm`): as written.
      const outside = relative(SRC, path).startsWith("..");
      const target = outside ? path : [path, `${path}.ts`, join(path, "index.ts")].find(isFile);
      if (target === undefined) problems.push(`${at}: ${spec} does not resolve`);
      else edges.push({ from: rel(f), to: rel(target), line, kind });
    }
  }
  return { files: all.map(rel), edges, problems };
}

/** Each step of `graph` that breaks the folder order, as `file:line: why`. */
function orderProblems({ files: all, edges }) {
  const out = [];
  for (const f of all) {
    if (!RANK.has(folderOf(f))) out.push(`${f}: in no layer folder (${[...RANK.keys()].join(", ")})`);
    if (f.endsWith(".worker.ts") !== (folderOf(f) === "workers")) out.push(`${f}: workers/ holds the *.worker.ts files, and only those`);
  }
  for (const { from, to, line, kind } of edges) {
    const [a, b] = [folderOf(from), folderOf(to)];
    const at = `${from}:${line}: ${kind} of ${to}`;
    if (to.startsWith("../pkg/") && a !== "core") out.push(`${at}: the core's package is reached through core/ only`);
    if (to.startsWith("../")) continue;
    if (RANK.get(b) > RANK.get(a)) out.push(`${at} goes up the order (${a}/ is below ${b}/)`);
    if (kind === "worker" && b !== "workers") out.push(`${at}: a worker is a file of workers/`);
  }
  return out;
}

/** The cycles of `edges` between the nodes `node` maps files to (folders,
 *  or files themselves), one per strongly connected set, each as the
 *  nodes around it with the file:line of each step. */
function cycles(edges, node) {
  const next = new Map();
  for (const e of edges) {
    const [a, b] = [node(e.from), node(e.to)];
    if (a === b || e.to.startsWith("../")) continue;
    if (!next.has(a)) next.set(a, new Map());
    if (!next.get(a).has(b)) next.get(a).set(b, `${e.from}:${e.line}`);
  }
  // Tarjan's strongly connected components.
  const index = new Map();
  const low = new Map();
  const stack = [];
  const sets = [];
  const connect = (v) => {
    index.set(v, index.size);
    low.set(v, index.get(v));
    stack.push(v);
    for (const w of next.get(v)?.keys() ?? []) {
      if (!index.has(w)) connect(w), low.set(v, Math.min(low.get(v), low.get(w)));
      else if (stack.includes(w)) low.set(v, Math.min(low.get(v), index.get(w)));
    }
    if (low.get(v) === index.get(v)) {
      const set = stack.splice(stack.indexOf(v));
      if (set.length > 1) sets.push(new Set(set));
    }
  };
  [...next.keys()].sort().forEach((v) => index.has(v) || connect(v));
  // Per set, the shortest way round from its first node (breadth first).
  return sets.map((set) => {
    const start = [...set].sort()[0];
    const back = new Map([[start, null]]);
    const queue = [start];
    let last = null;
    while (last === null) {
      const v = queue.shift();
      for (const w of next.get(v).keys()) {
        if (w === start) last = v;
        else if (set.has(w) && !back.has(w)) back.set(w, v), queue.push(w);
        if (last !== null) break;
      }
    }
    const ring = [last];
    while (back.get(ring[0]) !== null) ring.unshift(back.get(ring[0]));
    const steps = ring.map((v, i) => `${v} → ${ring[i + 1] ?? start} (${next.get(v).get(ring[i + 1] ?? start)})`);
    return `cycle: ${steps.join(", ")}`;
  });
}

const graph = importGraph();

test("web/src keeps its folder order (imports go down or sideways among pages)", (t) => {
  assert.ok(graph.edges.length > 200, `the parser found the imports (${graph.edges.length})`);
  // What each folder uses, bottom to top (every run shows the order as it is).
  for (const folder of LAYERS.flat()) {
    const uses = new Set(graph.edges.filter((e) => folderOf(e.from) === folder && !e.to.startsWith("../")).map((e) => folderOf(e.to)));
    uses.delete(folder);
    t.diagnostic(`${folder}/ → ${[...uses].sort((a, b) => RANK.get(a) - RANK.get(b)).join(", ") || "(none)"}`);
  }
  assert.deepEqual([...graph.problems, ...orderProblems(graph)], []);
});

test("no cycle among web/src's folders, nor among its files", () => {
  assert.deepEqual(cycles(graph.edges, folderOf), []);
  assert.deepEqual(cycles(graph.edges, (f) => f), []);
});

test("the order check bites: a planted workers/ → lab/ import fails it", (t) => {
  const worker = resolve(SRC, "workers/step.worker.ts");
  // One reference of each kind, lines 1 to 5, before the file's own text.
  const planted = [
    `import { LabSim } from "../lab/sim";`,
    `export { defaultState } from "../lab/state";`,
    `const late = () => import("../lab/hook");`,
    `const w = () => new Worker(new URL("../lab/main.ts", import.meta.url), { type: "module" });`,
    `import Page from "../lab/loop.ts?worker";`,
    "",
  ].join("\n");
  const g = importGraph((f) => (f === worker ? planted : "") + readFileSync(f, "utf8"));
  const before = new Set([...orderProblems(graph), ...cycles(graph.edges, folderOf)]);
  const found = [...orderProblems(g), ...cycles(g.edges, folderOf), ...cycles(g.edges, (f) => f)].filter((p) => !before.has(p));
  for (const p of found) t.diagnostic(`planted: ${p}`);
  assert.ok(found.some((p) => p.startsWith("workers/step.worker.ts:1: import of lab/sim.ts goes up the order")), "the planted import goes up");
  for (const [line, kind, to] of [[2, "import", "state"], [3, "import()", "hook"], [4, "worker", "main"], [5, "worker", "loop"]]) {
    const at = `workers/step.worker.ts:${line}: ${kind} of lab/${to}.ts goes up the order`;
    assert.ok(found.some((p) => p.startsWith(at)), at);
  }
  assert.ok(found.some((p) => /^cycle: .*\bworkers → lab \(workers\/step\.worker\.ts:1\)/.test(p)), "the planted import closes a cycle of folders");
  assert.ok(found.some((p) => /^cycle: .*workers\/step\.worker\.ts → lab\/[a-z]+\.ts \(workers\/step\.worker\.ts:[1-5]\)/.test(p)), "and one of files");
});
