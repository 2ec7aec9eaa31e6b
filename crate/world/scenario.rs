//! Scenario files: a documented JSON schema for the runner (`steer run`),
//! the presets in `scenarios/` and the browser lab.
//!
//! Angles are in **degrees** in files (fields ending in `Deg`), distances
//! in metres, speeds in m/s, times in seconds; everything else in the code
//! is radians. Unknown fields are rejected, so a typo never silently falls
//! back to a default.
//!
//! ```json
//! {
//!   "name": "fig7", "description": "…", "source": "paper 000 Fig. 7",
//!   "duration": 40,
//!   "vehicle": { "vMax": 2.0 },                 // optional, VehicleParams
//!   "funnel": { "bound": { "kind": "literal" } }, // optional, FunnelConfig
//!   "controller": "relaxed",                    // optional: standard (default) | relaxed | seek
//!   "reading": "paper",                         // optional: ours (default) | paper, what `funnel` and `relaxed` start from
//!   "relaxed": { "diskMargin": 0.8 },           // optional, RelaxedConfig
//!   "avoidance": { "method": "orca", "radius": 0.3 }, // optional: off (default) | separation | orca
//!   "obstacles": [{ "kind": "disc", "x": 0, "y": 2, "radius": 1 },
//!                 { "kind": "segment", "x1": -5, "y1": 4, "x2": 5, "y2": 4 }],
//!   "agents": [{
//!     "x": 0, "y": 0, "thetaDeg": 0, "v": 0, "omega": 0,
//!     "goals": [{
//!       "x": 10, "y": 5, "betaDeg": 90, "dTol": 0.25, "epsTolDeg": 5,
//!       "speed": 1.3, "halting": false, "switch": "endOfSteering",
//!       "motion": { "kind": "linear", "velocity": [0.3, 0] }
//!     }]
//!   }]
//! }
//! ```

use core::fmt;

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::avoidance::{config::AvoidanceConfig, config::Obstacle};
use crate::base::field_error::{self, FieldError};
use crate::base::vehicle::{VehicleParams, VehicleState};
use crate::funnelling::config::FunnelConfig;
use crate::funnelling::controller::{ControllerKind, Reading};
use crate::funnelling::goal::Goal;
use crate::funnelling::relaxed::RelaxedConfig;
use crate::world::precision;
use crate::world::{goals::GoalMotion, goals::GoalSpec, goals::SwitchRule, World};

/// A scenario file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
pub struct Scenario {
    /// Short name.
    pub name: String,
    /// What it shows.
    #[serde(default)]
    pub description: String,
    /// Which paper figure it reproduces, if any.
    #[serde(default)]
    pub source: String,
    /// What the paper claims for that figure, in a sentence.
    #[serde(default)]
    pub claim: String,
    /// What we measure, with the test that asserts it (`tests/fidelity.rs`)
    /// or "refuted: …" with the numbers.
    #[serde(default)]
    pub measured: String,
    /// Simulated duration, s.
    #[serde(default = "default_duration")]
    pub duration: f32,
    /// Vehicle parameters (defaults: pedestrian).
    #[serde(default)]
    pub vehicle: VehicleParams,
    /// The η table to run with, relative to the scenario file;
    /// it must have been built for `vehicle` (`eta-table --vehicle`).
    /// Without it `steer run` uses the committed table if it matches the
    /// vehicle, else builds the matching one or loads it from its cache.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub table: Option<String>,
    /// Which reading of the papers `funnel` and `relaxed` start from:
    /// `ours` (the defaults) or `paper` (paper 000's standard and paper
    /// 001's relaxed funnelling as written, [`Reading`]); fields given in
    /// `funnel` and `relaxed` then override the reading's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reading: Option<Reading>,
    /// Funnelling settings.
    #[serde(default)]
    pub funnel: FunnelConfig,
    /// Which controller: `seek` (plain seek, β and ε_tol ignored: paper
    /// 000 Fig. 1), `standard` or `relaxed` (paper 001: region goals with `dTol` the disk
    /// radius and `epsTolDeg` the half-width τ of T).
    #[serde(default)]
    pub controller: ControllerKind,
    /// Relaxed-controller settings.
    #[serde(default)]
    pub relaxed: RelaxedConfig,
    /// Avoidance between agents and of the obstacles: `method`
    /// off (default), separation or orca, the body `radius` and settings
    /// ([`AvoidanceConfig`]).
    #[serde(default, skip_serializing_if = "is_default_avoidance")]
    pub avoidance: AvoidanceConfig,
    /// Static obstacles: `{"kind": "disc", "x", "y", "radius"}` or
    /// `{"kind": "segment", "x1", "y1", "x2", "y2"}` (avoided when the
    /// avoidance is on).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub obstacles: Vec<Obstacle>,
    /// The agents.
    pub agents: Vec<AgentSpec>,
}

