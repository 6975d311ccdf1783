//! Event rewards ([`EventReward`], `reward on …` in the language): each step, every controller's
//! terms read the match's event stream ([`crate::Match::events`]) in order, then the state events
//! (the ball entering or in a region, a player with the ball), and pay a term's weight when its
//! pattern completes. The bookkeeping per controller and term is one [`EventProgress`], kept in the
//! env's state (so snapshots carry it) and sized when the env is built: stepping allocates nothing.

use serde::{Deserialize, Serialize};

use crate::geometry::Side;
use crate::obs::RawObservation;
use crate::scenario::{EventAtom, EventKind, EventReward, EventStep, EventTeam, RewardKind, Scenario};
use crate::stats::Event;

/// How far one controller has come through one event term in this episode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct EventProgress {
    /// The sequence step waited for (0-based).
    step: u8,
    /// Events of the current `all of` step already seen (bit k: its k-th event).
    seen: u32,
    /// A `once` term that has paid: it is finished for the episode.
    done: bool,
}

impl EventProgress {
    /// Whether a `once` term has paid this episode.
    pub fn done(&self) -> bool {
        self.done
    }

    /// The sequence step the term waits for (0-based).
    pub fn step(&self) -> usize {
        usize::from(self.step)
    }

    /// Whether this progress can belong to a term of `steps` sequence steps (a restored
    /// snapshot's, checked before stepping indexes the sequence with it).
    pub(crate) fn fits(&self, steps: usize) -> bool {
        self.step() < steps.max(1)
    }
}

/// One controller's point of view after a step: its team, the player it drives, its observation
/// (team frame) and where the ball was (team frame, normalised) before the step.
#[derive(Clone, Copy, Debug)]
pub struct Viewpoint<'a> {
    /// The controller's team.
    pub side: Side,
    /// The player it drives (index in its team).
    pub player: usize,
    /// Its observation after the step.
    pub observation: &'a RawObservation,
    /// The ball's (x, y) in its team frame before the step.
    pub previous_ball: [f32; 2],
}

/// The event terms of a scenario, with their weights, in the order declared.
#[derive(Clone, Debug, Default)]
pub struct EventRewards {
    terms: Vec<(EventReward, f32)>,
}

impl EventRewards {
    /// The scenario's event terms (the other terms are paid elsewhere).
    pub fn new(scenario: &Scenario) -> EventRewards {
        let terms = scenario
            .rewards
            .iter()
            .filter_map(|t| match &t.reward {
                RewardKind::Event(reward) => Some((reward.clone(), t.weight)),
                _ => None,
            })
            .collect();
        EventRewards { terms }
    }

    /// Number of event terms (the length of a controller's progress slice).
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Sequence steps of term `k` (0 past the last term).
    pub(crate) fn steps(&self, k: usize) -> usize {
        self.terms.get(k).map_or(0, |(t, _)| t.sequence.len())
    }

    /// Whether the scenario has no event term.
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The reward one controller earns for a step whose match events are `events`, advancing
    /// its `progress` (one per term, in order).
    pub fn pay(&self, progress: &mut [EventProgress], events: &[Event], view: &Viewpoint<'_>) -> f32 {
        let mut paid = 0.0;
        for ((reward, value), p) in self.terms.iter().zip(progress) {
            for event in events {
                if p.done {
                    break;
                }
                if advance(reward, p, |atom| happened(atom, event, view)) {
                    paid += value;
                }
            }
            // The state after the step comes after everything that happened during it.
            if !p.done && advance(reward, p, |atom| holds(atom, view)) {
                paid += value;
            }
        }
        paid
    }
}

/// Advances `p` by one occurrence (`matches` says which events of the awaited step it is);
/// true when it completed the whole pattern, which then starts over or, if `once`, is done.
fn advance(reward: &EventReward, p: &mut EventProgress, matches: impl Fn(&EventAtom) -> bool) -> bool {
    let step = &reward.sequence[usize::from(p.step)];
    let complete = match step {
        EventStep::One(atom) => matches(atom),
        EventStep::AnyOf(atoms) => atoms.iter().any(matches),
        EventStep::AllOf(atoms) => {
            for (k, atom) in atoms.iter().enumerate() {
                if matches(atom) {
                    p.seen |= 1 << k;
                }
            }
            // Checked at build: at most 32 atoms.
            let all = if atoms.len() >= 32 { u32::MAX } else { (1u32 << atoms.len()) - 1 };
            p.seen == all
        }
    };
    if !complete {
        return false;
    }
    p.seen = 0;
    p.step += 1;
    if usize::from(p.step) < reward.sequence.len() {
        return false;
    }
    p.step = 0;
    p.done = reward.once;
    true
}

