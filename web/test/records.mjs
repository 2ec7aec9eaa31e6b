// Figures records from the browser suites, in the format the figures
// report reads (crate/cli/records.rs `Record`, which refuses unknown
// fields): { source, command, kind, seeds, commit, date, cores, figures:
// [{ id, what, value, unit, digits }] }, one file per source, named as
// `records::file_name` names it, written atomically into $FIGURES_DIR or
// the repository's target/figures. A figure whose value is not finite is
// left out (the report refuses null) and said on stderr.
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, renameSync, writeFileSync } from "node:fs";
import { availableParallelism } from "node:os";
import { resolve } from "node:path";
import { webDir } from "./harness.mjs";

export const repoDir = resolve(webDir, "..");

/** Where deterministic records go: $FIGURES_DIR (relative to the
 *  repository), else target/figures; timed ones belong to the report's
 *  full mode: target/figures-full (`make figures-full` reads it). */
export const figuresDir = (kind = "deterministic") =>
  resolve(repoDir, kind === "timed" ? "target/figures-full" : (process.env.FIGURES_DIR ?? "target/figures"));

/** The figures of `source`'s committed record (docs/figures/), or null. */
export function committedFigures(source) {
  const path = resolve(repoDir, "docs", "figures", fileName(source));
  return existsSync(path) ? JSON.parse(readFileSync(path, "utf8")).figures : null;
}

/** `records::file_name`: every character but ASCII letters, digits, `.`, `-`, `_` becomes `_`. */
export const fileName = (source) => `${source.replace(/[^A-Za-z0-9._-]/g, "_")}.json`;

function commit() {
  try {
    return execFileSync("git", ["rev-parse", "HEAD"], { cwd: repoDir, encoding: "utf8" }).trim();
  } catch {
    return "unknown";
  }
}

/** A figure: `id` dotted (letters, digits, `_`, `-`), `what` one line. */
export const figure = (id, what, value, unit, digits) => ({ id, what, value, unit, digits });

/** Writes the record of `source`; returns its path. `kind`: "deterministic" or "timed". */
export function writeRecord({ source, command, kind, seeds = { tuning: [], report: [] }, figures }) {
  const kept = figures.filter((f) => {
    if (Number.isFinite(f.value)) return true;
    console.error(`# ${source}: ${f.id} is ${f.value}: left out of the record`);
    return false;
  });
  const record = { source, command, kind, seeds, commit: commit(), date: new Date().toISOString().slice(0, 10), cores: availableParallelism(), figures: kept };
  const dir = figuresDir(kind);
  mkdirSync(dir, { recursive: true });
  const path = resolve(dir, fileName(source));
  const tmp = `${path}.tmp-${process.pid}`;
  // The seed lists on one line each, as records::Record::to_json writes them.
  const text = JSON.stringify(record, null, 2).replace(/\[\s*([-\d.,\s]*?)\s*\]/g, (_, items) => `[${items.split(",").map((x) => x.trim()).filter(Boolean).join(", ")}]`);
  writeFileSync(tmp, `${text}\n`);
  renameSync(tmp, path);
  return path;
}
