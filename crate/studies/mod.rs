//! The seeded studies behind the figures: whole batches of runs over the
//! operating envelope, summarised per cell. They sit above the world and
//! the controllers, and are compiled only with the `studies` feature (the
//! command line and the tests have it; the page's wasm does not).
//!
//! | module | paper | what |
//! |---|---|---|
//! | [`reach`] | 000 §5 | seeded reach study behind the acceptance figures |
//! | [`region`] | 001 §5 | seeded region-goal study: standard vs relaxed |
//! | [`envelope`] | 000 §4–6, 001 §4 | the whole operating envelope: tolerances × speed × distance, static, moving and chained goals, both controllers |
//! | [`vehicle`] | 000 §3, §5 | per-vehicle measures in the vehicle's units: η interpolation error, reachability agreement, reach and oriented entries at D ≥ 5 turning radii |
//! | [`car_like`] | — | car-like vehicles (a minimum turning radius): oriented arrival without pivoting, per distance band in turning radii |
//! | [`car_entry`] | — | whether a forward-only car-like vehicle can still enter its goal's disk oriented: the sampled search behind the car-like study's deciding test |
//! | [`short_range`] | 000 §5 | vehicles that turn on the spot: oriented entries per distance band (0.4–60 m), at rest and moving, halting and pass-through, the unavoidable entries counted |
//! | [`avoidance`] | 000 §7, 001 §7 | the avoidance benchmark scenarios (circle swap, corridor, doorway, paper figures) and the seeded study behind `steer avoid` |
//! | [`cost`] | 000 §7, 001 Table 1 | the cases the cost benches time and the counted cost claims count |

pub mod avoidance;
pub mod car_entry;
pub mod car_like;
pub mod cost;
pub mod envelope;
pub mod reach;
pub mod region;
pub mod short_range;
pub mod vehicle;
