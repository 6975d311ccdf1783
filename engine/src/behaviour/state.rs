//! One player's behaviour as the match plays it: his stages and where he is in them.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::env::StickyState;
use crate::scenario::{Behaviour, Condition, Stage};

/// A stage as the match keeps it: [`Stage`] without its JSON-only field attributes (snapshots
/// are postcard, which needs every field written).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct StageState {
    pub(crate) behaviour: Behaviour,
    pub(crate) until: Option<Condition>,
}

/// A behaviour-driven player's program and progress (part of the match state, so snapshots keep
/// it).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub(crate) struct PlayerBehaviour {
    /// The stages, as the scenario gives them; empty for a player of the built-in AI.
    pub(crate) stages: Vec<StageState>,
    /// Index of the stage being played.
    pub(crate) stage: usize,
    /// The stage has finished by itself (arrived, passed, shot).
    pub(crate) done: bool,
    /// Where the player stood when the stage began, or when it finished (m, global frame):
    /// the place `hold_position` keeps and a finished `pass_to` / `dribble_to` returns to.
    pub(crate) anchor: Vec2,
    /// A script-driven player's virtual gamepad (global frame), as an agent's.
    pub(crate) sticky: StickyState,
    /// Where he last chose to meet a loose ball (m) and the in-play tick he chose it.
    pub(crate) meet: Option<(Vec2, u64)>,
}

impl PlayerBehaviour {
    /// The program `stages` for a player starting at `at` (m).
    pub(crate) fn new(stages: &[Stage], at: Vec2) -> PlayerBehaviour {
        let stages = stages.iter().map(|s| StageState { behaviour: s.behaviour.clone(), until: s.until.clone() });
        PlayerBehaviour {
            stages: stages.collect(),
            stage: 0,
            done: false,
            anchor: at,
            sticky: StickyState::default(),
            meet: None,
        }
    }

    /// The behaviour being played; `None` for a built-in-AI player.
    #[inline]
    pub(crate) fn current(&self) -> Option<&Behaviour> {
        self.stages.get(self.stage).map(|s| &s.behaviour)
    }

    /// Whether the current stage hands the player to the built-in AI, and at which θ.
    #[inline]
    pub(crate) fn builtin(&self) -> Option<Option<f32>> {
        match self.current() {
            Some(Behaviour::Builtin { difficulty }) => Some(*difficulty),
            _ => None,
        }
    }

    /// Moves on to the next stage, if there is one, from position `at` (m). Returns whether it
    /// moved.
    pub(crate) fn advance(&mut self, at: Vec2) -> bool {
        if self.stage + 1 >= self.stages.len() {
            return false;
        }
        self.stage += 1;
        self.done = false;
        self.anchor = at;
        self.sticky = StickyState::default();
        self.meet = None;
        true
    }
}
