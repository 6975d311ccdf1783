//! Frame stacking (docs/grf-compatibility.md#frame-stacking, GRF's `FrameStack(k=4)` behind `stacked=True`):
//! the last `k` encoded observations concatenated along the last axis, oldest first.
//!
//! A frame is viewed as `(n_pixels, channels)`: an `(H, W, C)` Super Mini Map has `channels = C`
//! and stacks to `(H, W, k·C)` with, per pixel, `[t-k+1 (C values), …, t-1, t]`; a flat `(115,)`
//! vector has `channels = 115` (one "pixel") and stacks to `(115·k,)` = `[t-k+1 block, …, t]`.

/// A ring buffer of the last `k` frames of `frame_len` values each, allocated once. Serialisable,
/// so that a saved environment state can carry its stacked frames (GRF saves its deque too).
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct FrameStack<T> {
    /// `k` slots of `frame_len` values.
    frames: Vec<T>,
    frame_len: usize,
    channels: usize,
    k: usize,
    /// Slot of the oldest frame (the next to be overwritten).
    oldest: usize,
}

impl<T: Copy + Default> FrameStack<T> {
    /// Whether `other` (for instance one read back from bytes) has this stack's shape and is
    /// internally consistent, so that it can replace this one.
    pub fn same_shape(&self, other: &FrameStack<T>) -> bool {
        other.frame_len == self.frame_len
            && other.channels == self.channels
            && other.k == self.k
            && other.frames.len() == self.frames.len()
            && other.oldest < other.k
    }

    /// A stack of `k` frames of `frame_len` values, each frame viewed as `(frame_len / channels,
    /// channels)`; all slots start at `T::default()`. GRF always uses `k = 4`.
    ///
    /// # Panics
    /// When `k` or `channels` is 0 or `channels` does not divide `frame_len` (construction-time
    /// programming errors).
    pub fn new(frame_len: usize, channels: usize, k: usize) -> FrameStack<T> {
        assert!(k > 0, "FrameStack needs k ≥ 1");
        assert!(
            channels > 0 && frame_len.is_multiple_of(channels),
            "FrameStack: {channels} channels do not divide a frame of {frame_len}"
        );
        FrameStack { frames: vec![T::default(); frame_len * k], frame_len, channels, k, oldest: 0 }
    }

    /// Values per frame.
    pub fn frame_len(&self) -> usize {
        self.frame_len
    }

    /// Channels per pixel of a frame (its last axis).
    pub fn channels(&self) -> usize {
        self.channels
    }

    /// Number of frames kept.
    pub fn k(&self) -> usize {
        self.k
    }

    /// Length of the stacked output: `k * frame_len`.
    pub fn stacked_len(&self) -> usize {
        self.frames.len()
    }

    /// Fills every slot with `first` (GRF's reset: `k` copies of the first observation).
    ///
    /// `first.len()` must be [`FrameStack::frame_len`]; otherwise nothing changes (and debug
    /// builds panic).
    pub fn reset(&mut self, first: &[T]) {
        debug_assert_eq!(first.len(), self.frame_len, "FrameStack::reset: wrong frame length");
        if first.len() != self.frame_len {
            return;
        }
        for slot in self.frames.chunks_exact_mut(self.frame_len.max(1)) {
            slot.copy_from_slice(first);
        }
        self.oldest = 0;
    }

    /// Appends `frame` as the newest, dropping the oldest.
    ///
    /// `frame.len()` must be [`FrameStack::frame_len`]; otherwise nothing changes (and debug
    /// builds panic).
    pub fn push(&mut self, frame: &[T]) {
        debug_assert_eq!(frame.len(), self.frame_len, "FrameStack::push: wrong frame length");
        if frame.len() != self.frame_len {
            return;
        }
        let start = self.oldest * self.frame_len;
        self.frames[start..start + self.frame_len].copy_from_slice(frame);
        self.oldest = (self.oldest + 1) % self.k;
    }

    /// Writes the frames concatenated along the last axis, oldest first: for pixel `p` and age
    /// slot `j` (0 = oldest, `k - 1` = newest), `out[(p * k + j) * channels + c]` is channel `c`
    /// of pixel `p` of that frame.
    ///
    /// `out.len()` must be [`FrameStack::stacked_len`]; otherwise nothing is written (and debug
    /// builds panic).
    pub fn write_stacked(&self, out: &mut [T]) {
        debug_assert_eq!(out.len(), self.stacked_len(), "FrameStack::write_stacked: wrong output length");
        if out.len() != self.stacked_len() || out.is_empty() {
            return;
        }
        let (k, c) = (self.k, self.channels);
        for j in 0..k {
            let slot = (self.oldest + j) % k;
            let frame = &self.frames[slot * self.frame_len..(slot + 1) * self.frame_len];
            // Constant channel counts let the per-pixel copy inline (SMM 4, pixels 3, gray 1).
            match c {
                1 => interleave::<T, 1>(frame, out, k, j),
                3 => interleave::<T, 3>(frame, out, k, j),
                4 => interleave::<T, 4>(frame, out, k, j),
                _ => {
                    for (dst, src) in out.chunks_exact_mut(k * c).zip(frame.chunks_exact(c)) {
                        dst[j * c..(j + 1) * c].copy_from_slice(src);
                    }
                }
            }
        }
    }
}

