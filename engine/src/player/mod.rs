//! Players: roles and per-player state.

mod player;
mod role;

pub use player::{top_speed, Player, DRIBBLE_SPEED, SPRINT_SPEED, WALK_SPEED};
pub use role::Role;
