//! The body contacts of one tick, as the separation found them, for what follows from them
//! (GRF's trips, `game/trip.rs`).

use crate::player::MAX_PLAYERS_PER_TEAM;

/// Most contacts kept in one tick; more than a crowded goalmouth holds. Later ones are dropped.
const CAPACITY: usize = 24;

/// One contact, measured before the two were pushed apart.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Contact {
    /// The two players, indices into the match's players, `i < j`.
    pub(crate) i: u8,
    pub(crate) j: u8,
    /// How far apart (m) their centres were.
    pub(crate) apart: f32,
    /// How far apart (m) they will be in 30 ms at their current runs (GRF's penetration).
    pub(crate) ahead: f32,
}

/// The contacts of one tick, in the order the separation resolved them. A fixed array: the tick
/// allocates nothing.
#[derive(Clone, Debug)]
pub(crate) struct Contacts {
    list: [Contact; CAPACITY],
    len: usize,
    /// The players (indices) in order along the pitch as the last tick's contact scan sorted them:
    /// the next scan starts from it, nearly sorted already. It changes how fast the scan is, never
    /// what it finds, so it is scratch like the rest. Its first `along_players` are the match's
    /// players, the rest empty slots ([`Contacts::order`]).
    along: [u8; 2 * MAX_PLAYERS_PER_TEAM],
    along_players: usize,
}

impl Default for Contacts {
    fn default() -> Self {
        Contacts {
            list: [Contact::default(); CAPACITY],
            len: 0,
            along: std::array::from_fn(|k| k as u8),
            along_players: 2 * MAX_PLAYERS_PER_TEAM,
        }
    }
}

impl Contacts {
    /// Forgets the last tick's contacts.
    pub(crate) fn clear(&mut self) {
        self.len = 0;
    }

    /// Notes a contact (dropped when full).
    pub(crate) fn push(&mut self, contact: Contact) {
        if self.len < CAPACITY {
            self.list[self.len] = contact;
            self.len += 1;
        }
    }

    /// The last order along the pitch of a match's `n` players (at most 22): each of `0..n` once.
    /// Sorting and scanning just these, not every slot a match could hold, spares a drill of a
    /// few players a pass over twenty empty ones each tick. An order kept for another number of
    /// players starts again from `0..n`.
    pub(crate) fn order(&mut self, n: usize) -> &mut [u8] {
        if n != self.along_players {
            self.along = std::array::from_fn(|k| k as u8);
            self.along_players = n;
        }
        &mut self.along[..n]
    }

    /// This tick's contacts.
    pub(crate) fn as_slice(&self) -> &[Contact] {
        &self.list[..self.len]
    }
}
