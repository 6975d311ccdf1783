//! The Super Mini Map, GRF's `extracted` representation (docs/grf-compatibility.md#smm): a `uint8` image of shape
//! `(H, W, 4)` (row-major, index `(y * W + x) * 4 + channel`), default 72 × 96, computed from one
//! controller's [`RawObservation`] (already in the controller's own frame).
//!
//! Channels: 0 the left team (the controller's own), 1 the right team, 2 the ball, 3 the active
//! player. Each object marks a single pixel with 255; everything else is 0. Every player in the
//! arrays is drawn, sent-off ones included (GRF draws the arrays as they are).

use super::RawObservation;

/// Default width in pixels (GRF `SMM_WIDTH`).
pub const SMM_WIDTH: usize = 96;
/// Default height in pixels (GRF `SMM_HEIGHT`).
pub const SMM_HEIGHT: usize = 72;
/// Channels per pixel: left team, right team, ball, active player.
pub const SMM_CHANNELS: usize = 4;

/// Value of a marked pixel.
const MARK: u8 = 255;
const LEFT_TEAM: usize = 0;
const RIGHT_TEAM: usize = 1;
const BALL: usize = 2;
const ACTIVE: usize = 3;
// GRF's MINIMAP_NORM_{X,Y}_{MIN,MAX}: x spans [-1, 1], y spans ±1/2.25.
const X_MIN: f64 = -1.0;
const X_MAX: f64 = 1.0;
const Y_MIN: f64 = -1.0 / 2.25;
const Y_MAX: f64 = 1.0 / 2.25;

/// Pixel `(px, py)` of the point `(x, y)`, exactly as GRF's `mark_points`: scaled in float64,
/// truncated toward zero, then clamped into the image (`width`, `height` ≥ 1).
fn pixel(x: f32, y: f32, width: usize, height: usize) -> (usize, usize) {
    // `as i64` truncates toward zero like Python's int() and saturates (NaN → 0).
    let px = ((f64::from(x) - X_MIN) / (X_MAX - X_MIN) * width as f64) as i64;
    let py = ((f64::from(y) - Y_MIN) / (Y_MAX - Y_MIN) * height as f64) as i64;
    (px.clamp(0, width as i64 - 1) as usize, py.clamp(0, height as i64 - 1) as usize)
}

