//! Match statistics, folded from the engine's [`Event`] stream as it happens: goals, shots, shots
//! on target, passes attempted and completed, possession, fouls, cards, offsides and restarts, per
//! team. [`crate::Match::stats`] gives them at any moment; `touchline run --stats` prints them.

mod event;

use serde::{Deserialize, Serialize};

pub use event::{EVENTS_PER_STEP, Event, EventLog};

use crate::game::GameMode;
use crate::geometry::Side;

/// One team's counts over the match so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct TeamStats {
    /// Goals credited to the team.
    pub goals: u32,
    /// Shots taken.
    pub shots: u32,
    /// Shots whose path was heading between the posts and under the bar when struck.
    pub shots_on_target: u32,
    /// Passes played (ground, driven and lofted; set pieces included).
    pub passes: u32,
    /// Passes whose next touch was by a team-mate.
    pub passes_completed: u32,
    /// Passes whose next touch was by an opponent.
    #[serde(default)]
    pub passes_intercepted: u32,
    /// Times the team won the ball in open play from a player of the other team.
    #[serde(default)]
    pub possessions_won: u32,
    /// Times the team put the ball out of play (over a touch line or a goal line, goals aside).
    #[serde(default)]
    pub out_of_play: u32,
    /// Ticks (10 ms) of play with the ball at a player of this team's feet, or last touched by
    /// this team while loose.
    pub possession_ticks: u64,
    /// Fouls committed.
    pub fouls: u32,
    /// Yellow cards shown.
    pub yellow_cards: u32,
    /// Red cards shown (a second yellow included).
    pub red_cards: u32,
    /// Times caught offside.
    pub offsides: u32,
    /// Corner kicks awarded.
    pub corners: u32,
    /// Throw-ins awarded.
    pub throw_ins: u32,
    /// Goal kicks awarded.
    pub goal_kicks: u32,
    /// Free kicks awarded (after fouls and offsides).
    pub free_kicks: u32,
    /// Penalty kicks awarded.
    pub penalties: u32,
}

/// Both teams' statistics, `[left, right]`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct MatchStats {
    /// Per team, left first.
    pub teams: [TeamStats; 2],
}

impl MatchStats {
    /// Counts `event`.
    pub(crate) fn record(&mut self, event: Event) {
        match event {
            Event::Goal { side, .. } => self.teams[side.index()].goals += 1,
            Event::Shot { side, on_target, .. } => {
                let t = &mut self.teams[side.index()];
                t.shots += 1;
                t.shots_on_target += u32::from(on_target);
            }
            Event::Pass { side, .. } => self.teams[side.index()].passes += 1,
            Event::PassCompleted { side, .. } => self.teams[side.index()].passes_completed += 1,
            Event::PassIntercepted { side, .. } => self.teams[side.index()].passes_intercepted += 1,
            Event::PossessionWon { side, .. } => self.teams[side.index()].possessions_won += 1,
            Event::OutOfPlay { side, .. } => self.teams[side.index()].out_of_play += 1,
            Event::Foul { side, .. } => self.teams[side.index()].fouls += 1,
            Event::Advantage { .. } | Event::Save { .. } => {}
            Event::YellowCard { side, .. } => self.teams[side.index()].yellow_cards += 1,
            Event::RedCard { side, .. } => self.teams[side.index()].red_cards += 1,
            Event::Offside { side, .. } => self.teams[side.index()].offsides += 1,
            Event::Restart { side, mode } => {
                let t = &mut self.teams[side.index()];
                match mode {
                    GameMode::Corner => t.corners += 1,
                    GameMode::ThrowIn => t.throw_ins += 1,
                    GameMode::GoalKick => t.goal_kicks += 1,
                    GameMode::FreeKick => t.free_kicks += 1,
                    GameMode::Penalty => t.penalties += 1,
                    GameMode::Normal | GameMode::KickOff => {}
                }
            }
        }
    }

    /// Possession of `side` in percent of the ticks either team had the ball (50 when neither had).
    pub fn possession_percent(&self, side: Side) -> f64 {
        let [a, b] = [self.teams[0].possession_ticks, self.teams[1].possession_ticks];
        if a + b == 0 {
            return 50.0;
        }
        100.0 * self.teams[side.index()].possession_ticks as f64 / (a + b) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_fold_into_counts() {
        let mut s = MatchStats::default();
        s.record(Event::Shot { side: Side::Left, player: 9, on_target: true });
        s.record(Event::Shot { side: Side::Left, player: 9, on_target: false });
        s.record(Event::Pass { side: Side::Right, player: 3, to: Some(5) });
        s.record(Event::PassCompleted { side: Side::Right, player: 3 });
        s.record(Event::PassIntercepted { side: Side::Right, player: 3, by: 5 });
        s.record(Event::PossessionWon { side: Side::Left, player: 5, from: 2 });
        s.record(Event::OutOfPlay { side: Side::Left, player: Some(5) });
        s.record(Event::Restart { side: Side::Right, mode: GameMode::Corner });
        s.record(Event::YellowCard { side: Side::Left, player: 4 });
        assert_eq!((s.teams[0].shots, s.teams[0].shots_on_target, s.teams[0].yellow_cards), (2, 1, 1));
        assert_eq!((s.teams[1].passes, s.teams[1].passes_completed, s.teams[1].corners), (1, 1, 1));
        assert_eq!(s.teams[1].passes_intercepted, 1);
        assert_eq!((s.teams[0].possessions_won, s.teams[0].out_of_play), (1, 1));
        assert_eq!(s.possession_percent(Side::Left), 50.0);
        s.teams[0].possession_ticks = 30;
        s.teams[1].possession_ticks = 10;
        assert_eq!(s.possession_percent(Side::Left), 75.0);
    }
}
