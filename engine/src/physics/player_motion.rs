//! Player kinematics: bounded acceleration and turning towards the desired velocity, and
//! position-based separation of bodies that overlap.

use glam::{Vec2, Vec4};

use super::contacts::{Contact, Contacts};
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH, RIM_HALF_LENGTH, RIM_HALF_WIDTH};
use crate::player::{MAX_PLAYERS_PER_TEAM, Player};

/// Radius of a player's body for collisions (m).
pub(crate) const BODY_RADIUS: f32 = 0.35;
/// Bodies overlap nearer than this (m): two radii.
pub(crate) const MIN_DIST: f32 = 2.0 * BODY_RADIUS;

/// A player's movement limits, from his attributes and team difficulty.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MotionLimits {
    /// Acceleration towards a faster desired velocity (m/s²).
    pub(crate) acceleration: f32,
    /// Deceleration (m/s²).
    pub(crate) deceleration: f32,
}

impl Default for MotionLimits {
    fn default() -> Self {
        MotionLimits { acceleration: 7.0, deceleration: 12.0 }
    }
}

// Facing turns at most 0.12 rad per tick (12 rad/s); cos and sin precomputed so that no
// transcendental function runs per tick.
pub(super) const TURN_COS: f32 = 0.992_808_6;
pub(super) const TURN_SIN: f32 = 0.119_712_2;

/// Moves `player` one tick of `dt` seconds at the velocity he asks for (m/s), turning to `look`
/// when he stands (a [`crate::game::PlayerInput`]'s velocity and look, after the match's caps).
pub(crate) fn move_player(player: &mut Player, velocity: Vec2, look: Vec2, limits: MotionLimits, dt: f32) {
    let mut desired = velocity;
    // Inputs that push a player further outside the pitch are dropped (docs/grf-compatibility.md#action-effects).
    if player.position.x.abs() > HALF_LENGTH + 2.0 && desired.x * player.position.x > 0.0 {
        desired.x = 0.0;
    }
    if player.position.y.abs() > HALF_WIDTH + 2.0 && desired.y * player.position.y > 0.0 {
        desired.y = 0.0;
    }
    let dv = desired - player.velocity;
    let speeding_up = desired.length_squared() > player.velocity.length_squared();
    let rate = if speeding_up { limits.acceleration } else { limits.deceleration };
    let max_dv = rate * dt;
    let len2 = dv.length_squared();
    player.velocity += if len2 > max_dv * max_dv { dv * (max_dv / len2.sqrt()) } else { dv };
    player.position += player.velocity * dt;

    let look = if desired.length_squared() > 0.25 { desired } else { look };
    turn_towards(&mut player.facing, look);
}

/// Keeps a player inside the pitch's rim (the advertising boards), stopping him against it.
pub(crate) fn keep_inside_rim(player: &mut Player) {
    let p = &mut player.position;
    if p.x.abs() > RIM_HALF_LENGTH {
        p.x = p.x.clamp(-RIM_HALF_LENGTH, RIM_HALF_LENGTH);
        player.velocity.x = 0.0;
    }
    if p.y.abs() > RIM_HALF_WIDTH {
        p.y = p.y.clamp(-RIM_HALF_WIDTH, RIM_HALF_WIDTH);
        player.velocity.y = 0.0;
    }
}

/// Turns the unit vector `facing` towards `target` by at most one tick's turn.
fn turn_towards(facing: &mut Vec2, target: Vec2) {
    let len2 = target.length_squared();
    if len2 < 1e-6 {
        return;
    }
    // cos(facing, target) >= TURN_COS, tested as facing·target >= TURN_COS·|target|: the
    // division normalising the target is then off the path to the branch (this function runs for
    // every player every tick, and that division's latency was most of its time).
    let len = len2.sqrt();
    if facing.dot(target) >= TURN_COS * len {
        *facing = target / len;
        return;
    }
    let t = target / len;
    let cross = facing.perp_dot(target);
    let s = if cross >= 0.0 { TURN_SIN } else { -TURN_SIN };
    let f = *facing;
    *facing = Vec2::new(f.x * TURN_COS - f.y * s, f.x * s + f.y * TURN_COS).normalize_or(t);
}

