// The lab's legend: one entry per control mode of the core (the bindings'
// `Mode`, in plain words and colours from src/ui/modes.ts), then the
// overlays' lines. Built from the core's list, so it names every mode the
// core has and no other.

import { Mode } from "../core/wasm";
import { MANOEUVRE_WORDS, MODE_ORDER, MODE_WORDS, type ModeKey } from "../ui/modes";

/** The shapes paper 000 §6 gives a target per mode (circle: a position to
 *  reach, triangle: a heading to reach). */
const SHAPE: Readonly<Record<ModeKey, string>> = {
  PositionOnly: "circle",
  Funnelling: "circle tri",
  OrientationOnly: "tri",
  EndOfSteering: "circle tri",
};

/** Fills `el` (the stage's .legend). */
export function buildLegend(el: HTMLElement): void {
  el.replaceChildren();
  const keys = Object.keys(Mode).filter((k) => Number.isNaN(Number(k))) as ModeKey[];
  keys.sort((a, b) => MODE_ORDER.indexOf(a) - MODE_ORDER.indexOf(b));
  for (const key of keys) {
    const w = MODE_WORDS[key];
    const item = document.createElement("span");
    item.className = "mode";
    item.dataset["mode"] = key;
    item.title = `${w.word}: ${w.meaning} (paper: ${w.paper})`;
    for (const s of SHAPE[key].split(" ")) {
      const i = document.createElement("i");
      i.className = `sw ${s}`;
      i.style.color = w.colour;
      item.append(i);
    }
    item.append(w.word);
    el.append(item);
  }
  // A car-like vehicle's manoeuvre (ui/modes.ts), shown while one is in force.
  const car = document.createElement("span");
  car.className = "mode";
  car.dataset["carLike"] = "manoeuvre";
  car.title = `${MANOEUVRE_WORDS.word}: a car-like vehicle ${MANOEUVRE_WORDS.meaning}`;
  const sw = document.createElement("i");
  sw.className = "sw tri";
  sw.style.color = MANOEUVRE_WORDS.colour;
  car.append(sw, `${MANOEUVRE_WORDS.word} (car-like)`);
  car.hidden = true;
  el.append(car);
  for (const [cls, text] of [["eta", "η: heading a straight seek arrives with"], ["ghost", "predicted seek path"], ["gamma", "γ: heading steered"]] as const) {
    const item = document.createElement("span");
    const i = document.createElement("i");
    i.className = `ln ${cls}`;
    item.append(i, text);
    el.append(item);
  }
  const more = document.createElement("a");
  more.href = "learn.html#modes";
  more.textContent = "what the modes mean";
  el.append(more);
}

/** Shows the car-like manoeuvre's entry of `el`'s legend while a vehicle
 *  that cannot turn on the spot is in force, and hides "turning on the
 *  spot" meanwhile (such a vehicle never does). */
export function legendCarLike(el: HTMLElement, carLike: boolean): void {
  const car = el.querySelector<HTMLElement>('[data-car-like]');
  const spot = el.querySelector<HTMLElement>('[data-mode="OrientationOnly"]');
  if (car && car.hidden === carLike) car.hidden = !carLike;
  if (spot && spot.hidden !== carLike) spot.hidden = carLike;
}
