//! Named places of the language: pitch regions, formations, unit conversions.
//!
//! Everything is in scenario units: x from the own goal line (−1) to the opponent's (+1), y across
//! with the touchlines at ±0.42 (docs/grf-compatibility.md#scenario-semantics). For players these are the
//! team's own frame; for the ball and end conditions the left team's frame (global).

use touchline_engine::Role;
use touchline_engine::geometry::coords::{SCENARIO_LINES, SCENARIO_RIM};
use touchline_engine::scenario::Region;

/// Metres per scenario unit along x for players (the engine places a player at 55·x m,
/// docs/grf-compatibility.md#scenario-semantics).
pub(crate) const PLAYER_X_METRES: f64 = 55.0;
/// Metres per scenario unit across for players (2.36 · 36 m, docs/grf-compatibility.md#scenario-semantics).
pub(crate) const PLAYER_Y_METRES: f64 = 2.36 * 36.0;
/// Metres per unit along x for the ball (54.4 m, docs/grf-compatibility.md#scenario-semantics).
pub(crate) const BALL_X_METRES: f64 = 54.4;
/// Metres per unit across for the ball (83.6 m, docs/grf-compatibility.md#scenario-semantics).
pub(crate) const BALL_Y_METRES: f64 = 83.6;

/// Penalty area depth, 16.5 m (Law 1), in player x units.
const PENALTY_DEPTH: f32 = (16.5 / PLAYER_X_METRES) as f32;
/// Penalty area half width, 20.15 m (Law 1; docs/grf-compatibility.md#pitch-geometry), in player y units.
const PENALTY_HALF_WIDTH: f32 = (20.15 / PLAYER_Y_METRES) as f32;
/// Goal area depth, 5.5 m (Law 1).
const GOAL_AREA_DEPTH: f32 = (5.5 / PLAYER_X_METRES) as f32;
/// Goal area half width: 3.66 m half goal + 5.5 m (Law 1).
const GOAL_AREA_HALF_WIDTH: f32 = (9.16 / PLAYER_Y_METRES) as f32;
/// Centre circle radius, 9.15 m (Law 1), in x units.
const CENTRE_CIRCLE: f32 = (9.15 / PLAYER_X_METRES) as f32;
/// The rim: the farthest a player or the ball may start, or a behaviour's point may be.
pub(crate) const RIM: [f32; 2] = SCENARIO_RIM;

/// Whether a point is finite and within the rim (where a player may start).
pub(crate) fn within_rim(p: [f32; 2]) -> bool {
    p.iter().all(|v| v.is_finite()) && p[0].abs() <= RIM[0] && p[1].abs() <= RIM[1]
}

/// Touchline y in scenario units ([`SCENARIO_LINES`]).
const TOUCHLINE: f32 = SCENARIO_LINES[1];

/// The x and y ranges of the pitch and the rim, for a diagnostic's help: `"x in [-1, 1]{x_note}, y
/// in [-0.42, 0.42]{y_note}; the rim allows |x| <= 1.1, |y| <= 0.48"`, from the engine's
/// [`SCENARIO_LINES`] and [`SCENARIO_RIM`].
pub(super) fn units_help(x_note: &str, y_note: &str) -> String {
    let [x, y] = SCENARIO_LINES;
    let [rim_x, rim_y] = SCENARIO_RIM;
    format!("x in [-{x}, {x}]{x_note}, y in [-{y}, {y}]{y_note}; the rim allows |x| <= {rim_x}, |y| <= {rim_y}")
}

/// Names of the built-in regions, for suggestions.
pub(crate) const REGION_NAMES: [&str; 8] = [
    "pitch",
    "own_half",
    "opponent_half",
    "penalty_area",
    "opponent_penalty_area",
    "goal_area",
    "opponent_goal_area",
    "centre_circle",
];

/// The region called `name`, in the frame of whoever uses it.
pub(crate) fn region(name: &str) -> Option<Region> {
    let rect = |x0: f32, x1: f32, y0: f32, y1: f32| Some(Region::Rect { x: [x0, x1], y: [y0, y1] });
    match name {
        "pitch" => rect(-1.0, 1.0, -TOUCHLINE, TOUCHLINE),
        "own_half" => rect(-1.0, 0.0, -TOUCHLINE, TOUCHLINE),
        "opponent_half" => rect(0.0, 1.0, -TOUCHLINE, TOUCHLINE),
        "penalty_area" => rect(-1.0, -1.0 + PENALTY_DEPTH, -PENALTY_HALF_WIDTH, PENALTY_HALF_WIDTH),
        "opponent_penalty_area" => rect(1.0 - PENALTY_DEPTH, 1.0, -PENALTY_HALF_WIDTH, PENALTY_HALF_WIDTH),
        "goal_area" => rect(-1.0, -1.0 + GOAL_AREA_DEPTH, -GOAL_AREA_HALF_WIDTH, GOAL_AREA_HALF_WIDTH),
        "opponent_goal_area" => rect(1.0 - GOAL_AREA_DEPTH, 1.0, -GOAL_AREA_HALF_WIDTH, GOAL_AREA_HALF_WIDTH),
        "centre_circle" => Some(Region::Circle { x: 0.0, y: 0.0, r: CENTRE_CIRCLE }),
        _ => None,
    }
}

