// The tarball `make npm` packs, installed as a user installs it: into a
// scratch folder of its own under target/npm-user/ (cleared first; left
// for a look after a failure, and ignored by git like all of target/).
import { execFileSync } from "node:child_process";
import { mkdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

export const npmDir = resolve(dirname(fileURLToPath(import.meta.url)), "..");
export const repo = resolve(npmDir, "..");
const { name, version } = JSON.parse(readFileSync(join(npmDir, "package.json"), "utf8"));
export const tarball = resolve(process.env.STEERING_CORE_TGZ ?? join(repo, "target/npm", `${name}-${version}.tgz`));

/** A fresh folder target/npm-user/`kind` with the tarball installed; returns its path. */
export function installed(kind) {
  const scratch = join(repo, "target/npm-user", kind);
  rmSync(scratch, { recursive: true, force: true });
  mkdirSync(scratch, { recursive: true });
  writeFileSync(join(scratch, "package.json"), JSON.stringify({ name: `steering-core-${kind}`, private: true, type: "module" }));
  execFileSync("npm", ["install", "--no-audit", "--no-fund", "--loglevel=error", tarball], { cwd: scratch, stdio: "inherit" });
  return scratch;
}
