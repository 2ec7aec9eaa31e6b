//! Funnelling control towards oriented targets (paper 000) and relaxed
//! funnelling towards oriented region goals (paper 001): the seek
//! controller that defines η, the η table, the goal and its memory, and the
//! two controllers, which plan and step one agent through one [`update::Update`].
//! The vehicle they steer is [`crate::base::vehicle`]; the world of many
//! agents, goal queues and scenarios is [`crate::world`]; the studies that
//! measure them are `crate::studies`.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`seek`] | 000 §3 | PD seek; the static reach simulation that *defines* η; the committed step |
//! | [`ghost`] | 000 §3, Fig. 1c | the predicted seek path behind η (the generator's simulation, points bounded), drawn by the lab and the learn page |
//! | [`table`] | 000 §3, 001 Fig. 3 | the η table: file format, lookup, generator |
//! | [`goal`] | 000 §5 | the oriented goal (β, D_tol, ε_tol) and what an agent remembers of it between updates: position met, passes and laps, β's direction |
//! | [`update`] | 000 Fig. 4–5 | one update's context ([`update::Update`]: table, limits, state, goal, memory) and report (the [`update::Mode`] of Fig. 5, the [`update::Internals`] the page draws) |
//! | [`config`] | 000 §4, Fig. 4 | the standard controller's settings: the μ bound and gain, where to aim, the seek threshold, the terminal line pursuit |
//! | [`approach`] | 000 Figs. 4–5, 001 §4.1 | what both controllers share: the tolerance phase, halting, moving goals led and lapped, the entry aim, the table lookup |
//! | [`funnel`] | 000 §4–5, Figs. 4–5 | the funnelling update, the four modes, μ bounds, halting |
//! | [`relaxed`] | 001 §4, Fig. 7 | relaxed funnelling: arc 𝒜, span F, interval T, α_r |
//! | [`short_range`] | — | unicycles near a static goal: funnelling, slower, or turning first (walking round the disk, turning on the spot, walking in), chosen by simulated time |
//! | [`manoeuvre`] | — | car-like vehicles: near the goal, a Dubins path to the goal pose tracked by pure pursuit instead of turning on the spot |
//! | [`reverse`] | — | car-like vehicles with a reverse gear: a Reeds–Shepp path near the goal, forwards and backwards, gear changes at rest |
//! | [`controller`] | 000 vs 001 §4 | the choice of controller (the name scenario files and the page use) and a controller with its settings |
//! | [`vehicle_file`] | — | vehicle JSON files (`--vehicle`, the reference pedestrian, car and robot): parsed, fields named, ranges and the generator's ratios checked |

pub mod approach;
pub mod config;
pub mod controller;
pub mod funnel;
pub mod ghost;
pub mod goal;
pub mod manoeuvre;
pub mod relaxed;
pub mod reverse;
pub mod seek;
pub mod short_range;
pub mod table;
pub mod update;
pub mod vehicle_file;
