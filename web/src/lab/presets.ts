// The paper scenarios that exist as files (scenarios/*.json), bundled as raw
// JSON text and handed to the core's scenario parser on selection.

const files = import.meta.glob<string>("../../../scenarios/*.json", { query: "?raw", import: "default" });

export interface Preset {
  /** File name without .json: the URL's `preset` value. */
  name: string;
  load(): Promise<string>;
}

export const PRESETS: readonly Preset[] = Object.entries(files)
  .map(([path, load]) => ({ name: path.replace(/^.*\//, "").replace(/\.json$/, ""), load }))
  .sort((a, b) => a.name.localeCompare(b.name));

export function presetNames(): string[] {
  return PRESETS.map((p) => p.name);
}

export function findPreset(name: string): Preset | undefined {
  return PRESETS.find((p) => p.name === name);
}

/** The menu's groups, in order: each paper's figures, then what goes
 *  beyond the papers: the avoidance scenarios, the car-like vehicles,
 *  arrival at short range. */
export const PRESET_GROUPS = [
  "Paper 000 · funnelling towards oriented targets",
  "Paper 001 · region goals (relaxed funnelling)",
  "Avoidance between agents (beyond the papers)",
  "Car-like vehicles (beyond the papers)",
  "Short range (beyond the papers)",
] as const;

/** The menu group of a preset, from its name (`p000_…`, `p001_…`,
 *  `car_like_…`, `short_range_…`, the rest). */
export function presetGroup(name: string): string {
  if (name.startsWith("p000_")) return PRESET_GROUPS[0];
  if (name.startsWith("p001_")) return PRESET_GROUPS[1];
  if (name.startsWith("car_like_")) return PRESET_GROUPS[3];
  if (name.startsWith("short_range_")) return PRESET_GROUPS[4];
  return PRESET_GROUPS[2];
}

/** Readable titles: the figure, then what it shows. A file without one
 *  gets its name in words (a new scenario still reads as a title). */
const TITLES: Readonly<Record<string, string>> = {
  p000_fig1_seek: "Fig. 1 · plain seek: three targets, no heading asked",
  p000_fig3_funnel: "Fig. 3 · funnelling: the same targets, each with a heading",
  p000_fig6_face_to_face: "Fig. 6 · pairs meeting face to face (moving targets)",
  p000_fig7_variety: "Fig. 7 · eight agents, three targets each",
  p000_fig8_eighty: "Fig. 8 · eighty agents, five moving targets",
  p001_fig5_gait: "Fig. 5 · twelve walkers, one start, all ending north",
  p001_fig6b_centre: "Fig. 6b · region goal, aiming at the centre (standard)",
  p001_fig6c_relaxed: "Fig. 6c · region goal, aiming at a better point (relaxed)",
  p001_fig8_zero_delta_eta_relaxed: "Fig. 8 · relaxed: a point of the arc with Δη = 0",
  p001_fig9_arc_end_relaxed: "Fig. 9 · relaxed: goal facing back, the arc's end",
  p001_fig10_beta0_standard: "Fig. 10a · nine entities, goal facing 0° (standard)",
  p001_fig10_beta0_relaxed: "Fig. 10d · nine entities, goal facing 0° (relaxed)",
  p001_fig10_beta45_standard: "Fig. 10b · nine entities, goal facing 45° (standard)",
  p001_fig10_beta45_relaxed: "Fig. 10e · nine entities, goal facing 45° (relaxed)",
  p001_fig10_beta120_standard: "Fig. 10c · nine entities, goal facing 120° (standard)",
  p001_fig10_beta120_relaxed: "Fig. 10f · nine entities, goal facing 120° (relaxed)",
  p001_fig11_tol5_standard: "Fig. 11 · heading tolerance ±5° (standard)",
  p001_fig11_tol5_relaxed: "Fig. 11 · heading tolerance ±5° (relaxed)",
  p001_fig11_tol15_standard: "Fig. 11 · heading tolerance ±15° (standard)",
  p001_fig11_tol15_relaxed: "Fig. 11 · heading tolerance ±15° (relaxed)",
  p001_fig11_tol30_standard: "Fig. 11 · heading tolerance ±30° (standard)",
  p001_fig11_tol30_relaxed: "Fig. 11 · heading tolerance ±30° (relaxed)",
  p001_fig11_tol45_standard: "Fig. 11 · heading tolerance ±45° (standard)",
  p001_fig11_tol45_relaxed: "Fig. 11 · heading tolerance ±45° (relaxed)",
  p001_fig12_successive_standard: "Fig. 12 · successive region goals (standard)",
  p001_fig12_successive_relaxed: "Fig. 12 · successive region goals (relaxed)",
  avoid_circle8: "Circle swap, 8 agents",
  avoid_circle32: "Circle swap, 32 agents",
  avoid_circle100: "Circle swap, 100 agents",
  avoid_corridor: "Corridor: two groups of 12 crossing",
  avoid_doorway: "Doorway: ten agents through a narrow gap",
  avoid_fig6: "Paper 000 Fig. 6 with avoidance",
  avoid_fig8: "Paper 000 Fig. 8 with avoidance",
  car_like_parking: "Parking a car that cannot turn on the spot",
  car_like_reverse_parking: "Backing into a bay: a car with a reverse gear",
  short_range_turn_or_loop: "Turning first vs looping: near targets on foot",
};

/** The title the menu shows for a preset. */
export function presetTitle(name: string): string {
  return TITLES[name] ?? name.replace(/^p\d{3}_/, "").replace(/_/g, " ");
}

/** Menu order within a group: by figure number, then by title as the
 *  menu shows it (Fig. 10a before 10d, ±5° before ±15°). */
export function presetOrder(a: string, b: string): number {
  const fig = (n: string): number => Number(/_fig(\d+)/.exec(n)?.[1] ?? 999);
  return fig(a) - fig(b) || presetTitle(a).localeCompare(presetTitle(b), "en", { numeric: true }) || a.localeCompare(b);
}
