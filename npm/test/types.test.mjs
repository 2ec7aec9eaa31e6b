// The package's typings as a TypeScript user meets them: the tarball
// installed under target/npm-user/types, a module that uses it compiled
// with `--strict` and `lib: ["es2022", "dom"]` (the front end's pinned
// tsc; no ESNext.Disposable, no skipLibCheck), fields the runtime
// defaults left out, and a wrong call refused.
import { test } from "node:test";
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { writeFileSync } from "node:fs";
import { join } from "node:path";
import { installed, repo } from "./install.mjs";

const tsc = join(repo, "web/node_modules/.bin/tsc");

const USE = `
import { createLab, loadTable, init, Lab, StateField, Mode, MODE_NAMES, TABLE_URL, type AgentConfig, type Internals } from "steering-core";
import type { FunnelFigure, ArriveDetail } from "steering-core/funnel-figure.js";
export async function run(): Promise<number> {
  const lab: Lab = await createLab({ table: TABLE_URL });
  // halting and relaxed default to false; v and omega to 0.
  lab.addAgent({ x: 0, y: 0, theta: 0, goals: [{ x: 4, y: 1, beta: 1.57, dTol: 0.25, epsTol: 0.09, speed: 1.3 }] });
  const many: AgentConfig[] = [1, 2, 3].map((k) => ({ x: k, y: 0, theta: 0, goals: [{ x: 4, y: k, beta: 0, dTol: 0.3, epsTol: 0.2, speed: 1, halting: true }] }));
  const first: number = lab.addAgents(many);
  // Vehicle limits: any subset, the rest at the core's defaults.
  lab.setParams({ vMax: 1.5 });
  lab.step(1);
  const s: Float32Array = lab.state();
  const m: Mode = lab.mode(0);
  const name: string = MODE_NAMES[m];
  const done: boolean = lab.done(0) && lab.atRest(first);
  const inter: Internals = lab.internals(0);
  const arrived: boolean = inter.mode === Mode.EndOfSteering;
  const bytes: Uint8Array = await loadTable();
  const fig: FunnelFigure | null = document.querySelector("funnel-figure");
  fig?.addEventListener("arrive", (e) => { const d: ArriveDetail = e.detail; void d; });
  lab.free();
  void init; void bytes; void name; void done; void arrived;
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
  return spawnSync(tsc, ["--noEmit", "--strict", "--module", "nodenext", "--moduleResolution", "nodenext", "--target", "es2022", "--lib", "es2022,dom", "--skipLibCheck", "false", file], { cwd: dir, encoding: "utf8" });
}

test("the typings compile a user's strict TypeScript (lib es2022 + dom) and refuse a wrong agent", () => {
  const scratch = installed("types");
  writeFileSync(join(scratch, "use.ts"), USE);
  writeFileSync(join(scratch, "wrong.ts"), WRONG);
  const ok = compile(scratch, "use.ts");
  assert.equal(ok.status, 0, ok.stdout + ok.stderr);
  const wrong = compile(scratch, "wrong.ts");
  assert.notEqual(wrong.status, 0, "a misnamed field compiles");
  assert.match(wrong.stdout, /heading/);
});
