// Sliders with units, selects, checkboxes and buttons, built into a panel element.
// Each control writes through a callback; `set` updates it from outside
// (a drag on the canvas, a preset, the URL) without firing the callback.

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
}

export interface Control {
  set(v: number): void;
  el: HTMLElement;
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
  const out = document.createElement("output");
  out.htmlFor.add(s.id);
  const show = (v: number): void => {
    out.textContent = `${(v * k).toFixed(s.digits ?? 2)} ${s.unit}`;
  };
  const set = (v: number): void => {
    input.value = String(v * k);
    show(v);
  };
  input.addEventListener("input", () => {
    const v = Number(input.value) / k;
    show(v);
    s.onInput(v);
  });
  set(s.value);
  row.append(input, out);
  parent.append(row);
  return { set, el: row };
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
