// Runs one browser suite (a script of web/test) in a child Node, with this
// Node's own flags (e.g. --test-name-pattern): `node [flags] test/suite.mjs
// SCRIPT [args]`. When the suite's browser process crashed under it (exit
// code BROWSER_CRASHED, harness.mjs `launch`), the suite runs once more
// from the start and that run's result stands; it is said loudly. Any
// other failure is the suite's own and is never run again. Why: Chromium's
// browser process can crash by itself (a SIGSEGV inside the host's
// libfontconfig, on a thread of its pool, has been seen), which says
// nothing of the pages; a second crash in a row fails the run.
import { spawnSync } from "node:child_process";
import { BROWSER_CRASHED } from "./harness.mjs";

// No parseArgs here: everything after the script's path is the script's
// own, passed through untouched (the script parses it itself).
const [script, ...args] = process.argv.slice(2);
if (!script) {
  console.error("usage: node [node flags] web/test/suite.mjs SCRIPT [ARGS...]");
  process.exit(2);
}
const run = () => spawnSync(process.execPath, [...process.execArgv, script, ...args], { stdio: "inherit" });
let r = run();
if (r.status === BROWSER_CRASHED) {
  console.error(`\n*** ${script}: Chromium crashed under the suite; running it once more from the start.\n`);
  r = run();
  if (r.status === BROWSER_CRASHED) console.error(`\n*** ${script}: Chromium crashed again; the run fails.\n`);
}
process.exit(r.status ?? 1);
