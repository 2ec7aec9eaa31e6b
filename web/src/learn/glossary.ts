// The learn page's symbols: each one's definition, typeset (subscripts as
// <sub>) wherever the prose writes it, with a hover / tap / focus
// definition and a short glossary after the introduction. The page's
// source writes a subscript with an underscore (v_dt, D_η), which keeps
// the HTML readable; this pass turns it into what a reader expects.

/** Symbol as written in the source → its definition. Longer spellings
 *  first: the pattern below tries them in this order (Δη before η, v_dt
 *  before v_d). */
const SYMBOLS: ReadonlyArray<[string, string]> = [
  ["Δη", "Δη = β − (θ+α+η): the wanted final direction minus the one seek would arrive with."],
  ["μ_max", "μ_max: the bound on |μ|, how far funnelling may steer off the radial direction."],
  ["D_tol", "D_tol: the position tolerance; closer than this, the position counts as reached."],
  ["R_min", "R_min: the vehicle's minimum turning radius, kept at every speed (a car-like vehicle; 0 for one that turns on the spot)."],
  ["ε_tol", "ε_tol: the orientation tolerance; the largest |β − θ| accepted on arrival."],
  ["D_η", "D_η: the table's first (smallest) distance ring; below it η is not sampled."],
  ["T_η", "T_η: the η table, η sampled over D, α, v_c, ω_c and v_d."],
  ["v_dt", "v_dt: the largest desired speed at which seek still reaches the target (stored in the table)."],
  ["v_c", "v_c: the vehicle's current speed."],
  ["ω_c", "ω_c: the vehicle's current angular speed (turn rate)."],
  ["v_d", "v_d: the desired speed the vehicle is asked to drive at."],
  ["α_r", "α_r: the direction relaxed funnelling chooses within the arc 𝒜 (relative to the heading)."],
  ["η", "η: the radial–tangential angle, from the radial direction (towards the target) to the final direction a seek would arrive with."],
  ["α", "α: the radial angle, from the vehicle's heading to the direction of the target."],
  ["β", "β: the heading wanted at the target (the target's orientation)."],
  ["θ", "θ: the vehicle's heading, the direction it faces (an angle measured from the x axis)."],
  ["γ", "γ = θ + α + μ: the modulated heading fed to the seek controller."],
  ["μ", "μ = −gain·Δη: how far funnelling steers off the radial direction, bounded by μ_max."],
  ["τ", "τ: a region goal's heading tolerance; any heading within β ± τ will do."],
  ["𝒜", "𝒜: the restricted arc, the part of the table ring nearest the goal disk that lies inside it."],
  ["D", "D: the distance from the vehicle to the target."],
  ["F", "F: the span of final directions α+η over the arc 𝒜."],
  ["T", "T = β ± τ: the interval of wanted headings of a region goal."],
];

const escape = (s: string): string => s.replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
const reEscape = (s: string): string => s.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");

/** Any symbol, not inside a longer word (so "F" of "Fig." and "T" of "The" stay text). */
const PATTERN = new RegExp(`(?<![\\p{L}\\p{N}_])(${SYMBOLS.map(([s]) => reEscape(s)).join("|")})(?![\\p{L}\\p{N}_])`, "gu");
const INDEX = new Map(SYMBOLS.map(([s], k) => [s, k]));

/** A symbol's HTML: the part after "_" as a subscript. */
function typeset(sym: string): string {
  const i = sym.indexOf("_");
  return i < 0 ? escape(sym) : `${escape(sym.slice(0, i))}<sub>${escape(sym.slice(i + 1))}</sub>`;
}

/** Plain text with its symbols typeset (a label, a diagram line). */
export function typesetText(text: string): string {
  return escape(text).replace(PATTERN, (s) => typeset(s));
}

/** Rewrites the text (never the tags) of `el`'s HTML: each symbol typeset,
 *  and with `define`, wrapped in a definition (hover, tap or focus shows
 *  it; described by the glossary's entry). The first of each symbol in the
 *  element takes keyboard focus. */
function rewrite(el: Element, define: boolean): void {
  const seen = new Set<string>();
  el.innerHTML = el.innerHTML.split(/(<[^>]*>)/).map((part) => part.startsWith("<") ? part : part.replace(PATTERN, (s) => {
    if (!define) return typeset(s);
    const k = INDEX.get(s)!;
    const focus = seen.has(s) ? "" : ' tabindex="0"';
    seen.add(s);
    // The definition rides along, shown by CSS on hover / focus; hidden
    // from screen readers, which read the glossary's entry instead.
    return `<span class="sym"${focus} aria-describedby="gl-${k}">${typeset(s)}<span class="def" aria-hidden="true">${typesetText(SYMBOLS[k]![1])}</span></span>`;
  })).join("");
}

/** Keeps an open definition inside the viewport (a symbol near the right
 *  edge of a phone would push it off screen). */
function keepInView(sym: Element): void {
  const def = sym.querySelector<HTMLElement>(".def");
  if (!def) return;
  def.style.left = "";
  const r = def.getBoundingClientRect();
  const over = r.right - (document.documentElement.clientWidth - 8);
  if (over > 0) def.style.left = `${-Math.min(over, r.left - 8)}px`;
}

/** Tap (or click) on a symbol toggles its definition, for touch screens
 *  where there is no hover and only a symbol's first use takes focus; a
 *  tap elsewhere closes it. */
function tapToDefine(root: Document): void {
  root.addEventListener("click", (e) => {
    const sym = e.target instanceof Element ? e.target.closest(".sym") : null;
    for (const o of root.querySelectorAll(".sym.open")) {
      if (o !== sym) o.classList.remove("open");
    }
    if (!sym) return;
    const open = sym.classList.toggle("open");
    if (open) keepInView(sym);
    else if (sym instanceof HTMLElement) sym.blur();
  });
  root.addEventListener("focusin", (e) => {
    if (e.target instanceof Element && e.target.classList.contains("sym")) keepInView(e.target);
  });
  root.addEventListener("pointerover", (e) => {
    const sym = e.target instanceof Element ? e.target.closest(".sym") : null;
    if (sym) keepInView(sym);
  });
}

/** Typesets the page's headings and prose, defines its symbols, and adds
 *  the glossary after the introduction. Run before the figures write their
 *  live numbers (the rewrite replaces the prose's elements). */
export function defineSymbols(root: Document): void {
  tapToDefine(root);
  for (const h of root.querySelectorAll("section.chapter h2")) rewrite(h, false);
  for (const p of root.querySelectorAll(".prose p")) rewrite(p, true);
  const intro = root.querySelector("header.intro");
  if (!intro) return;
  const box = document.createElement("details");
  box.className = "glossary";
  box.innerHTML = "<summary>The symbols on this page</summary><dl></dl>";
  const dl = box.querySelector("dl")!;
  SYMBOLS.forEach(([s, def], k) => {
    const dt = document.createElement("dt");
    dt.innerHTML = typeset(s);
    const dd = document.createElement("dd");
    dd.id = `gl-${k}`;
    dd.innerHTML = typesetText(def.startsWith(`${s}:`) ? def.slice(s.length + 2) : def);
    dl.append(dt, dd);
  });
  intro.append(box);
}
