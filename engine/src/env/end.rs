//! Episode-end conditions evaluated after every step, in GRF's order
//! (docs/grf-compatibility.md#episode-length): a goal, the ball going out of play, a change of possession
//! (each when the scenario asks), then the time limit, which truncates rather than terminates. Beyond GRF,
//! the ends drills from a restart need: a keeper's save, a keeper holding the ball, the starting restart taken.

use crate::behaviour::Scope;
use crate::game::{GameMode, Match};
use crate::geometry::Side;
use crate::geometry::coords::world_to_obs;
use crate::scenario::{EndCondition, Scenario};
use crate::stats::Event;

/// What the end conditions remember between steps.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct EndTracker {
    previous_mode: Option<GameMode>,
    previous_owner: Option<Side>,
    /// The game mode after the last step, or at the episode's start (for `restart_taken`; GRF's
    /// `previous_mode` above starts unset instead).
    last_mode: GameMode,
    /// The team whose shot is still live: struck, and touched by nobody but the shooter since.
    shot: Option<Side>,
}

impl EndTracker {
    /// Whether the scenario's conditions end the episode after a step that left `game` (score,
    /// game mode, ball owner, ball position, and the match for `When` conditions, read in the
    /// global frame), `steps` being the number of steps taken this episode.
    /// `saved`: [`EndTracker::save`] found a save in this step.
    pub(crate) fn terminated(&mut self, scenario: &Scenario, game: &Match, steps: u32, saved: bool) -> bool {
        let (score, mode, owner) = (game.score(), game.mode(), game.observed_owner().map(|o| o.0));
        let ball = world_to_obs(game.ball().xy());
        let taken = self.last_mode != GameMode::Normal && mode == GameMode::Normal;
        self.last_mode = mode;
        let extra = scenario.end_when.iter().any(|c| match c {
            EndCondition::Save => saved,
            // `in_hands` is only cleared when someone next takes the ball: a keeper about to take
            // a set piece is not holding it.
            EndCondition::KeeperHoldsBall => {
                game.in_hands && game.taker.is_none() && game.owner.is_some_and(|g| game.players[g].is_keeper())
            }
            EndCondition::RestartTaken => taken,
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

    /// Starts tracking a new episode from its first observation: `owner`, the team with the ball,
    /// and `mode`, the game mode it starts in.
    pub(crate) fn reset(&mut self, owner: Option<Side>, mode: GameMode) {
        self.previous_mode = None;
        self.previous_owner = owner;
        self.last_mode = mode;
        self.shot = None;
    }

    /// Judges whether a goalkeeper saved a shot during the last step and, if so, records
    /// [`Event::Save`] among the step's events (for `reward on save`) and returns true. A save:
    /// the shot of one team, touched by nobody else since, was next touched by the other team's
    /// keeper and did not go in. A keeper who catches it, takes it at his feet or parries it over
    /// a line saves it at once; one who only deflects it saves it once the ball is no longer
    /// heading into his goal (a fingertip that the ball beats is a goal, not a save).
    pub(crate) fn save(&mut self, game: &mut Match) -> bool {
        let keeper = |side: Side, player: usize| game.team(side).get(player).is_some_and(|p| p.is_keeper());
        let mut saved = None;
        for event in game.events() {
            match *event {
                Event::Shot { side, .. } => {
                    self.shot = Some(side);
                    saved = None;
                }
                Event::PossessionWon { side, player, .. } | Event::OutOfPlay { side, player: Some(player) }
                    if self.shot.is_some_and(|s| s != side) && keeper(side, player) =>
                {
                    saved = Some((side, player));
                    self.shot = None;
                }
                Event::Goal { .. } => {
                    saved = None;
                    self.shot = None;
                }
                Event::OutOfPlay { .. } | Event::PossessionWon { .. } | Event::Restart { .. } => self.shot = None,
                _ => {}
            }
        }
        if let Some(shooting) = self.shot {
            match game.last_touch() {
                Some((side, player)) if side != shooting && keeper(side, player) => {
                    if !crate::rules::goal::on_target(game.ball()) {
                        saved = Some((side, player));
                        self.shot = None;
                    }
                }
                Some((side, _)) if side == shooting => {}
                // Touched by an outfield defender (a block), or nobody has it any more.
                _ => self.shot = None,
            }
        }
        if let Some((side, player)) = saved {
            game.record(Event::Save { side, player });
        }
        saved.is_some()
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
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::ThrowIn, None, [0.0; 2]), 1, false));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1, false));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Corner, None, [0.0; 2]), 1, false));
    }

    #[test]
    fn possession_change_ignores_loose_balls() {
        let mut g = game();
        let s = Scenario { end_episode_on_possession_change: true, ..Scenario::default() };
        let mut t = EndTracker::default();
        t.reset(Some(Side::Left), GameMode::Normal);
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1, false));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, Some(Side::Left), [0.0; 2]), 1, false));
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1, false));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, Some(Side::Right), [0.0; 2]), 1, false));
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
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.3, 0.0]), 49, false));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.3, 0.0]), 50, false));
        assert!(t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [-0.3, 0.1]), 2, false));
    }

    #[test]
    fn when_conditions_read_the_match() {
        let mut g = game();
        let s = Scenario {
            end_when: vec![EndCondition::When(Condition::Score { side: Side::Right, op: Comparison::Ge, goals: 1 })],
            ..Scenario::default()
        };
        let mut t = EndTracker::default();
        assert!(!t.terminated(&s, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 1, false));
        g.score = [0, 1];
        assert!(t.terminated(&s, set(&mut g, [0, 1], GameMode::Normal, None, [0.0; 2]), 2, false));
        let steps = Scenario {
            end_when: vec![EndCondition::When(Condition::Steps { op: Comparison::Ge, steps: 3 })],
            ..Scenario::default()
        };
        assert!(!t.terminated(&steps, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 2, false));
        assert!(t.terminated(&steps, set(&mut g, [0, 0], GameMode::Normal, None, [0.0; 2]), 3, false));
    }

    #[test]
    fn score_ends_only_when_asked() {
        let mut g = game();
        let mut t = EndTracker::default();
        assert!(!t.terminated(&Scenario::default(), set(&mut g, [1, 0], GameMode::Normal, None, [0.0; 2]), 1, false));
        let s = Scenario { end_episode_on_score: true, ..Scenario::default() };
        assert!(t.terminated(&s, set(&mut g, [0, 1], GameMode::Normal, None, [0.0; 2]), 1, false));
    }
}