/// Whether match event `event` is the atom's event, for the atom's team and player.
fn happened(atom: &EventAtom, event: &Event, view: &Viewpoint<'_>) -> bool {
    // The team that did it and the player who did it, as the atom's kind reads the event.
    let (team, player): (Side, Option<usize>) = match (&atom.event, *event) {
        (EventKind::GoalFor, Event::Goal { side, player }) => (side, player),
        (EventKind::GoalAgainst, Event::Goal { side, .. }) => (side.opponent(), None),
        (EventKind::Shot, Event::Shot { side, player, .. }) => (side, Some(player)),
        (EventKind::ShotOnTarget, Event::Shot { side, player, on_target: true }) => (side, Some(player)),
        (EventKind::Pass, Event::Pass { side, player, .. }) => (side, Some(player)),
        (EventKind::PassCompleted, Event::PassCompleted { side, player }) => (side, Some(player)),
        (EventKind::PassIntercepted, Event::PassIntercepted { side, player, .. }) => (side, Some(player)),
        (EventKind::PossessionWon, Event::PossessionWon { side, player, .. }) => (side, Some(player)),
        (EventKind::PossessionLost, Event::PossessionWon { side, from, .. }) => (side.opponent(), Some(from)),
        (EventKind::OutOfPlay, Event::OutOfPlay { side, player }) => (side, player),
        (EventKind::Foul, Event::Foul { side, player, .. }) => (side, Some(player)),
        (EventKind::Card | EventKind::YellowCard, Event::YellowCard { side, player }) => (side, Some(player)),
        (EventKind::Card | EventKind::RedCard, Event::RedCard { side, player }) => (side, Some(player)),
        (EventKind::Offside, Event::Offside { side, player }) => (side, Some(player)),
        (EventKind::Save, Event::Save { side, player }) => (side, Some(player)),
        _ => return false,
    };
    team == watched(atom, view.side) && (!atom.by_player || player == Some(view.player))
}

/// Whether the state event `atom` holds after the step.
fn holds(atom: &EventAtom, view: &Viewpoint<'_>) -> bool {
    let obs = view.observation;
    let [x, y, _] = obs.ball;
    let has_ball = || {
        // The observation's teams are in the controller's frame: 0 is its own.
        let team = if watched(atom, view.side) == view.side { 0 } else { 1 };
        obs.ball_owned_team == team && (!atom.by_player || obs.ball_owned_player == obs.active)
    };
    match &atom.event {
        EventKind::BallIn(region) => region.contains(x, y),
        EventKind::BallEnters(region) => {
            region.contains(x, y) && !region.contains(view.previous_ball[0], view.previous_ball[1])
        }
        EventKind::HasBall => has_ball(),
        EventKind::HasBallIn(region) => has_ball() && region.contains(x, y),
        _ => false,
    }
}

