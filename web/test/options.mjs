// The command-line options of the Node scripts in web/test: node:util
// parseArgs (strict: an unknown or malformed flag stops the script before
// it starts a browser or a long run), `--help` printing the usage built from
// the same table, and numbers checked with an error naming the flag.
import { parseArgs } from "node:util";
import { basename } from "node:path";

/** Parses `process.argv` against `spec` ({ name: { type, default?,
 *  multiple?, short?, arg?, help } }; `arg` names the value in the usage).
 *  `usage`: the first lines of the help (what the script does, how it is
 *  called). `positionals`: how many bare arguments are allowed (a number,
 *  or true: any; a stray one is refused, not ignored). `--help` / `-h`
 *  prints the usage and exits 0; a bad flag prints the error and the usage
 *  and exits 2. Returns parseArgs's { values, positionals }. */
export function options(usage, spec, { positionals = 0 } = {}) {
  const config = { help: { type: "boolean", short: "h", default: false } };
  for (const [name, o] of Object.entries(spec)) {
    config[name] = { type: o.type };
    for (const k of ["default", "multiple", "short"]) if (o[k] !== undefined) config[name][k] = o[k];
  }
  const text = helpText(usage, spec);
  let parsed;
  try {
    parsed = parseArgs({ options: config, allowPositionals: positionals !== 0 });
  } catch (e) {
    console.error(`${e.message}\n\n${text}`);
    process.exit(2);
  }
  const most = positionals === true ? Infinity : positionals;
  if (parsed.positionals.length > most) {
    console.error(`${most} argument(s) at most besides the options, not ${parsed.positionals.map((p) => JSON.stringify(p)).join(" ")}\n\n${text}`);
    process.exit(2);
  }
  if (parsed.values.help) {
    console.log(text);
    process.exit(0);
  }
  return parsed;
}

function helpText(usage, spec) {
  const rows = Object.entries(spec).map(([name, o]) => {
    const flag = `${o.short ? `-${o.short}, ` : ""}--${name}${o.type === "string" ? ` ${o.arg ?? "VALUE"}` : ""}`;
    const shown = typeof o.default === "string" && o.default !== "" ? o.default : JSON.stringify(o.default);
    const dflt = o.default === undefined || o.default === false || (Array.isArray(o.default) && !o.default.length) ? "" : ` (default ${shown})`;
    return [flag, `${o.help ?? ""}${o.multiple ? " (repeatable)" : ""}${dflt}`];
  });
  rows.push(["-h, --help", "print this help and exit"]);
  const w = Math.max(...rows.map(([f]) => f.length));
  return `${usage.trim()}\n\nOptions:\n${rows.map(([f, h]) => `  ${f.padEnd(w)}  ${h}`).join("\n")}`;
}

/** Stops the script on a bad value: the message (naming the flag) on
 *  stderr, exit code 2, as parseArgs's own errors. */
function refuse(message) {
  console.error(`${basename(process.argv[1] ?? "")}: ${message} (--help lists the options)`);
  process.exit(2);
}

/** `--name`'s value as a whole number ≥ `min`; refused naming the flag
 *  otherwise. */
export function whole(values, name, min = 0) {
  const v = values[name];
  const n = Number(v);
  if (typeof v !== "string" || v.trim() === "" || !Number.isInteger(n) || n < min) {
    refuse(`--${name}: a whole number ≥ ${min}, not ${JSON.stringify(v)}`);
  }
  return n;
}

/** `--name`'s value, one of `allowed`; refused naming the flag otherwise. */
export function oneOf(values, name, allowed) {
  const v = values[name];
  if (!allowed.includes(v)) refuse(`--${name}: one of ${allowed.join(", ")}; not ${JSON.stringify(v)}`);
  return v;
}

/** `--name`'s value as a comma-separated list of whole numbers ≥ `min`
 *  (empty: none); refused naming the flag and the bad item otherwise. */
export function wholeList(values, name, min = 1) {
  return wholeItems(String(values[name]), `--${name}`, min);
}

/** `text` (a flag's value or a positional argument, named `label`) as a
 *  comma-separated list of whole numbers ≥ `min` (empty: none). */
export function wholeItems(text, label, min = 1) {
  return text
    .split(",")
    .map((s) => s.trim())
    .filter(Boolean)
    .map((s) => {
      const n = Number(s);
      if (!Number.isInteger(n) || n < min) refuse(`${label}: whole numbers ≥ ${min}, comma-separated; not ${JSON.stringify(s)}`);
      return n;
    });
}

/** `--name`'s value as a comma-separated list of items from `allowed`;
 *  refused naming the flag and the bad item otherwise. */
export function choiceList(values, name, allowed) {
  const items = String(values[name]).split(",").map((s) => s.trim()).filter(Boolean);
  for (const s of items) if (!allowed.includes(s)) refuse(`--${name}: each of ${allowed.join(", ")}; not ${JSON.stringify(s)}`);
  return items;
}
