//! The engine's event stream: what happened this step, in order (goals, shots, passes and their
//! outcome, possession won, the ball going out, fouls, cards, offsides, restarts).
//! [`crate::stats::MatchStats`] is folded from it and the env's event rewards read it. Events are
//! observations: recording one never draws from the random stream or changes the play.

use serde::{Deserialize, Serialize};

use crate::geometry::Side;

/// Most events one env step keeps; later ones still count in the statistics but are not listed.
/// Ten ticks rarely hold more than a handful (a pass, a touch, a whistle).
pub const EVENTS_PER_STEP: usize = 32;

/// Something the referee or the statistician saw. `side` is the team that did it (the passer, the
/// shooter, the offender, the team awarded the restart for restarts).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum Event {
    /// A goal credited to `side` (own goals count for the other team, Law 10).
    Goal {
        /// The team credited.
        side: Side,
        /// The scorer (index in his team): the last player of `side` to touch the ball; `None`
        /// for an own goal or a ball nobody touched.
        player: Option<usize>,
    },
    /// A shot by `player` of `side`; `on_target` when its path crosses the goal line between the
    /// posts and under the bar.
    Shot {
        /// The shooting team.
        side: Side,
        /// The shooter (index in his team).
        player: usize,
        /// Heading into the goal when struck.
        on_target: bool,
    },
    /// A pass played by `player` of `side`.
    Pass {
        /// The passing team.
        side: Side,
        /// The passer (index in his team).
        player: usize,
        /// The team-mate it is meant for (index in his team); `None` when he has nobody to pass
        /// to. An agent's team hands control to him (GRF selects a pass's target player).
        #[serde(default)]
        to: Option<usize>,
    },
    /// The last pass of `side` reached a team-mate (onside).
    PassCompleted {
        /// The passing team.
        side: Side,
        /// The passer (index in his team).
        player: usize,
    },
    /// The last pass of `side` was next touched by an opponent (a tackle, a trap, a deflection
    /// or a keeper's save).
    PassIntercepted {
        /// The passing team.
        side: Side,
        /// The passer (index in his team).
        player: usize,
        /// The opponent who touched it (index in his team).
        by: usize,
    },
    /// `player` of `side` took the ball at his feet in open play when a player of the other team
    /// was the last to have it there (a ball won by a tackle, an interception or a loose ball).
    /// Set pieces and kickoffs hand the ball over without this event.
    PossessionWon {
        /// The team that won the ball.
        side: Side,
        /// The player who has it now (index in his team).
        player: usize,
        /// The opponent who had it last (index in his team).
        from: usize,
    },
    /// The ball went wholly over a touch line or a goal line outside the goal (Law 9), last
    /// touched by `side` (the team the restart goes against).
    OutOfPlay {
        /// The team that put it out.
        side: Side,
        /// The last player to touch it (index in his team); `None` when nobody had.
        player: Option<usize>,
    },
    /// A foul by `player` of `side` (Law 12).
    Foul {
        /// The offending team.
        side: Side,
        /// The offender (index in his team).
        player: usize,
        /// Inside the offender's own penalty area: a penalty kick.
        penalty: bool,
    },
    /// The referee let play go on after a foul because the fouled team kept the ball (advantage).
    Advantage {
        /// The team that benefited.
        side: Side,
    },
    /// A yellow card (caution) for `player` of `side`.
    YellowCard {
        /// The cautioned player's team.
        side: Side,
        /// The player (index in his team).
        player: usize,
    },
    /// A red card (sending-off, also after a second yellow) for `player` of `side`.
    RedCard {
        /// The player's team.
        side: Side,
        /// The player (index in his team).
        player: usize,
    },
    /// `player` of `side` was penalised for being offside (Law 11).
    Offside {
        /// The offending team.
        side: Side,
        /// The offender (index in his team).
        player: usize,
    },
    /// A goalkeeper of `side` saved a shot of the other team: the shot, touched by nobody else
    /// since, was caught, taken at his feet, parried over a line, or deflected so that it no
    /// longer heads into the goal. Judged by the env after each step (see `Env::step`), so it
    /// comes last among a step's events.
    Save {
        /// The keeper's team.
        side: Side,
        /// The keeper (index in his team).
        player: usize,
    },
    /// A restart awarded to `side` (kickoffs after goals and half-time included).
    Restart {
        /// The team taking it.
        side: Side,
        /// Which restart.
        mode: crate::game::GameMode,
    },
}

/// This step's events, in a buffer sized once (no allocation while playing).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct EventLog {
    events: Vec<Event>,
}

impl Default for EventLog {
    fn default() -> EventLog {
        EventLog { events: Vec::with_capacity(EVENTS_PER_STEP) }
    }
}

impl EventLog {
    /// Records `event` if there is room (see [`EVENTS_PER_STEP`]).
    pub(crate) fn push(&mut self, event: Event) {
        if self.events.len() < EVENTS_PER_STEP {
            self.events.push(event);
        }
    }

    /// Forgets the events (the env calls this at the start of every step).
    pub(crate) fn clear(&mut self) {
        self.events.clear();
    }

    /// The events in the order they happened.
    pub fn as_slice(&self) -> &[Event] {
        &self.events
    }
}
