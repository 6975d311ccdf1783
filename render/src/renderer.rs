//! [`Renderer`]: draws a [`Scene`] into an RGBA image of a fixed size.
//!
//! The pitch is painted once per renderer (tiny-skia, anti-aliased) and copied under each frame;
//! players, ball and scoreboard are then drawn with the small routines below: anti-aliased discs
//! and rings from exact distances, and bitmap text. They use only `+ - × ÷` and `sqrt` on `f32`
//! (all correctly rounded by IEEE 754), so the moving parts of a frame are the same bytes on every
//! platform, and drawing a frame allocates nothing.

use thiserror::Error;
use tiny_skia::Pixmap;
use touchline_engine::Side;
use touchline_engine::geometry::pitch::BALL_RADIUS;

use crate::font::{ADVANCE, GLYPH_HEIGHT, GLYPH_WIDTH, glyph, text_width};
use crate::layout::Layout;
use crate::palette;
use crate::scene::{Scene, mode_label};

/// Largest width or height accepted (pixels): 8K, far more than any use needs.
pub const MAX_SIDE: usize = 8192;

/// Player radius (m) as drawn: a player seen from above is about 1 m across at the shoulders,
/// drawn wider so that shirt numbers fit.
const PLAYER_RADIUS: f32 = 1.0;
/// Smallest player radius (pixels), so that players stay visible in 96 × 72 images.
const MIN_PLAYER_RADIUS: f32 = 1.5;
/// Ball radius as drawn (m): about four times the real 0.11 m, so that it shows in small images.
const BALL_DRAWN_RADIUS: f32 = 0.45;

/// A renderer's options.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Draw the scoreboard band (score, match clock, game mode) at the top. Default true; the
    /// `pixels` observations leave it out.
    pub scoreboard: bool,
}

impl Default for RenderOptions {
    fn default() -> RenderOptions {
        RenderOptions { scoreboard: true }
    }
}

/// Why a renderer cannot be made.
#[derive(Debug, Error, PartialEq, Eq)]
#[non_exhaustive]
pub enum RenderError {
    /// Width or height is 0 or above [`MAX_SIDE`].
    #[error("cannot render {width} × {height} images: each side must be between 1 and {MAX_SIDE} pixels")]
    Size {
        /// Requested width (pixels).
        width: usize,
        /// Requested height (pixels).
        height: usize,
    },
}

/// Draws [`Scene`]s into a `height × width` RGBA image (row-major, 4 bytes per pixel, opaque).
#[derive(Clone, Debug)]
pub struct Renderer {
    layout: Layout,
    options: RenderOptions,
    /// The pitch, painted once (RGBA, opaque).
    background: Vec<u8>,
    /// The last frame drawn (RGBA, opaque).
    frame: Vec<u8>,
}

impl Renderer {
    /// A renderer for `width × height` images.
    ///
    /// # Errors
    /// [`RenderError::Size`] when a side is 0 or above [`MAX_SIDE`].
    pub fn new(width: usize, height: usize, options: RenderOptions) -> Result<Renderer, RenderError> {
        let bad = || RenderError::Size { width, height };
        if !(1..=MAX_SIDE).contains(&width) || !(1..=MAX_SIDE).contains(&height) {
            return Err(bad());
        }
        let layout = Layout::new(width, height, options.scoreboard);
        let mut pixmap = Pixmap::new(width as u32, height as u32).ok_or_else(bad)?;
        crate::pitch::paint(&mut pixmap, &layout);
        let background = pixmap.take();
        let frame = background.clone();
        Ok(Renderer { layout, options, background, frame })
    }

    /// Image width (pixels).
    pub fn width(&self) -> usize {
        self.layout.width
    }

    /// Image height (pixels).
    pub fn height(&self) -> usize {
        self.layout.height
    }

