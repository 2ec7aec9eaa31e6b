//! A wander behaviour as a pipeline of components, built from JSON
//! (paper 004 introduction: "these can be combined in various ways").
//!
//! One step is
//!
//! ```text
//! source ──► hold (timed transitions, §5) ──► quantize (discrete set, §2)
//!        ──► control (displacement | velocity | acceleration + clamps, §1)
//!        ──► constant-speed agent ──► trace
//! ```
//!
//! where the source is one of: random numbers from a distribution (§1–2),
//! a vector field (§3), a time function (§4), a transition table (§6) or a
//! generated path to follow (§7). Sources that produce a normalised value
//! in `[-1, 1]` are scaled by the clamp of the controlled quantity; the
//! table and the path follower produce angles directly.
//!
//! Everything random comes from one seeded [`Rng`] (streams per concern),
//! and every angle function is the deterministic one from [`crate::base::trig`],
//! so a config and a seed give the same trajectory bit for bit natively and
//! in WebAssembly. A step allocates nothing: the trace is a preallocated
//! ring buffer.

use glam::Vec2;
use serde::{Deserialize, Serialize};

pub use super::config::{AgentConfig, MixPart, SourceConfig, WanderConfig};
use super::control::{Agent, Control};
use super::distribution::Sampler;
use super::error::WanderError;
use super::field::FieldSource;
use super::generated_path::PathFollower;
use super::markov::Markov;
use super::time_fn::TimeFn;
use super::timed::Hold;
use crate::base::rng::Rng;

/// A built source.
#[derive(Clone, Debug, PartialEq)]
enum Source {
    Random(Sampler),
    Field(FieldSource),
    Time(TimeFn),
    Markov(Markov),
    Path(PathFollower),
    Mix(Vec<(f32, Source)>),
}

impl Source {
    /// Builds a validated source; a path moves `agent` onto its start.
    fn build(cfg: &SourceConfig, rng: &mut Rng, agent: &mut Agent) -> Result<Self, WanderError> {
        Ok(match cfg {
            SourceConfig::Random { distribution } => Self::Random(Sampler::new(distribution, rng)?),
            SourceConfig::Field { field } => Self::Field(FieldSource::new(field, rng)?),
            SourceConfig::TimeFunction { function } => Self::Time(TimeFn::new(function, rng)?),
            SourceConfig::Markov { markov } => Self::Markov(Markov::new(markov)?),
            SourceConfig::Path { path, lookahead } => {
                let f = PathFollower::new(path, *lookahead, rng)?;
                (agent.pos, agent.heading) = f.start_pose();
                Self::Path(f)
            }
            SourceConfig::Mix { parts } => Self::Mix(
                parts
                    .iter()
                    .map(|p| Ok((p.weight, Self::build(&p.source, rng, agent)?)))
                    .collect::<Result<_, WanderError>>()?,
            ),
        })
    }

    /// The command (radians) for `step`; normalised sources are scaled by
    /// `scale`, the clamp of the controlled quantity.
    #[inline]
    fn command(&mut self, step: u32, agent: &Agent, scale: f32, rng: &mut Rng) -> f32 {
        match self {
            Self::Random(s) => scale * s.sample(step, rng),
            Self::Field(f) => scale * f.sample(step, agent.pos, rng),
            Self::Time(t) => scale * t.value(step),
            Self::Markov(m) => m.sample(rng),
            Self::Path(p) => p.sample(agent.pos, agent.heading),
            Self::Mix(parts) => parts
                .iter_mut()
                .map(|(w, s)| *w * s.command(step, agent, scale, rng))
                .sum(),
        }
    }
}

/// Poses in a fixed-capacity ring, oldest overwritten first.
#[derive(Clone, PartialEq)]
struct Trace {
    data: Vec<f32>,
    start: usize,
    len: usize,
}

impl core::fmt::Debug for Trace {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "Trace {{ {} of {} poses }}", self.len, self.capacity())
    }
}

impl Trace {
    fn new(capacity: usize) -> Self {
        Self {
            data: vec![0.0; capacity * 3],
            start: 0,
            len: 0,
        }
    }

    fn capacity(&self) -> usize {
        self.data.len() / 3
    }

    #[inline]
    fn push(&mut self, a: &Agent) {
        let cap = self.capacity();
        let slot = if self.len < cap {
            self.len += 1;
            (self.start + self.len - 1) % cap
        } else {
            let s = self.start;
            self.start = (self.start + 1) % cap;
            s
        };
        self.data[slot * 3..slot * 3 + 3].copy_from_slice(&[a.pos.x, a.pos.y, a.heading]);
    }

    fn copy_into(&self, out: &mut [f32]) -> usize {
        let cap = self.capacity();
        let n = self.len.min(out.len() / 3);
        // The ring is at most two contiguous runs.
        let first = n.min(cap - self.start);
        out[..first * 3].copy_from_slice(&self.data[self.start * 3..(self.start + first) * 3]);
        out[first * 3..n * 3].copy_from_slice(&self.data[..(n - first) * 3]);
        n
    }
}

/// A running wander behaviour: build with [`Wanderer::from_json`], call
/// [`Wanderer::step`], read poses with [`Wanderer::pose`] or the whole
/// trace as a flat `[x0, y0, θ0, x1, y1, θ1, …]` buffer (oldest first,
/// θ in radians wrapped to `(-π, π]`) with [`Wanderer::trace`].
#[derive(Clone, Debug, PartialEq)]
pub struct Wanderer {
    config: WanderConfig,
    rng: Rng,
    agent: Agent,
    control: Control,
    source: Source,
    hold: Option<Hold>,
    command: f32,
    step: u32,
    trace: Trace,
}

