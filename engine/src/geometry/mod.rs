//! Pitch geometry and the one converter between engine metres and GRF's normalised coordinates.

pub mod coords;
pub mod pitch;

pub use coords::{Side, TeamFrame};