/// Names of the built-in formations, for suggestions.
pub(crate) const FORMATION_NAMES: [&str; 6] = ["4-4-2", "4-3-3", "4-2-3-1", "3-5-2", "5-3-2", "4-5-1"];

/// The players of a named formation (role, x, y in the team's own frame), keeper first, all in
/// the own half so that either team can take the kickoff from them.
pub(crate) fn formation(name: &str) -> Option<&'static [(Role, f32, f32)]> {
    use Role::*;
    const BACK_FOUR: [(Role, f32, f32); 4] = [(LB, -0.5, -0.3), (CB, -0.55, -0.1), (CB, -0.55, 0.1), (RB, -0.5, 0.3)];
    const F442: [(Role, f32, f32); 11] = [
        (GK, -1.0, 0.0),
        BACK_FOUR[0],
        BACK_FOUR[1],
        BACK_FOUR[2],
        BACK_FOUR[3],
        (LM, -0.25, -0.3),
        (CM, -0.3, -0.1),
        (CM, -0.3, 0.1),
        (RM, -0.25, 0.3),
        (CF, -0.05, -0.08),
        (CF, -0.05, 0.08),
    ];
    const F433: [(Role, f32, f32); 11] = [
        (GK, -1.0, 0.0),
        BACK_FOUR[0],
        BACK_FOUR[1],
        BACK_FOUR[2],
        BACK_FOUR[3],
        (CM, -0.3, -0.15),
        (DM, -0.38, 0.0),
        (CM, -0.3, 0.15),
        (LM, -0.1, -0.3),
        (CF, -0.05, 0.0),
        (RM, -0.1, 0.3),
    ];
    const F4231: [(Role, f32, f32); 11] = [
        (GK, -1.0, 0.0),
        BACK_FOUR[0],
        BACK_FOUR[1],
        BACK_FOUR[2],
        BACK_FOUR[3],
        (DM, -0.38, -0.08),
        (DM, -0.38, 0.08),
        (LM, -0.2, -0.3),
        (AM, -0.2, 0.0),
        (RM, -0.2, 0.3),
        (CF, -0.05, 0.0),
    ];
    const F352: [(Role, f32, f32); 11] = [
        (GK, -1.0, 0.0),
        (CB, -0.55, -0.15),
        (CB, -0.58, 0.0),
        (CB, -0.55, 0.15),
        (LM, -0.25, -0.33),
        (CM, -0.3, -0.12),
        (DM, -0.38, 0.0),
        (CM, -0.3, 0.12),
        (RM, -0.25, 0.33),
        (CF, -0.05, -0.08),
        (CF, -0.05, 0.08),
    ];
    const F532: [(Role, f32, f32); 11] = [
        (GK, -1.0, 0.0),
        (LB, -0.45, -0.33),
        (CB, -0.55, -0.15),
        (CB, -0.58, 0.0),
        (CB, -0.55, 0.15),
        (RB, -0.45, 0.33),
        (CM, -0.3, -0.15),
        (CM, -0.32, 0.0),
        (CM, -0.3, 0.15),
        (CF, -0.05, -0.08),
        (CF, -0.05, 0.08),
    ];
    const F451: [(Role, f32, f32); 11] = [
        (GK, -1.0, 0.0),
        BACK_FOUR[0],
        BACK_FOUR[1],
        BACK_FOUR[2],
        BACK_FOUR[3],
        (LM, -0.25, -0.3),
        (CM, -0.3, -0.12),
        (DM, -0.38, 0.0),
        (CM, -0.3, 0.12),
        (RM, -0.25, 0.3),
        (CF, -0.05, 0.0),
    ];
    Some(match name {
        "4-4-2" => &F442,
        "4-3-3" => &F433,
        "4-2-3-1" => &F4231,
        "3-5-2" => &F352,
        "5-3-2" => &F532,
        "4-5-1" => &F451,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formations_have_eleven_one_keeper_in_own_half() {
        for name in FORMATION_NAMES {
            let f = formation(name).unwrap();
            assert_eq!(f.len(), 11, "{name}");
            assert_eq!(f.iter().filter(|p| p.0 == Role::GK).count(), 1, "{name}");
            assert!(f.iter().all(|p| p.1 <= 0.0 && p.2.abs() <= 0.42), "{name}");
            let outfield: usize = name.split('-').map(|n| n.parse::<usize>().unwrap()).sum();
            assert_eq!(outfield, 10, "{name}");
        }
    }

    #[test]
    fn regions_lie_on_the_pitch() {
        for name in REGION_NAMES {
            let [[x0, x1], [y0, y1]] = region(name).unwrap().bounds();
            assert!(x0 >= -1.0 && x1 <= 1.0 && y0 >= -0.42 && y1 <= 0.42, "{name}");
        }
        assert!(region("opponent_penalty_area").unwrap().contains(0.9, 0.0));
        assert!(!region("penalty_area").unwrap().contains(0.9, 0.0));
    }
}
