//! Episode-end conditions evaluated after every step, in GRF's order (grf.md §7.2): a goal, the
//! ball going out of play, a change of possession (each when the scenario asks), then the time
//! limit, which truncates rather than terminates.

use crate::behaviour::Scope;
use crate::game::{GameMode, Match};
use crate::geometry::Side;
use crate::geometry::coords::world_to_obs;
use crate::scenario::{EndCondition, Scenario};

/// What the end conditions remember between steps.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct EndTracker {
    previous_mode: Option<GameMode>,
    previous_owner: Option<Side>,
}

impl EndTracker {
    /// Whether the scenario's conditions end the episode after a step that left `game` (score,
    /// game mode, ball owner, ball position, and the match for `When` conditions, read in the
    /// global frame), `steps` being the number of steps taken this episode.
    pub(crate) fn terminated(&mut self, scenario: &Scenario, game: &Match, steps: u32) -> bool {
        let (score, mode, owner) = (game.score(), game.mode(), game.owner().map(|o| o.0));
        let ball = world_to_obs(game.ball().xy());
        let extra = scenario.end_when.iter().any(|c| match c {
            EndCondition::Steps(n) => steps >= *n,
            EndCondition::BallIn(region) => region.contains(ball[0], ball[1]),
            // Scripts run in the env's hooks, which read the same step (see `Env::step`).
            EndCondition::Script { .. } => false,
            EndCondition::When(condition) => condition.holds(game, &Scope::global(steps)),
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
    use crate::player::Role;
    use crate::scenario::{Comparison, Condition, PlayerEntry};

    /// `g` after a step that left `score`, `mode`, a ball owner of team `owner` and the ball at
    /// `ball` (normalised units).
    fn set(g: &mut Match, score: [u32; 2], mode: GameMode, owner: Option<Side>, ball: [f32; 2]) -> &Match {
        g.score = score;
        g.mode = mode;
        g.owner = owner.map(|side| g.global_index(side, 0));
        g.ball.position = crate::geometry::coords::obs_to_world(ball[0], ball[1]).extend(0.11);
        g
    }

    fn game() -> Match {
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            ..Scenario::default()
        };
        Match::new(&s, 0, 1)
    }

    #[test]
    fn out_of_play_needs_normal_then_set_piece() {
        let mut g = game();
        let s = Scenario { end_episode_on_out_of_play: true, ..Scenario::default() };
        let mut t = EndTracker::default();
        // First observation non-normal does not end.
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::ThrowIn, None, [0.0; 2]), 1));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Corner, None, [0.0; 2]), 1));
    }

    #[test]
    fn possession_change_ignores_loose_balls() {
        let mut g = game();
        let s = Scenario { end_episode_on_possession_change: true, ..Scenario::default() };
        let mut t = EndTracker::default();
        t.reset(Some(Side::Left));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, Some(Side::Left), [0.0; 2]), 1));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, Some(Side::Right), [0.0; 2]), 1));
    }

    #[test]
    fn extra_conditions_end_the_episode() {
        let mut g = game();
        use crate::scenario::Region;
        let s = Scenario {
            end_when: vec![
                EndCondition::Steps(50),
                EndCondition::BallIn(Region::Rect { x: [-1.0, 0.0], y: [-0.42, 0.42] }),
            ],
            ..Scenario::default()
        };
        let mut t = EndTracker::default();
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.3, 0.0]), 49));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.3, 0.0]), 50));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [-0.3, 0.1]), 2));
    }

    #[test]
    fn when_conditions_read_the_match() {
        let mut g = game();
        let s = Scenario {
            end_when: vec![EndCondition::When(Condition::Score { side: Side::Right, op: Comparison::Ge, goals: 1 })],
            ..Scenario::default()
        };
        let mut t = EndTracker::default();
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1));
        g.score = [0, 1];
        assert!(t.terminated(&s, set(&mut g, [0, 1], GameMode::Normal, None, [0.0; 2]), 2));
        let steps = Scenario {
            end_when: vec![EndCondition::When(Condition::Steps { op: Comparison::Ge, steps: 3 })],
            ..Scenario::default()
        };
        assert!(!t.terminated(&steps, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 2));
        assert!(t.terminated(&steps, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 3));
    }

    #[test]
    fn score_ends_only_when_asked() {
        let mut g = game();
        let mut t = EndTracker::default();
        assert!(!t.terminated(&Scenario::default(), set(&mut g, [1, 0], GameMode::Normal, None, [0.0; 2]), 1));
        let s = Scenario { end_episode_on_score: true, ..Scenario::default() };
        assert!(t.terminated(&s, set(&mut g, [0, 1], GameMode::Normal, None, [0.0; 2]), 1));
    }
}