    /// Draws `scene` and returns the frame: `height × width × 4` bytes, RGBA, row-major, alpha
    /// always 255. The result depends only on the scene, the size and the options.
    pub fn render(&mut self, scene: &Scene) -> &[u8] {
        self.frame.copy_from_slice(&self.background);
        let l = self.layout;
        let mut canvas = Canvas { data: &mut self.frame, width: l.width, height: l.height };
        let r = (PLAYER_RADIUS * l.scale).max(MIN_PLAYER_RADIUS);
        let outlined = r >= 4.0;

        // Ball shadow on the grass, under everybody.
        let height = (scene.ball[2] - BALL_RADIUS).max(0.0);
        let ball_r = (BALL_DRAWN_RADIUS * l.scale).max(1.0) * (1.0 + 0.08 * height);
        let [bx, by] = l.pixel(scene.ball[0], scene.ball[1]);
        canvas.disc(bx, by, ball_r, palette::SHADOW, palette::SHADOW_ALPHA);

        for p in scene.players.iter().filter(|p| p.on_pitch && p.controlled) {
            let [x, y] = l.pixel(p.position[0], p.position[1]);
            let width = (0.3 * r).max(1.0);
            canvas.ring(x, y, r + 0.8 + width, width, palette::CONTROLLED);
        }
        // Shirt numbers once a player is about 8 pixels across, bigger in big images.
        let font = if r >= 4.0 { (((1.4 * r) / GLYPH_HEIGHT as f32) as usize).max(1) } else { 0 };
        for p in scene.players.iter().filter(|p| p.on_pitch) {
            let [x, y] = l.pixel(p.position[0], p.position[1]);
            let shirt = match (p.side, p.goalkeeper) {
                (Side::Left, false) => palette::LEFT,
                (Side::Left, true) => palette::LEFT_KEEPER,
                (Side::Right, false) => palette::RIGHT,
                (Side::Right, true) => palette::RIGHT_KEEPER,
            };
            if outlined {
                canvas.disc(x, y, r + 1.0, palette::OUTLINE, 1.0);
            }
            canvas.disc(x, y, r, shirt, 1.0);
            if font >= 1 {
                let mut digits = [0u8; 3];
                let text = number_text(p.number, &mut digits);
                let ink = if p.goalkeeper { palette::OUTLINE } else { palette::WHITE };
                let w = text_width(text) * font;
                let left = (x - w as f32 / 2.0).round() as i64;
                let top = (y - (GLYPH_HEIGHT * font) as f32 / 2.0).round() as i64;
                canvas.text(left, top, font, text, ink);
            }
        }
        for p in scene.players.iter().filter(|p| p.on_pitch && p.has_ball) {
            let [x, y] = l.pixel(p.position[0], p.position[1]);
            let size = (0.9 * r).max(2.0);
            canvas.triangle_down(x, y - r - 1.5 - size, size, palette::WHITE);
        }

        // The ball, lifted up the image by its height (an oblique view from the south stand).
        let lift = height * l.scale;
        if outlined {
            canvas.disc(bx, by - lift, ball_r + 1.0, palette::OUTLINE, 1.0);
        }
        canvas.disc(bx, by - lift, ball_r, palette::WHITE, 1.0);

        if self.options.scoreboard {
            draw_scoreboard(&mut canvas, l.band, scene);
        }
        &self.frame
    }

    /// The last frame drawn (RGBA, as [`Renderer::render`] returned it).
    pub fn frame(&self) -> &[u8] {
        &self.frame
    }

    /// Writes the last frame as RGB into `out` (`height × width × 3` bytes).
    ///
    /// # Panics
    /// When `out` has another length (a programming error).
    pub fn write_rgb(&self, out: &mut [u8]) {
        assert_eq!(out.len(), self.layout.width * self.layout.height * 3, "RGB buffer size");
        for (rgb, rgba) in out.chunks_exact_mut(3).zip(self.frame.chunks_exact(4)) {
            rgb.copy_from_slice(&rgba[..3]);
        }
    }

    /// Writes the last frame as grey levels into `out` (`height × width` bytes), with OpenCV's
    /// `COLOR_RGB2GRAY` weights in fixed point: `Y = (4899 R + 9617 G + 1868 B + 8192) >> 14`
    /// (0.299, 0.587, 0.114, as GRF's `pixels_gray`, docs/grf-compatibility.md#pixels).
    ///
    /// # Panics
    /// When `out` has another length (a programming error).
    pub fn write_gray(&self, out: &mut [u8]) {
        assert_eq!(out.len(), self.layout.width * self.layout.height, "grey buffer size");
        for (y, p) in out.iter_mut().zip(self.frame.chunks_exact(4)) {
            let v = 4899 * u32::from(p[0]) + 9617 * u32::from(p[1]) + 1868 * u32::from(p[2]) + 8192;
            *y = (v >> 14) as u8;
        }
    }
}

/// The decimal digits of `n` in `buf`.
fn number_text(n: u8, buf: &mut [u8; 3]) -> &str {
    let mut len = 0;
    if n >= 100 {
        buf[len] = b'0' + n / 100;
        len += 1;
    }
    if n >= 10 {
        buf[len] = b'0' + n / 10 % 10;
        len += 1;
    }
    buf[len] = b'0' + n % 10;
    len += 1;
    std::str::from_utf8(&buf[..len]).unwrap_or("")
}

