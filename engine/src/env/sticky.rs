//! Sticky actions (grf.md §5.3): a controller's held direction, sprint and dribble persist until
//! released; pass, shot and sliding buttons last one step; `builtin_ai` hands the player to the
//! built-in AI until any other action arrives.

use crate::game::{Action, DIRECTIONS, KickKind};

/// What one step's action asks beyond the held state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Press {
    /// Nothing this step.
    None,
    /// A pass or shot button.
    Kick(KickKind),
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
}

impl StickyState {
    /// Applies `action` (already in the global frame) and returns the one-step press it makes.
    /// Actions outside the default and v2 sets (keeper rush, pressure, team pressure, switch and
    /// their releases) change nothing yet.
    pub fn apply(&mut self, action: Action) -> Press {
        if action != Action::BuiltinAi && action != Action::Idle {
            self.builtin = false;
        }
        if let Some(i) = action.direction_index() {
            self.direction = Some(i as u8);
            return Press::None;
        }
        match action {
            Action::LongPass => Press::Kick(KickKind::LongPass),
            Action::HighPass => Press::Kick(KickKind::HighPass),
            Action::ShortPass => Press::Kick(KickKind::ShortPass),
            Action::Shot => Press::Kick(KickKind::Shot),
            Action::Sliding => Press::Slide,
            Action::Sprint => {
                self.sprint = true;
                Press::None
            }
            Action::ReleaseSprint => {
                self.sprint = false;
                Press::None
            }
            Action::Dribble => {
                self.dribble = true;
                Press::None
            }
            Action::ReleaseDribble => {
                self.dribble = false;
                Press::None
            }
            Action::ReleaseDirection => {
                self.direction = None;
                Press::None
            }
            Action::BuiltinAi => {
                *self = StickyState { builtin: true, ..StickyState::default() };
                Press::None
            }
            _ => Press::None,
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
        assert_eq!(s.apply(Action::Right), Press::None);
        assert_eq!(s.bits(false), [0, 0, 0, 0, 1, 0, 0, 0, 0, 0]);
        // Idle changes nothing; a pass is a one-step press and keeps the direction.
        s.apply(Action::Idle);
        assert_eq!(s.apply(Action::ShortPass), Press::Kick(KickKind::ShortPass));
        assert_eq!(s.direction_action(), Some(Action::Right));
        s.apply(Action::Sprint);
        s.apply(Action::Dribble);
        assert_eq!(s.bits(false)[8..], [1, 1]);
        // Another direction replaces the old one.
        s.apply(Action::TopLeft);
        assert_eq!(s.bits(false)[..8], [0, 1, 0, 0, 0, 0, 0, 0]);
        // Seen from the right team, top_left is bottom_right.
        assert_eq!(s.bits(true)[..8], [0, 0, 0, 0, 0, 1, 0, 0]);
        s.apply(Action::ReleaseDirection);
        s.apply(Action::ReleaseSprint);
        s.apply(Action::ReleaseDribble);
        assert_eq!(s.bits(false), [0; 10]);
    }

    #[test]
    fn builtin_ai_clears_everything_until_another_action() {
        let mut s = StickyState::default();
        s.apply(Action::Left);
        s.apply(Action::Sprint);
        s.apply(Action::BuiltinAi);
        assert!(s.builtin && s.direction.is_none() && !s.sprint);
        s.apply(Action::Idle);
        assert!(s.builtin);
        s.apply(Action::Bottom);
        assert!(!s.builtin);
    }
}
