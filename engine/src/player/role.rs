//! Player roles, numbered as GRF's `e_PlayerRole` (GRF 2.10's raw observation, `left_team_roles`).

use serde::{Deserialize, Serialize};

/// A player's role in the formation. The numeric value is the one observations carry
/// (`left_team_roles`), as in GRF: 0 GK … 9 CF.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[repr(u8)]
pub enum Role {
    /// Goalkeeper.
    GK = 0,
    /// Centre back.
    CB = 1,
    /// Left back.
    LB = 2,
    /// Right back.
    RB = 3,
    /// Defensive midfield.
    DM = 4,
    /// Central midfield.
    CM = 5,
    /// Left midfield.
    LM = 6,
    /// Right midfield.
    RM = 7,
    /// Attacking midfield.
    AM = 8,
    /// Centre forward.
    CF = 9,
}

impl Role {
    /// All roles in numeric order.
    pub const ALL: [Role; 10] =
        [Role::GK, Role::CB, Role::LB, Role::RB, Role::DM, Role::CM, Role::LM, Role::RM, Role::AM, Role::CF];

    /// The role's short name (`"GK"`, `"CB"`, …).
    pub fn name(self) -> &'static str {
        match self {
            Role::GK => "GK",
            Role::CB => "CB",
            Role::LB => "LB",
            Role::RB => "RB",
            Role::DM => "DM",
            Role::CM => "CM",
            Role::LM => "LM",
            Role::RM => "RM",
            Role::AM => "AM",
            Role::CF => "CF",
        }
    }

    /// Parses a short name (`"CB"`); `None` for anything else.
    pub fn from_name(name: &str) -> Option<Role> {
        Role::ALL.into_iter().find(|r| r.name() == name)
    }

    /// Whether the role is a defender's (CB, LB, RB): used by the AI to keep a back line.
    pub fn is_defender(self) -> bool {
        matches!(self, Role::CB | Role::LB | Role::RB)
    }

    /// Whether the role is a forward's, attacking or wide midfielder's: these go into the box at a corner.
    pub fn is_attacker(self) -> bool {
        matches!(self, Role::CF | Role::AM | Role::LM | Role::RM)
    }

    /// How attacking the role plays on the ball, in [0, 1]: GRF 2.10's mind-set per role (GK and
    /// CB 0, full backs and DM 0.25, wide and central midfield 0.5, AM 0.75, CF 1). Below 0.25 a
    /// player is prone to clear a contested ball first time rather than control it.
    pub fn mind_set(self) -> f32 {
        match self {
            Role::GK | Role::CB => 0.0,
            Role::LB | Role::RB | Role::DM => 0.25,
            Role::CM | Role::LM | Role::RM => 0.5,
            Role::AM => 0.75,
            Role::CF => 1.0,
        }
    }
}

impl std::fmt::Display for Role {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mind_set_runs_from_the_keeper_to_the_centre_forward() {
        let mind_sets = [Role::GK, Role::CB, Role::RB, Role::DM, Role::CM, Role::AM, Role::CF].map(Role::mind_set);
        assert_eq!(mind_sets, [0.0, 0.0, 0.25, 0.25, 0.5, 0.75, 1.0]);
    }

    #[test]
    fn names_round_trip_and_numbers_match_grf() {
        for (i, role) in Role::ALL.into_iter().enumerate() {
            assert_eq!(role as usize, i);
            assert_eq!(Role::from_name(role.name()), Some(role));
        }
        assert_eq!(Role::from_name("XX"), None);
    }
}
