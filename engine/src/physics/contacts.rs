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
    /// what it finds, so it is scratch like the rest.
    pub(crate) along: [u8; 2 * MAX_PLAYERS_PER_TEAM],
}

impl Default for Contacts {
    fn default() -> Self {
        Contacts { list: [Contact::default(); CAPACITY], len: 0, along: std::array::from_fn(|k| k as u8) }
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

    /// This tick's contacts.
    pub(crate) fn as_slice(&self) -> &[Contact] {
        &self.list[..self.len]
    }
}