/// The band at the top: `■ 1 - 0 ■` on the left, the clock in the middle, the game mode on the
/// right (when it fits).
fn draw_scoreboard(canvas: &mut Canvas<'_>, band: usize, scene: &Scene) {
    canvas.fill_rect(0, 0, canvas.width as i64, band as i64, palette::BOARD);
    let font = (band * 2 / 3 / GLYPH_HEIGHT).max(1);
    let text_h = GLYPH_HEIGHT * font;
    let top = (band.saturating_sub(text_h) / 2) as i64;
    let margin = (2 * font) as i64;

    // Score, between chips of the teams' colours.
    let score = format_score(scene.score);
    let chip = (GLYPH_WIDTH * font) as i64;
    let mut x = margin;
    canvas.fill_rect(x, top, chip, text_h as i64, palette::LEFT);
    x += chip + (ADVANCE * font) as i64;
    canvas.text(x, top, font, score.as_str(), palette::BOARD_TEXT);
    x += (text_width(score.as_str()) * font + ADVANCE * font) as i64;
    canvas.fill_rect(x, top, chip, text_h as i64, palette::RIGHT);
    let score_end = x + chip;

    let clock = scene.clock();
    let mut buf = [0u8; 16];
    let clock = clock_text(clock.minutes, clock.seconds, &mut buf);
    let clock_w = (text_width(clock) * font) as i64;
    let clock_x = (canvas.width as i64 - clock_w) / 2;
    if clock_x > score_end + margin {
        canvas.text(clock_x, top, font, clock, palette::BOARD_TEXT);
    }
    let mode = mode_label(scene.mode);
    let mode_w = (text_width(mode) * font) as i64;
    let mode_x = canvas.width as i64 - margin - mode_w;
    if mode_x > clock_x + clock_w + margin {
        canvas.text(mode_x, top, font, mode, palette::BOARD_MODE);
    }
}

/// `"L - R"` without allocating: scores fit in a small inline buffer.
fn format_score(score: [u32; 2]) -> InlineText {
    use std::fmt::Write;
    let mut t = InlineText::default();
    let _ = write!(t, "{} - {}", score[0], score[1]);
    t
}

/// `MM:SS` (minutes as many digits as needed) in `buf`.
fn clock_text(minutes: u32, seconds: u32, buf: &mut [u8; 16]) -> &str {
    use std::io::Write;
    let mut cursor = std::io::Cursor::new(&mut buf[..]);
    let _ = write!(cursor, "{minutes:02}:{seconds:02}");
    let len = cursor.position() as usize;
    std::str::from_utf8(&buf[..len]).unwrap_or("")
}

/// A short string on the stack (up to 32 bytes; more is cut).
#[derive(Default)]
struct InlineText {
    buf: [u8; 32],
    len: usize,
}

impl InlineText {
    fn as_str(&self) -> &str {
        std::str::from_utf8(&self.buf[..self.len]).unwrap_or("")
    }
}

impl std::fmt::Write for InlineText {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let n = s.len().min(self.buf.len() - self.len);
        self.buf[self.len..self.len + n].copy_from_slice(&s.as_bytes()[..n]);
        self.len += n;
        Ok(())
    }
}

/// An RGBA image being drawn on; every shape is clipped to it.
struct Canvas<'a> {
    data: &'a mut [u8],
    width: usize,
    height: usize,
}

