//! Where the pitch goes in an image: a uniform scale (pixels per metre) fitting the pitch with its
//! rim below an optional scoreboard band, centred.

use tiny_skia::Transform;

/// Half length of the area shown (m): the pitch (55 m) plus 3 m, enough for the goals (2.55 m).
pub(crate) const VIEW_HALF_LENGTH: f32 = 58.0;
/// Half width of the area shown (m): the pitch (36 m) plus 3 m.
pub(crate) const VIEW_HALF_WIDTH: f32 = 39.0;

/// Image size and the mapping from metres to pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Layout {
    pub(crate) width: usize,
    pub(crate) height: usize,
    /// Pixels per metre.
    pub(crate) scale: f32,
    /// Pixel position of the centre spot.
    pub(crate) origin: [f32; 2],
    /// Height of the scoreboard band at the top (0 without a scoreboard).
    pub(crate) band: usize,
}

impl Layout {
    pub(crate) fn new(width: usize, height: usize, scoreboard: bool) -> Layout {
        // The band takes a 16th of the height but at least one line of 7-pixel text with margins.
        let band = if scoreboard { (height / 16).max(11).min(height / 2) } else { 0 };
        let free = (height - band) as f32;
        let scale = (width as f32 / (2.0 * VIEW_HALF_LENGTH)).min(free / (2.0 * VIEW_HALF_WIDTH));
        Layout { width, height, scale, origin: [width as f32 / 2.0, band as f32 + free / 2.0], band }
    }

    /// Pixel coordinates of a point on the ground `(x, y)` (m).
    #[inline]
    pub(crate) fn pixel(&self, x: f32, y: f32) -> [f32; 2] {
        [self.origin[0] + x * self.scale, self.origin[1] + y * self.scale]
    }

    /// The same mapping for tiny-skia.
    pub(crate) fn transform(&self) -> Transform {
        Transform::from_row(self.scale, 0.0, 0.0, self.scale, self.origin[0], self.origin[1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_and_centres() {
        let l = Layout::new(96, 72, false);
        assert_eq!(l.band, 0);
        assert!((l.scale - 96.0 / 116.0).abs() < 1e-6);
        assert_eq!(l.pixel(0.0, 0.0), [48.0, 36.0]);
        let l = Layout::new(1280, 720, true);
        assert_eq!(l.band, 45);
        assert!((l.scale - 675.0 / 78.0).abs() < 1e-4);
        // The view's corners stay inside the image.
        let [x0, y0] = l.pixel(-VIEW_HALF_LENGTH, -VIEW_HALF_WIDTH);
        let [x1, y1] = l.pixel(VIEW_HALF_LENGTH, VIEW_HALF_WIDTH);
        assert!(x0 >= 0.0 && y0 >= 45.0 - 1e-3 && x1 <= 1280.0 && y1 <= 720.0 + 1e-3);
    }
}