fn is_default_avoidance(a: &AvoidanceConfig) -> bool {
    *a == AvoidanceConfig::default()
}

fn default_duration() -> f32 {
    60.0
}

/// An agent in a scenario file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
pub struct AgentSpec {
    /// Start x, m.
    pub x: f32,
    /// Start y, m.
    pub y: f32,
    /// Start heading, degrees.
    #[serde(default)]
    pub theta_deg: f32,
    /// Start speed, m/s.
    #[serde(default)]
    pub v: f32,
    /// Start angular speed, rad/s.
    #[serde(default)]
    pub omega: f32,
    /// Goal queue.
    #[serde(default)]
    pub goals: Vec<GoalFile>,
}

/// A goal in a scenario file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
pub struct GoalFile {
    /// Target x, m.
    pub x: f32,
    /// Target y, m.
    pub y: f32,
    /// Target orientation β, degrees.
    #[serde(default)]
    pub beta_deg: f32,
    /// Position tolerance, m.
    #[serde(default = "default_d_tol")]
    pub d_tol: f32,
    /// Orientation tolerance, degrees.
    #[serde(default = "default_eps_deg")]
    pub eps_tol_deg: f32,
    /// Desired speed, m/s.
    #[serde(default = "default_speed")]
    pub speed: f32,
    /// Arrive at rest (refused on a goal in linear or circular motion:
    /// see [`GoalMotion`]).
    #[serde(default)]
    pub halting: bool,
    /// When to move on to the next goal.
    #[serde(default)]
    pub switch: SwitchRule,
    /// How the goal moves.
    #[serde(default)]
    pub motion: GoalMotion,
}

fn default_d_tol() -> f32 {
    0.25
}
fn default_eps_deg() -> f32 {
    5.0
}
fn default_speed() -> f32 {
    1.3
}

/// Longest scenario, s ([`crate::base::ranges::DURATION`]).
pub const MAX_DURATION: f32 = crate::base::ranges::DURATION.max as f32;

/// Most agents in a scenario ([`crate::base::ranges::AGENTS`]).
pub const MAX_SCENARIO_AGENTS: usize = crate::base::ranges::AGENTS.max as usize;

/// Most goals queued per agent in a scenario.
pub const MAX_GOALS: usize = 10_000;

/// Most agent-steps (agents × duration / dt) in a scenario: 1e9 keeps a
/// run to minutes, not hours (100,000 agents × 3,600 s at 60 Hz, 2.2e10,
/// is refused); 1,000 agents × 3,600 s at 60 Hz is 2.16e8.
pub const MAX_AGENT_STEPS: u64 = 1_000_000_000;

