//! Game modes, numbered as GRF's `e_GameMode` (docs/grf-compatibility.md#game-modes).

use serde::{Deserialize, Serialize};

/// The pending restart while the ball is dead or waiting for the taker; `Normal` in open play.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[repr(u8)]
pub enum GameMode {
    /// Open play.
    #[default]
    Normal = 0,
    /// Kickoff (Law 8).
    KickOff = 1,
    /// Goal kick (Law 16).
    GoalKick = 2,
    /// Free kick (Law 13).
    FreeKick = 3,
    /// Corner kick (Law 17).
    Corner = 4,
    /// Throw-in (Law 15).
    ThrowIn = 5,
    /// Penalty kick (Law 14).
    Penalty = 6,
}

impl GameMode {
    /// All modes in numeric order.
    pub const ALL: [GameMode; 7] = [
        GameMode::Normal,
        GameMode::KickOff,
        GameMode::GoalKick,
        GameMode::FreeKick,
        GameMode::Corner,
        GameMode::ThrowIn,
        GameMode::Penalty,
    ];

    /// GRF's name, e.g. `"ThrowIn"`.
    pub fn name(self) -> &'static str {
        match self {
            GameMode::Normal => "Normal",
            GameMode::KickOff => "KickOff",
            GameMode::GoalKick => "GoalKick",
            GameMode::FreeKick => "FreeKick",
            GameMode::Corner => "Corner",
            GameMode::ThrowIn => "ThrowIn",
            GameMode::Penalty => "Penalty",
        }
    }
}