impl Canvas<'_> {
    /// Blends `rgb` over pixel `(x, y)` with coverage `a` in [0, 1].
    #[inline]
    fn blend(&mut self, x: usize, y: usize, rgb: [u8; 3], a: f32) {
        let i = (y * self.width + x) * 4;
        for (out, fg) in self.data[i..i + 3].iter_mut().zip(rgb) {
            let bg = f32::from(*out);
            *out = (bg + (f32::from(fg) - bg) * a + 0.5) as u8;
        }
    }

    /// Pixel rows and columns that a shape of half-size `reach` around `(cx, cy)` touches.
    fn span(&self, cx: f32, cy: f32, reach: f32) -> (std::ops::Range<usize>, std::ops::Range<usize>) {
        let clip = |v: f32, max: usize| (v.max(0.0) as usize).min(max);
        let xs = clip(cx - reach - 1.0, self.width)..clip(cx + reach + 2.0, self.width);
        let ys = clip(cy - reach - 1.0, self.height)..clip(cy + reach + 2.0, self.height);
        (xs, ys)
    }

    /// A disc of radius `r` (pixels) centred at `(cx, cy)`, anti-aliased over one pixel, at
    /// opacity `alpha`.
    fn disc(&mut self, cx: f32, cy: f32, r: f32, rgb: [u8; 3], alpha: f32) {
        if !(cx.is_finite() && cy.is_finite()) {
            return;
        }
        let (xs, ys) = self.span(cx, cy, r);
        for y in ys {
            let dy = y as f32 + 0.5 - cy;
            for x in xs.clone() {
                let dx = x as f32 + 0.5 - cx;
                let d = (dx * dx + dy * dy).sqrt();
                let a = (r - d + 0.5).clamp(0.0, 1.0);
                if a > 0.0 {
                    self.blend(x, y, rgb, a * alpha);
                }
            }
        }
    }

    /// A ring of outer radius `r` and width `w` (pixels) centred at `(cx, cy)`, anti-aliased.
    fn ring(&mut self, cx: f32, cy: f32, r: f32, w: f32, rgb: [u8; 3]) {
        if !(cx.is_finite() && cy.is_finite()) {
            return;
        }
        let (xs, ys) = self.span(cx, cy, r);
        for y in ys {
            let dy = y as f32 + 0.5 - cy;
            for x in xs.clone() {
                let dx = x as f32 + 0.5 - cx;
                let d = (dx * dx + dy * dy).sqrt();
                let a = (r - d + 0.5).clamp(0.0, 1.0).min((d - (r - w) + 0.5).clamp(0.0, 1.0));
                if a > 0.0 {
                    self.blend(x, y, rgb, a);
                }
            }
        }
    }

    /// A triangle pointing down with its tip at `(cx, tip_y + size)` and a base `size` wide at
    /// `tip_y`: a pixel is inside when its centre is.
    fn triangle_down(&mut self, cx: f32, base_y: f32, size: f32, rgb: [u8; 3]) {
        if !(cx.is_finite() && base_y.is_finite()) {
            return;
        }
        let (xs, ys) = self.span(cx, base_y + size / 2.0, size);
        for y in ys {
            let v = y as f32 + 0.5 - base_y;
            if !(0.0..=size).contains(&v) {
                continue;
            }
            let half = (size - v) / 2.0;
            for x in xs.clone() {
                if (x as f32 + 0.5 - cx).abs() <= half {
                    self.blend(x, y, rgb, 1.0);
                }
            }
        }
    }

    /// An axis-aligned rectangle of whole pixels.
    fn fill_rect(&mut self, x: i64, y: i64, w: i64, h: i64, rgb: [u8; 3]) {
        let x0 = x.clamp(0, self.width as i64) as usize;
        let x1 = (x + w).clamp(0, self.width as i64) as usize;
        let y0 = y.clamp(0, self.height as i64) as usize;
        let y1 = (y + h).clamp(0, self.height as i64) as usize;
        for row in y0..y1 {
            for col in x0..x1 {
                let i = (row * self.width + col) * 4;
                self.data[i..i + 3].copy_from_slice(&rgb);
            }
        }
    }

    /// `text` with its top-left corner at `(x, y)`, each font pixel a `scale × scale` square.
    fn text(&mut self, x: i64, y: i64, scale: usize, text: &str, rgb: [u8; 3]) {
        let s = scale as i64;
        for (k, c) in text.chars().enumerate() {
            let gx = x + (k * ADVANCE) as i64 * s;
            for (row, bits) in glyph(c).iter().enumerate() {
                for col in 0..GLYPH_WIDTH {
                    if bits & (0x10 >> col) != 0 {
                        self.fill_rect(gx + col as i64 * s, y + row as i64 * s, s, s, rgb);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_checked() {
        assert!(Renderer::new(0, 10, RenderOptions::default()).is_err());
        assert!(Renderer::new(10, MAX_SIDE + 1, RenderOptions::default()).is_err());
        let r = Renderer::new(1, 1, RenderOptions::default()).expect("1 × 1 is fine");
        assert_eq!(r.frame().len(), 4);
    }

    #[test]
    fn texts() {
        let mut b = [0; 3];
        assert_eq!(number_text(7, &mut b), "7");
        assert_eq!(number_text(11, &mut b), "11");
        assert_eq!(number_text(200, &mut b), "200");
        let mut b = [0; 16];
        assert_eq!(clock_text(5, 7, &mut b), "05:07");
        assert_eq!(clock_text(123, 0, &mut b), "123:00");
        assert_eq!(format_score([10, 2]).as_str(), "10 - 2");
    }

    #[test]
    fn grey_uses_opencv_weights() {
        let mut r = Renderer::new(2, 1, RenderOptions { scoreboard: false }).expect("renderer");
        r.frame = vec![255, 0, 0, 255, 10, 200, 30, 255];
        let mut out = [0u8; 2];
        r.write_gray(&mut out);
        // round(0.299 · 255) = 76; round(0.299·10 + 0.587·200 + 0.114·30) = 123.8 → 124.
        assert_eq!(out, [76, 124]);
    }

    #[test]
    fn shapes_outside_the_image_are_clipped() {
        let mut data = vec![0u8; 4 * 4 * 4];
        let mut c = Canvas { data: &mut data, width: 4, height: 4 };
        c.disc(-100.0, 2.0, 3.0, [255; 3], 1.0);
        c.disc(f32::NAN, 2.0, 3.0, [255; 3], 1.0);
        c.ring(2.0, 2.0, 50.0, 1.0, [255; 3]);
        c.text(-20, -20, 3, "88", [255; 3]);
        c.fill_rect(3, 3, 100, 100, [9; 3]);
        assert_eq!(data[(3 * 4 + 3) * 4], 9);
    }
}
