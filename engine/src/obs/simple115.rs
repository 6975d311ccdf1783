//! The `simple115v2` and legacy `simple115` float vectors (docs/grf-compatibility.md#simple115): 115 `f32`
//! per controller, computed from its [`RawObservation`] (already in the controller's own frame, so "left" is the
//! controller's team).
//!
//! | index   | content                                                        |
//! |---------|----------------------------------------------------------------|
//! | 0–21    | left team positions `x0, y0, x1, y1, …`                        |
//! | 22–43   | left team directions                                           |
//! | 44–65   | right team positions                                           |
//! | 66–87   | right team directions                                          |
//! | 88–90   | ball `x, y, z`                                                 |
//! | 91–93   | ball direction `x, y, z`                                       |
//! | 94–96   | ball ownership one-hot: nobody (-1), left (0), right (1)       |
//! | 97–107  | active player one-hot over 11 slots (all zero if `active` = -1) |
//! | 108–114 | game mode one-hot over 7 modes                                 |
//!
//! Missing players (teams of fewer than 11) are padded with -1: per block in `simple115v2`,
//! once at the end of the 88-value player region in the legacy `simple115`.

use super::RawObservation;

/// Length of both encodings.
pub const SIMPLE115_LEN: usize = 115;

/// Players per team slot count of the encoding.
const SLOTS: usize = 11;
/// Values per player block (11 players × x, y).
const BLOCK: usize = 2 * SLOTS;
/// End of the player region (four blocks).
const PLAYERS_END: usize = 4 * BLOCK;
const BALL: usize = 88;
const BALL_DIRECTION: usize = 91;
const BALL_OWNED_TEAM: usize = 94;
const ACTIVE: usize = 97;
const GAME_MODE: usize = 108;
/// Padding value for missing players.
const PAD: f32 = -1.0;

/// The four player blocks in encoding order.
fn player_blocks(obs: &RawObservation) -> [&[[f32; 2]]; 4] {
    [&obs.left_team, &obs.left_team_direction, &obs.right_team, &obs.right_team_direction]
}

/// Writes `pairs` flattened from `out[0]` on, at most `out.len() / 2` of them; returns the number
/// of values written.
fn write_pairs(pairs: &[[f32; 2]], out: &mut [f32]) -> usize {
    let mut n = 0;
    for (dst, src) in out.chunks_exact_mut(2).zip(pairs) {
        dst.copy_from_slice(src);
        n += 2;
    }
    n
}

/// Ball, ownership, active player and game mode (indices 88–114); `out[88..]` must be zero.
fn encode_tail(obs: &RawObservation, out: &mut [f32; SIMPLE115_LEN]) {
    out[BALL..BALL + 3].copy_from_slice(&obs.ball);
    out[BALL_DIRECTION..BALL_DIRECTION + 3].copy_from_slice(&obs.ball_direction);
    // GRF asserts -1 ≤ team ≤ 1; anything else leaves the one-hot empty.
    if let Ok(slot) = usize::try_from(obs.ball_owned_team + 1)
        && slot < 3
    {
        out[BALL_OWNED_TEAM + slot] = 1.0;
    }
    if let Ok(slot) = usize::try_from(obs.active)
        && slot < SLOTS
    {
        out[ACTIVE + slot] = 1.0;
    }
    out[GAME_MODE + obs.game_mode as usize] = 1.0;
}

/// `simple115v2` (GRF `fixed_positions=True`): each of the four player blocks is padded with -1
/// to exactly 22 values, so every index has a fixed meaning whatever the team sizes.
///
/// Values are unbounded `f32` (GRF's space is `Box(-inf, inf)`); in practice positions lie in
/// [-1.01, 1.01] × [-0.43, 0.43], one-hots in {0, 1} and padding is -1.
pub fn encode_simple115v2(obs: &RawObservation, out: &mut [f32; SIMPLE115_LEN]) {
    out.fill(0.0);
    for (i, block) in player_blocks(obs).into_iter().enumerate() {
        let dst = &mut out[i * BLOCK..(i + 1) * BLOCK];
        let written = write_pairs(block, dst);
        dst[written..].fill(PAD);
    }
    encode_tail(obs, out);
}