/// Share of an overlap the player on the ball gives way (the other takes the rest): GRF's
/// possession bias of +0.4 in a contact splits it 30 / 70 (GRF 2.10's body contact).
const CARRIER_SHARE: f32 = 0.3;
/// A player in contact with the man on the ball is drawn to a spot beside him and slightly in
/// front, 0.3π off his facing and a body's width out, this share of the way each tick (GRF's
/// carrier pull, 0.3 × balance): a challenger from behind is not locked there, he comes round.
const PULL_RATE: f32 = 0.002;
/// The pulled spot's angle off the carrier's facing (rad): 0.3π.
const PULL_ANGLE_COS: f32 = 0.587_785_3;
const PULL_ANGLE_SIN: f32 = 0.809_017;
/// How far (m) each of two players in contact, neither on the ball, steps aside per tick.
const SIDESTEP: f32 = 0.02;
/// How far ahead (s) a contact's depth is judged: GRF's 30 ms.
const CONTACT_LOOKAHEAD: f32 = 0.03;
/// Most a contact moves a player in one tick (m): GRF clamps offsets to 8 m/s × 10 ms.
const MAX_CONTACT_STEP: f32 = 0.08;

/// Pushes apart every pair of overlapping player bodies and removes the approaching part of their
/// relative velocity; then keeps everyone inside the rim. Equal shares, except that the player on
/// the ball (`owner`, an index into `players`) gives way less and draws the other round to his
/// side (GRF's body contact): nobody is locked head-on, and two bodies never drift along together.
///
/// Pairs are resolved in order, (0, 1), (0, 2), … (1, 2), …, each seeing the positions the pairs
/// before it left. Most ticks bring no contact at all, so a compact copy of the positions is
/// scanned first and only the rows (player `i` against everyone after him) that hold a contact
/// are resolved: the same pairs in the same order, so the same result bit for bit, without
/// walking every pair of `Player`s every tick.
pub(crate) fn separate_players(players: &mut [Player], owner: Option<usize>, contacts: &mut Contacts) {
    contacts.clear();
    let n = players.len();
    if n > MAX_PLAYERS {
        // More than a match holds (scenarios allow 11 a side): no compact copy, every row.
        for i in 0..n {
            resolve_contacts(players, i, owner, contacts);
        }
    } else {
        let mut bodies = Bodies::of(players);
        // Rows before the first that holds a contact hold none: start there.
        let first = bodies.first_row_with_contact(players, contacts.order(n)).unwrap_or(n);
        for i in first..n {
            if players[i].active && bodies.may_touch_later(i, n) {
                let moved = resolve_contacts(players, i, owner, contacts);
                // Only the players of this row's contacts moved: copying their positions alone
                // leaves the same bodies as copying everyone's (a row was most of the scan's cost).
                bodies.refresh(players, moved);
            }
        }
    }
    for p in players.iter_mut() {
        keep_inside_rim(p);
    }
}

/// Most players in a match.
const MAX_PLAYERS: usize = 2 * MAX_PLAYERS_PER_TEAM;
/// [`MAX_PLAYERS`] rounded up to whole groups of four, the width of the scan's SIMD operations.
const SLOTS: usize = MAX_PLAYERS.next_multiple_of(4);

/// The players' positions, x and y apart, for the contact scan of [`separate_players`]. An
/// inactive player (and each slot past the last player) stands at infinity, where nobody touches
/// him.
struct Bodies {
    x: [f32; SLOTS],
    y: [f32; SLOTS],
}

impl Bodies {
    /// The positions of `players` (at most [`MAX_PLAYERS`]).
    fn of(players: &[Player]) -> Bodies {
        let mut bodies = Bodies { x: [f32::INFINITY; SLOTS], y: [f32::INFINITY; SLOTS] };
        // The slots walked with the players (indexed by player, each store was bounds-checked).
        for ((x, y), p) in bodies.x.iter_mut().zip(&mut bodies.y).zip(players) {
            if p.active {
                (*x, *y) = (p.position.x, p.position.y);
            }
        }
        bodies
    }

    /// Copies again the positions of the players in `moved` (a bit per player, all active).
    fn refresh(&mut self, players: &[Player], mut moved: u32) {
        while moved != 0 {
            let k = moved.trailing_zeros() as usize;
            moved &= moved - 1;
            self.x[k] = players[k].position.x;
            self.y[k] = players[k].position.y;
        }
    }

