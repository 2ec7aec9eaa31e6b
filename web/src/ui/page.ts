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

/** The message bar's text, or null when it is hidden. */
export function currentMessage(): string | null {
  const el = $("message");
  return el.hidden ? null : el.textContent;
}

/** Items the message bar lists before "… and N more". */
export const MAX_MESSAGE_ITEMS = 8;
/** Characters of one listed item (a 10,000-character key stays one line). */
const MAX_ITEM_CHARS = 160;

/** The bar's text for `title` and a bulleted list of `items`, capped: at
 *  most MAX_MESSAGE_ITEMS items of at most MAX_ITEM_CHARS characters, then
 *  "… and N more", so 10,000 bad link keys make a few lines, not a
 *  175,000 px box that squeezes the canvas to nothing. */
export function messageList(title: string, items: readonly string[]): string {
  const shown = items.slice(0, MAX_MESSAGE_ITEMS).map((t) => (t.length > MAX_ITEM_CHARS ? `${t.slice(0, MAX_ITEM_CHARS)}…` : t));
  const more = items.length - shown.length;
  return [title, ...shown.map((t) => `• ${t}`), ...(more > 0 ? [`… and ${more.toLocaleString("en")} more`] : [])].join("\n");
}

/** Shows `title` and a capped list of `items` (see messageList). */
export function showMessages(title: string, items: readonly string[], kind?: "warn" | "error"): void {
  showMessage(messageList(title, items), kind);
}

/** The core's version in the header. */
export function showVersion(version: string): void {
  $("version").textContent = `core ${version}`;
}
