#!/usr/bin/env python3
"""Writes the paper-figure presets in this folder (deterministic: fixed seeds).

Run from the repository root: python3 scenarios/make_presets.py
Schema: crate/funnelling/scenario.rs. Angles in degrees, distances in metres.
"""
import json, math, random, os, re

HERE = os.path.dirname(os.path.abspath(__file__))

def goal(x, y, beta, **kw):
    g = {"x": round(x, 3), "y": round(y, 3), "betaDeg": round(beta, 2)}
    g.update(kw)
    return g

def agent(x, y, theta, goals, v=0.0):
    return {"x": round(x, 3), "y": round(y, 3), "thetaDeg": round(theta, 2), "v": v, "goals": goals}

# What each figure claims and what we measure, shown in the lab's side
# panel: the captions of docs/presets.json rendered from the figures
# records in docs/figures/ (written by `make figures`), so the preset menu,
# docs/FIGURES.md and the tests show the same numbers (tests/figures.rs
# checks it). Placeholders: {id} the figure's value and unit, {id:num} the
# value alone, {verdict:SOURCE} the verdict of that fidelity test's record.
ROOT = os.path.dirname(HERE)


def load_records(folder):
    figures, verdicts = {}, {}
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(folder, name)) as f:
            r = json.load(f)
        for fig in r["figures"]:
            figures[fig["id"]] = fig
        if "claim" in r:
            verdicts[r["source"]] = r["claim"]["verdict"]
    return figures, verdicts


def shown(fig, num_only=False):
    n = "%.*f" % (fig["digits"], fig["value"])
    unit = fig["unit"]
    if num_only or unit == "":
        return n
    return n + "°" if unit == "°" else n + " " + unit


def render(template, figures, verdicts):
    def one(m):
        key = m.group(1)
        if key.startswith("verdict:"):
            return verdicts[key[len("verdict:"):]]
        fid, _, how = key.partition(":")
        if fid not in figures:
            raise SystemExit("docs/presets.json: no figure `%s` in docs/figures (run `make figures`)" % fid)
        return shown(figures[fid], how == "num")
    return re.sub(r"\{([^{}]*)\}", one, template)


def captions():
    with open(os.path.join(ROOT, "docs", "presets.json")) as f:
        caps = json.load(f)["captions"]
    figures, verdicts = load_records(os.path.join(ROOT, "docs", "figures"))
    out = {}
    for c in caps:
        for p in c["presets"]:
            out[p] = (c["claim"], render(c["measured"], figures, verdicts))
    return out


FIDELITY = captions()


def write(name, source, description, agents, duration=40.0, **extra):
    sc = {"name": name, "source": source, "description": description, "duration": duration, "agents": agents}
    if name in FIDELITY:
        sc["claim"], sc["measured"] = FIDELITY[name]
    sc.update(extra)
    path = os.path.join(HERE, name + ".json")
    text = json.dumps(sc, indent=1) + "\n"
    # Unchanged files keep their time stamp: the crate includes some
    # presets, and a rewrite would rebuild it.
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                return
    with open(path, "w") as f:
        f.write(text)

# Paper 000 Fig. 1 / paper 001 Fig. 1a: plain seek to three position goals.
# The seek controller ignores beta and epsTol (with the standard
# controller and epsTol 180 a target behind was still funnelled towards
# beta); epsTol 180 only draws the targets without an orientation triangle.
write("p000_fig1_seek", "paper 000 Fig. 1, paper 001 Fig. 1a",
      "Seek: three agents reach three position targets without a prescribed orientation (red circles).",
      [agent(0, 0, 0, [goal(6, 4, 0, epsTolDeg=180, halting=True)]),
       agent(0, -1, 0, [goal(7, -2, 0, epsTolDeg=180, halting=True)]),
       agent(0, -2, 0, [goal(-3, -5, 0, epsTolDeg=180, halting=True)])], duration=20, controller="seek")

# Paper 000 Fig. 3 / paper 001 Fig. 1b: the same targets with prescribed orientations.
write("p000_fig3_funnel", "paper 000 Fig. 3, paper 001 Fig. 1b",
      "Funnelling: the same three targets, now each with a prescribed orientation (circle + triangle).",
      [agent(0, 0, 0, [goal(6, 4, -90, halting=True)]),
       agent(0, -1, 0, [goal(7, -2, 90, halting=True)]),
       agent(0, -2, 0, [goal(-3, -5, 0, halting=True)])], duration=25)

