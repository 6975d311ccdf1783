//! The AI's sliding tackle, on GRF's conditions (GRF 2.10's AI): the other team has the ball, the
//! slider is across the ball from the carrier (duel likeliness at least 0.7), the ball 200 ms ahead
//! lies just beyond a standing tackle's reach, and the carrier is running with it, so that his
//! touch is loose enough to slide in on. Slides are what bring the AI's fouls, free kicks and
//! cards (Law 12: a challenge that meets the man first, or from behind, is a foul).

use super::MatchView;
use crate::game::{GameMode, duel_likeliness};

/// The ball (200 ms ahead) must lie between these distances (m): GRF's 0.7–1.6 m, starting where
/// touchline's standing tackle stops reaching.
const SLIDE_FROM: f32 = 0.9;
const SLIDE_TO: f32 = 1.6;
/// The slider must be at least this likely to get to the ball round the carrier (GRF: 0.7).
const MIN_LIKELINESS: f32 = 0.7;
/// The carrier must run at least this fast (m/s) for his touch to be loose enough.
const RUNNING: f32 = 4.0;

/// Whether player `g` of the built-in AI slides in now.
pub(crate) fn should_slide(view: &MatchView, g: usize) -> bool {
    let p = &view.players[g];
    let Some(o) = view.owner else { return false };
    let carrier = &view.players[o];
    if carrier.side == p.side || p.is_keeper() || view.mode != GameMode::Normal {
        return false;
    }
    let ball = view.ball.xy();
    let ahead = ball + carrier.velocity * 0.2;
    let d = p.position.distance(ahead);
    (SLIDE_FROM..=SLIDE_TO).contains(&d)
        && carrier.velocity.length() >= RUNNING
        && duel_likeliness(p.position, carrier.position, ball) >= MIN_LIKELINESS
}
