//! One module per subcommand: its clap arguments and its `run` function.

pub(crate) mod run;
pub(crate) mod scenarios;
pub(crate) mod stats;