/// Refuses structs written as positional arrays (serde accepts
/// `["name", "", …]` for a struct): in a scenario, an array either holds
/// objects only (`agents`, `goals`) or is a pair of numbers under
/// `velocity` / `center`.
///
/// # Errors
/// [`ScenarioError::Parse`] naming the path of the first such array
/// (`path` is the path of `v`, empty at the top).
fn refuse_positional(v: &serde_json::Value, path: &str) -> Result<(), ScenarioError> {
    use serde_json::Value;
    let positional = |path: &str| {
        ScenarioError::Parse(FieldError::new(
            path,
            "is not an object with named fields (positional arrays are refused)",
        ))
    };
    let top = path.is_empty();
    match v {
        Value::Object(m) => m.iter().try_for_each(|(k, x)| {
            let pair =
                matches!(x, Value::Array(a) if a.len() == 2 && a.iter().all(Value::is_number));
            let here = if top {
                k.clone()
            } else {
                format!("{path}.{k}")
            };
            if (k == "velocity" || k == "center") && pair {
                Ok(())
            } else {
                refuse_positional(x, &here)
            }
        }),
        Value::Array(_) if top => Err(positional(path)),
        Value::Array(a) => a.iter().enumerate().try_for_each(|(i, x)| {
            let here = format!("{path}[{i}]");
            if x.is_object() {
                refuse_positional(x, &here)
            } else {
                Err(positional(&here))
            }
        }),
        _ if top => Err(ScenarioError::Parse(FieldError::new(
            path,
            "expected an object (a scenario)",
        ))),
        _ => Ok(()),
    }
}

/// True when field path `path` lies inside `outer` (or is it).
fn within(path: &str, outer: &str) -> bool {
    path.strip_prefix(outer)
        .is_some_and(|rest| rest.is_empty() || outer.is_empty() || rest.starts_with(['.', '[']))
}

/// The scenario `value` with its `funnel` and `relaxed` objects laid over
/// `reading`'s settings: a field the file gives wins, the others are the
/// reading's.
///
/// # Errors
/// `funnel` or `relaxed` is not an object.
fn with_reading(
    mut value: serde_json::Value,
    reading: Reading,
) -> Result<serde_json::Value, ScenarioError> {
    let bases = [
        ("funnel", serde_json::to_value(reading.funnel())),
        ("relaxed", serde_json::to_value(reading.relaxed())),
    ];
    for (key, base) in bases {
        let mut base =
            base.map_err(|e| ScenarioError::Parse(FieldError::new(key, e.to_string())))?;
        if let Some(given) = value.get(key) {
            let given = given.as_object().ok_or_else(|| {
                ScenarioError::Parse(FieldError::new(key, "expected an object of settings"))
            })?;
            if let Some(b) = base.as_object_mut() {
                b.extend(given.iter().map(|(k, v)| (k.clone(), v.clone())));
            }
        }
        value[key] = base;
    }
    Ok(value)
}

/// Why a scenario was refused: always the path of the field at fault in
/// the file (`agents[0].goals[1].x`) and what is wrong with it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ScenarioError {
    /// Not valid JSON for the schema (a syntax error, a wrong type, a
    /// missing or unknown field).
    Parse(FieldError),
    /// A value out of range, or values inconsistent together.
    Invalid(FieldError),
}

impl ScenarioError {
    /// The field at fault and what is wrong with it.
    #[must_use]
    pub fn field(&self) -> &FieldError {
        match self {
            Self::Parse(e) | Self::Invalid(e) => e,
        }
    }

    /// An invalid value at `path`.
    fn invalid(path: impl Into<String>, e: impl fmt::Display) -> Self {
        Self::Invalid(FieldError::new(path, e.to_string()))
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Parse(e) => write!(f, "scenario is not valid: {e}"),
            Self::Invalid(e) => write!(f, "scenario is inconsistent: {e}"),
        }
    }
}

impl std::error::Error for ScenarioError {}

/// An obstacle list's refusal (`obstacles[1]: …`) with its path apart.
fn obstacle_error(e: &str) -> ScenarioError {
    match e.split_once(": ") {
        Some((path, rest)) if path.starts_with("obstacles[") => ScenarioError::invalid(path, rest),
        _ => ScenarioError::invalid("obstacles", e),
    }
}

