//! Conditions: the small expression language shared by player behaviours (`do A until COND then
//! B`) and episode-end conditions (`end when COND`). Plain serde data; the engine evaluates them
//! against the match (see `crate::behaviour`).
//!
//! **Frames.** Points and regions in a condition are read in a frame chosen by where the condition
//! is used: in a behaviour, the frame of the behaving player's team (own goal at x = -1, as player
//! positions are written); in `end when`, the global frame (the left team attacks +x). Players and
//! sides are absolute (`left`, `right`, player index in the team's list).

use serde::{Deserialize, Serialize};

use super::random::Region;
use crate::game::GameMode;
use crate::geometry::Side;

/// Something on the pitch a condition or behaviour refers to.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Target {
    /// The ball.
    Ball,
    /// The player whose behaviour this is (only meaningful inside a behaviour; `end when`
    /// conditions may not use it).
    Me,
    /// Player `i` (index in the scenario's list) of the left team.
    Left(usize),
    /// Player `i` of the right team.
    Right(usize),
    /// A fixed point `[x, y]`, normalised units, in the frame of use (see the module docs).
    Point([f32; 2]),
}

/// How two numbers compare.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Comparison {
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `==`
    Eq,
    /// `!=`
    Ne,
}

impl Comparison {
    /// Whether `lhs OP rhs` holds.
    pub fn holds(self, lhs: f32, rhs: f32) -> bool {
        self.compare(lhs, rhs)
    }

    /// Whether `lhs OP rhs` holds, for any ordered values (step counts, goals).
    pub fn compare<T: PartialOrd>(self, lhs: T, rhs: T) -> bool {
        match self {
            Comparison::Lt => lhs < rhs,
            Comparison::Le => lhs <= rhs,
            Comparison::Gt => lhs > rhs,
            Comparison::Ge => lhs >= rhs,
            Comparison::Eq => lhs == rhs,
            Comparison::Ne => lhs != rhs,
        }
    }

    /// The operator as written in `.tl` text.
    pub fn symbol(self) -> &'static str {
        match self {
            Comparison::Lt => "<",
            Comparison::Le => "<=",
            Comparison::Gt => ">",
            Comparison::Ge => ">=",
            Comparison::Eq => "==",
            Comparison::Ne => "!=",
        }
    }
}

/// Who has the ball at his feet.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Owner {
    /// Nobody (the ball is loose or in flight).
    Nobody,
    /// A player of this team.
    Team(Side),
    /// This player (`Target::Me`, `Target::Left(i)` or `Target::Right(i)`).
    Player(Target),
}

/// The deepest nesting of `all`, `any` and `not` a decoded [`Condition`] may have. Decoders recurse
/// once per level and postcard has no limit of its own, so a snapshot crafted with a condition
/// nested 100,000 deep would overflow the stack; the scenario language stops at 64 levels.
pub(crate) const MAX_CONDITION_DEPTH: usize = 128;

thread_local! {
    /// Levels of [`Condition`] being decoded on this thread.
    static DECODING_DEPTH: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// Decodes one nested level of a condition, refusing to go past [`MAX_CONDITION_DEPTH`].
fn nested<'de, D, T>(decoder: D) -> Result<T, D::Error>
where
    D: serde::Deserializer<'de>,
    T: Deserialize<'de>,
{
    let depth = DECODING_DEPTH.with(|d| {
        d.set(d.get() + 1);
        d.get()
    });
    let result = if depth > MAX_CONDITION_DEPTH {
        Err(serde::de::Error::custom(format!("conditions nested deeper than {MAX_CONDITION_DEPTH} levels")))
    } else {
        T::deserialize(decoder)
    };
    DECODING_DEPTH.with(|d| d.set(d.get() - 1));
    result
}

/// A condition on the state of the match. Evaluated after every tick for behaviours and after
/// every env step for end conditions.
///
/// Decoding refuses conditions nested deeper than 128 levels of `all`, `any` and `not`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Condition {
    /// Every condition holds (`A and B`).
    #[serde(deserialize_with = "nested")]
    All(Vec<Condition>),
    /// At least one holds (`A or B`).
    #[serde(deserialize_with = "nested")]
    Any(Vec<Condition>),
    /// The condition does not hold (`not A`).
    #[serde(deserialize_with = "nested")]
    Not(Box<Condition>),
    /// `distance(a, b) OP metres`: the distance on the pitch between two targets, in metres.
    Distance {
        /// First target.
        a: Target,
        /// Second target.
        b: Target,
        /// Comparison.
        op: Comparison,
        /// Right-hand side (m).
        metres: f32,
    },
    /// `WHAT in REGION`: the target (ball or a player) is inside the region (frame of use).
    In {
        /// What must be inside.
        what: Target,
        /// The region.
        region: Region,
    },
    /// `owner is …`: who has the ball.
    Owner(Owner),
    /// `game_mode is corner`: the current game mode (restart being taken, or normal play).
    Mode(GameMode),
    /// `steps OP N`: env steps taken in the episode (10 ticks each).
    Steps {
        /// Comparison.
        op: Comparison,
        /// Right-hand side (steps).
        steps: u32,
    },
    /// `score(left) OP N`: goals of a team.
    Score {
        /// Whose goals.
        side: Side,
        /// Comparison.
        op: Comparison,
        /// Right-hand side (goals).
        goals: u32,
    },
    /// `done`: the behaviour stage this condition ends has finished by itself (arrived at its
    /// point, made its pass or shot). Only meaningful inside a behaviour.
    Done,
}

