//! Agent actions with GRF's numbering (docs/grf-compatibility.md#core-actions, #action-sets).

use glam::Vec2;
use serde::{Deserialize, Serialize};

use crate::error::EngineError;

/// A core action, numbered as GRF's `e_BackendAction`. Agents send an index into an
/// [`ActionSet`], which maps to one of these.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[repr(u8)]
#[allow(missing_docs)] // the names are GRF's and say what they do
pub enum Action {
    Idle = 0,
    Left = 1,
    TopLeft = 2,
    Top = 3,
    TopRight = 4,
    Right = 5,
    BottomRight = 6,
    Bottom = 7,
    BottomLeft = 8,
    LongPass = 9,
    HighPass = 10,
    ShortPass = 11,
    Shot = 12,
    KeeperRush = 13,
    Sliding = 14,
    Pressure = 15,
    TeamPressure = 16,
    Switch = 17,
    Sprint = 18,
    Dribble = 19,
    ReleaseDirection = 20,
    ReleaseLongPass = 21,
    ReleaseHighPass = 22,
    ReleaseShortPass = 23,
    ReleaseShot = 24,
    ReleaseKeeperRush = 25,
    ReleaseSliding = 26,
    ReleasePressure = 27,
    ReleaseTeamPressure = 28,
    ReleaseSwitch = 29,
    ReleaseSprint = 30,
    ReleaseDribble = 31,
    BuiltinAi = 32,
}

/// The eight movement directions in sticky-action order (docs/grf-compatibility.md#sticky-actions).
pub const DIRECTIONS: [Action; 8] = [
    Action::Left,
    Action::TopLeft,
    Action::Top,
    Action::TopRight,
    Action::Right,
    Action::BottomRight,
    Action::Bottom,
    Action::BottomLeft,
];

impl Action {
    /// The GRF name (`"short_pass"`, …).
    pub fn name(self) -> &'static str {
        use Action::*;
        match self {
            Idle => "idle",
            Left => "left",
            TopLeft => "top_left",
            Top => "top",
            TopRight => "top_right",
            Right => "right",
            BottomRight => "bottom_right",
            Bottom => "bottom",
            BottomLeft => "bottom_left",
            LongPass => "long_pass",
            HighPass => "high_pass",
            ShortPass => "short_pass",
            Shot => "shot",
            KeeperRush => "keeper_rush",
            Sliding => "sliding",
            Pressure => "pressure",
            TeamPressure => "team_pressure",
            Switch => "switch",
            Sprint => "sprint",
            Dribble => "dribble",
            ReleaseDirection => "release_direction",
            ReleaseLongPass => "release_long_pass",
            ReleaseHighPass => "release_high_pass",
            ReleaseShortPass => "release_short_pass",
            ReleaseShot => "release_shot",
            ReleaseKeeperRush => "release_keeper_rush",
            ReleaseSliding => "release_sliding",
            ReleasePressure => "release_pressure",
            ReleaseTeamPressure => "release_team_pressure",
            ReleaseSwitch => "release_switch",
            ReleaseSprint => "release_sprint",
            ReleaseDribble => "release_dribble",
            BuiltinAi => "builtin_ai",
        }
    }

    /// Index 0–7 of a movement direction in [`DIRECTIONS`], `None` for other actions.
    pub fn direction_index(self) -> Option<usize> {
        let id = self as u8;
        (1..=8).contains(&id).then(|| (id - 1) as usize)
    }

    /// Unit movement vector of a direction action in the global frame (x right, y down the
    /// screen, i.e. "top" is -y); `None` for other actions.
    pub fn direction_vector(self) -> Option<Vec2> {
        const D: f32 = std::f32::consts::FRAC_1_SQRT_2;
        Some(match self {
            Action::Left => Vec2::new(-1.0, 0.0),
            Action::TopLeft => Vec2::new(-D, -D),
            Action::Top => Vec2::new(0.0, -1.0),
            Action::TopRight => Vec2::new(D, -D),
            Action::Right => Vec2::new(1.0, 0.0),
            Action::BottomRight => Vec2::new(D, D),
            Action::Bottom => Vec2::new(0.0, 1.0),
            Action::BottomLeft => Vec2::new(-D, D),
            _ => return None,
        })
    }

    /// The action as seen from the other side of the pitch: directions turn by 180° (left ↔ right,
    /// top ↔ bottom, diagonals to their opposites); others are unchanged. Its own inverse.
    pub fn rotated(self) -> Action {
        match self.direction_index() {
            Some(i) => DIRECTIONS[(i + 4) % 8],
            None => self,
        }
    }
}

