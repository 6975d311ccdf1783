//! Players: roles and per-player state.

#[expect(clippy::module_inception, reason = "one main type per file, named after it")]
mod player;
mod role;

pub use player::{top_speed, Player, DRIBBLE_SPEED, SPRINT_SPEED, WALK_SPEED};
pub use role::Role;
