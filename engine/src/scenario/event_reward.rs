//! Event rewards as a scenario declares them (`reward on possession_won then shot_on_target once
//! 1`): a pattern of match events, paid the first time it completes in an episode or each time.
//! The env evaluates them ([`crate::reward`]) from the match's event stream and the state after
//! each step, separately for every controller: "own" is the controller's team, regions are in its
//! team's frame (normalised units, attacking towards x = +1, as its observation).

use serde::{Deserialize, Serialize};

use super::random::Region;

/// Most steps of one sequence (`A then B then …`).
pub const MAX_EVENT_SEQUENCE: usize = 16;
/// Most events in one `any of` / `all of` group.
pub const MAX_EVENT_GROUP: usize = 32;

/// A pattern of events and how often it pays; the term's weight is the payment.
///
/// JSON: `{"sequence": [STEP, …], "once": true}` with each STEP `{"one": ATOM}`,
/// `{"any_of": [ATOM, …]}` or `{"all_of": [ATOM, …]}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EventReward {
    /// The steps that must happen in this order (one step for a plain event or group). Events
    /// in between do not matter; a step completes when its event happens after the step before.
    pub sequence: Vec<EventStep>,
    /// Pay only the first time the pattern completes in an episode; otherwise it starts over
    /// and pays each time.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub once: bool,
}

/// One step of a sequence.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum EventStep {
    /// This event.
    One(EventAtom),
    /// Any one of these events.
    AnyOf(Vec<EventAtom>),
    /// Every one of these events, in any order (each since the step before completed).
    AllOf(Vec<EventAtom>),
}

/// One event, seen from one team, optionally only when the controlled player does it.
///
/// JSON: `{"event": KIND}` plus `"team": "opponent"` and `"by_player": true` when set.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EventAtom {
    /// What happens.
    pub event: EventKind,
    /// Whose event: the controller's team (default) or the opponents.
    #[serde(default, skip_serializing_if = "EventTeam::is_own")]
    pub team: EventTeam,
    /// Only when the player doing it is the one the controller drives.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub by_player: bool,
}

/// Whose event an atom watches.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EventTeam {
    /// The controller's team.
    #[default]
    Own,
    /// The other team.
    Opponent,
}

impl EventTeam {
    fn is_own(&self) -> bool {
        *self == EventTeam::Own
    }
}

/// The events a reward can watch. Each is done by a team (the atom's [`EventTeam`]) and, where
/// it names one, by a player of that team (the scorer, the shooter, the passer, …).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum EventKind {
    /// The team scored (player: the scorer; none for an own goal of the other team).
    GoalFor,
    /// The team conceded (no player).
    GoalAgainst,
    /// A shot (player: the shooter).
    Shot,
    /// A shot heading between the posts and under the bar when struck.
    ShotOnTarget,
    /// A pass played (player: the passer).
    Pass,
    /// A pass that reached a team-mate (player: the passer).
    PassCompleted,
    /// A pass whose next touch was an opponent's (player: the passer).
    PassIntercepted,
    /// The ball won in open play from the other team (player: who has it now).
    PossessionWon,
    /// The ball lost in open play to the other team (player: who had it).
    PossessionLost,
    /// The ball put out of play over a touch line or goal line (player: the last to touch it).
    OutOfPlay,
    /// A foul committed (player: the offender).
    Foul,
    /// A yellow or red card shown to the team (player: the one booked).
    Card,
    /// A yellow card.
    YellowCard,
    /// A red card (a second yellow included).
    RedCard,
    /// Caught offside (player: the offender).
    Offside,
    /// The team's goalkeeper saved a shot of the other team (player: the keeper); see
    /// [`crate::Event::Save`].
    Save,
    /// The ball goes from outside the region to inside it during a step (no player, no team:
    /// the region is in the controller's team frame).
    BallEnters(Region),
    /// The ball is in the region after a step: happens at every such step (no player).
    BallIn(Region),
    /// A player of the team has the ball at his feet after a step: happens at every such step.
    HasBall,
    /// As `HasBall`, with the ball in the region (the controller's team frame).
    HasBallIn(Region),
}

impl EventKind {
    /// Whether the event names a player, so that `by_player` can apply.
    pub fn has_player(&self) -> bool {
        !matches!(self, EventKind::GoalAgainst | EventKind::BallEnters(_) | EventKind::BallIn(_))
    }

    /// Whether the event is about the ball only, whoever has it (no team).
    pub fn is_ball_only(&self) -> bool {
        matches!(self, EventKind::BallEnters(_) | EventKind::BallIn(_))
    }

