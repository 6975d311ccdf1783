//! The read-only state API scripts see: a `State` value `s` passed to each hook, with getters named
//! after GRF's raw observation (grf.md §3.1).
//!
//! Frame and units, as the observation: the team's own frame, GRF-normalised (x ∈ [-1, 1] from the
//! team's own goal to the opponents' goal, y ∈ [-0.42, 0.42], the ball's z in metres); `left_team`
//! is always the script's own team. A reward hook is called once per team that has agents, in that
//! team's frame; an end hook once per step, in the left team's frame.
//!
//! | getter | value |
//! |---|---|
//! | `s.ball`, `s.ball_direction`, `s.ball_rotation` | `[x, y, z]` floats (direction: movement per step) |
//! | `s.ball_owned_team` | -1 nobody, 0 own team, 1 opponents |
//! | `s.ball_owned_player` | index in the owner's team, or -1 |
//! | `s.left_team`, `s.right_team` | positions, array of `[x, y]` (own team, opponents) |
//! | `s.left_team_direction`, `s.right_team_direction` | movement per step, array of `[dx, dy]` |
//! | `s.left_team_tired_factor`, `s.right_team_tired_factor` | fatigue in [0, 0.99] |
//! | `s.left_team_yellow_card`, `s.right_team_yellow_card` | booked (bools) |
//! | `s.left_team_active`, `s.right_team_active` | still on the pitch (false once sent off) |
//! | `s.left_team_roles`, `s.right_team_roles` | role numbers 0 GK … 9 CF (GRF's order) |
//! | `s.score` | `[own goals, opponents' goals]` |
//! | `s.game_mode` | 0 normal, 1 kickoff, 2 goal kick, 3 free kick, 4 corner, 5 throw-in, 6 penalty |
//! | `s.steps`, `s.steps_left` | steps taken this episode, steps left |
//! | `s.episode` | 0-based episode index since seeding |
//! | `s.side` | `"left"` or `"right"`: which team this view belongs to |
//! | `s.active`, `s.designated` | the first agent's player and the team's designated player (-1 none) |
//! | `s.controlled` | the players the team's agents drive, one index per agent |
//! | `s.actions` | the actions those agents just took, GRF names (`"short_pass"`, …); empty at reset |
//! | `s.sticky_actions` | the first agent's 10 sticky-action flags |
//! | `s.prev` | the same view one step earlier, or `()` at reset |
//!
//! Function: `f32(x)` rounds a float to single precision, as the engine computes.

use std::sync::Arc;

use rhai::{Array, Dynamic, Engine};
use serde::{Deserialize, Serialize};
use touchline_engine::{Action, HookView, RawObservation, Side};

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