impl GoalFile {
    /// Converts to the internal (radian) form.
    #[must_use]
    pub fn to_spec(&self) -> GoalSpec {
        GoalSpec {
            goal: Goal {
                pos: Vec2::new(self.x, self.y),
                beta: self.beta_deg.to_radians(),
                d_tol: self.d_tol,
                eps_tol: self.eps_tol_deg.to_radians(),
                speed: self.speed,
                halting: self.halting,
                vel: Vec2::ZERO,
            },
            motion: self.motion,
            switch: self.switch,
        }
    }
}

impl Scenario {
    /// Parses a scenario from JSON text.
    ///
    /// # Errors
    /// [`ScenarioError`] naming the path of the field at fault
    /// (`agents[0].goals[1].x: expected a number, found a list`).
    pub fn from_json(text: &str) -> Result<Self, ScenarioError> {
        Self::from_bytes(text.as_bytes())
    }

    /// [`Scenario::from_json`] on a file's bytes as read (bytes that are
    /// not UTF-8 are refused at the field they are in).
    ///
    /// # Errors
    /// As [`Scenario::from_json`].
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, ScenarioError> {
        let value: serde_json::Value =
            field_error::from_slice(bytes).map_err(ScenarioError::Parse)?;
        let positional = refuse_positional(&value, "");
        let typed = match value.get("reading").and_then(serde_json::Value::as_str) {
            Some("paper") => with_reading(value, Reading::Paper)
                .and_then(|v| field_error::from_value(&v).map_err(ScenarioError::Parse)),
            // From the bytes, for the line and column beside the path.
            _ => field_error::from_slice(bytes).map_err(ScenarioError::Parse),
        };
        // A struct written as a positional array is named as such when the
        // schema's own refusal lies inside it (or there is none: serde
        // reads a struct from an array); other refusals are the schema's
        // (`x: [1]` is a list where a number belongs).
        let s: Self = match (typed, positional) {
            (Ok(_), Err(p)) => return Err(p),
            (Err(e), Err(p)) if within(&e.field().path, &p.field().path) => return Err(p),
            (Err(e), _) => return Err(e),
            (Ok(s), Ok(())) => s,
        };
        s.validate()?;
        Ok(s)
    }

    /// Sets the reading and replaces `funnel` and `relaxed` with its
    /// settings (`steer run --reading`).
    pub fn set_reading(&mut self, reading: Reading) {
        self.reading = Some(reading);
        self.funnel = reading.funnel();
        self.relaxed = reading.relaxed();
    }

    /// What a user is shown for the controller this scenario runs:
    /// `paper 001 relaxed`, `ours standard`, `custom standard`, …
    /// ([`Reading::label`]).
    #[must_use]
    pub fn controller_label(&self) -> String {
        Reading::label(self.controller, &self.funnel, &self.relaxed)
    }

    /// Checks every value.
    ///
    /// # Errors
    /// The first invalid value, with its path in the file.
    pub fn validate(&self) -> Result<(), ScenarioError> {
        self.vehicle
            .validate()
            .map_err(|e| ScenarioError::invalid("vehicle", e))?;
        self.funnel
            .validate()
            .map_err(|e| ScenarioError::invalid("funnel", e))?;
        self.relaxed
            .validate()
            .map_err(|e| ScenarioError::invalid("relaxed", e))?;
        self.avoidance
            .validate()
            .map_err(|e| ScenarioError::invalid("avoidance", e))?;
        crate::avoidance::config::validate_obstacles(&self.obstacles)
            .map_err(|e| obstacle_error(&e))?;
        crate::base::ranges::DURATION
            .check(self.duration)
            .map_err(|e| ScenarioError::invalid("duration", e))?;
        let n = self.agents.len();
        if n > MAX_SCENARIO_AGENTS {
            return Err(ScenarioError::invalid(
                "agents",
                format!("{n} agents (at most {MAX_SCENARIO_AGENTS})"),
            ));
        }
        let work = n as u64 * u64::from(self.steps());
        if work > MAX_AGENT_STEPS {
            return Err(ScenarioError::invalid(
                "agents",
                format!(
                    "{n} agents × {} steps (duration {} s at dt {} s) = {work} agent-steps, more \
                     than {MAX_AGENT_STEPS}: shorten the duration or use fewer agents",
                    self.steps(),
                    self.duration,
                    self.vehicle.dt
                ),
            ));
        }
        for (i, a) in self.agents.iter().enumerate() {
            self.validate_agent(i, a)?;
        }
        Ok(())
    }

