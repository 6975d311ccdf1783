//! Player behaviours at run time: the native players of Scenic4RL-style behaviours
//! ([`crate::scenario::Behaviour`]) and the evaluation of conditions ([`Scope`],
//! [`Condition::holds`](crate::scenario::Condition::holds)).
//!
//! **Design.** A scenario's behaviour is plain data (a list of [`Stage`](crate::scenario::Stage)s
//! per player). At match set-up the match copies each player's stages into per-player state
//! (stage index, done flag, anchor point, a scripted player's gamepad), which is part of the match
//! and so of snapshots. A match where nobody has a behaviour keeps that state empty and runs
//! exactly as before (same random draws, same trajectory).
//!
//! Every tick of play, before the built-in AI:
//! 1. each behaviour player's current stage ends when its `until` condition holds (read in his
//!    team's frame, `me` = him), or, without one, when the behaviour has finished by itself
//!    (arrived, passed, shot); the player moves on to the next stage, one stage per tick, and
//!    stays on the last;
//! 2. the players the behaviours drive this tick are marked *native*: every behaviour but
//!    `builtin`, except the taker of a pending set piece, whom the AI's set-piece logic plays
//!    (a restart never waits on a behaviour, so GRF's anti-stalling rule cannot freeze).
//!
//! The team AI then decides for the others only (it neither plans for native players nor
//! writes their inputs, and a team whose players are all native skips it: behaviours run at
//! native speed, faster than the AI). After it, each native player's [`PlayerInput`] is computed
//! from his behaviour (`behaviour::movement`: idle, hold_position, follow, move_to, mark; `behaviour::ball_play`:
//! dribble_to, pass_to, press, reusing the AI's ball prediction, closing down and kick aiming).
//! During a set piece the other behaviours go on as in play (nobody but the taker may touch the
//! ball then), except that `press` stands 9.15 m off the ball at the other team's restart.
//! A lazy player only stands (lazy wins); an agent-driven player follows the agent (the
//! behaviour resumes when control leaves him). `builtin(θ)` hands the player to the team AI at
//! his own θ: his skill-scaled attributes (top speed, acceleration, kick accuracy, tackling)
//! and the AI's decisions for him (noise, pressing reach, aim) use it.
//!
//! `script` behaviours are stepped by the env, not here: every env step it asks its hooks for
//! the player's action (`Hooks::behaviour_action`) and applies it as an agent's (sticky state in
//! the player's behaviour state); the tick leaves that input alone.
//!
//! [`PlayerInput`]: crate::game::PlayerInput

mod ball_play;
mod condition;
mod drive;
mod movement;
mod state;

pub use condition::Scope;
pub(crate) use state::PlayerBehaviour;