/// What a condition may refer to where it is used.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CheckContext {
    /// Inside a behaviour (`me` and `done` allowed) rather than `end when`.
    pub(crate) in_behaviour: bool,
    /// Players each side fields in every episode `[left, right]`.
    pub(crate) players: [usize; 2],
}

impl Target {
    /// Checks a target: `me` only inside a behaviour, player indices in range, points finite
    /// and on the pitch.
    pub(crate) fn check(&self, ctx: CheckContext) -> Result<(), String> {
        match *self {
            Target::Me if !ctx.in_behaviour => Err("`me` names no player in `end when`".into()),
            Target::Left(i) if i >= ctx.players[0] => Err(format!("left player {i} does not exist")),
            Target::Right(i) if i >= ctx.players[1] => Err(format!("right player {i} does not exist")),
            Target::Point([x, y]) if !super::on_pitch(x, y) => Err(format!("point ({x}, {y}) is off the pitch")),
            _ => Ok(()),
        }
    }
}

impl Condition {
    /// Checks every part of the condition (see [`Target::check`]): finite distances, sound
    /// regions, owners that are players, `done` only inside a behaviour.
    pub(crate) fn check(&self, ctx: CheckContext) -> Result<(), String> {
        match self {
            Condition::All(all) | Condition::Any(all) => all.iter().try_for_each(|c| c.check(ctx)),
            Condition::Not(c) => c.check(ctx),
            Condition::Distance { a, b, metres, .. } => {
                a.check(ctx)?;
                b.check(ctx)?;
                if metres.is_finite() { Ok(()) } else { Err(format!("distance {metres} m is not finite")) }
            }
            Condition::In { what, region } => {
                what.check(ctx)?;
                region.check()
            }
            Condition::Owner(Owner::Player(t)) => match t {
                Target::Ball | Target::Point(_) => Err("only a player can own the ball".into()),
                _ => t.check(ctx),
            },
            Condition::Done if !ctx.in_behaviour => Err("`done` means nothing in `end when`".into()),
            Condition::Owner(_) | Condition::Mode(_) | Condition::Steps { .. } | Condition::Score { .. } => Ok(()),
            Condition::Done => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 17, item 11: a condition nested 100,000 deep in a snapshot's bytes (postcard: `not`
    /// is variant 2, then `steps OP N` is variant 7) is refused instead of overflowing the stack.
    #[test]
    fn deep_conditions_are_refused_when_decoded() {
        let encode = |depth: usize| {
            let mut bytes = vec![2u8; depth];
            bytes.extend_from_slice(&[7, 0, 5]);
            bytes
        };
        let shallow: Condition = postcard::from_bytes(&encode(MAX_CONDITION_DEPTH)).unwrap();
        assert!(matches!(shallow, Condition::Not(_)));
        let err = postcard::from_bytes::<Condition>(&encode(100_000)).unwrap_err();
        assert!(!err.to_string().is_empty());
        let text =
            format!("{}{{\"steps\": {{\"op\": \"ge\", \"steps\": 5}}}}{}", "{\"not\": ".repeat(200), "}".repeat(200));
        assert!(serde_json::from_str::<Condition>(&text).is_err());
    }
}