/// Which actions an agent may send, and in what order (docs/grf-compatibility.md#action-sets).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ActionSet {
    /// The 19-action set every GRF environment uses.
    #[default]
    Default,
    /// The default set plus `builtin_ai` at index 19 (20 actions).
    V2,
}

const DEFAULT_SET: [Action; 19] = [
    Action::Idle,
    Action::Left,
    Action::TopLeft,
    Action::Top,
    Action::TopRight,
    Action::Right,
    Action::BottomRight,
    Action::Bottom,
    Action::BottomLeft,
    Action::LongPass,
    Action::HighPass,
    Action::ShortPass,
    Action::Shot,
    Action::Sprint,
    Action::ReleaseDirection,
    Action::ReleaseSprint,
    Action::Sliding,
    Action::Dribble,
    Action::ReleaseDribble,
];

const V2_SET: [Action; 20] = {
    let mut set = [Action::BuiltinAi; 20];
    let mut i = 0;
    while i < 19 {
        set[i] = DEFAULT_SET[i];
        i += 1;
    }
    set
};

impl ActionSet {
    /// The actions in index order.
    pub fn actions(self) -> &'static [Action] {
        match self {
            ActionSet::Default => &DEFAULT_SET,
            ActionSet::V2 => &V2_SET,
        }
    }

    /// Number of actions (19 or 20).
    pub fn len(self) -> usize {
        self.actions().len()
    }

    /// Always false; here for clippy's `len_without_is_empty`.
    pub fn is_empty(self) -> bool {
        false
    }

    /// The set's name as GRF spells it (`"default"`, `"v2"`).
    pub fn name(self) -> &'static str {
        match self {
            ActionSet::Default => "default",
            ActionSet::V2 => "v2",
        }
    }

    /// The action at `index`.
    ///
    /// # Errors
    /// [`EngineError::UnknownAction`] when `index` is outside the set.
    pub fn decode(self, index: u32) -> Result<Action, EngineError> {
        self.actions().get(index as usize).copied().ok_or(EngineError::UnknownAction {
            index,
            set: self.name(),
            len: self.len(),
        })
    }

    /// The index of `action` in this set, if it is in it.
    pub fn encode(self, action: Action) -> Option<u32> {
        self.actions().iter().position(|a| *a == action).map(|i| i as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbering_matches_grf() {
        let set = ActionSet::Default;
        assert_eq!(set.len(), 19);
        assert_eq!(set.decode(1).unwrap(), Action::Left);
        assert_eq!(set.decode(12).unwrap(), Action::Shot);
        assert_eq!(set.decode(13).unwrap(), Action::Sprint);
        assert_eq!(set.decode(18).unwrap(), Action::ReleaseDribble);
        assert!(set.decode(19).is_err());
        assert_eq!(ActionSet::V2.decode(19).unwrap(), Action::BuiltinAi);
        assert_eq!(ActionSet::V2.len(), 20);
        assert_eq!(Action::BuiltinAi as u8, 32);
        assert_eq!(set.encode(Action::Dribble), Some(17));
    }

    #[test]
    fn rotation_is_an_involution() {
        for a in ActionSet::V2.actions() {
            assert_eq!(a.rotated().rotated(), *a);
        }
        assert_eq!(Action::Left.rotated(), Action::Right);
        assert_eq!(Action::TopLeft.rotated(), Action::BottomRight);
        assert_eq!(Action::Top.rotated(), Action::Bottom);
        assert_eq!(Action::Shot.rotated(), Action::Shot);
    }

    #[test]
    fn directions_are_unit_vectors_in_sticky_order() {
        for (i, d) in DIRECTIONS.iter().enumerate() {
            assert_eq!(d.direction_index(), Some(i));
            assert!((d.direction_vector().unwrap().length() - 1.0).abs() < 1e-6);
        }
        assert_eq!(Action::Top.direction_vector().unwrap().y, -1.0);
    }
}
