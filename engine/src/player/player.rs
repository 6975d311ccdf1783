//! One player's state.

use glam::Vec2;

use super::{Attributes, Role};
use crate::game::Kick;
use crate::geometry::Side;

/// A player on the pitch (engine frame, SI units).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Player {
    /// Team.
    pub side: Side,
    /// Index within the team (the observation order).
    pub index: usize,
    /// Role from the scenario.
    pub role: Role,
    /// Position on the ground (m).
    pub position: Vec2,
    /// Velocity (m/s).
    pub velocity: Vec2,
    /// Unit vector the player faces.
    pub facing: Vec2,
    /// A lazy player only stands and reacts physically.
    pub lazy: bool,
    /// Whether an agent may control this player.
    pub controllable: bool,
    /// False once sent off (the laws issue adds sending-offs).
    pub active: bool,
    /// Cards shown to the player (observed as `yellow_card` when ≥ 1).
    pub cards: u8,
    /// Fatigue in [0, 0.99] (observed as `tired_factor`; 0 = fresh).
    pub fatigue: f32,
    /// Top sprint speed now (m/s): his fresh top speed lowered by fatigue
    /// (docs/grf-compatibility.md#action-effects, #controlled-players).
    pub max_speed: f32,
    /// Top sprint speed when fresh (m/s), from his speed attribute and the team's difficulty.
    pub fresh_speed: f32,
    /// Abilities of his team slot (docs/grf-compatibility.md#player-stats), before difficulty and fatigue.
    pub attributes: Attributes,
    /// Home position in the team's own frame (m), from the formation.
    pub home: Vec2,
    /// Ticks during which the player cannot touch the ball (just kicked it, or was tackled).
    pub(crate) touch_cooldown: u16,
    /// Ticks left of a sliding tackle; the player cannot steer while sliding.
    pub(crate) slide_ticks: u16,
    /// Ticks left of a goalkeeper's dive.
    pub(crate) dive_ticks: u16,
    /// A kick being wound up by the player on the ball, and the ticks until the ball leaves his
    /// foot (it never does if he loses the ball first).
    pub(crate) pending_kick: Option<(Kick, u16)>,
    /// The run (m/s) he was on when he asked for the kick he is winding up: GRF's kick animations
    /// carry the body's run into the touch, and a shot hit across that run is the harder one.
    #[serde(default)]
    pub(crate) kick_run: Vec2,
    /// Where he faced when he asked for that kick: a standing kicker's pass is played round
    /// from it (`game::touch`), though he turns to the target while he winds up.
    #[serde(default)]
    pub(crate) kick_facing: Vec2,
    /// An agent's player is stepping to a loose ball by himself (GRF's automatic ball control).
    #[serde(default)]
    pub(crate) controlling_ball: bool,
    /// A kick (shot or pass) an agent asked for at a loose ball at his feet before he had it, and
    /// the ticks left: struck at his first touch once its wind-up has passed, forgotten a second
    /// after that. He never shows as the ball's owner.
    #[serde(default)]
    pub(crate) queued_kick: Option<(Kick, u16)>,
    /// Ticks until the touch of a standing tackle he has started lands (0: none).
    #[serde(default)]
    pub(crate) interfere_ticks: u16,
    /// Ticks left of a stumble or fall after a body contact (GRF's trip, `game/trip.rs`): he
    /// cannot steer or touch the ball.
    #[serde(default)]
    pub(crate) trip_ticks: u16,
}

/// Walking speed (m/s) with a direction and no modifier (docs/grf-compatibility.md#action-effects).
pub const WALK_SPEED: f32 = 5.0;
/// Sprint speed (m/s) of the fastest player (docs/grf-compatibility.md#action-effects).
pub const SPRINT_SPEED: f32 = 8.0;
/// Speed with the dribble button held (m/s, docs/grf-compatibility.md#action-effects).
pub const DRIBBLE_SPEED: f32 = 3.5;

impl Player {
    /// Notes his run and facing as he asks for a kick ([`Player::kick_run`], `kick_facing`).
    pub(crate) fn ready_kick(&mut self) {
        self.kick_run = self.velocity;
        self.kick_facing = self.facing;
    }

    /// GRF's possession point (m): 0.05 s of his run and 0.1 m along his facing ahead of him.
    /// GRF's possession test measures the ball from here
    /// (docs/grf-compatibility.md#raw-observation), so a player walking away from a ball leaves it
    /// and one walking onto it takes it.
    pub(crate) fn possession_point(&self) -> Vec2 {
        self.position + self.velocity * 0.05 + self.facing * 0.1
    }

    /// A fresh player standing at `position` (m), facing the opponents' goal.
    pub fn new(side: Side, index: usize, role: Role, position: Vec2, home: Vec2) -> Player {
        Player {
            side,
            index,
            role,
            position,
            velocity: Vec2::ZERO,
            facing: Vec2::new(side.attack_sign(), 0.0),
            lazy: false,
            controllable: true,
            active: true,
            cards: 0,
            fatigue: 0.0,
            max_speed: SPRINT_SPEED,
            fresh_speed: SPRINT_SPEED,
            attributes: Attributes::uniform(1.0),
            home,
            touch_cooldown: 0,
            slide_ticks: 0,
            dive_ticks: 0,
            pending_kick: None,
            kick_run: Vec2::ZERO,
            kick_facing: Vec2::ZERO,
            queued_kick: None,
            controlling_ball: false,
            interfere_ticks: 0,
            trip_ticks: 0,
        }
    }

    /// Whether the player is the goalkeeper.
    #[inline]
    pub fn is_keeper(&self) -> bool {
        self.role == Role::GK
    }

    /// Whether the player is in the middle of a sliding tackle.
    #[inline]
    pub fn is_sliding(&self) -> bool {
        self.slide_ticks > 0
    }

    /// An ability after the team's difficulty and his fatigue: `stat · (0.3 + 0.7·θ) · (1 − 0.3·f)`
    /// (docs/grf-compatibility.md#controlled-players), in [0, 1].
    #[inline]
    pub fn skill(&self, stat: f32, theta: f32) -> f32 {
        stat * super::difficulty_scale(theta) * super::fatigue::skill_factor(self.fatigue)
    }

    /// Stops the player where he stands and clears any action in progress.
    pub(crate) fn halt(&mut self) {
        self.velocity = Vec2::ZERO;
        self.slide_ticks = 0;
        self.dive_ticks = 0;
        self.pending_kick = None;
        self.touch_cooldown = 0;
        self.queued_kick = None;
        self.interfere_ticks = 0;
    }
}

/// Top sprint speed (m/s) for a velocity stat in [0, 1]: 8 · (0.9 + 0.1·stat) (docs/grf-compatibility.md#player-stats).
pub fn top_speed(stat: f32) -> f32 {
    SPRINT_SPEED * (0.9 + 0.1 * stat.clamp(0.0, 1.0))
}

/// Distance (m) from `at` to the nearest active player of `players` (infinite when none).
pub fn nearest_distance(players: &[Player], at: Vec2) -> f32 {
    players.iter().filter(|p| p.active).map(|p| p.position.distance_squared(at)).fold(f32::INFINITY, f32::min).sqrt()
}
