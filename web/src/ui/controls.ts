// Sliders with units, selects, checkboxes and buttons, built into a panel element.
// Each control writes through a callback; `set` updates it from outside
// (a drag on the canvas, a preset, the URL) without firing the callback.
// A slider given `parse` also has a number box: a typed value is checked by
// `parse` (the core's range), and a refused one is reported under the row
// while the previous value stays.

const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const INTEGER = /^[+-]?\d+$/;

/** A decimal number as a person types it ("1.5", "-2", "1e3"), else null:
 *  no hexadecimal, no "Infinity", no empty text; an integer field takes
 *  digits only ("0x10" and "16.0" are refused). */
export function parseDecimal(text: string, integer: boolean): number | null {
  const t = text.trim();
  if (!(integer ? INTEGER : DECIMAL).test(t)) return null;
  const v = Number(t);
  return Number.isFinite(v) ? v : null;
}

export interface SliderSpec {
  id: string;
  label: string;
  unit: string;
  min: number;
  max: number;
  step: number;
  value: number;
  /** Displayed value = value × display (e.g. rad → deg). */
  display?: number;
  digits?: number;
  onInput(v: number): void;
  /** Checks a typed value (shown units): the value, or why it is refused.
   *  With it, the row has a number box instead of a read-only output. */
  parse?(text: string): { value: number } | { error: string };
}

export interface Control {
  set(v: number): void;
  el: HTMLElement;
  /** Moves the slider's ends (e.g. the desired speed's maximum follows the max speed). */
  setRange(min: number, max: number): void;
  /** Shows `text` under the row (null hides it). */
  note(text: string | null): void;
}

/** A `<label>` row of class `className` that starts with the control's name. */
function labelledRow(className: string, label: string): HTMLLabelElement {
  const row = document.createElement("label");
  row.className = className;
  const name = document.createElement("span");
  name.className = "name";
  name.textContent = label;
  row.append(name);
  return row;
}

export function slider(parent: HTMLElement, s: SliderSpec): Control {
  const k = s.display ?? 1;
  const row = labelledRow("slider", s.label);
  const input = document.createElement("input");
  input.type = "range";
  input.id = s.id;
  input.min = String(s.min * k);
  input.max = String(s.max * k);
  input.step = String(s.step * k);
  const msg = document.createElement("div");
  msg.className = "field-msg";
  msg.id = `${s.id}-msg`;
  msg.setAttribute("role", "alert");
  msg.hidden = true;
  const note = (text: string | null): void => {
    msg.hidden = text === null;
    msg.textContent = text ?? "";
  };
  let current = s.value;
  let show: (v: number) => void;
  let tail: HTMLElement;
  const { parse } = s;
  if (parse) {
    // A number box: the exact value, typed or shown.
    row.classList.add("numeric");
    tail = document.createElement("span");
    tail.className = "numbox";
    const box = document.createElement("input");
    box.type = "text";
    box.inputMode = "decimal";
    box.id = `${s.id}-num`;
    box.setAttribute("aria-label", `${s.label} (${s.unit || "value"})`);
    tail.append(box, ` ${s.unit}`);
    show = (v) => {
      box.value = String(Number((v * k).toFixed(s.digits ?? 2)));
    };
    box.addEventListener("change", () => {
      const r = parse(box.value);
      if ("error" in r) {
        note(`${r.error}; ${Number((current * k).toFixed(s.digits ?? 2))}${s.unit ? ` ${s.unit}` : ""} kept`);
        show(current);
        return;
      }
      note(null);
      set(r.value);
      s.onInput(r.value);
    });
  } else {
    const out = document.createElement("output");
    out.htmlFor.add(s.id);
    tail = out;
    show = (v) => {
      out.textContent = `${(v * k).toFixed(s.digits ?? 2)} ${s.unit}`;
    };
  }
  const set = (v: number): void => {
    current = v;
    input.value = String(v * k);
    show(v);
  };
  input.addEventListener("input", () => {
    const v = Number(input.value) / k;
    current = v;
    show(v);
    note(null);
    s.onInput(v);
  });
  const setRange = (min: number, max: number): void => {
    input.min = String(min * k);
    input.max = String(max * k);
    input.value = String(current * k);
  };
  set(s.value);
  row.append(input, tail);
  parent.append(row, msg);
  return { set, el: row, setRange, note };
}

export interface SelectSpec<T extends string> {
  id: string;
  label: string;
  options: ReadonlyArray<{ value: T; label: string }>;
  value: T;
  onChange(v: T): void;
}

export function select<T extends string>(parent: HTMLElement, s: SelectSpec<T>): { set(v: T): void; el: HTMLElement } {
  const row = labelledRow("select", s.label);
  const input = document.createElement("select");
  input.id = s.id;
  for (const o of s.options) input.add(new Option(o.label, o.value));
  input.value = s.value;
  input.addEventListener("change", () => {
    const o = s.options[input.selectedIndex];
    if (o) s.onChange(o.value);
  });
  row.append(input);
  parent.append(row);
  return { set: (v) => { input.value = v; }, el: row };
}

export function checkbox(
  parent: HTMLElement,
  id: string,
  label: string,
  value: boolean,
  onChange: (v: boolean) => void,
): { set(v: boolean): void; el: HTMLElement } {
  const row = document.createElement("label");
  row.className = "check";
  const input = document.createElement("input");
  input.type = "checkbox";
  input.id = id;
  input.checked = value;
  input.addEventListener("change", () => onChange(input.checked));
  row.append(input, document.createTextNode(` ${label}`));
  parent.append(row);
  return { set: (v) => { input.checked = v; }, el: row };
}

export function button(parent: HTMLElement, id: string, label: string, title: string, onClick: () => void): HTMLButtonElement {
  const b = document.createElement("button");
  b.type = "button";
  b.id = id;
  b.textContent = label;
  b.title = title;
  b.addEventListener("click", onClick);
  parent.append(b);
  return b;
}

export function section(parent: HTMLElement, title: string): HTMLFieldSetElement {
  const box = document.createElement("fieldset");
  const legend = document.createElement("legend");
  legend.textContent = title;
  box.append(legend);
  parent.append(box);
  return box;
}

/** A row of buttons (class `row`), appended to `parent`. */
export function row(parent: HTMLElement): HTMLDivElement {
  const r = document.createElement("div");
  r.className = "row";
  parent.append(r);
  return r;
}

/** A help paragraph (class `help`), appended to `parent`. */
export function help(parent: HTMLElement): HTMLParagraphElement {
  const p = document.createElement("p");
  p.className = "help";
  parent.append(p);
  return p;
}