    /// Checks agent `i` (`agents[i]` in the file).
    fn validate_agent(&self, i: usize, a: &AgentSpec) -> Result<(), ScenarioError> {
        let at = format!("agents[{i}]");
        let st = VehicleState::new(Vec2::new(a.x, a.y), a.theta_deg.to_radians(), a.v, a.omega);
        st.validate(&self.vehicle)
            .map_err(|e| ScenarioError::invalid(&at, e))?;
        if a.goals.len() > MAX_GOALS {
            return Err(ScenarioError::invalid(
                format!("{at}.goals"),
                format!("{} goals (at most {MAX_GOALS})", a.goals.len()),
            ));
        }
        let specs: Vec<GoalSpec> = a.goals.iter().map(GoalFile::to_spec).collect();
        for (k, (spec, g)) in specs.iter().zip(&a.goals).enumerate() {
            spec.validate(&self.vehicle)
                .map_err(|e| ScenarioError::invalid(format!("{at}.goals[{k}]"), e))?;
            if let GoalMotion::FaceAgent { agent, .. } = g.motion {
                if agent >= self.agents.len() || agent == i {
                    return Err(ScenarioError::invalid(
                        format!("{at}.goals[{k}].motion.agent"),
                        format!("agent {i} faces agent {agent}, which does not exist or is itself"),
                    ));
                }
            }
        }
        precision::check_agent(&self.vehicle, st.pos, &specs, Some(self.duration)).map_err(|e| {
            ScenarioError::invalid(
                &at,
                format!(
                    "{e} (f32 positions resolve a quarter of one step, slowest goal speed × dt, \
                     only within that range: move the scene nearer the origin)"
                ),
            )
        })
    }

    /// Builds the world. The agents' internals are provisional until the
    /// first step or [`World::plan`] with the η table (the first row of a
    /// trajectory should come after `plan`).
    ///
    /// # Errors
    /// Any invalid agent or goal, with its path in the file.
    pub fn world(&self) -> Result<World, ScenarioError> {
        self.validate()?;
        let mut w = World::new(self.vehicle, self.funnel)
            .map_err(|e| ScenarioError::invalid("vehicle", e))?;
        w.set_controller(self.controller, self.relaxed)
            .map_err(|e| ScenarioError::invalid("relaxed", e))?;
        w.set_avoidance(self.avoidance, self.obstacles.clone())
            .map_err(|e| ScenarioError::invalid("avoidance", e))?;
        for (i, a) in self.agents.iter().enumerate() {
            let st = VehicleState::new(
                Vec2::new(a.x, a.y),
                crate::base::angle::wrap(a.theta_deg.to_radians()),
                a.v,
                a.omega,
            );
            let goals = a.goals.iter().map(GoalFile::to_spec).collect();
            w.add_agent(st, goals)
                .map_err(|e| ScenarioError::invalid(format!("agents[{i}]"), e))?;
        }
        Ok(w)
    }