    /// The first row (player `i` against everyone after him) that may hold a contact,
    /// as [`Bodies::may_touch_later`] judges each row, without scanning every row: the match's
    /// players sorted along the pitch (`along`, last tick's order, kept for the next), each is
    /// compared only with those less than a contact's distance further along. A pair that far
    /// apart in x is at least as far apart in the squared distance as the row scan computes it
    /// (rounding is monotonic), so no pair the row scan finds is missed. With any active position
    /// not finite, every row is scanned (`Some(0)`).
    ///
    /// Never inlined: inlined into the tick, its loops cost 2 % of a full match's step more (the
    /// tick's values it keeps in registers crowd them out).
    #[inline(never)]
    fn first_row_with_contact(&self, players: &[Player], along: &mut [u8]) -> Option<usize> {
        let x = |k: u8| self.x[k as usize];
        // Insertion sort: players move centimetres a tick, so this is a pass with few swaps.
        // Inactive players are at infinity, at the end.
        for k in 1..along.len() {
            let a = along[k];
            let mut m = k;
            while m > 0 && x(along[m - 1]) > x(a) {
                along[m] = along[m - 1];
                m -= 1;
            }
            along[m] = a;
        }
        let mut first = None::<usize>;
        for (k, &a) in along.iter().enumerate() {
            let (xa, ya) = (x(a), self.y[a as usize]);
            if !xa.is_finite() || !ya.is_finite() {
                // Inactive players stand at infinity (tested first: it spares the look-up of every
                // player's flag); an active one off the map is a position gone wrong.
                if players[a as usize].active {
                    return Some(0);
                }
                continue;
            }
            for &b in &along[k + 1..] {
                let dx = x(b) - xa;
                if dx >= MIN_DIST {
                    break;
                }
                let dy = self.y[b as usize] - ya;
                // (A player whose position is not finite is caught as `a` on his own turn.)
                if dx * dx + dy * dy < MIN_DIST * MIN_DIST {
                    let row = a.min(b) as usize;
                    first = Some(first.map_or(row, |f| f.min(row)));
                }
            }
        }
        first
    }

    /// Whether player `i` may touch any of the players after him, up to `n`: the squared
    /// distance computed as [`resolve_contacts`] computes it, four players at a time (glam's
    /// `Vec4` is SIMD), and true also for anything it cannot rule out (a non-finite position), so
    /// a row it passes over holds no contact. Only the groups that hold players are scanned (a
    /// drill has a handful).
    fn may_touch_later(&self, i: usize, n: usize) -> bool {
        let (xi, yi) = (Vec4::splat(self.x[i]), Vec4::splat(self.y[i]));
        let apart = Vec4::splat(MIN_DIST * MIN_DIST);
        let mut near = 0u32;
        for c in (i + 1) / 4..n.div_ceil(4) {
            let dx = Vec4::from_slice(&self.x[4 * c..]) - xi;
            let dy = Vec4::from_slice(&self.y[4 * c..]) - yi;
            near |= (!(dx * dx + dy * dy).cmpge(apart).bitmask() & 0b1111) << (4 * c);
        }
        near >> (i + 1) != 0
    }
}

/// Resolves the contacts of player `i` with each player after him, in order, noting each in
/// `contacts`. Returns the players it moved, a bit each (those past the 32nd left out): `i` and
/// everyone in contact with him.
fn resolve_contacts(players: &mut [Player], i: usize, owner: Option<usize>, contacts: &mut Contacts) -> u32 {
    let mut moved = 0u32;
    if !players[i].active {
        return moved;
    }
    for j in (i + 1)..players.len() {
        if !players[j].active {
            continue;
        }
        let d = players[j].position - players[i].position;
        let d2 = d.length_squared();
        if d2 >= MIN_DIST * MIN_DIST {
            continue;
        }
        let dist = d2.sqrt();
        // Two bodies on the same spot part across the pitch, the lower index to -y, so that
        // neither pushes the other along the length of the pitch.
        let normal = if dist > 1e-5 { d / dist } else { Vec2::new(0.0, 1.0) };
        let overlap = MIN_DIST - dist;
        let ahead = (d + (players[j].velocity - players[i].velocity) * CONTACT_LOOKAHEAD).length();
        contacts.push(Contact { i: i as u8, j: j as u8, apart: dist, ahead });
        moved |= bit(i) | bit(j);
        let share_i = match owner {
            Some(o) if o == i => CARRIER_SHARE,
            Some(o) if o == j => 1.0 - CARRIER_SHARE,
            _ => 0.5,
        };
        players[i].position -= normal * (overlap * share_i).min(MAX_CONTACT_STEP);
        players[j].position += normal * (overlap * (1.0 - share_i)).min(MAX_CONTACT_STEP);
        let closing = (players[j].velocity - players[i].velocity).dot(normal);
        if closing < 0.0 {
            let impulse = normal * (closing * 0.5);
            players[i].velocity += impulse;
            players[j].velocity -= impulse;
        }
        match owner {
            Some(o) if o == i => pull_round(players, i, j),
            Some(o) if o == j => pull_round(players, j, i),
            // Neither has the ball: each steps aside round the other (GRF's players share
            // each other's movement in a contact), so two bodies pushing head-on slide past
            // each other instead of drifting along locked together.
            _ => {
                let side = normal.perp() * SIDESTEP;
                players[i].position -= side;
                players[j].position += side;
            }
        }
    }
    moved
}