    /// The region the event is about, if any.
    pub fn region(&self) -> Option<&Region> {
        match self {
            EventKind::BallEnters(r) | EventKind::BallIn(r) | EventKind::HasBallIn(r) => Some(r),
            _ => None,
        }
    }

    /// Whether the event is a state of the match after a step (checked once per step, after
    /// the step's match events) rather than an event of the match's stream.
    pub fn is_state(&self) -> bool {
        matches!(self, EventKind::BallEnters(_) | EventKind::BallIn(_) | EventKind::HasBall | EventKind::HasBallIn(_))
    }
}

impl EventStep {
    /// The step's events.
    pub fn atoms(&self) -> &[EventAtom] {
        match self {
            EventStep::One(a) => std::slice::from_ref(a),
            EventStep::AnyOf(atoms) | EventStep::AllOf(atoms) => atoms,
        }
    }
}

impl EventReward {
    /// Checks the pattern: 1 to [`MAX_EVENT_SEQUENCE`] steps, groups of 1 to
    /// [`MAX_EVENT_GROUP`] events, `by_player` only on the team's own events that name a player,
    /// no `opponent` on ball-only events, valid regions.
    pub(crate) fn check(&self) -> Result<(), String> {
        if self.sequence.is_empty() || self.sequence.len() > MAX_EVENT_SEQUENCE {
            return Err(format!(
                "an event reward needs 1 to {MAX_EVENT_SEQUENCE} steps in sequence, found {}",
                self.sequence.len()
            ));
        }
        for step in &self.sequence {
            let atoms = step.atoms();
            if atoms.is_empty() || atoms.len() > MAX_EVENT_GROUP {
                return Err(format!("an event group needs 1 to {MAX_EVENT_GROUP} events, found {}", atoms.len()));
            }
            for atom in atoms {
                if atom.by_player && (!atom.event.has_player() || atom.team == EventTeam::Opponent) {
                    return Err(format!(
                        "{:?} of the {:?} team names no player the controller drives: `by_player` cannot apply",
                        atom.event, atom.team
                    ));
                }
                if atom.team == EventTeam::Opponent && atom.event.is_ball_only() {
                    return Err(format!("{:?} is about the ball only: it has no team", atom.event));
                }
                if let Some(region) = atom.event.region() {
                    region.check()?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_reads_and_writes_back() {
        let text = r#"{"sequence": [
            {"one": {"event": "possession_won", "by_player": true}},
            {"any_of": [{"event": "shot_on_target"}, {"event": {"ball_enters": {"circle": {"x": 1.0, "y": 0.0, "r": 0.2}}}}]},
            {"all_of": [{"event": "foul", "team": "opponent"}, {"event": "has_ball"}]}
        ], "once": true}"#;
        let reward: EventReward = serde_json::from_str(text).unwrap();
        assert_eq!(reward.sequence.len(), 3);
        assert!(reward.once);
        assert_eq!(reward.sequence[2].atoms()[0].team, EventTeam::Opponent);
        assert!(reward.check().is_ok());
        let back: EventReward = serde_json::from_str(&serde_json::to_string(&reward).unwrap()).unwrap();
        assert_eq!(back, reward);
        assert!(serde_json::from_str::<EventReward>(r#"{"sequence": [], "twice": true}"#).is_err());
    }

    #[test]
    fn checks_name_bad_patterns() {
        let atom = |event, team, by_player| EventAtom { event, team, by_player };
        let one = |a| EventReward { sequence: vec![EventStep::One(a)], once: false };
        assert!(one(atom(EventKind::GoalAgainst, EventTeam::Own, true)).check().is_err());
        assert!(one(atom(EventKind::Shot, EventTeam::Opponent, true)).check().is_err());
        let enters = EventKind::BallEnters(Region::Circle { x: 0.0, y: 0.0, r: 0.1 });
        assert!(one(atom(enters.clone(), EventTeam::Opponent, false)).check().is_err());
        assert!(one(atom(enters, EventTeam::Own, false)).check().is_ok());
        assert!(
            one(atom(EventKind::BallIn(Region::Circle { x: 0.0, y: 0.0, r: 0.0 }), EventTeam::Own, false))
                .check()
                .is_err()
        );
        assert!(EventReward { sequence: vec![EventStep::AnyOf(vec![])], once: true }.check().is_err());
        assert!(EventReward { sequence: vec![], once: true }.check().is_err());
    }
}
