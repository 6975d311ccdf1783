//! [`Video`]: a replay drawn into an animated GIF, an MP4 (through `ffmpeg`) or a folder of PNG
//! frames, on the CPU. Used by `touchline replay` and by Python (`touchline.Replay.write_video`,
//! the GRF layer's `write_video`).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use thiserror::Error;

use crate::replay::Replay;
use crate::{RenderOptions, Renderer, Scene};

/// How a replay is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VideoOptions {
    /// Frame width in pixels (16 to 8192).
    pub width: u32,
    /// Frame height in pixels (16 to 8192).
    pub height: u32,
    /// Draw every Nth step (at least 1; GRF's videos show every step).
    pub every: u32,
    /// Frames per second (1 to 100; 10 is real time, as GRF's videos).
    pub fps: u32,
}

impl Default for VideoOptions {
    /// 640 × 360, every step, 10 frames per second.
    fn default() -> VideoOptions {
        VideoOptions { width: 640, height: 360, every: 1, fps: 10 }
    }
}

/// Why a video could not be written.
#[derive(Debug, Error)]
#[error("cannot write the video {}: {reason}", path.display())]
pub struct VideoError {
    /// The output.
    pub path: PathBuf,
    /// Why.
    pub reason: String,
}

/// Where frames go.
enum Sink {
    Gif(gif::Encoder<BufWriter<File>>),
    Png(PathBuf),
    Ffmpeg(std::process::Child),
}

/// A replay being drawn into `out`: `NAME.gif`, `NAME.mp4` (needs `ffmpeg` on the PATH) or a
/// folder (one `frame_00000.png` per frame, made if missing).
pub struct Video {
    sink: Sink,
    renderer: Renderer,
    options: VideoOptions,
    out: PathBuf,
    rgb: Vec<u8>,
    frames: usize,
}

impl Video {
    /// Opens `out` for frames of `options`' size.
    ///
    /// # Errors
    /// A size or rate out of range, an unknown extension, a file or folder that cannot be made, or
    /// `.mp4` without `ffmpeg`.
    pub fn create(out: &Path, options: VideoOptions) -> Result<Video, VideoError> {
        let err = |reason: String| VideoError { path: out.to_path_buf(), reason };
        if !(16..=8192).contains(&options.width) || !(16..=8192).contains(&options.height) {
            return Err(err(format!("{} × {} pixels: each side must be 16 to 8192", options.width, options.height)));
        }
        if options.every == 0 || !(1..=100).contains(&options.fps) {
            return Err(err(format!(
                "every {} and {} fps: every must be 1 or more, fps 1 to 100",
                options.every, options.fps
            )));
        }
        let renderer = Renderer::new(options.width as usize, options.height as usize, RenderOptions::default())
            .map_err(|e| err(e.to_string()))?;
        let extension = out.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        let sink = match extension.as_deref() {
            Some("gif") => {
                let file = File::create(out).map_err(|e| err(e.to_string()))?;
                let mut encoder =
                    gif::Encoder::new(BufWriter::new(file), options.width as u16, options.height as u16, &[])
                        .map_err(|e| err(e.to_string()))?;
                encoder.set_repeat(gif::Repeat::Infinite).map_err(|e| err(e.to_string()))?;
                Sink::Gif(encoder)
            }
            Some("mp4") => Sink::Ffmpeg(spawn_ffmpeg(out, options).map_err(err)?),
            Some(other) => return Err(err(format!("unknown video type `.{other}`: use .gif, .mp4 or a folder"))),
            None => {
                std::fs::create_dir_all(out).map_err(|e| err(e.to_string()))?;
                Sink::Png(out.to_path_buf())
            }
        };
        let rgb = vec![0u8; options.width as usize * options.height as usize * 3];
        Ok(Video { sink, renderer, options, out: out.to_path_buf(), rgb, frames: 0 })
    }

    /// The frames of `replay` this video shows (every `every`th, from the first).
    pub fn frames_of(&self, replay: &Replay) -> Vec<usize> {
        (0..=replay.steps()).step_by(self.options.every as usize).collect()
    }

