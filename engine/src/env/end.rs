//! Episode-end conditions evaluated after every step, in GRF's order (grf.md §7.2): a goal, the
//! ball going out of play, a change of possession (each when the scenario asks), then the time
//! limit, which truncates rather than terminates.

use crate::game::GameMode;
use crate::geometry::Side;
use crate::scenario::Scenario;

/// What the end conditions remember between steps.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct EndTracker {
    previous_mode: Option<GameMode>,
    previous_owner: Option<Side>,
}

impl EndTracker {
    /// Whether the scenario's conditions end the episode after a step that left `score`, `mode`
    /// and ball owner team `owner` (None when nobody has the ball at his feet).
    pub(crate) fn terminated(
        &mut self,
        scenario: &Scenario,
        score: [u32; 2],
        mode: GameMode,
        owner: Option<Side>,
    ) -> bool {
        let scored = scenario.end_episode_on_score && (score[0] > 0 || score[1] > 0);
        let out = scenario.end_episode_on_out_of_play
            && self.previous_mode == Some(GameMode::Normal)
            && mode != GameMode::Normal;
        let lost = scenario.end_episode_on_possession_change
            && matches!((self.previous_owner, owner), (Some(a), Some(b)) if a != b);
        self.previous_mode = Some(mode);
        if owner.is_some() {
            self.previous_owner = owner;
        }
        scored || out || lost
    }

    /// Starts tracking a new episode from its first observation.
    pub(crate) fn reset(&mut self, owner: Option<Side>) {
        self.previous_mode = None;
        self.previous_owner = owner;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn out_of_play_needs_normal_then_set_piece() {
        let s = Scenario { end_episode_on_out_of_play: true, ..Scenario::default() };
        let mut t = EndTracker::default();
        // First observation non-normal does not end.
        assert!(!t.terminated(&s, [0, 0], GameMode::ThrowIn, None));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None));
        assert!(t.terminated(&s, [0, 0], GameMode::Corner, None));
    }

    #[test]
    fn possession_change_ignores_loose_balls() {
        let s = Scenario { end_episode_on_possession_change: true, ..Scenario::default() };
        let mut t = EndTracker::default();
        t.reset(Some(Side::Left));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, Some(Side::Left)));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None));
        assert!(t.terminated(&s, [0, 0], GameMode::Normal, Some(Side::Right)));
    }

    #[test]
    fn score_ends_only_when_asked() {
        let mut t = EndTracker::default();
        assert!(!t.terminated(&Scenario::default(), [1, 0], GameMode::Normal, None));
        let s = Scenario { end_episode_on_score: true, ..Scenario::default() };
        assert!(t.terminated(&s, [0, 1], GameMode::Normal, None));
    }
}
