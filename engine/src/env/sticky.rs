//! Sticky actions (docs/grf-compatibility.md#sticky-actions): a controller's held direction, sprint and
//! dribble persist until released; pass, shot and sliding buttons last one step; `builtin_ai` hands the player to the
//! built-in AI until any other action arrives.
//!
//! Pass and shot buttons work as GRF's gauge (GRF 2.10's human controller): a button pressed in
//! consecutive steps is one button held down, filling a gauge by 100 ms a step. The kick is asked
//! for when the button is released (the first step without it), or while it is still held once the
//! gauge passes 500 ms, with a power that grows with the gauge. A button pressed by a player who
//! does not have the ball is lost: GRF does not buffer it into a later kick.

use crate::game::{Action, DIRECTIONS, KickKind};

/// What one step's action asks beyond the held state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Press {
    /// Nothing this step.
    None,
    /// A pass or shot button released (or held past 500 ms): the kick and its input power in
    /// [0.01, 1] (`input_power` in this module).
    Kick(KickKind, f32),
    /// The sliding button.
    Slide,
}

/// One controller's virtual gamepad, in the global frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct StickyState {
    /// Held direction: index into [`DIRECTIONS`].
    pub direction: Option<u8>,
    /// Sprint held.
    pub sprint: bool,
    /// Dribble held.
    pub dribble: bool,
    /// The built-in AI drives the player (`builtin_ai`, v2 action set).
    pub builtin: bool,
    /// The pass or shot button held down, if any.
    #[serde(default)]
    pub held: Option<HeldButton>,
}

/// A pass or shot button held down across steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct HeldButton {
    /// Which button.
    pub kind: KickKind,
    /// How long it has been held (ms): 100 after the step it was pressed in.
    pub gauge_ms: u16,
    /// The kick was already asked for while the button stayed down (gauge past 500 ms).
    pub fired: bool,
}

/// One step of holding a button (ms): 10 ticks of 10 ms.
const STEP_MS: u16 = 100;
/// A button still held asks for its kick once the gauge passes this (ms).
const FIRE_WHILE_HELD_MS: u16 = 500;

/// GRF's input power for a kick whose button was held `gauge_ms`: the gauge factor
/// g = clamp((gauge − 60 ms) / 940 ms, 0, 1) raised to 0.7 (short pass), 0.65 (long pass), 0.55
/// (high pass) or 0.6 (shot), in [0.01, 1]. One step's press gives 0.110, 0.129, 0.176 and 0.150.
pub(crate) fn input_power(kind: KickKind, gauge_ms: u16) -> f32 {
    let g = ((f32::from(gauge_ms) - 60.0) / 940.0).clamp(0.0, 1.0);
    let exponent = match kind {
        KickKind::ShortPass => 0.7,
        KickKind::LongPass => 0.65,
        KickKind::HighPass => 0.55,
        KickKind::Shot => 0.6,
    };
    libm::powf(g, exponent).clamp(0.01, 1.0)
}

impl HeldButton {
    fn release(self) -> Press {
        if self.fired { Press::None } else { Press::Kick(self.kind, input_power(self.kind, self.gauge_ms)) }
    }
}

impl StickyState {
    /// Applies `action` (already in the global frame) and returns the press it makes this step.
    /// `on_ball`: whether the player has the ball, without which a pass or shot button is lost.
    /// Actions outside the default and v2 sets (keeper rush, pressure, team pressure, switch and
    /// their releases) change nothing yet.
    pub fn apply(&mut self, action: Action, on_ball: bool) -> Press {
        if action != Action::BuiltinAi && action != Action::Idle {
            self.builtin = false;
        }
        let button = match action {
            Action::LongPass => Some(KickKind::LongPass),
            Action::HighPass => Some(KickKind::HighPass),
            Action::ShortPass => Some(KickKind::ShortPass),
            Action::Shot => Some(KickKind::Shot),
            _ => None,
        };
        if let Some(kind) = button {
            return self.press_button(kind, on_ball);
        }
        // Any other action releases a held button.
        let released = self.held.take().map_or(Press::None, HeldButton::release);
        if let Some(i) = action.direction_index() {
            self.direction = Some(i as u8);
            return released;
        }
        match action {
            Action::Sliding if released == Press::None => return Press::Slide,
            Action::Sprint => self.sprint = true,
            Action::ReleaseSprint => self.sprint = false,
            Action::Dribble => self.dribble = true,
            Action::ReleaseDribble => self.dribble = false,
            Action::ReleaseDirection => self.direction = None,
            Action::BuiltinAi => *self = StickyState { builtin: true, ..StickyState::default() },
            _ => {}
        }
        released
    }

