//! The read-only state API scripts see: a `State` value `s` passed to each hook, with getters named
//! after GRF's raw observation ([`RawObservation`]). Every property, with its type, unit, frame and
//! range, is in the scripts reference, `grammar/scripts.md`; [`STATE_PROPERTIES`] lists the names.

use std::sync::Arc;

use rhai::{Array, Dynamic, Engine};
use serde::{Deserialize, Serialize};
use touchline_engine::{Action, HookView, RawObservation, Side};

/// The properties of the state `s`, in the order of the reference's table (`grammar/scripts.md`,
/// which `dsl/tests/script_reference.rs` checks against this list). A script that reads another is
/// refused when it compiles (`tl::S010`).
pub const STATE_PROPERTIES: &[&str] = &[
    "ball",
    "ball_direction",
    "ball_rotation",
    "ball_owned_team",
    "ball_owned_player",
    "left_team",
    "right_team",
    "left_team_direction",
    "right_team_direction",
    "left_team_tired_factor",
    "right_team_tired_factor",
    "left_team_yellow_card",
    "right_team_yellow_card",
    "left_team_active",
    "right_team_active",
    "left_team_roles",
    "right_team_roles",
    "score",
    "game_mode",
    "steps",
    "steps_left",
    "episode",
    "side",
    "active",
    "designated",
    "controlled",
    "actions",
    "sticky_actions",
    "prev",
];

/// One team's view of the state after a step (what `s` reads).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct TeamState {
    pub(crate) obs: RawObservation,
    pub(crate) left: bool,
    pub(crate) controlled: Vec<i64>,
    pub(crate) actions: Vec<Action>,
    pub(crate) steps: u32,
    pub(crate) episode: u64,
}

impl TeamState {
    /// Copies `side`'s view out of `view`, reusing buffers (no allocation once sized).
    pub(crate) fn fill(&mut self, view: &HookView<'_>, side: Side) {
        let n = view.observations.len();
        let (start, len) = match side {
            Side::Left => (0, view.left_controllers),
            Side::Right => (view.left_controllers, n - view.left_controllers),
        };
        if len > 0 {
            self.obs.clone_from(&view.observations[start]);
        } else {
            self.obs.fill(view.game, side, None, None, [0; 10], view.steps_left);
        }
        self.left = side == Side::Left;
        self.controlled.clear();
        self.controlled.extend(view.observations[start..start + len].iter().map(|o| i64::from(o.active)));
        self.actions.clear();
        if !view.actions.is_empty() {
            self.actions.extend_from_slice(&view.actions[start..start + len]);
        }
        self.steps = view.steps;
        self.episode = view.episode;
    }
}

/// The value a hook receives: the current view and the previous step's.
#[derive(Clone, Debug)]
pub(crate) struct State {
    pub(crate) now: Arc<TeamState>,
    pub(crate) prev: Option<Arc<TeamState>>,
}

fn floats(values: impl Iterator<Item = f32>) -> Array {
    values.map(|v| Dynamic::from_float(f64::from(v))).collect()
}

fn pairs(values: &[[f32; 2]]) -> Array {
    values.iter().map(|p| Dynamic::from_array(floats(p.iter().copied()))).collect()
}

fn bools(values: &[bool]) -> Array {
    values.iter().map(|&b| Dynamic::from_bool(b)).collect()
}

/// Registers `State` and its getters.
pub(crate) fn register(engine: &mut Engine) {
    engine.register_type_with_name::<State>("State");
    macro_rules! get {
        ($name:literal, |$o:ident, $s:ident| $body:expr) => {
            engine.register_get($name, |st: &mut State| {
                let $s: &TeamState = &st.now;
                let $o: &RawObservation = &$s.obs;
                let _ = (&$o, &$s);
                $body
            });
        };
    }
    get!("ball", |o, s| floats(o.ball.iter().copied()));
    get!("ball_direction", |o, s| floats(o.ball_direction.iter().copied()));
    get!("ball_rotation", |o, s| floats(o.ball_rotation.iter().copied()));
    get!("ball_owned_team", |o, s| i64::from(o.ball_owned_team));
    get!("ball_owned_player", |o, s| i64::from(o.ball_owned_player));
    get!("left_team", |o, s| pairs(&o.left_team));
    get!("right_team", |o, s| pairs(&o.right_team));
    get!("left_team_direction", |o, s| pairs(&o.left_team_direction));
    get!("right_team_direction", |o, s| pairs(&o.right_team_direction));
    get!("left_team_tired_factor", |o, s| floats(o.left_team_tired_factor.iter().copied()));
    get!("right_team_tired_factor", |o, s| floats(o.right_team_tired_factor.iter().copied()));
    get!("left_team_yellow_card", |o, s| bools(&o.left_team_yellow_card));
    get!("right_team_yellow_card", |o, s| bools(&o.right_team_yellow_card));
    get!("left_team_active", |o, s| bools(&o.left_team_active));
    get!("right_team_active", |o, s| bools(&o.right_team_active));
    get!("left_team_roles", |o, s| o
        .left_team_roles
        .iter()
        .map(|&r| Dynamic::from_int(i64::from(r)))
        .collect::<Array>());
    get!("right_team_roles", |o, s| o
        .right_team_roles
        .iter()
        .map(|&r| Dynamic::from_int(i64::from(r)))
        .collect::<Array>());
    get!("score", |o, s| o.score.iter().map(|&g| Dynamic::from_int(i64::from(g))).collect::<Array>());
    get!("game_mode", |o, s| o.game_mode as i64);
    get!("steps_left", |o, s| i64::from(o.steps_left));
    get!("steps", |o, s| i64::from(s.steps));
    get!("episode", |o, s| i64::try_from(s.episode).unwrap_or(i64::MAX));
    get!("side", |o, s| if s.left { "left" } else { "right" });
    get!("active", |o, s| i64::from(o.active));
    get!("designated", |o, s| i64::from(o.designated));
    get!("controlled", |o, s| s.controlled.iter().map(|&i| Dynamic::from_int(i)).collect::<Array>());
    get!("actions", |o, s| s.actions.iter().map(|a| Dynamic::from(a.name())).collect::<Array>());
    get!("sticky_actions", |o, s| o.sticky_actions.iter().map(|&b| Dynamic::from_int(i64::from(b))).collect::<Array>());
    // Rounds to single precision: the engine computes in f32, and a script that wants the
    // built-in rewards bit for bit (examples/rewards/checkpoints.rhai) rounds as it does.
    engine.register_fn("f32", |x: f64| f64::from(x as f32));
    engine.register_get("prev", |st: &mut State| match &st.prev {
        Some(prev) => Dynamic::from(State { now: Arc::clone(prev), prev: None }),
        None => Dynamic::UNIT,
    });
}