/// Legacy `simple115` (GRF `fixed_positions=False`): the four player blocks are written
/// back-to-back (2·N_left + 2·N_left + 2·N_right + 2·N_right values) and only the end of the
/// 88-value player region is padded with -1, so with fewer than 11 left players the right team's
/// data moves to lower indices. Identical to [`encode_simple115v2`] for 11 v 11.
pub fn encode_simple115(obs: &RawObservation, out: &mut [f32; SIMPLE115_LEN]) {
    out.fill(0.0);
    let mut at = 0;
    for block in player_blocks(obs) {
        at += write_pairs(block, &mut out[at..PLAYERS_END]);
    }
    out[at..PLAYERS_END].fill(PAD);
    encode_tail(obs, out);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::game::GameMode;

    /// A 2 v 3 observation with distinguishable values: left positions 1.x, left directions 2.x,
    /// right positions 3.x, right directions 4.x.
    fn small() -> RawObservation {
        RawObservation {
            left_team: vec![[1.0, 1.1], [1.2, 1.3]],
            left_team_direction: vec![[2.0, 2.1], [2.2, 2.3]],
            right_team: vec![[3.0, 3.1], [3.2, 3.3], [3.4, 3.5]],
            right_team_direction: vec![[4.0, 4.1], [4.2, 4.3], [4.4, 4.5]],
            ball: [0.5, -0.25, 0.11],
            ball_direction: [0.01, -0.02, 0.03],
            ball_owned_team: -1,
            active: 1,
            game_mode: GameMode::Normal,
            ..RawObservation::default()
        }
    }

    fn full() -> RawObservation {
        let team = |base: f32| (0..11).map(|i| [base + i as f32 * 0.01, -base - i as f32 * 0.01]).collect();
        RawObservation {
            left_team: team(0.1),
            left_team_direction: team(0.2),
            right_team: team(0.3),
            right_team_direction: team(0.4),
            ..RawObservation::default()
        }
    }

    fn v2(obs: &RawObservation) -> [f32; 115] {
        let mut out = [f32::NAN; 115];
        encode_simple115v2(obs, &mut out);
        out
    }

    fn legacy(obs: &RawObservation) -> [f32; 115] {
        let mut out = [f32::NAN; 115];
        encode_simple115(obs, &mut out);
        out
    }

    #[test]
    fn full_teams_land_in_their_blocks_in_both_variants() {
        let obs = full();
        for out in [v2(&obs), legacy(&obs)] {
            for i in 0..11 {
                assert_eq!(out[2 * i..2 * i + 2], obs.left_team[i]);
                assert_eq!(out[22 + 2 * i..22 + 2 * i + 2], obs.left_team_direction[i]);
                assert_eq!(out[44 + 2 * i..44 + 2 * i + 2], obs.right_team[i]);
                assert_eq!(out[66 + 2 * i..66 + 2 * i + 2], obs.right_team_direction[i]);
            }
        }
        assert_eq!(v2(&obs), legacy(&obs));
    }

    #[test]
    fn v2_pads_each_block_independently() {
        let out = v2(&small());
        assert_eq!(out[0..4], [1.0, 1.1, 1.2, 1.3]);
        assert!(out[4..22].iter().all(|&v| v == -1.0));
        assert_eq!(out[22..26], [2.0, 2.1, 2.2, 2.3]);
        assert!(out[26..44].iter().all(|&v| v == -1.0));
        assert_eq!(out[44..50], [3.0, 3.1, 3.2, 3.3, 3.4, 3.5]);
        assert!(out[50..66].iter().all(|&v| v == -1.0));
        assert_eq!(out[66..72], [4.0, 4.1, 4.2, 4.3, 4.4, 4.5]);
        assert!(out[72..88].iter().all(|&v| v == -1.0));
    }

    #[test]
    fn legacy_packs_blocks_and_pads_only_the_end() {
        let out = legacy(&small());
        assert_eq!(out[0..4], [1.0, 1.1, 1.2, 1.3]);
        assert_eq!(out[4..8], [2.0, 2.1, 2.2, 2.3]);
        // The right team's data shifts down to index 8.
        assert_eq!(out[8..14], [3.0, 3.1, 3.2, 3.3, 3.4, 3.5]);
        assert_eq!(out[14..20], [4.0, 4.1, 4.2, 4.3, 4.4, 4.5]);
        assert!(out[20..88].iter().all(|&v| v == -1.0));
        // Everything from the ball on is identical to v2.
        assert_eq!(out[88..], v2(&small())[88..]);
    }

    #[test]
    fn ball_and_direction() {
        let out = v2(&small());
        assert_eq!(out[88..91], [0.5, -0.25, 0.11]);
        assert_eq!(out[91..94], [0.01, -0.02, 0.03]);
    }

    #[test]
    fn ownership_one_hot() {
        let mut obs = small();
        for (team, expected) in [(-1, [1.0, 0.0, 0.0]), (0, [0.0, 1.0, 0.0]), (1, [0.0, 0.0, 1.0]), (7, [0.0; 3])] {
            obs.ball_owned_team = team;
            assert_eq!(v2(&obs)[94..97], expected, "team {team}");
            assert_eq!(legacy(&obs)[94..97], expected, "team {team}");
        }
    }

    #[test]
    fn active_one_hot() {
        let mut obs = full();
        for active in 0..11 {
            obs.active = active;
            let out = v2(&obs);
            for slot in 0..11 {
                assert_eq!(out[97 + slot], if slot as i32 == active { 1.0 } else { 0.0 });
            }
        }
        for active in [-1, 11, 40] {
            obs.active = active;
            assert!(v2(&obs)[97..108].iter().all(|&v| v == 0.0), "active {active}");
        }
    }

    #[test]
    fn game_mode_one_hot() {
        let mut obs = small();
        for mode in GameMode::ALL {
            obs.game_mode = mode;
            let out = v2(&obs);
            for m in 0..7 {
                assert_eq!(out[108 + m], if m == mode as usize { 1.0 } else { 0.0 }, "{mode:?}");
            }
        }
    }

    #[test]
    fn overwrites_stale_contents() {
        let mut out = [9.0; 115];
        encode_simple115v2(&RawObservation::default(), &mut out);
        // Empty teams: all padding; ball zero; owner team 0 (left), active 0 and Normal (defaults).
        assert!(out[..88].iter().all(|&v| v == -1.0));
        assert!(out[88..94].iter().all(|&v| v == 0.0));
        assert_eq!(out[94..97], [0.0, 1.0, 0.0]);
        assert_eq!(out[97], 1.0);
        assert!(out[98..108].iter().all(|&v| v == 0.0));
        assert_eq!(out[108..115], [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    }
}