impl Wanderer {
    /// Validates `config` and builds the pipeline; the initial pose is the
    /// first trace entry. A path source puts the agent on the path's first
    /// point, heading along it (the configured position is ignored).
    pub fn new(config: WanderConfig) -> Result<Self, WanderError> {
        config.validate()?;
        // Construction-time randomness (fields, paths, noise seeds) uses its
        // own stream, so changing e.g. a hold interval does not regenerate
        // the field.
        let mut build = Rng::with_stream(config.seed, 0x57a7);
        let mut agent = Agent {
            pos: Vec2::new(config.agent.x, config.agent.y),
            heading: crate::base::angle::wrap(config.agent.heading_deg.to_radians()),
            speed: config.agent.speed,
        };
        let source = Source::build(&config.source, &mut build, &mut agent)?;
        let control = Control::new(&config.control, agent.heading)?;
        let hold = config.hold.as_ref().map(Hold::new).transpose()?;
        let mut trace = Trace::new(config.trace_capacity as usize);
        trace.push(&agent);
        Ok(Self {
            rng: Rng::with_stream(config.seed, 0x3a9d),
            config,
            agent,
            control,
            source,
            hold,
            command: 0.0,
            step: 0,
            trace,
        })
    }

    /// Parses, validates and builds.
    pub fn from_json(json: &str) -> Result<Self, WanderError> {
        Self::new(WanderConfig::from_json(json)?)
    }

    /// The configuration this wanderer was built from.
    #[must_use]
    pub fn config(&self) -> &WanderConfig {
        &self.config
    }

    /// Back to step 0 with the same seed (replays the same trajectory).
    pub fn reset(&mut self) {
        // The config was validated when `self` was built.
        if let Ok(w) = Self::new(self.config.clone()) {
            *self = w;
        }
    }

    /// Advances one step: maybe draw a new command, apply it under the
    /// clamps, move forward, record the pose. Allocation-free.
    pub fn step(&mut self) {
        let due = match &mut self.hold {
            Some(h) => h.due(&mut self.rng),
            None => true,
        };
        if due {
            let q =
                self.source
                    .command(self.step, &self.agent, self.control.scale(), &mut self.rng);
            self.command = self.control.quantize(q);
        }
        self.control.apply(&mut self.agent, self.command);
        self.agent.advance();
        self.step = self.step.wrapping_add(1);
        self.trace.push(&self.agent);
    }

    /// Runs `n` steps.
    pub fn run(&mut self, n: u32) {
        for _ in 0..n {
            self.step();
        }
    }

    /// Steps taken since construction or [`Wanderer::reset`].
    #[must_use]
    pub fn steps(&self) -> u32 {
        self.step
    }

    /// Current `[x, y, θ]`.
    #[must_use]
    pub fn pose(&self) -> [f32; 3] {
        [self.agent.pos.x, self.agent.pos.y, self.agent.heading]
    }

    /// The agent.
    #[must_use]
    pub fn agent(&self) -> &Agent {
        &self.agent
    }

    /// Current angular velocity (radians per step; 0 in displacement mode).
    #[must_use]
    pub fn angular_velocity(&self) -> f32 {
        self.control.velocity()
    }

    /// The command applied at the last step (radians, before clamping).
    #[must_use]
    pub fn command(&self) -> f32 {
        self.command
    }

    /// Number of poses in the trace (≤ `trace_capacity`).
    #[must_use]
    pub fn trace_len(&self) -> usize {
        self.trace.len
    }

    /// Copies the trace, oldest first, into `out` as `[x, y, θ]` triples;
    /// returns the number of poses written (limited by `out.len() / 3`).
    pub fn trace_into(&self, out: &mut [f32]) -> usize {
        self.trace.copy_into(out)
    }

    /// The trace as a new flat buffer `[x0, y0, θ0, x1, …]`, oldest first.
    #[must_use]
    pub fn trace(&self) -> Vec<f32> {
        let mut v = vec![0.0; self.trace.len * 3];
        self.trace.copy_into(&mut v);
        v
    }

    /// The generated path as flat `[x0, y0, x1, y1, …]` (empty unless the
    /// source is a path), for drawing under the agent.
    #[must_use]
    pub fn path_points(&self) -> &[f32] {
        match &self.source {
            Source::Path(p) => p.flat(),
            _ => &[],
        }
    }
}

/// One labelled variant of a preset.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PresetVariant {
    /// Caption (the paper's figure caption, or ours).
    pub label: String,
    /// Paper figure it reproduces (e.g. "screenshot106"), if any.
    #[serde(default)]
    pub figure: Option<String>,
    /// The behaviour.
    pub config: WanderConfig,
}

/// A preset file under `scenarios/wander/`: one component, its figure
/// series as variants.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WanderPreset {
    /// Title for the gallery.
    pub title: String,
    /// Paper section it illustrates (e.g. "004 §1").
    pub section: String,
    /// Suggested steps to run before drawing.
    pub steps: u32,
    /// The variants, drawn side by side.
    pub variants: Vec<PresetVariant>,
}

impl WanderPreset {
    /// Parses a preset and validates every variant.
    pub fn from_json(json: &str) -> Result<Self, WanderError> {
        let p: Self = crate::base::field_error::from_str(json)
            .map_err(|e| WanderError::Json(e.to_string()))?;
        if p.variants.is_empty() {
            return Err(WanderError::Empty {
                what: "preset.variants",
            });
        }
        for v in &p.variants {
            v.config.validate()?;
        }
        Ok(p)
    }
}
