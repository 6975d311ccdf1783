//! Observation encoders: pure functions of the match state writing into caller-owned buffers.
//! `raw` (GRF's dict of arrays, grf.md §3.1) is here; simple115v2, SMM and pixels come with the
//! Python issue.

mod raw;

pub use raw::RawObservation;
