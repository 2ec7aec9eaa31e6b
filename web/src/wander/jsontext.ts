// What the wander gallery's JSON box checks before the core reads the text:
// its nesting depth. A deep enough nesting (thousands of levels) would
// overflow structuredClone's stack, a raw "Maximum call stack size
// exceeded" on the page; the text is measured first, in one pass that
// reads no value, and refused with a message. The rest (syntax, duplicate keys, unknown fields, ranges) is the
// core's: the box goes to `WanderLab.fromJson`, the parser the native code
// uses (serde_json: a duplicate key is an error, as in the files).

/** Deepest nesting a wander configuration needs is 4; 32 leaves room. */
export const MAX_JSON_DEPTH = 32;

/** The deepest `{`/`[` nesting of JSON `text` (strings skipped), counting
 *  no further than `stop` (the text is not otherwise checked). */
export function jsonDepth(text: string, stop = Infinity): number {
  let depth = 0;
  let max = 0;
  let inString = false;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (inString) {
      if (c === 92 /* \ */) i++;
      else if (c === 34 /* " */) inString = false;
    } else if (c === 34) inString = true;
    else if (c === 123 /* { */ || c === 91 /* [ */) {
      depth++;
      if (depth > max) {
        max = depth;
        if (max > stop) return max;
      }
    } else if (c === 125 /* } */ || c === 93 /* ] */) depth--;
  }
  return max;
}

/** Why `text` is refused before parsing, or null. */
export function tooDeep(text: string): string | null {
  const d = jsonDepth(text, MAX_JSON_DEPTH);
  return d > MAX_JSON_DEPTH ? `JSON: nested more than ${MAX_JSON_DEPTH} levels deep (a configuration needs 4); not read` : null;
}
