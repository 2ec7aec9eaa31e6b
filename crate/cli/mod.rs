//! The command lines (native only): argument structures parsed with clap's
//! derive API, so every binary has `--help`, refuses unknown flags and
//! says when a number overflows. The structures live in the library, not in
//! `crate/bin/`, so tests can feed them argument vectors
//! (`try_parse_from`) without spawning processes.
//!
//! | module | what |
//! |---|---|
//! | [`steer`] | `steer run / reach / relaxed / envelope / avoid`: one enum variant and one argument struct per subcommand |
//! | [`eta_table`] | `eta-table`: output file, vehicle file, sample counts per axis, thread count |
//! | [`crowd_metrics`] | `crowd-metrics`: `--write-presets`, repeatable `--set key=value` |
//! | [`pool`] | `--threads`: the rayon pool a study or the table generator runs on |
//! | [`records`] | figures records: the JSON a test, study or benchmark writes per measurement (read, checked, written atomically), `--record` |
//! | [`study_records`] | what `steer reach / relaxed / envelope / avoid --record` write: each summary row as figures, tuning and report seeds |
//! | [`report`] | `steer report`: `docs/FIGURES.md` from the records, the presets' `measured` templates, `--check` |
//! | [`report_sections`] | the report's Peers section and its instruction counts |
//! | [`report_table`] | one record as the report shows it: source, command, seeds, its figures |
//! | [`table_cache`] | the η tables built for other vehicles, cached by parameter key (`steer run`) |
//! | [`trajectory`] | `steer run`'s output streamed (CSV, time-ordered JSON, JSON Lines) to a temporary file renamed onto `--out` when complete, the `--out` checks before simulating |

pub mod crowd_metrics;
pub mod eta_table;
pub mod pool;
pub mod records;
pub mod report;
pub mod report_sections;
pub mod report_table;
pub mod steer;
pub mod study_records;
pub mod table_cache;
pub mod trajectory;
