// Runs `make test`'s jobs side by side, `--jobs` at a time, each a shell
// command, in the order given (longest first keeps the lanes even): the
// two build lanes, then the browser suites (and the other jobs that only
// wait on a built page or package). Why: a suite mostly waits on its page
// (frames, workers, timers), and a lane of builds and tests often runs on
// one core, so one job at a time left a core of the two idle.
//
// A job named NAME@DEP,... starts only once the jobs DEP, ... have ended
// well (a browser suite after the lane that builds the page): a free lane
// takes the first job in order whose jobs before it have ended; a job
// whose DEP failed does not run, and counts as failed.
//
// Each job's output is kept whole and printed when it ends (never two
// jobs' lines interleaved), and also written to target/lanes/NAME.log;
// its time goes to target/NAME.log for `--log NAME` (default lanes:
// "seconds job exit start" per line, start in seconds from the run's), which `make test` prints beside its
// stages. Every job runs even when one fails; the run then fails, naming
// the failed jobs.
//
//   node web/test/lanes.mjs [--jobs N] [--log NAME] NAME[@DEP,...]=COMMAND ...
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
    console.error(`${arg}: a job is NAME[@DEP,...]=COMMAND`);
    process.exit(2);
  }
  const [name, deps = ""] = arg.slice(0, eq).split("@");
  return { name, after: deps ? deps.split(",") : [], command: arg.slice(eq + 1) };
});
if (queue.length === 0) {
  console.error("usage: node web/test/lanes.mjs [--jobs N] [--log NAME] NAME[@DEP,...]=COMMAND ...");
  process.exit(2);
}
const names = new Set(queue.map((j) => j.name));
for (const job of queue) {
  const unknown = job.after.filter((d) => !names.has(d) || d === job.name);
  if (unknown.length > 0) {
    console.error(`${job.name}: waits on ${unknown.join(", ")}, not another job of this run`);
    process.exit(2);
  }
}

// The repository's root (not harness.mjs's webDir: that module loads vite
// and Playwright, which the build lanes run before).
const root = resolve(dirname(fileURLToPath(import.meta.url)), "../..");
const logDir = resolve(root, "target/lanes");
mkdirSync(logDir, { recursive: true });
const timesLog = resolve(root, `target/${values.log}.log`);
writeFileSync(timesLog, "");
const runStart = Date.now();

/** Runs one job in the repository's root; resolves to its exit code and seconds. */
function run(job) {
  const started = Date.now();
  const at = Math.round((started - runStart) / 1000);
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
      appendFileSync(timesLog, `${seconds} ${job.name} ${code ?? 1} ${at}\n`);
      done({ job, code: code ?? 1, seconds });
    });
  });
}

const results = [];
/** Exit code of each ended job, by name. */
const ended = new Map();
/** Jobs running now. */
let running = 0;
/** The lanes waiting for a job to end (none ready for them yet). */
let waiting = [];
const wake = () => {
  const lanes = waiting;
  waiting = [];
  for (const go of lanes) go();
};

/** The first job in order whose jobs before it have all ended, taken off
 *  the queue; undefined when none is ready yet. */
function takeReady() {
  const i = queue.findIndex((j) => j.after.every((d) => ended.has(d)));
  return i < 0 ? undefined : queue.splice(i, 1)[0];
}

function finish(result) {
  results.push(result);
  ended.set(result.job.name, result.code);
  wake();
}

async function lane() {
  while (queue.length > 0) {
    const job = takeReady();
    if (!job && running === 0) {
      // Nothing runs and nothing can start: the jobs left wait on each other.
      for (const j of queue.splice(0)) {
        console.log(`--- ${j.name}: not run (waits in a circle on ${j.after.join(", ")})`);
        appendFileSync(timesLog, `0 ${j.name} 1 ${Math.round((Date.now() - runStart) / 1000)}\n`);
        results.push({ job: j, code: 1, seconds: 0 });
      }
      wake();
      break;
    }
    if (!job) {
      await new Promise((go) => waiting.push(go));
      continue;
    }
    const failedDeps = job.after.filter((d) => ended.get(d) !== 0);
    if (failedDeps.length > 0) {
      console.log(`--- ${job.name}: not run (${failedDeps.join(", ")} failed)`);
      appendFileSync(timesLog, `0 ${job.name} 1 ${Math.round((Date.now() - runStart) / 1000)}\n`);
      finish({ job, code: 1, seconds: 0 });
      continue;
    }
    running += 1;
    const result = await run(job);
    running -= 1;
    finish(result);
  }
}
await Promise.all(Array.from({ length: Math.min(jobs, queue.length) }, lane));

const failed = results.filter((r) => r.code !== 0);
for (const r of results) console.log(`  ${r.job.name.padEnd(20)} ${String(r.seconds).padStart(5)} s${r.code ? "  FAILED" : ""}`);
if (failed.length > 0) {
  console.error(`\nfailed: ${failed.map((r) => r.job.name).join(", ")} (their output above, and in target/lanes/)`);
  process.exit(1);
}