    /// The pass or shot button `kind` is down this step.
    fn press_button(&mut self, kind: KickKind, on_ball: bool) -> Press {
        match self.held {
            Some(held) if held.kind == kind && held.fired && on_ball => {
                // Still held after its kick, with the ball back at his feet: a new press.
                self.held = Some(HeldButton { kind, gauge_ms: STEP_MS, fired: false });
                Press::None
            }
            Some(mut held) if held.kind == kind => {
                if !held.fired && held.gauge_ms + 10 > FIRE_WHILE_HELD_MS {
                    // Held past 500 ms: the kick goes at this step's first tick.
                    held.fired = true;
                    self.held = Some(held);
                    return Press::Kick(kind, input_power(kind, held.gauge_ms + 10));
                }
                held.gauge_ms = (held.gauge_ms + STEP_MS).min(1000);
                self.held = Some(held);
                Press::None
            }
            other => {
                let released = other.map_or(Press::None, HeldButton::release);
                self.held = on_ball.then_some(HeldButton { kind, gauge_ms: STEP_MS, fired: false });
                released
            }
        }
    }

    /// The observation's `sticky_actions` (uint8, 10): the 8 directions, sprint, dribble. With
    /// `rotate` the directions are given as seen from the right team (turned by 180°).
    pub fn bits(&self, rotate: bool) -> [u8; 10] {
        let mut bits = [0u8; 10];
        if let Some(d) = self.direction {
            let d = if rotate { (d as usize + 4) % 8 } else { d as usize };
            bits[d] = 1;
        }
        bits[8] = u8::from(self.sprint);
        bits[9] = u8::from(self.dribble);
        bits
    }

    /// The held direction's action, if any.
    pub fn direction_action(&self) -> Option<Action> {
        self.direction.map(|d| DIRECTIONS[d as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sticky_semantics_follow_grf() {
        let mut s = StickyState::default();
        assert_eq!(s.apply(Action::Right, true), Press::None);
        assert_eq!(s.bits(false), [0, 0, 0, 0, 1, 0, 0, 0, 0, 0]);
        // Idle changes nothing; a pass keeps the direction and is made when the button is released.
        s.apply(Action::Idle, true);
        assert_eq!(s.apply(Action::ShortPass, true), Press::None);
        assert_eq!(
            s.apply(Action::Idle, true),
            Press::Kick(KickKind::ShortPass, input_power(KickKind::ShortPass, 100))
        );
        assert_eq!(s.direction_action(), Some(Action::Right));
        s.apply(Action::Sprint, true);
        s.apply(Action::Dribble, true);
        assert_eq!(s.bits(false)[8..], [1, 1]);
        // Another direction replaces the old one.
        s.apply(Action::TopLeft, true);
        assert_eq!(s.bits(false)[..8], [0, 1, 0, 0, 0, 0, 0, 0]);
        // Seen from the right team, top_left is bottom_right.
        assert_eq!(s.bits(true)[..8], [0, 0, 0, 0, 0, 1, 0, 0]);
        s.apply(Action::ReleaseDirection, true);
        s.apply(Action::ReleaseSprint, true);
        s.apply(Action::ReleaseDribble, true);
        assert_eq!(s.bits(false), [0; 10]);
    }

    #[test]
    fn builtin_ai_clears_everything_until_another_action() {
        let mut s = StickyState::default();
        s.apply(Action::Left, false);
        s.apply(Action::Sprint, false);
        s.apply(Action::BuiltinAi, false);
        assert!(s.builtin && s.direction.is_none() && !s.sprint);
        s.apply(Action::Idle, false);
        assert!(s.builtin);
        s.apply(Action::Bottom, false);
        assert!(!s.builtin);
    }

    #[test]
    fn one_step_powers_are_grfs() {
        let p = |k| input_power(k, 100);
        assert!((p(KickKind::ShortPass) - 0.110).abs() < 0.001);
        assert!((p(KickKind::LongPass) - 0.129).abs() < 0.001);
        assert!((p(KickKind::HighPass) - 0.176).abs() < 0.001);
        assert!((p(KickKind::Shot) - 0.150).abs() < 0.001);
    }

    #[test]
    fn a_held_button_fires_once_past_500_ms_and_not_again_on_release() {
        let mut s = StickyState::default();
        for _ in 0..5 {
            assert_eq!(s.apply(Action::Shot, true), Press::None);
        }
        // The sixth step of holding: the gauge passes 500 ms at its first tick.
        assert_eq!(s.apply(Action::Shot, true), Press::Kick(KickKind::Shot, input_power(KickKind::Shot, 510)));
        assert_eq!(s.apply(Action::Shot, false), Press::None);
        assert_eq!(s.apply(Action::Idle, false), Press::None);
        assert!(s.held.is_none());
        // Held on past its kick until the ball is back at his feet: that is a new press.
        for _ in 0..6 {
            s.apply(Action::Shot, false);
        }
        assert_eq!(s.apply(Action::Shot, true), Press::None);
        assert_eq!(s.held.map(|h| (h.gauge_ms, h.fired)), Some((100, false)));
    }

    #[test]
    fn a_button_pressed_without_the_ball_is_lost() {
        let mut s = StickyState::default();
        assert_eq!(s.apply(Action::LongPass, false), Press::None);
        assert_eq!(s.apply(Action::Idle, true), Press::None);
        // Another button releases the first one's kick and starts its own hold.
        s.apply(Action::ShortPass, true);
        assert_eq!(
            s.apply(Action::Shot, true),
            Press::Kick(KickKind::ShortPass, input_power(KickKind::ShortPass, 100))
        );
        assert_eq!(s.held.map(|h| h.kind), Some(KickKind::Shot));
    }
}
