//! [`HumanController`]: turns the buttons a person holds into one action per env step.
//!
//! The engine takes one action per controlled player per step, with GRF's sticky semantics
//! (`engine/src/env/sticky.rs`): a direction, sprint and dribble stay held until released; a pass
//! or shot button pressed in consecutive steps is one button held down, filling the kick gauge,
//! and the kick is made when another action arrives. A person, though, presses several keys at
//! once. The controller keeps what it has already told the engine and sends one change per step,
//! in the order that keeps a kick aimed: a new direction before a new kick, and nothing but the
//! kick while its button stays down (any other action would release it early).

use touchline_engine::Action;

/// A button of the play page (keyboard or gamepad), named as the protocol sends it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Button {
    Up,
    Down,
    Left,
    Right,
    Sprint,
    Dribble,
    ShortPass,
    LongPass,
    HighPass,
    Shot,
    Sliding,
}

impl Button {
    /// Every button, in protocol order.
    pub(crate) const ALL: [Button; 11] = [
        Button::Up,
        Button::Down,
        Button::Left,
        Button::Right,
        Button::Sprint,
        Button::Dribble,
        Button::ShortPass,
        Button::LongPass,
        Button::HighPass,
        Button::Shot,
        Button::Sliding,
    ];

    /// The protocol's name of the button.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Button::Up => "up",
            Button::Down => "down",
            Button::Left => "left",
            Button::Right => "right",
            Button::Sprint => "sprint",
            Button::Dribble => "dribble",
            Button::ShortPass => "short_pass",
            Button::LongPass => "long_pass",
            Button::HighPass => "high_pass",
            Button::Shot => "shot",
            Button::Sliding => "sliding",
        }
    }

    /// The button called `name` in the protocol.
    pub(crate) fn from_name(name: &str) -> Option<Button> {
        Button::ALL.into_iter().find(|b| b.name() == name)
    }

    /// The kick action of a pass or shot button.
    fn kick(self) -> Option<Action> {
        match self {
            Button::ShortPass => Some(Action::ShortPass),
            Button::LongPass => Some(Action::LongPass),
            Button::HighPass => Some(Action::HighPass),
            Button::Shot => Some(Action::Shot),
            _ => None,
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// The eight directions by screen offset `(dx + 1) + 3 (dy + 1)`, y down the screen as the
/// engine's global frame; the centre is no direction.
const DIRECTION_BY_OFFSET: [Option<Action>; 9] = [
    Some(Action::TopLeft),
    Some(Action::Top),
    Some(Action::TopRight),
    Some(Action::Left),
    None,
    Some(Action::Right),
    Some(Action::BottomLeft),
    Some(Action::Bottom),
    Some(Action::BottomRight),
];

/// One person's buttons and what the engine has been told of them.
#[derive(Clone, Debug, Default)]
pub(crate) struct HumanController {
    /// Buttons held now.
    held: [bool; Button::ALL.len()],
    /// Buttons pressed since the last step: a tap shorter than a step still counts once.
    latched: [bool; Button::ALL.len()],
    /// Direction last sent, in the global (screen) frame.
    sent_direction: Option<Action>,
    sent_sprint: bool,
    sent_dribble: bool,
    /// The pass or shot button sent last step, whose gauge fills while it stays down.
    kicking: Option<Button>,
    /// The player is handed to the built-in AI.
    builtin: bool,
}

impl HumanController {
    /// Sets the buttons held now; `pressed` were pressed (and maybe already released) since the
    /// last message. A newly held button counts as pressed.
    pub(crate) fn set_buttons(&mut self, held: &[Button], pressed: &[Button]) {
        let mut now = [false; Button::ALL.len()];
        for b in held {
            now[b.index()] = true;
        }
        for (i, &down) in now.iter().enumerate() {
            self.latched[i] |= down && !self.held[i];
        }
        for b in pressed {
            self.latched[b.index()] = true;
        }
        self.held = now;
    }

    /// Hands the player to the built-in AI, or takes him back.
    pub(crate) fn toggle_builtin(&mut self) {
        self.builtin = !self.builtin;
        // `builtin_ai` clears the engine's sticky state; taking the player back starts from it.
        self.sent_direction = None;
        self.sent_sprint = false;
        self.sent_dribble = false;
        self.kicking = None;
    }

    /// The player is handed to the built-in AI.
    pub(crate) fn builtin(&self) -> bool {
        self.builtin
    }

    /// Forgets the sticky state the engine was told of (a new episode starts with none); the
    /// buttons held stay held.
    pub(crate) fn new_episode(&mut self) {
        let held = self.held;
        *self = HumanController { held, builtin: self.builtin, ..HumanController::default() };
    }

    fn down(&self, b: Button) -> bool {
        self.held[b.index()] || self.latched[b.index()]
    }

    /// The direction the buttons ask for (global frame): opposite buttons cancel.
    fn direction(&self) -> Option<Action> {
        let axis = |minus: Button, plus: Button| i32::from(self.down(plus)) - i32::from(self.down(minus));
        let (dx, dy) = (axis(Button::Left, Button::Right), axis(Button::Up, Button::Down));
        DIRECTION_BY_OFFSET[((dx + 1) + 3 * (dy + 1)) as usize]
    }

    /// The action for the next step, for a player of a team that attacks to the right on screen
    /// when `rotated` is false (the right team's actions are in its own frame, turned by 180°).
    pub(crate) fn next_action(&mut self, rotated: bool) -> Action {
        let action = self.choose();
        // Taps of directions, sprint and dribble have been seen by `choose`; a tapped kick or
        // sliding waits in its latch until it is sent.
        for b in [Button::Up, Button::Down, Button::Left, Button::Right, Button::Sprint, Button::Dribble] {
            self.latched[b.index()] = false;
        }
        if rotated { action.rotated() } else { action }
    }

    fn choose(&mut self) -> Action {
        if self.builtin {
            return Action::BuiltinAi;
        }
        // A kick button still down keeps filling its gauge; anything else would fire it early.
        if let Some(k) = self.kicking.take()
            && self.held[k.index()]
        {
            self.kicking = Some(k);
            return k.kick().unwrap_or(Action::Idle);
        }
        // A new direction first, so that a kick pressed with it goes that way.
        let direction = self.direction();
        if direction != self.sent_direction {
            self.sent_direction = direction;
            return direction.unwrap_or(Action::ReleaseDirection);
        }
        let kicks = [Button::ShortPass, Button::LongPass, Button::HighPass, Button::Shot];
        if let Some(k) = kicks.into_iter().find(|&k| self.latched[k.index()] || self.held[k.index()]) {
            self.kicking = self.held[k.index()].then_some(k);
            self.latched[k.index()] = false;
            return k.kick().unwrap_or(Action::Idle);
        }
        if self.down(Button::Sliding) {
            self.latched[Button::Sliding.index()] = false;
            return Action::Sliding;
        }
        if self.down(Button::Sprint) != self.sent_sprint {
            self.sent_sprint = !self.sent_sprint;
            return if self.sent_sprint { Action::Sprint } else { Action::ReleaseSprint };
        }
        if self.down(Button::Dribble) != self.sent_dribble {
            self.sent_dribble = !self.sent_dribble;
            return if self.sent_dribble { Action::Dribble } else { Action::ReleaseDribble };
        }
        Action::Idle
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steps(c: &mut HumanController, n: usize) -> Vec<Action> {
        (0..n).map(|_| c.next_action(false)).collect()
    }

    #[test]
    fn a_held_direction_is_sent_once_and_released_when_let_go() {
        let mut c = HumanController::default();
        c.set_buttons(&[Button::Right, Button::Up], &[]);
        assert_eq!(steps(&mut c, 3), [Action::TopRight, Action::Idle, Action::Idle]);
        c.set_buttons(&[], &[]);
        assert_eq!(steps(&mut c, 2), [Action::ReleaseDirection, Action::Idle]);
        c.set_buttons(&[Button::Left, Button::Right], &[]);
        assert_eq!(steps(&mut c, 1), [Action::Idle], "opposite buttons cancel");
    }

    #[test]
    fn a_tap_shorter_than_a_step_is_one_press_and_the_next_action_releases_it() {
        let mut c = HumanController::default();
        c.set_buttons(&[], &[Button::ShortPass]);
        assert_eq!(steps(&mut c, 3), [Action::ShortPass, Action::Idle, Action::Idle]);
    }

    #[test]
    fn a_held_shot_fills_the_gauge_and_holds_back_other_changes() {
        let mut c = HumanController::default();
        c.set_buttons(&[Button::Shot], &[]);
        assert_eq!(steps(&mut c, 2), [Action::Shot, Action::Shot]);
        c.set_buttons(&[Button::Shot, Button::Sprint], &[]);
        assert_eq!(steps(&mut c, 1), [Action::Shot], "sprint waits for the shot");
        c.set_buttons(&[Button::Sprint], &[]);
        assert_eq!(steps(&mut c, 2), [Action::Sprint, Action::Idle]);
    }

    #[test]
    fn a_direction_pressed_with_a_pass_goes_first() {
        let mut c = HumanController::default();
        c.set_buttons(&[Button::Down], &[Button::LongPass]);
        assert_eq!(steps(&mut c, 3), [Action::Bottom, Action::LongPass, Action::Idle]);
        c.set_buttons(&[Button::Down, Button::HighPass], &[]);
        assert_eq!(steps(&mut c, 2), [Action::HighPass, Action::HighPass], "held: the gauge fills");
    }

    #[test]
    fn the_right_team_turns_screen_directions_into_its_own_frame() {
        let mut c = HumanController::default();
        c.set_buttons(&[Button::Right], &[]);
        assert_eq!(c.next_action(true), Action::Left);
    }

    #[test]
    fn the_player_handed_to_the_ai_comes_back_with_no_sticky_state() {
        let mut c = HumanController::default();
        c.set_buttons(&[Button::Right, Button::Sprint], &[]);
        assert_eq!(steps(&mut c, 2), [Action::Right, Action::Sprint]);
        c.toggle_builtin();
        assert_eq!(steps(&mut c, 2), [Action::BuiltinAi, Action::BuiltinAi]);
        c.toggle_builtin();
        assert_eq!(steps(&mut c, 3), [Action::Right, Action::Sprint, Action::Idle]);
    }

    #[test]
    fn button_names_round_trip() {
        for b in Button::ALL {
            assert_eq!(Button::from_name(b.name()), Some(b));
        }
        assert_eq!(Button::from_name("jump"), None);
    }
}