# Paper 000 Fig. 6: pairs meeting face to face, each goal is the other's pose, with halting.
pairs = []
for k, (ax, ay, at, bx, by, bt) in enumerate([(-6, 4, 0, 6, 6, 180), (-5, 0, 30, 7, -1, 150), (-6, -5, -20, 4, -7, 90)]):
    i = 2 * k
    pairs.append(agent(ax, ay, at, [goal(bx, by, 0, dTol=1.2, epsTolDeg=10, speed=1.2, halting=True,
                                         motion={"kind": "faceAgent", "agent": i + 1, "distance": 0.0})], v=1.0))
    pairs.append(agent(bx, by, bt, [goal(ax, ay, 0, dTol=1.2, epsTolDeg=10, speed=1.2, halting=True,
                                         motion={"kind": "faceAgent", "agent": i, "distance": 0.0})], v=1.0))
write("p000_fig6_face_to_face", "paper 000 Fig. 6",
      "Dynamic targets with final halting: pairs of agents whose goals are each other's pose meet face to face.",
      pairs, duration=30)

# Paper 000 Fig. 7: a wide variety of relative orientations and distances, successive targets, halting.
rnd = random.Random(7)
agents = []
for i in range(8):
    a = i * 45.0
    x, y = 12 * math.cos(math.radians(a)), 12 * math.sin(math.radians(a))
    goals = []
    for j in range(3):
        r = rnd.uniform(3, 16)
        b = rnd.uniform(-180, 180)
        gx, gy = x + r * math.cos(math.radians(b)), y + r * math.sin(math.radians(b))
        goals.append(goal(gx, gy, rnd.uniform(-180, 180), halting=(j == 2), switch="endOfSteering"))
        x, y = gx, gy
    agents.append(agent(12 * math.cos(math.radians(a)), 12 * math.sin(math.radians(a)), rnd.uniform(-180, 180), goals))
write("p000_fig7_variety", "paper 000 Fig. 7",
      "A wide variety of relative orientations and distances, three successive targets each, final halting.",
      agents, duration=90)

# Paper 000 Fig. 8: 80 entities assigned to five moving targets (targets circle slowly).
rnd = random.Random(8)
agents = []
centres = [(0, 0), (25, 10), (-25, 12), (15, -22), (-18, -20)]
for i in range(80):
    t = i % 5
    cx, cy = centres[t]
    a = rnd.uniform(0, 360)
    r = rnd.uniform(15, 35)
    x, y = cx + r * math.cos(math.radians(a)), cy + r * math.sin(math.radians(a))
    agents.append(agent(x, y, rnd.uniform(-180, 180), [goal(cx + 3, cy, 90, dTol=0.5, epsTolDeg=10, speed=rnd.uniform(1.0, 1.8),
                                                             motion={"kind": "circle", "center": [cx, cy], "angularSpeed": 0.05})],
                        v=rnd.uniform(0, 1.5)))
write("p000_fig8_eighty", "paper 000 Fig. 8",
      "Performance case: 80 agents assigned to five slowly moving oriented targets. The paper draws a "
      "500-point polyline per agent; the lab keeps the last 3,000 points (50 s at 60 Hz), since 500 "
      "points of 60 Hz steps would show only the last 8 s, not the three sections.",
      agents, duration=60)

# Paper 001 Figs. 10-12: relaxed vs standard funnelling towards region goals
# (tolerance disk of radius dTol, orientation interval betaDeg +/- epsTolDeg).
# Each case is written twice, identical except for "controller"; `steer run
# --controller` overrides it, `steer relaxed` compares both.
def nine_from_left(goals, x0=-14.0):
    return [agent(x0, y, 0, goals, v=1.3) for y in [-4, -3, -2, -1, 0, 1, 2, 3, 4]]

def both(name, source, description, agents, duration):
    for ctl in ("standard", "relaxed"):
        write(name + "_" + ctl, source, description + " Controller: " + ctl + ".", agents,
              duration=duration, controller=ctl)

