//! Observation encoders: pure functions of the match state writing into caller-owned buffers,
//! with no allocation.
//!
//! | encoder | docs/grf-compatibility.md | shape | dtype | values |
//! |---|---|---|---|---|
//! | [`RawObservation`] (`raw`) | #raw-observation | dict of arrays | f32 / ints | positions x ∈ [-1.01, 1.01], y ∈ [-0.43, 0.43] |
//! | [`encode_simple115v2`] (`simple115v2`) | #simple115 | `(115,)` | f32 | unbounded; players/ball in env units, one-hots 0/1, padding -1 |
//! | [`encode_simple115`] (legacy `simple115`) | #simple115 | `(115,)` | f32 | as v2, right team shifted when the left has < 11 players |
//! | [`encode_smm`] (Super Mini Map, `extracted`) | #smm | `(H, W, 4)`, default `(72, 96, 4)` | u8 | 0 or 255 |
//! | [`FrameStack`] (`stacked=True`) | #frame-stacking | last axis × 4: `(460,)` or `(H, W, 16)` | as the frame | as the frame |
//!
//! Each encoder works on one controller's [`RawObservation`], which is already in that
//! controller's frame ("left" = its own team; [`crate::Env::observations`] gives one per
//! controller); stacking several controllers into GRF's leading `M` axis is the caller's job.

mod raw;
mod simple115;
mod smm;
mod stack;

pub use raw::RawObservation;
pub use simple115::{SIMPLE115_LEN, encode_simple115, encode_simple115v2};
pub use smm::{SMM_CHANNELS, SMM_HEIGHT, SMM_WIDTH, encode_smm};
pub use stack::FrameStack;
