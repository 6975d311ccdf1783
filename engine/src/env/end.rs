//! Episode-end conditions evaluated after every step, in GRF's order (grf.md §7.2): a goal, the
//! ball going out of play, a change of possession (each when the scenario asks), then the time
//! limit, which truncates rather than terminates.

use crate::game::GameMode;
use crate::geometry::Side;
use crate::scenario::{EndCondition, Scenario};

/// What the end conditions remember between steps.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct EndTracker {
    previous_mode: Option<GameMode>,
    previous_owner: Option<Side>,
}

impl EndTracker {
    /// Whether the scenario's conditions end the episode after a step that left `score`, `mode`
    /// and ball owner team `owner` (None when nobody has the ball at his feet).
    /// `steps` is the number of steps taken this episode and `ball` the ball's position in
    /// normalised global units, for the scenario's extra conditions ([`EndCondition`]).
    pub(crate) fn terminated(
        &mut self,
        scenario: &Scenario,
        score: [u32; 2],
        mode: GameMode,
        owner: Option<Side>,
        steps: u32,
        ball: [f32; 2],
    ) -> bool {
        let extra = scenario.end_when.iter().any(|c| match c {
            EndCondition::Steps(n) => steps >= *n,
            EndCondition::BallIn(region) => region.contains(ball[0], ball[1]),
            // Scripts run in the env's hooks, which read the same step (see `Env::step`).
            EndCondition::Script { .. } => false,
            // Refused by `Scenario::validate` until the condition evaluator lands (issue 9).
            EndCondition::When(_) => false,
        });
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
        scored || out || lost || extra
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
        assert!(!t.terminated(&s, [0, 0], GameMode::ThrowIn, None, 1, [0.0; 2]));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None, 1, [0.0; 2]));
        assert!(t.terminated(&s, [0, 0], GameMode::Corner, None, 1, [0.0; 2]));
    }

    #[test]
    fn possession_change_ignores_loose_balls() {
        let s = Scenario { end_episode_on_possession_change: true, ..Scenario::default() };
        let mut t = EndTracker::default();
        t.reset(Some(Side::Left));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None, 1, [0.0; 2]));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, Some(Side::Left), 1, [0.0; 2]));
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None, 1, [0.0; 2]));
        assert!(t.terminated(&s, [0, 0], GameMode::Normal, Some(Side::Right), 1, [0.0; 2]));
    }

    #[test]
    fn extra_conditions_end_the_episode() {
        use crate::scenario::Region;
        let s = Scenario {
            end_when: vec![
                EndCondition::Steps(50),
                EndCondition::BallIn(Region::Rect { x: [-1.0, 0.0], y: [-0.42, 0.42] }),
            ],
            ..Scenario::default()
        };
        let mut t = EndTracker::default();
        assert!(!t.terminated(&s, [0, 0], GameMode::Normal, None, 49, [0.3, 0.0]));
        assert!(t.terminated(&s, [0, 0], GameMode::Normal, None, 50, [0.3, 0.0]));
        assert!(t.terminated(&s, [0, 0], GameMode::Normal, None, 2, [-0.3, 0.1]));
    }

    #[test]
    fn score_ends_only_when_asked() {
        let mut t = EndTracker::default();
        assert!(!t.terminated(&Scenario::default(), [1, 0], GameMode::Normal, None, 1, [0.0; 2]));
        let s = Scenario { end_episode_on_score: true, ..Scenario::default() };
        assert!(t.terminated(&s, [0, 1], GameMode::Normal, None, 1, [0.0; 2]));
    }
}
