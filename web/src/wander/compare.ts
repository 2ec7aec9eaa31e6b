// One line per gallery panel (a wander component, its preset file's name):
// what its tiles show and what to compare across them.

export const COMPARE: Readonly<Record<string, string>> = {
  control:
    "Each tile randomises one quantity of the heading: its displacement (a new random heading each step, limited to ±10°, ±30°, ±90°…), its velocity (turn rate) or its acceleration. Compare along a row (one scale per row): the tighter the limit on displacement, the straighter the walk; randomising velocity or acceleration instead gives smooth curves and loops.",
  distributions:
    "The random numbers come from different distributions: smooth noise, Perlin noise, a hand-drawn curve, or a small discrete set of angles. Compare the smooth ones (gentle curves) with the discrete sets, whose walks turn only by the set's angles (90°: a grid-like walk).",
  fields:
    "The turn comes from a random vector field over the plane instead of over time. Compare the fields that set displacement, velocity and acceleration, then the sink that traps the agent, and the remedy: switching fields every 100 steps.",
  "time-functions":
    "The turn is a function of time: sines of different frequencies and blends with noise. Compare sin(t) (slow, wide curves) with sin(50t) (fast wiggles), then the sums that mix both scales.",
  timed:
    "A new random value is drawn only at random intervals and held in between. Compare the clamped-velocity tiles from low to very high: the higher the clamp, the tighter the loops.",
  markov:
    "A transition table picks the next angle range from the current one (a Markov chain). Compare the single table with two tables that change with different probabilities: how often the walk switches between calm and turning stretches. Each tile's note measures its own trace: the share of steps in each angle range (the bar in its corner, light to dark: 0–15°, 15–30°, 30–45°), and how often the angle changes.",
  paths:
    "A random path is generated first (grey), then followed at constant speed. Compare the fractal paths (jagged, from subdivided midpoints) with the closed curves from sums of sines or saw-tooth waves.",
  composed:
    "Components combined with weights. Compare each mix with its parts in the panels above: a little noise on top of sines, or a jitter on a Markov chain.",
};
