//! # touchline-render
//!
//! Seeing touchline matches, on the CPU only (no GPU, no window system, so it works the same on
//! headless servers):
//!
//! - [`Scene`] is what a frame shows, captured from an [`touchline_engine::Env`] or a replay step;
//! - [`Renderer`] draws scenes into RGBA images of any size: the pitch with its markings and goals,
//!   players in their team's colours with shirt numbers, a yellow ring round agent-driven players,
//!   a white marker over the ball carrier, the ball with a shadow that shows its height, and a
//!   scoreboard (score, match clock, game mode). A frame depends only on the scene and the size;
//! - [`PixelsEncoder`] gives the `pixels` (RGB) and `pixels_gray` observations (docs/grf-compatibility.md#pixels);
//! - [`replay`] records episodes into a compact, versioned, checksummed file and plays them back,
//!   re-simulating bit for bit;
//! - [`video`] draws a replay into an animated GIF, an MP4 (through `ffmpeg`) or PNG frames.

#![deny(missing_docs)]

mod font;
mod layout;
mod palette;
mod pitch;
mod pixels;
mod renderer;
pub mod replay;
mod scene;
pub mod video;

pub use pixels::{PIXELS_HEIGHT, PIXELS_WIDTH, PixelsEncoder, PixelsKind};
pub use renderer::{MAX_SIDE, RenderError, RenderOptions, Renderer};
pub use scene::{CLOCK_SECONDS_PER_STEP, ClockText, Scene, ScenePlayer};
