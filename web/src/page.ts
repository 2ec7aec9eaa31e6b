// What every page does around its canvas: find its elements by id, show a
// message in the bar under the header, show the core's version.

/** The element with `id`; its absence is a bug in the page's HTML. */
export function $<T extends HTMLElement = HTMLElement>(id: string): T {
  const el = document.getElementById(id);
  if (!el) throw new Error(`#${id} missing from ${location.pathname.replace(/^.*\//, "") || "index.html"}`);
  return el as T;
}

/** Shows `text` in the message bar (null hides it); `kind` colours it. */
export function showMessage(text: string | null, kind?: "warn" | "error"): void {
  const el = $("message");
  el.hidden = text === null;
  el.className = kind ? `message ${kind}` : "message";
  el.textContent = text ?? "";
}

/** The core's version in the header. */
export function showVersion(version: string): void {
  $("version").textContent = `core ${version}`;
}
