//! Funnelling control towards oriented targets (paper 000) and relaxed
//! funnelling towards oriented region goals (paper 001): the vehicle, the
//! seek controller that defines η, the η table, the two controllers, the
//! multi-agent world, scenario files and the measurement studies.
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`vehicle`] | 000 §3 | forward-only unicycle, every limit enforced exactly; `VehicleParams` |
//! | [`seek`] | 000 §3 | PD seek; the static reach simulation that *defines* η; the committed step |
//! | [`ghost`] | 000 §3, Fig. 1c | the predicted seek path behind η (the generator's simulation, points bounded), drawn by the lab and the learn page |
//! | [`table`] | 000 §3, 001 Fig. 3 | the η table: file format, lookup, generator |
//! | [`funnel`] | 000 §4–5, Figs. 4–5 | the funnelling update, the four modes, μ bounds, halting |
//! | [`relaxed`] | 001 §4, Fig. 7 | relaxed funnelling: arc 𝒜, span F, interval T, α_r; controller choice |
//! | [`goals`] | 000 §6 | goal-queue entries: motion (static, linear, circle, facing an agent), switch rule, which goals may halt |
//! | [`world`] | 000 §6 | many agents with goal queues, moving and successive targets |
//! | [`world_edit`] | 000 §6, Fig. 5 | edits of a running world: pose reset, new goals (queue and memory restart), the seeded random crowd |
//! | [`world_split`] | 000 §6, Fig. 6 | issue 17: a world split into contiguous slices that step alone (facing links kept inside one), for the lab's stepping workers |
//! | [`vehicle_file`] | — | vehicle JSON files (`--vehicle`, the reference pedestrian, car and robot): parsed, fields named, ranges and the generator's ratios checked |
//! | [`vehicle_study`] | 000 §3, §5 | per-vehicle measures in the vehicle's units: η interpolation error at D ≥ 4 turning radii, reachability agreement, reach and oriented entries at D ≥ 5 turning radii |
//! | [`ranges`] | — | one table of validation ranges (key, min, max, unit, integer, cross-field bound) that the checks below and the page use |
//! | [`scenario`] | — | the scenario JSON schema (degrees in files) and its validation: positional arrays refused, agents × steps bounded |
//! | [`precision`] | — | the coordinate range where f32 resolves a quarter of one step (slowest goal speed × dt), measured; checked on every agent and goal |
//! | [`envelope`] | 000 §4–6, 001 §4 | seeded study over the whole operating envelope: tolerances × speed × distance, static, moving and chained goals, both controllers |
//! | [`study`] | 000 §5 | seeded reach study behind the acceptance figures |
//! | [`region_study`] | 001 §5 | seeded region-goal study: standard vs relaxed |

pub mod approach;
pub mod config;
pub mod controller;
pub mod funnel;
pub mod ghost;
pub mod goal;
pub mod relaxed;
pub mod seek;
pub mod table;
pub mod update;
pub mod vehicle_file;
