//! touchline's scenario front end: turns what a user names or writes into a checked
//! [`Scenario`](touchline_engine::Scenario).
//!
//! A scenario comes from one of three places (see [`load`]):
//!
//! - the **stdlib**, by name (`academy_empty_goal_close`, `11_vs_11_stochastic`, …): the scenarios of
//!   Google Research Football, embedded in this crate ([`stdlib`]);
//! - a **compiled scenario**, a `.json` file holding a `Scenario` serialised with serde ([`load_json`]);
//! - a **`.tl` file** in the scenario language (`grammar/README.md`), compiled on load
//!   ([`compile_file`]; [`compile`] takes the text itself).
//!
//! Every failure is a [`LoadError`], a [`miette::Diagnostic`] with a stable code (`tl::E001` …
//! `tl::E004`, or the compiler's `tl::E1xx` with every diagnostic of the file); [`render_plain`]
//! renders one as fixed, colourless text for snapshots and Python exception messages.
//!
//! ```
//! let scenario = touchline_dsl::load("academy_empty_goal_close").unwrap();
//! assert_eq!(scenario.game_duration, 400);
//! assert_eq!(scenario.ball_position, [0.77, 0.0]);
//! ```
#![deny(missing_docs)]

mod build_env;
mod compile;
pub mod diagnostic;
pub mod excerpt;
mod format;
mod load;
mod load_error;
mod print;
mod source_file;
mod span;
pub mod stdlib;
mod suggest;
pub mod syntax;

pub mod script;
pub mod watch;

pub use compile::{Compiled, PRELUDE, check_file, compile, compile_file};

pub use build_env::{BuildError, attach, build_env, build_env_with, script_dir};
pub use diagnostic::{Code, Diagnostic, Diagnostics};
pub use format::format_source;
pub use load::{load, load_file, load_json};
pub use load_error::{JsonError, LoadError, render_plain};
pub use print::scenario_to_tl;
pub use watch::Watched;
