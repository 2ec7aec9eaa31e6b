// Runs `make test`'s browser suites (and the other jobs that only wait on a
// built page or package) side by side, `--jobs` at a time, each a shell
// command, in the order given (longest first keeps the lanes even). Why:
// a suite mostly waits on its page (frames, workers, timers), so one at a
// time left a core of the two idle for some ten minutes.
//
// Each job's output is kept whole and printed when it ends (never two
// jobs' lines interleaved), and also written to target/lanes/NAME.log;
// its time goes to target/NAME.log for `--log NAME` (default lanes:
// "seconds job exit" per line), which `make test` prints beside its stages. Every job runs even when one fails; the
// run then fails, naming the failed jobs.
//
//   node web/test/lanes.mjs [--jobs N] [--log NAME] NAME=COMMAND ...
import { spawn } from "node:child_process";
import { appendFileSync, mkdirSync, writeFileSync } from "node:fs";
import { dirname, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { parseArgs } from "node:util";

const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: { jobs: { type: "string", default: "2" }, log: { type: "string", default: "lanes" } },
});
const jobs = Number(values.jobs);
if (!Number.isInteger(jobs) || jobs < 1) {
  console.error(`--jobs: ${values.jobs} is not a whole number of at least 1`);
  process.exit(2);
}
const queue = positionals.map((arg) => {
  const eq = arg.indexOf("=");
  if (eq < 1) {
    console.error(`${arg}: a job is NAME=COMMAND`);
    process.exit(2);
  }
  return { name: arg.slice(0, eq), command: arg.slice(eq + 1) };
});
if (queue.length === 0) {
  console.error("usage: node web/test/lanes.mjs [--jobs N] [--log NAME] NAME=COMMAND ...");
  process.exit(2);
}

// The repository's root (not harness.mjs's webDir: that module loads vite
// and Playwright, which the build lanes run before).
const root = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const logDir = resolve(root, "target/lanes");
mkdirSync(logDir, { recursive: true });
const timesLog = resolve(root, `target/${values.log}.log`);
writeFileSync(timesLog, "");

/** Runs one job in the repository's root; resolves to its exit code and seconds. */
function run(job) {
  const started = Date.now();
  console.log(`--- ${job.name}: started (${job.command})`);
  return new Promise((done) => {
    const child = spawn("bash", ["-c", job.command], { cwd: root, stdio: ["ignore", "pipe", "pipe"] });
    const out = [];
    child.stdout.on("data", (b) => out.push(b));
    child.stderr.on("data", (b) => out.push(b));
    child.on("close", (code, signal) => {
      const seconds = Math.round((Date.now() - started) / 1000);
      const text = Buffer.concat(out).toString();
      writeFileSync(resolve(logDir, `${job.name}.log`), text);
      const exit = code ?? `signal ${signal}`;
      process.stdout.write(`\n=== ${job.name} (${seconds} s, exit ${exit}) ===\n${text}=== end of ${job.name} ===\n\n`);
      appendFileSync(timesLog, `${seconds} ${job.name} ${code ?? 1}\n`);
      done({ job, code: code ?? 1, seconds });
    });
  });
}

const results = [];
async function lane() {
  for (let job = queue.shift(); job; job = queue.shift()) results.push(await run(job));
}
await Promise.all(Array.from({ length: Math.min(jobs, queue.length) }, lane));

const failed = results.filter((r) => r.code !== 0);
for (const r of results) console.log(`  ${r.job.name.padEnd(20)} ${String(r.seconds).padStart(5)} s${r.code ? "  FAILED" : ""}`);
if (failed.length > 0) {
  console.error(`\nfailed: ${failed.map((r) => r.job.name).join(", ")} (their output above, and in target/lanes/)`);
  process.exit(1);
}
