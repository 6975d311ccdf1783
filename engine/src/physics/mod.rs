//! Physics: the ball's flight, bounce and roll against rapier3d colliders for the ground, posts,
//! crossbars and nets, and the players' kinematics and body collisions.

mod ball;
mod colliders;
mod contacts;
mod player_motion;
mod strides;

pub use ball::{
    BALL_DRAG, BOUNCE_RESTITUTION, Ball, ROLL_DECELERATION, ROLL_QUADRATIC, ROLL_QUADRATIC_TOTAL, bounce_keep,
    rolled_speed,
};
pub use colliders::{PitchColliders, Surface};
pub(crate) use contacts::{Contact, Contacts};
pub(crate) use player_motion::{MIN_DIST, MotionLimits, keep_inside_rim, separate_players};
pub(crate) use strides::{Stride, Strides};

/// Length of one tick (s): 10 ms, GRF's physics step (docs/grf-compatibility.md#time-base).
pub const TICK_SECONDS: f32 = 0.01;