impl FrameStack<f32> {
    /// Whether every value held is finite (a stack read back from bytes is checked with this
    /// before its frames reach a learner).
    pub fn is_finite(&self) -> bool {
        self.frames.iter().all(|v| v.is_finite())
    }
}

/// Copies each `C`-channel pixel of `frame` into age slot `j` of the matching `k·C` pixel of `out`.
fn interleave<T: Copy, const C: usize>(frame: &[T], out: &mut [T], k: usize, j: usize) {
    for (dst, src) in out.chunks_exact_mut(k * C).zip(frame.as_chunks::<C>().0) {
        dst[j * C..(j + 1) * C].copy_from_slice(src);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stacked<T: Copy + Default>(s: &FrameStack<T>) -> Vec<T> {
        let mut out = vec![T::default(); s.stacked_len()];
        s.write_stacked(&mut out);
        out
    }

    #[test]
    fn reset_replicates_the_first_frame() {
        let mut s = FrameStack::<f32>::new(3, 3, 4);
        s.reset(&[1.0, 2.0, 3.0]);
        assert_eq!(stacked(&s), [1.0, 2.0, 3.0].repeat(4));
    }

    #[test]
    fn flat_vectors_stack_oldest_block_first() {
        let mut s = FrameStack::<f32>::new(2, 2, 4);
        s.reset(&[0.0, 0.5]);
        s.push(&[1.0, 1.5]);
        s.push(&[2.0, 2.5]);
        assert_eq!(stacked(&s), [0.0, 0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5]);
        s.push(&[3.0, 3.5]);
        s.push(&[4.0, 4.5]);
        assert_eq!(stacked(&s), [1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5]);
        // Wraps around the ring many times.
        for t in 5..20 {
            s.push(&[t as f32, t as f32 + 0.5]);
        }
        assert_eq!(stacked(&s), [16.0, 16.5, 17.0, 17.5, 18.0, 18.5, 19.0, 19.5]);
    }

    #[test]
    fn images_stack_along_the_channel_axis() {
        // A 2-pixel, 2-channel frame: value = 10 * t + 2 * pixel + channel.
        let frame = |t: u8| [10 * t, 10 * t + 1, 10 * t + 2, 10 * t + 3];
        let mut s = FrameStack::<u8>::new(4, 2, 4);
        s.reset(&frame(0));
        for t in 1..=5 {
            s.push(&frame(t));
        }
        // Frames t = 2..=5 remain; per pixel [t-3, t-2, t-1, t] × 2 channels.
        assert_eq!(stacked(&s), [20, 21, 30, 31, 40, 41, 50, 51, 22, 23, 32, 33, 42, 43, 52, 53]);
    }

    #[test]
    fn every_channel_count_matches_the_definition() {
        // 3 pixels, c channels; frame t holds 100 t + c p + ch; 6 frames pushed after the reset.
        for c in 1..=6 {
            let frame = |t: usize| (0..3 * c).map(|i| (100 * t + i) as u32).collect::<Vec<_>>();
            let mut s = FrameStack::<u32>::new(3 * c, c, 4);
            s.reset(&frame(0));
            for t in 1..=6 {
                s.push(&frame(t));
                let out = stacked(&s);
                for p in 0..3 {
                    for j in 0..4 {
                        let age_t = (t + j).saturating_sub(3);
                        for ch in 0..c {
                            assert_eq!(out[(p * 4 + j) * c + ch], (100 * age_t + c * p + ch) as u32, "c {c} t {t}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn reset_discards_history() {
        let mut s = FrameStack::<u8>::new(1, 1, 4);
        s.reset(&[1]);
        s.push(&[2]);
        s.push(&[3]);
        s.reset(&[9]);
        assert_eq!(stacked(&s), [9, 9, 9, 9]);
        s.push(&[8]);
        assert_eq!(stacked(&s), [9, 9, 9, 8]);
    }

    #[test]
    fn smm_shape() {
        use crate::obs::{SMM_CHANNELS, SMM_HEIGHT, SMM_WIDTH};
        let len = SMM_WIDTH * SMM_HEIGHT * SMM_CHANNELS;
        let mut s = FrameStack::<u8>::new(len, SMM_CHANNELS, 4);
        assert_eq!(s.stacked_len(), SMM_WIDTH * SMM_HEIGHT * 16);
        let mut a = vec![0; len];
        a[(5 * SMM_WIDTH + 7) * SMM_CHANNELS + 2] = 255;
        s.reset(&vec![0; len]);
        s.push(&a);
        let out = stacked(&s);
        // Pixel (7, 5), newest block (index 3), channel 2.
        let at = (5 * SMM_WIDTH + 7) * 16 + 3 * SMM_CHANNELS + 2;
        assert_eq!(out[at], 255);
        assert_eq!(out.iter().filter(|&&v| v != 0).count(), 1);
    }

    #[test]
    #[should_panic(expected = "do not divide")]
    fn channels_must_divide_the_frame() {
        let _ = FrameStack::<f32>::new(115, 4, 4);
    }
}