/// Writes the Super Mini Map of `obs` into `out`, a `(height, width, 4)` row-major `u8` image
/// (index `(y * width + x) * 4 + channel`). `out` is cleared first; then 255 marks, per channel:
/// every left-team player (0), every right-team player (1), the ball's x, y (2) and
/// `left_team[active]` (3, nothing if `active` is -1). Players who were sent off are still
/// drawn, as in GRF. Pixel of a point: `px = int((x + 1) / 2 · W)`,
/// `py = int((y + 1/2.25) / (2/2.25) · H)`, truncated toward zero, clamped to `[0, W-1]` and
/// `[0, H-1]`.
///
/// `out.len()` must be `width * height * 4` (the Python binding checks it); otherwise nothing is
/// written (and debug builds panic). [`SMM_WIDTH`] × [`SMM_HEIGHT`] is GRF's default size.
pub fn encode_smm(obs: &RawObservation, width: usize, height: usize, out: &mut [u8]) {
    let expected = width.checked_mul(height).and_then(|n| n.checked_mul(SMM_CHANNELS));
    debug_assert_eq!(Some(out.len()), expected, "SMM buffer must hold width * height * 4 bytes");
    if Some(out.len()) != expected {
        return;
    }
    out.fill(0);
    if out.is_empty() {
        return;
    }
    let mut mark = |[x, y]: [f32; 2], channel: usize| {
        let (px, py) = pixel(x, y, width, height);
        out[(py * width + px) * SMM_CHANNELS + channel] = MARK;
    };
    for &p in &obs.left_team {
        mark(p, LEFT_TEAM);
    }
    for &p in &obs.right_team {
        mark(p, RIGHT_TEAM);
    }
    mark([obs.ball[0], obs.ball[1]], BALL);
    if let Some(&p) = usize::try_from(obs.active).ok().and_then(|i| obs.left_team.get(i)) {
        mark(p, ACTIVE);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LEN: usize = SMM_WIDTH * SMM_HEIGHT * SMM_CHANNELS;

    fn at(out: &[u8], x: usize, y: usize, channel: usize) -> u8 {
        out[(y * SMM_WIDTH + x) * SMM_CHANNELS + channel]
    }

    /// The marked pixels of `channel` as (x, y).
    fn marked(out: &[u8], channel: usize) -> Vec<(usize, usize)> {
        let mut v = Vec::new();
        for y in 0..SMM_HEIGHT {
            for x in 0..SMM_WIDTH {
                match at(out, x, y, channel) {
                    0 => {}
                    255 => v.push((x, y)),
                    other => panic!("value {other} at ({x}, {y}, {channel})"),
                }
            }
        }
        v
    }

    fn encode(obs: &RawObservation) -> Vec<u8> {
        let mut out = vec![7; LEN];
        encode_smm(obs, SMM_WIDTH, SMM_HEIGHT, &mut out);
        out
    }

    #[test]
    fn pixel_mapping() {
        assert_eq!(pixel(0.0, 0.0, 96, 72), (48, 36));
        // Right goal line and beyond clamp to the last column; left edge to the first.
        assert_eq!(pixel(1.0, 0.0, 96, 72).0, 95);
        assert_eq!(pixel(1.5, 0.0, 96, 72).0, 95);
        assert_eq!(pixel(-1.0, 0.0, 96, 72).0, 0);
        assert_eq!(pixel(-3.0, 0.0, 96, 72).0, 0);
        // int((-0.42 + 0.4444) / 0.8889 * 72) = int(1.98) = 1; the bottom touchline is row 70.
        assert_eq!(pixel(0.0, -0.42, 96, 72).1, 1);
        assert_eq!(pixel(0.0, 0.42, 96, 72).1, 70);
        assert_eq!(pixel(0.0, 0.5, 96, 72).1, 71);
        assert_eq!(pixel(0.0, -0.5, 96, 72).1, 0);
        // Truncation, not rounding: x = -0.99 → int(0.48) = 0; x = 0.0199 → int(48.96) = 48.
        assert_eq!(pixel(-0.99, 0.0, 96, 72).0, 0);
        assert_eq!(pixel(0.0199, 0.0, 96, 72).0, 48);
        // Other sizes scale the same way.
        assert_eq!(pixel(0.0, 0.0, 10, 5), (5, 2));
        assert_eq!(pixel(f32::NAN, f32::INFINITY, 10, 5), (0, 4));
    }

    #[test]
    fn channels_mark_teams_ball_and_active() {
        let obs = RawObservation {
            left_team: vec![[0.0, 0.0], [-0.5, 0.2]],
            right_team: vec![[0.5, -0.2], [1.0, 0.42], [0.9, 0.1]],
            ball: [0.25, 0.1, 3.0],
            active: 1,
            // Sent-off players are drawn all the same.
            left_team_active: vec![true, false],
            ..RawObservation::default()
        };
        let out = encode(&obs);
        let px = |p: [f32; 2]| pixel(p[0], p[1], SMM_WIDTH, SMM_HEIGHT);
        let mut left: Vec<_> = obs.left_team.iter().map(|&p| px(p)).collect();
        left.sort_by_key(|&(x, y)| (y, x));
        assert_eq!(marked(&out, 0), left);
        // (-0.5, 0.2): int(0.5 / 2 · 96) = 24, int(0.6444 / 0.8889 · 72) = int(52.2) = 52.
        assert_eq!(left, vec![(48, 36), (24, 52)]);
        let mut right: Vec<_> = obs.right_team.iter().map(|&p| px(p)).collect();
        right.sort_by_key(|&(x, y)| (y, x));
        assert_eq!(marked(&out, 1), right);
        assert_eq!(marked(&out, 2), vec![px([0.25, 0.1])]);
        assert_eq!(marked(&out, 3), vec![(24, 52)]);
    }

    #[test]
    fn no_active_player_leaves_channel_empty_and_overlaps_remark() {
        let obs =
            RawObservation { left_team: vec![[0.0, 0.0], [0.001, 0.001]], active: -1, ..RawObservation::default() };
        let out = encode(&obs);
        assert_eq!(marked(&out, 0), vec![(48, 36)]);
        assert!(marked(&out, 3).is_empty());
        // Ball at the default (0, 0).
        assert_eq!(marked(&out, 2), vec![(48, 36)]);
        // An active index outside the team draws nothing either.
        let out = encode(&RawObservation { active: 5, ..obs });
        assert!(marked(&out, 3).is_empty());
    }

    #[test]
    fn clears_the_buffer_first() {
        let out = encode(&RawObservation::default());
        // Only the ball (at the centre) is marked.
        let nonzero: Vec<usize> = (0..LEN).filter(|&i| out[i] != 0).collect();
        assert_eq!(nonzero, vec![(36 * SMM_WIDTH + 48) * SMM_CHANNELS + 2]);
    }

    #[test]
    #[cfg(not(debug_assertions))]
    fn wrong_length_writes_nothing() {
        let mut out = vec![7; 10];
        encode_smm(&RawObservation::default(), SMM_WIDTH, SMM_HEIGHT, &mut out);
        assert!(out.iter().all(|&v| v == 7));
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "SMM buffer")]
    fn wrong_length_is_caught_in_debug() {
        let mut out = vec![7; 10];
        encode_smm(&RawObservation::default(), SMM_WIDTH, SMM_HEIGHT, &mut out);
    }

    #[test]
    fn empty_image_is_fine() {
        let mut out = [];
        encode_smm(&RawObservation::default(), 0, SMM_HEIGHT, &mut out);
    }
}