    /// Draws `scene` as the next frame.
    ///
    /// # Errors
    /// The encoder or `ffmpeg` failing.
    pub fn push(&mut self, scene: &Scene) -> Result<(), VideoError> {
        let err = |reason: String| VideoError { path: self.out.clone(), reason };
        let (w, h) = (self.options.width, self.options.height);
        let rgba = self.renderer.render(scene);
        match &mut self.sink {
            Sink::Gif(encoder) => {
                let mut pixels = rgba.to_vec();
                let mut frame = gif::Frame::from_rgba_speed(w as u16, h as u16, &mut pixels, 30);
                // GIF delays are in hundredths of a second.
                frame.delay = (100 / self.options.fps).max(1) as u16;
                encoder.write_frame(&frame).map_err(|e| err(e.to_string()))?;
            }
            Sink::Png(dir) => {
                self.renderer.write_rgb(&mut self.rgb);
                write_png(&dir.join(format!("frame_{:05}.png", self.frames)), w, h, &self.rgb)
                    .map_err(|e| err(e.to_string()))?;
            }
            Sink::Ffmpeg(child) => {
                self.renderer.write_rgb(&mut self.rgb);
                let stdin = child.stdin.as_mut().ok_or_else(|| err("ffmpeg has no input".into()))?;
                stdin.write_all(&self.rgb).map_err(|e| err(format!("ffmpeg stopped: {e}")))?;
            }
        }
        self.frames += 1;
        Ok(())
    }

    /// Finishes the file; returns the number of frames written.
    ///
    /// # Errors
    /// Flushing the file, or `ffmpeg` failing.
    pub fn finish(self) -> Result<usize, VideoError> {
        let err = |reason: String| VideoError { path: self.out.clone(), reason };
        match self.sink {
            Sink::Gif(encoder) => {
                let mut writer = encoder.into_inner().map_err(|e| err(e.to_string()))?;
                writer.flush().map_err(|e| err(e.to_string()))?;
            }
            Sink::Png(_) => {}
            Sink::Ffmpeg(mut child) => {
                drop(child.stdin.take());
                let status = child.wait().map_err(|e| err(e.to_string()))?;
                if !status.success() {
                    return Err(err(format!("ffmpeg failed ({status})")));
                }
            }
        }
        Ok(self.frames)
    }

    /// Draws every `every`th frame of `replay` into `out` (stored frames as they are: re-simulate
    /// first to check them); returns the number of frames written.
    ///
    /// # Errors
    /// As [`Video::create`], [`Video::push`] and [`Video::finish`].
    pub fn write(replay: &Replay, out: &Path, options: VideoOptions) -> Result<usize, VideoError> {
        let mut video = Video::create(out, options)?;
        let mut scene = Scene::default();
        for k in video.frames_of(replay) {
            replay.scene(k, &mut scene);
            video.push(&scene)?;
        }
        video.finish()
    }
}

/// Starts `ffmpeg` reading raw RGB frames on stdin and writing H.264 MP4.
fn spawn_ffmpeg(out: &Path, options: VideoOptions) -> Result<std::process::Child, String> {
    Command::new("ffmpeg")
        .args(["-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s"])
        .arg(format!("{}x{}", options.width, options.height))
        .args(["-r", &options.fps.to_string(), "-i", "-", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"])
        .arg(out)
        .stdin(Stdio::piped())
        .spawn()
        .map_err(|e| {
            format!("MP4 needs `ffmpeg` on the PATH ({e}); install it (e.g. `apt-get install ffmpeg`) or write a .gif or a folder of PNGs")
        })
}

/// Writes one RGB PNG.
pub fn write_png(path: &Path, width: u32, height: u32, rgb: &[u8]) -> std::io::Result<()> {
    let file = File::create(path)?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.write_header().and_then(|mut w| w.write_image_data(rgb)).map_err(std::io::Error::other)
}
