// Plain words on the pages: what a reader sees must not be code. `codeWords`
// finds, in a page's visible text, the spellings that belong to the source
// and not to the reader: a snake_case or camelCase identifier (a JSON key,
// a function), a file path or file name, a command-line flag or command
// (cargo, npm), degrees spelt "deg" (°) and "+/-" (±).
// The symbols the papers write with a subscript (D_tol, v_dt, …) are
// allowed by name (ALLOWED), each the spelling of one symbol the pages
// define; anything else with an underscore or an inner capital is flagged.
// Used by e2e-axe.mjs on the four pages at both widths, and on the presets'
// captions and the gallery's labels as files (they show once chosen).

/** Symbols written with a subscript, as the pages show them where they
 *  cannot typeset it (the lab's panel and HUD, canvas labels). */
export const ALLOWED = new Set([
  "D_tol", // position tolerance
  "D_eta", // the table's first ring (written D_η where it can be)
  "v_dt", // largest desired speed that still reaches the target
  "v_d", // desired speed
  "v_c", // current speed
  "v_max", // speed limit
  "R_min", // minimum turning radius
  "T_eta", // the η table
  "a_max", // acceleration limit
  "a_n", // normal (sideways) acceleration
  // The papers' own names of the four modes, quoted beside the lab's words.
  "Position_only",
  "Orientation_only",
  "End_of_Steering",
]);

/** [kind, pattern]: every match is a candidate; ALLOWED words are kept. */
const PATTERNS = [
  ["snake_case", /(?<![\p{L}\p{N}_])[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)+(?![\p{L}\p{N}_])/gu],
  ["camelCase", /(?<![\p{L}\p{N}_])[a-z]+[A-Z][A-Za-z0-9]*(?![\p{L}\p{N}_])/gu],
  ["file path", /(?<![\p{L}\p{N}_])(?:[\w.-]+\/)+[\w.-]+\.[a-z]{1,5}(?![\p{L}\p{N}_])/gu],
  ["file name", /(?<![\p{L}\p{N}_/])[\w-]+\.(?:rs|json|ts|mjs|js|toml|py|md|bin|planes|wasm)(?![\p{L}\p{N}_])/gu],
  ["flag", /(?<![\p{L}\p{N}_-])--[a-z][a-z0-9-]*/gu],
  ["command", /(?<![\p{L}\p{N}_])(?:cargo|npm|npx|wasm-pack) [a-z][a-z-]+/gu],
  // Degrees are written °, a tolerance ±.
  ["unit", /(?<![\p{L}\p{N}_])\d+(?:\.\d+)? ?(?:deg|degs)(?![\p{L}\p{N}_])|\+\/-/gu],
];

/** The code words of `text`: [{ kind, word, context }], each once. */
export function codeWords(text) {
  const out = [];
  const seen = new Set();
  for (const [kind, re] of PATTERNS) {
    for (const m of text.matchAll(re)) {
      const word = m[0];
      if (ALLOWED.has(word) || seen.has(`${kind} ${word}`)) continue;
      seen.add(`${kind} ${word}`);
      const at = m.index ?? 0;
      out.push({ kind, word, context: text.slice(Math.max(0, at - 40), at + word.length + 40).replace(/\s+/g, " ") });
    }
  }
  return out;
}

/** A page's visible text (innerText: what is rendered, not the closed
 *  parts) and its menus' chosen labels. Run in the page. */
export function visibleText() {
  const chosen = [...document.querySelectorAll("select")].map((s) => s.selectedOptions[0]?.textContent ?? "");
  return [document.body.innerText, ...chosen].join("\n");
}
