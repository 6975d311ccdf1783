//! Players: roles and per-player state.

#[expect(clippy::module_inception, reason = "one main type per file, named after it")]
mod player;
mod role;
mod attributes;
pub mod fatigue;

pub use player::{DRIBBLE_SPEED, Player, SPRINT_SPEED, WALK_SPEED, nearest_distance, top_speed};
pub use role::Role;
pub use attributes::Attributes;
