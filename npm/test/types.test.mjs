// The package's typings as a TypeScript user meets them: the tarball
// installed into a scratch folder, a module that uses it compiled in
// strict mode (the front end's pinned tsc), and a wrong call refused.
import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync, spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const npmDir = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const repo = resolve(npmDir, "..");
const { name, version } = JSON.parse(readFileSync(join(npmDir, "package.json"), "utf8"));
const tarball = resolve(process.env.STEERING_CORE_TGZ ?? join(repo, "target/npm", `${name}-${version}.tgz`));
const tsc = join(repo, "web/node_modules/.bin/tsc");

const USE = `
import { createLab, loadTable, init, Lab, StateField, Mode, TABLE_URL } from "steering-core";
export async function run(): Promise<number> {
  const lab: Lab = await createLab({ table: TABLE_URL });
  lab.addAgent({ x: 0, y: 0, theta: 0, goals: [{ x: 4, y: 1, beta: 1.57, dTol: 0.25, epsTol: 0.09, speed: 1.3, halting: true, relaxed: false }] });
  lab.step(1);
  const s: Float32Array = lab.state();
  const bytes: Uint8Array = await loadTable();
  void init; void bytes;
  return s[StateField.Mode] === Mode.EndOfSteering ? 1 : 0;
}
`;
const WRONG = `
import { createLab } from "steering-core";
export async function run(): Promise<void> {
  const lab = await createLab();
  lab.addAgent({ x: 0, y: 0, heading: 0, goals: [] });
}
`;

function compile(dir, file) {
  return spawnSync(tsc, ["--noEmit", "--strict", "--module", "nodenext", "--moduleResolution", "nodenext", "--target", "es2022", "--lib", "es2022,dom,ESNext.Disposable", "--skipLibCheck", "false", file], { cwd: dir, encoding: "utf8" });
}

test("the typings compile a user's strict TypeScript and refuse a wrong agent", (t) => {
  const scratch = mkdtempSync(join(tmpdir(), "steering-core-types-"));
  t.after(() => rmSync(scratch, { recursive: true, force: true }));
  writeFileSync(join(scratch, "package.json"), JSON.stringify({ name: "steering-core-types", private: true, type: "module" }));
  execFileSync("npm", ["install", "--no-audit", "--no-fund", "--loglevel=error", tarball], { cwd: scratch, stdio: "inherit" });
  writeFileSync(join(scratch, "use.ts"), USE);
  writeFileSync(join(scratch, "wrong.ts"), WRONG);
  const ok = compile(scratch, "use.ts");
  assert.equal(ok.status, 0, ok.stdout + ok.stderr);
  const wrong = compile(scratch, "wrong.ts");
  assert.notEqual(wrong.status, 0, "a misnamed field compiles");
  assert.match(wrong.stdout, /heading/);
});