/// The team whose events the atom watches, for a controller of `side`.
fn watched(atom: &EventAtom, side: Side) -> Side {
    match atom.team {
        EventTeam::Own => side,
        EventTeam::Opponent => side.opponent(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{Region, RewardTerm};

    fn atom(event: EventKind) -> EventAtom {
        EventAtom { event, team: EventTeam::Own, by_player: false }
    }

    fn rewards(terms: Vec<(EventReward, f32)>) -> EventRewards {
        let scenario = Scenario {
            rewards: terms
                .into_iter()
                .map(|(r, weight)| RewardTerm { reward: RewardKind::Event(r), weight })
                .chain([RewardTerm::scoring()])
                .collect(),
            ..Scenario::default()
        };
        EventRewards::new(&scenario)
    }

    fn view(obs: &RawObservation) -> Viewpoint<'_> {
        Viewpoint { side: Side::Left, player: 2, observation: obs, previous_ball: [0.0, 0.0] }
    }

    const SHOT: Event = Event::Shot { side: Side::Left, player: 2, on_target: true };
    const WON: Event = Event::PossessionWon { side: Side::Left, player: 3, from: 1 };
    const LOST: Event = Event::PossessionWon { side: Side::Right, player: 1, from: 2 };

    #[test]
    fn once_pays_the_first_time_and_each_time_every_time() {
        let shot = |once| EventReward { sequence: vec![EventStep::One(atom(EventKind::Shot))], once };
        let r = rewards(vec![(shot(true), 0.5), (shot(false), 0.25)]);
        assert_eq!(r.len(), 2);
        let obs = RawObservation::default();
        let mut p = vec![EventProgress::default(); 2];
        assert_eq!(r.pay(&mut p, &[SHOT, SHOT], &view(&obs)), 0.5 + 0.25 + 0.25);
        assert_eq!(r.pay(&mut p, &[SHOT], &view(&obs)), 0.25);
        assert!(p[0].done());
    }

    #[test]
    fn sequences_pay_in_order_only() {
        let seq = EventReward {
            sequence: vec![EventStep::One(atom(EventKind::PossessionWon)), EventStep::One(atom(EventKind::Shot))],
            once: false,
        };
        let r = rewards(vec![(seq, 1.0)]);
        let obs = RawObservation::default();
        let mut p = vec![EventProgress::default()];
        assert_eq!(r.pay(&mut p, &[SHOT, WON], &view(&obs)), 0.0);
        assert_eq!(p[0].step(), 1);
        assert_eq!(r.pay(&mut p, &[LOST], &view(&obs)), 0.0);
        assert_eq!(r.pay(&mut p, &[SHOT, SHOT], &view(&obs)), 1.0);
        assert_eq!(p[0].step(), 0);
    }

    #[test]
    fn groups_and_scopes() {
        let mut by_player = atom(EventKind::Shot);
        by_player.by_player = true;
        let mut lost = atom(EventKind::PossessionLost);
        lost.by_player = true;
        let any = EventReward { sequence: vec![EventStep::AnyOf(vec![by_player, atom(EventKind::Foul)])], once: false };
        let all =
            EventReward { sequence: vec![EventStep::AllOf(vec![atom(EventKind::PossessionWon), lost])], once: true };
        let r = rewards(vec![(any, 1.0), (all, 10.0)]);
        let obs = RawObservation::default();
        let mut p = vec![EventProgress::default(); 2];
        // Another player's shot is not the controlled player's.
        let other = Event::Shot { side: Side::Left, player: 7, on_target: false };
        assert_eq!(r.pay(&mut p, &[other], &view(&obs)), 0.0);
        assert_eq!(r.pay(&mut p, &[SHOT, WON], &view(&obs)), 1.0);
        // The controlled player (2) lost the ball: both parts of `all of` seen.
        assert_eq!(r.pay(&mut p, &[LOST], &view(&obs)), 10.0);
        assert_eq!(r.pay(&mut p, &[WON, LOST], &view(&obs)), 0.0);
    }

    #[test]
    fn state_events_read_the_observation() {
        let box_ = Region::Rect { x: [0.7, 1.0], y: [-0.2, 0.2] };
        let enters =
            EventReward { sequence: vec![EventStep::One(atom(EventKind::BallEnters(box_.clone())))], once: false };
        let mut mine = atom(EventKind::HasBallIn(box_));
        mine.by_player = true;
        let has = EventReward { sequence: vec![EventStep::One(mine)], once: false };
        let r = rewards(vec![(enters, 1.0), (has, 0.5)]);
        let mut obs = RawObservation {
            ball: [0.8, 0.0, 0.1],
            ball_owned_team: 0,
            ball_owned_player: 2,
            active: 2,
            ..RawObservation::default()
        };
        let mut p = vec![EventProgress::default(); 2];
        assert_eq!(r.pay(&mut p, &[], &view(&obs)), 1.5);
        // Still inside: no new entry, but the state pays again.
        let inside = Viewpoint { previous_ball: [0.8, 0.0], ..view(&obs) };
        assert_eq!(r.pay(&mut p, &[], &inside), 0.5);
        obs.ball_owned_player = 4;
        assert_eq!(r.pay(&mut p, &[], &Viewpoint { previous_ball: [0.8, 0.0], ..view(&obs) }), 0.0);
    }
}
