//! Players: roles and per-player state.

mod attributes;
pub mod fatigue;
#[expect(clippy::module_inception, reason = "one main type per file, named after it")]
mod player;
mod role;

pub use attributes::{Attributes, difficulty_scale};
pub use player::{DRIBBLE_SPEED, Player, SPRINT_SPEED, WALK_SPEED, nearest_distance, top_speed};
pub use role::Role;

/// Most players a team may field (Law 3).
pub const MAX_PLAYERS_PER_TEAM: usize = 11;