def far(beta, dist=25.0):
    b = math.radians(beta)
    return goal(dist * math.cos(b), dist * math.sin(b), beta, dTol=1.0, epsTolDeg=180, halting=True)

for beta, letters in [(0, "a/d"), (45, "b/e"), (120, "c/f")]:
    both("p001_fig10_beta%d" % beta, "paper 001 Fig. 10%s" % letters,
         "Nine entities enter from the left towards a 2 m region goal oriented %d° (tolerance 10°), then a distant goal in that direction." % beta,
         nine_from_left([goal(0, 0, beta, dTol=2.0, epsTolDeg=10), far(beta)]), 50)

for tol in [5, 15, 30, 45]:
    both("p001_fig11_tol%d" % tol, "paper 001 Fig. 11",
         "Widening orientation tolerance: a 2 m region goal oriented 90° with ±%d°, then a distant goal." % tol,
         nine_from_left([goal(0, 0, 90, dTol=2.0, epsTolDeg=tol), far(90)]), 50)

chain = [(0, 0, 30), (12, 8, -20), (24, 2, -60), (30, -10, -90)]
both("p001_fig12_successive", "paper 001 Fig. 12",
     "Successive region goals (2 m disks, 10° tolerance); the last one halts.",
     nine_from_left([goal(x, y, b, dTol=2.0, epsTolDeg=10, halting=(i == len(chain) - 1))
                     for i, (x, y, b) in enumerate(chain)]), 70)
# Paper 001 Figs. 6b/c, 8 and 9: one entity heading right towards a 2 m
# region goal. 6b: the standard controller aiming at the disk centre (the
# paper's standard: alpha measured to the centre) gives an artificially
# curved path; 6c: a better point of the disk (the relaxed point, paper
# arc) a smoother one. Fig. 8: the same case, relaxed: some point of the arc
# gives delta-eta = 0, the one of smallest |alpha_r| is taken. Fig. 9: a goal
# oriented back towards the entity: no point gives delta-eta = 0, the arc
# end of smallest |delta-eta| is taken.
def region(beta, eps=10):
    return [agent(-10, 0, 0, [goal(0, 0, beta, dTol=2.0, epsTolDeg=eps)], v=1.3)]

# Paper 001 Fig. 5: one initial state, one desired orientation, distinct
# targets (the protocol of [ALHB06]'s gait recordings): bearings +-20 and
# +-45 deg off the start heading, 4, 8 and 12 m away.
gait = []
for bearing in (-45, -20, 20, 45):
    for d in (4, 8, 12):
        b = math.radians(90 - bearing)
        gait.append(agent(0, 0, 90, [goal(d * math.cos(b), d * math.sin(b), 90, dTol=0.25, epsTolDeg=10)], v=1.3))
write("p001_fig5_gait", "paper 001 Fig. 5",
      "Twelve walkers leave the same pose for twelve targets with the same orientation (north), as in the gait "
      "recordings of [ALHB06] that Fig. 5 replicates.",
      gait, duration=20)
write("p001_fig6b_centre", "paper 001 Fig. 6b",
      "Standard funnelling towards a 2 m region goal oriented 90°, aiming at the disk centre: an artificially curved path.",
      region(90), duration=15, funnel={"aim": "centre"})
write("p001_fig6c_relaxed", "paper 001 Fig. 6c",
      "The same goal, aimed at a better point of the disk (relaxed funnelling, the paper's relaxed point on the arc): a smoother path.",
      region(90), duration=15, controller="relaxed", relaxed={"aim": "paperArc"})
write("p001_fig8_zero_delta_eta_relaxed", "paper 001 Fig. 8",
      "Relaxed funnelling, the case of Fig. 6b: some point of the arc gives Δη = 0; the one of smallest |α_r| is steered to.",
      region(10, 20), duration=15, controller="relaxed", relaxed={"aim": "paperArc"})
write("p001_fig9_arc_end_relaxed", "paper 001 Fig. 9",
      "A region goal oriented back towards the entity: no point of the arc gives Δη = 0, so the arc end of smallest |Δη| is steered to.",
      region(180), duration=20, controller="relaxed", relaxed={"aim": "paperArc"})
print("presets written to", HERE)
