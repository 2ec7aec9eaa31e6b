// The learn page (learn.html): an explorable explanation of funnelling.
// Loads the core and the η table once, then builds one live figure per
// section, each on its own Lab forked from the first (the table is shared,
// not copied). The test build's window.__learn tells the tests when every
// figure is up.

import { $, showMessage, showVersion } from "../ui/page";
import { limitDefaults, RangeTable } from "../lab/fields";
import { createLab, errorText, loadCore, precision, ranges, type Lab } from "../core/wasm";
import { setLinkContext, type LiveFigure } from "./figure";
import { defineSymbols, typesetText } from "./glossary";
import { challengesSection } from "./sections/challenges";
import { etaSection } from "./sections/eta";
import { modesSection, nameModes } from "./sections/modes";
import { modulationSection } from "./sections/modulation";
import { movingSection } from "./sections/moving";
import { regionSection } from "./sections/region";
import { seekSection } from "./sections/seek";
import { tableSection } from "./sections/table";

/** What the end-to-end test reads (the test build only). */
export interface LearnHook {
  ready: boolean;
  error: string | null;
  /** Section ids with a figure, in page order. */
  figures: string[];
  /** Frames drawn per figure. */
  frames(): Record<string, number>;
  /** Runs figure `name` to its end at once, as Play would (then it rewinds). */
  finish(name: string): void;
}

declare global {
  interface Window {
    __learn?: LearnHook;
  }
}

const SECTIONS: ReadonlyArray<[string, (host: HTMLElement, lab: Lab) => LiveFigure]> = [
  ["seek", seekSection],
  ["eta", etaSection],
  ["table", tableSection],
  ["modulation", modulationSection],
  ["modes", modesSection],
  ["moving", movingSection],
  ["region", regionSection],
  ["challenges", challengesSection],
];

const figures: LiveFigure[] = [];
const status = { ready: false, error: null as string | null, figures: [] as string[] };
// The test build's hook; the shipped build drops it.
if (import.meta.env.MODE === "test") {
  window.__learn = {
    get ready() { return status.ready; },
    get error() { return status.error; },
    figures: status.figures,
    frames: () => Object.fromEntries(figures.map((f) => [f.spec.name, f.frames])),
    finish: (name) => figures.find((f) => f.spec.name === name)?.finish(),
  };
}

async function start(): Promise<void> {
  defineSymbols(document);
  nameModes(document);
  showVersion(await loadCore());
  // The table in byte planes (src/core/tableplanes.ts: less than half the gzipped bytes).
  const lab = await createLab("tables/eta.planes");
  setLinkContext(new RangeTable(ranges(), precision()), limitDefaults(lab.params()));
  for (const [name, build] of SECTIONS) {
    figures.push(build($(`fig-${name}`), lab));
    status.figures.push(name);
  }
  for (const l of document.querySelectorAll(".fig-controls label > .name")) l.innerHTML = typesetText(l.textContent ?? "");
  status.ready = true;
}

start().catch((e: unknown) => {
  const msg = `The learn page could not start: ${errorText(e)}`;
  status.error = msg;
  showMessage(msg, "error");
});