    /// Number of steps for the duration.
    #[must_use]
    pub fn steps(&self) -> u32 {
        (self.duration / self.vehicle.dt).round() as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `"reading": "paper"` starts `funnel` and `relaxed` from the papers'
    /// algorithms; fields the file gives override them, and the scenario
    /// writes and reads back the same.
    #[test]
    fn the_reading_field_selects_the_papers_settings() {
        let goals = r#""agents": [{"x": 0, "y": 0, "goals": [{"x": 3, "y": 0}]}]"#;
        let sc = Scenario::from_json(&format!(
            r#"{{"name": "r", "controller": "relaxed", "reading": "paper", {goals}}}"#
        ))
        .unwrap();
        assert_eq!(sc.funnel, FunnelConfig::paper_000());
        assert_eq!(sc.relaxed, RelaxedConfig::paper_001());
        assert_eq!(sc.controller_label(), "paper 001 relaxed");
        let back = Scenario::from_json(&serde_json::to_string(&sc).unwrap()).unwrap();
        assert_eq!(back, sc);
        let sc = Scenario::from_json(&format!(
            r#"{{"name": "r", "reading": "paper", "funnel": {{"gain": 2}}, {goals}}}"#
        ))
        .unwrap();
        assert_eq!(sc.funnel.gain, 2.0);
        assert_eq!(
            sc.funnel.reachability,
            FunnelConfig::paper_000().reachability
        );
        assert_eq!(sc.controller_label(), "custom standard");
        let ours = Scenario::from_json(&format!(r#"{{"name": "r", {goals}}}"#)).unwrap();
        assert_eq!(ours.controller_label(), "ours standard");
        let e = Scenario::from_json(&format!(r#"{{"name": "r", "reading": "both", {goals}}}"#))
            .unwrap_err()
            .to_string();
        assert!(e.contains("unknown variant `both`"), "{e}");
    }

    /// Every refusal names the path of the field at fault, in a one-line
    /// file too (as the lab exports them), whichever reading it starts from.
    #[test]
    fn a_refused_file_names_the_path_of_the_field() {
        let goals = r#"[{"x": 1, "y": 0}, {"x": [1], "y": 0}]"#;
        for reading in ["ours", "paper"] {
            let text = format!(
                r#"{{"name": "p", "reading": "{reading}", "agents": [{{"x": 0, "y": 0, "goals": {goals}}}]}}"#
            );
            let e = Scenario::from_json(&text).unwrap_err();
            assert_eq!(e.field().path, "agents[0].goals[1].x");
            assert!(
                e.to_string().starts_with(
                    "scenario is not valid: agents[0].goals[1].x: expected a number, found a list"
                ),
                "{e}"
            );
        }
        let refused = |text: &str| Scenario::from_json(text).unwrap_err().to_string();
        let e = refused(r#"{"name": "p", "agents": [{"y": 0}]}"#);
        assert!(e.contains(": agents[0].x: missing"), "{e}");
        let e = refused(r#"{"name": "p", "agents": [{"x": 0, "y": 0, "thetaDeg": 1e999}]}"#);
        assert!(
            e.contains(": agents[0].thetaDeg: number out of range"),
            "{e}"
        );
        let e = refused(r#"{"name": "p", "agents": [{"x": 0, "y": 0, "goals": [{"x": 1, "y"#);
        assert!(e.contains(": agents[0].goals[0]: EOF while parsing"), "{e}");
        let e = refused(r#"{"name": "p", "agents": [{"x": 0, "y": 0, "goals": [{"x": 1, "y": "#);
        assert!(
            e.contains(": agents[0].goals[0].y: EOF while parsing"),
            "{e}"
        );
        let e = refused(r#"{"name": "p", "agents": [{"x": 0, "y": 0, "goals": [[1, 2]]}]}"#);
        assert!(e.contains(": agents[0].goals[0]: is not an object"), "{e}");
        let e = refused(
            r#"{"name": "p", "agents": [{"x": 0, "y": 0, "goals": [{"x": 3, "y": 0, "betaDeg": 3e38}]}]}"#,
        );
        assert!(e.contains(": agents[0].goals[0]: goal.beta"), "{e}");
    }

    /// The desired-speed range of `base::ranges` holds in files too.
    #[test]
    fn a_desired_speed_of_zero_is_refused_in_files_too() {
        let text = r#"{"name": "z", "agents": [{"x": 0, "y": 0, "goals": [{"x": 3, "y": 0, "speed": 0}]}]}"#;
        let e = Scenario::from_json(text).unwrap_err();
        assert_eq!(
            e.to_string(),
            "scenario is inconsistent: agents[0].goals[0]: goal.speed = 0 is outside [0.01, 2]"
        );
    }
}