/// Player `k`'s bit in a set of players (none past the 32nd).
fn bit(k: usize) -> u32 {
    1u32.checked_shl(k as u32).unwrap_or(0)
}

/// Draws `other`, in contact with the carrier `carrier`, towards the spot beside the carrier on
/// his side, 0.3π off the carrier's facing and a body's width out.
fn pull_round(players: &mut [Player], carrier: usize, other: usize) {
    let c = &players[carrier];
    let f = c.facing;
    let side = if f.perp_dot(players[other].position - c.position) >= 0.0 { 1.0 } else { -1.0 };
    let beside = Vec2::new(
        f.x * PULL_ANGLE_COS - side * f.y * PULL_ANGLE_SIN,
        side * f.x * PULL_ANGLE_SIN + f.y * PULL_ANGLE_COS,
    );
    let spot = c.position + beside * (2.0 * BODY_RADIUS);
    let o = &mut players[other];
    let step = (spot - o.position) * PULL_RATE;
    o.position += step.clamp_length_max(MAX_CONTACT_STEP);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;

    /// 22 players in a `width` × two-thirds-of-it box (6 m: plenty of contacts; 60 m: a few), a
    /// few inactive.
    fn crowd(seed: u32, width: f32) -> Vec<Player> {
        let mut state = seed.wrapping_mul(2_654_435_761).wrapping_add(1);
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state % 10_000) as f32 / 10_000.0
        };
        (0..MAX_PLAYERS)
            .map(|g| {
                let side = if g < MAX_PLAYERS_PER_TEAM { Side::Left } else { Side::Right };
                let mut p = Player::new(side, g % MAX_PLAYERS_PER_TEAM, Role::CM, Vec2::ZERO, Vec2::ZERO);
                p.position = Vec2::new(width * (next() - 0.5), width / 1.5 * (next() - 0.5));
                p.velocity = Vec2::new(4.0 * next() - 2.0, 4.0 * next() - 2.0);
                p.active = next() > 0.1;
                p
            })
            .collect()
    }

    #[test]
    fn the_contact_scan_resolves_exactly_as_every_row_would() {
        // One scan's scratch for all, as a match keeps it: each scan starts from the last one's
        // order along the pitch.
        let mut a = Contacts::default();
        for seed in 0..600 {
            let owner = (seed % 3 != 0).then_some(seed as usize % MAX_PLAYERS);
            let mut scanned = crowd(seed, if seed % 2 == 0 { 6.0 } else { 60.0 });
            if seed % 5 == 0 {
                // A drill's handful of players.
                scanned.truncate(3 + seed as usize % 7);
            }
            if seed % 7 == 0 {
                // A position gone bad: every row is scanned, as before.
                let last = scanned.len() - 1;
                scanned[last].position.x = f32::NAN;
            }
            let mut every_row = scanned.clone();
            let mut b = Contacts::default();
            separate_players(&mut scanned, owner, &mut a);
            for i in 0..every_row.len() {
                resolve_contacts(&mut every_row, i, owner, &mut b);
            }
            // Bit for bit (a NaN is not equal to itself).
            let bits = |c: &Contacts| {
                c.as_slice().iter().map(|c| (c.i, c.j, c.apart.to_bits(), c.ahead.to_bits())).collect::<Vec<_>>()
            };
            assert_eq!(bits(&a), bits(&b));
            every_row.iter_mut().for_each(keep_inside_rim);
            for (a, b) in scanned.iter().zip(&every_row) {
                assert_eq!(a.position.to_array().map(f32::to_bits), b.position.to_array().map(f32::to_bits));
                assert_eq!(a.velocity.to_array().map(f32::to_bits), b.velocity.to_array().map(f32::to_bits));
            }
        }
    }
}
