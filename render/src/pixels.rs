//! The `pixels` and `pixels_gray` observations (docs/grf-compatibility.md#pixels): a rendered frame of the match, by
//! default 96 × 72 as GRF's `channel_dimensions`.
//!
//! | kind | shape | dtype | values |
//! |---|---|---|---|
//! | [`PixelsKind::Rgb`] (`pixels`) | `(H, W, 3)` | u8 | 0..=255, RGB |
//! | [`PixelsKind::Gray`] (`pixels_gray`) | `(H, W, 1)` | u8 | 0..=255, `0.299 R + 0.587 G + 0.114 B` |
//!
//! Differences from GRF: GRF renders its 3-D broadcast view at 1280 × 720 and shrinks it with
//! OpenCV's `INTER_AREA`; touchline draws its 2-D top view directly at the requested size (no
//! scoreboard), which is faster and legible at 96 × 72. GRF gives pixels only to left-team
//! controllers; touchline gives every controller its own view, turned for the right team as the
//! other observations are (the viewer's team in red, attacking to the right), with only that
//! controller's player ringed. Stack frames with [`touchline_engine::obs::FrameStack`]
//! (`channels` = 3 or 1).

use touchline_engine::Env;

use crate::renderer::{RenderError, RenderOptions, Renderer};
use crate::scene::Scene;

/// GRF's default observation width (`channel_dimensions[0]`, docs/grf-compatibility.md#pixels).
pub const PIXELS_WIDTH: usize = 96;
/// GRF's default observation height (`channel_dimensions[1]`).
pub const PIXELS_HEIGHT: usize = 72;

/// Colour or grey.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelsKind {
    /// `pixels`: 3 channels, RGB.
    Rgb,
    /// `pixels_gray`: 1 channel.
    Gray,
}

impl PixelsKind {
    /// Channels per pixel: 3 or 1.
    pub fn channels(self) -> usize {
        match self {
            PixelsKind::Rgb => 3,
            PixelsKind::Gray => 1,
        }
    }
}

/// Encodes controllers' views of an env as `pixels` / `pixels_gray` observations. Holds a
/// [`Renderer`] (the pitch is painted once) and a scene buffer, so encoding allocates nothing.
#[derive(Clone, Debug)]
pub struct PixelsEncoder {
    renderer: Renderer,
    scene: Scene,
    kind: PixelsKind,
}

impl PixelsEncoder {
    /// An encoder of `width × height` observations of `kind`.
    ///
    /// # Errors
    /// [`RenderError::Size`] for a side of 0 or above [`crate::MAX_SIDE`].
    pub fn new(width: usize, height: usize, kind: PixelsKind) -> Result<PixelsEncoder, RenderError> {
        let renderer = Renderer::new(width, height, RenderOptions { scoreboard: false })?;
        Ok(PixelsEncoder { renderer, scene: Scene::default(), kind })
    }

    /// Bytes of one observation: `height × width × channels`.
    pub fn len(&self) -> usize {
        self.renderer.width() * self.renderer.height() * self.kind.channels()
    }

    /// Whether an observation has no bytes (never: sides are at least 1).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The shape of one observation, `(height, width, channels)`.
    pub fn shape(&self) -> [usize; 3] {
        [self.renderer.height(), self.renderer.width(), self.kind.channels()]
    }

    /// The kind of observation.
    pub fn kind(&self) -> PixelsKind {
        self.kind
    }

    /// Writes controller `controller`'s view of `env` into `out` (`len()` bytes, row-major
    /// `(H, W, C)`).
    ///
    /// # Panics
    /// When `out.len() != self.len()` (a programming error; the Python binding sizes it).
    pub fn encode(&mut self, env: &Env, controller: usize, out: &mut [u8]) {
        self.scene.capture_view(env, controller);
        self.encode_scene_into(out);
    }

    /// Writes the view of an already captured `scene` into `out`.
    ///
    /// # Panics
    /// As [`PixelsEncoder::encode`].
    pub fn encode_scene(&mut self, scene: &Scene, out: &mut [u8]) {
        self.renderer.render(scene);
        self.write(out);
    }

    fn encode_scene_into(&mut self, out: &mut [u8]) {
        self.renderer.render(&self.scene);
        self.write(out);
    }

    fn write(&self, out: &mut [u8]) {
        match self.kind {
            PixelsKind::Rgb => self.renderer.write_rgb(out),
            PixelsKind::Gray => self.renderer.write_gray(out),
        }
    }
}
