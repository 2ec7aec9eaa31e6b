// The web sources' house rules, checked as tests/layers.rs checks the
// crate's: no function in web/src longer than MAX_LINES lines (parsed with
// rolldown's TypeScript parser, so a function is what the language says it
// is), and no comment in web/src, web/test or the pages that names an
// issue or a stop (history goes in git log; a comment gives today's reason).
// Usage: node test/source.mjs   (node:test; `make test-tsc`)
import { test } from "node:test";
import assert from "node:assert/strict";
import { readdirSync, readFileSync } from "node:fs";
import { join, relative, resolve } from "node:path";
import { parseAst } from "rolldown/parseAst";
import { webDir } from "./harness.mjs";

const MAX_LINES = 150;

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
