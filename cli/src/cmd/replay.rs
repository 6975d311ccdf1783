//! `touchline replay FILE -o OUT`: draws a replay into a video (MP4 through `ffmpeg` when it is
//! installed), an animated GIF, or a folder of PNG frames; checks first that it re-simulates.

use std::fs::File;
use std::io::{BufWriter, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use touchline_render::replay::Replay;
use touchline_render::{RenderOptions, Renderer, Scene};

use crate::CliError;

/// Arguments of `touchline replay`.
#[derive(Debug, Args)]
pub(crate) struct ReplayArgs {
    /// A replay file written by `touchline run --record` (`.tlreplay`).
    file: PathBuf,

    /// Output: `NAME.gif` (animated GIF), `NAME.mp4` (needs `ffmpeg` on the PATH), or a folder
    /// (one PNG per frame, `frame_00000.png` …).
    #[arg(short, long)]
    output: PathBuf,

    /// Frame width in pixels.
    #[arg(long, default_value_t = 640, value_parser = clap::value_parser!(u32).range(16..=8192))]
    width: u32,

    /// Frame height in pixels.
    #[arg(long, default_value_t = 360, value_parser = clap::value_parser!(u32).range(16..=8192))]
    height: u32,

    /// Draw every Nth step (GRF's videos show every step at 10 frames per second).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    every: u32,

    /// Frames per second of the video (10 = real time, as GRF's).
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=100))]
    fps: u32,

    /// Skip the re-simulation check (draw the stored frames as they are).
    #[arg(long)]
    no_verify: bool,
}

/// Reads and decodes a replay file.
pub(crate) fn load(path: &Path) -> Result<Replay, CliError> {
    let bytes = std::fs::read(path).map_err(|source| CliError::Read { path: path.display().to_string(), source })?;
    Replay::from_bytes(&bytes).map_err(|source| CliError::Replay { path: path.to_path_buf(), source })
}

/// Re-simulates `replay` and fails if it does not reproduce.
pub(crate) fn verify(path: &Path, replay: &Replay) -> Result<(), CliError> {
    replay.simulate(|_, _| {}).map(|_| ()).map_err(|source| CliError::Replay { path: path.to_path_buf(), source })
}

/// Where frames go.
enum Sink {
    Gif(gif::Encoder<BufWriter<File>>),
    Png(PathBuf),
    Ffmpeg(std::process::Child),
}

/// Runs `touchline replay`.
pub(crate) fn run(args: &ReplayArgs) -> Result<(), CliError> {
    let replay = load(&args.file)?;
    if !args.no_verify {
        verify(&args.file, &replay)?;
    }
    let (w, h) = (args.width as usize, args.height as usize);
    let mut renderer = Renderer::new(w, h, RenderOptions::default())
        .map_err(|e| CliError::Video { path: args.output.clone(), reason: e.to_string() })?;
    let out = &args.output;
    let video_err = |reason: String| CliError::Video { path: out.clone(), reason };
    let extension = out.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let mut sink = match extension.as_deref() {
        Some("gif") => {
            let file = File::create(out).map_err(|e| video_err(e.to_string()))?;
            let mut encoder = gif::Encoder::new(BufWriter::new(file), args.width as u16, args.height as u16, &[])
                .map_err(|e| video_err(e.to_string()))?;
            encoder.set_repeat(gif::Repeat::Infinite).map_err(|e| video_err(e.to_string()))?;
            Sink::Gif(encoder)
        }
        Some("mp4") => Sink::Ffmpeg(spawn_ffmpeg(out, args.width, args.height, args.fps).map_err(video_err)?),
        Some(other) => return Err(video_err(format!("unknown video type `.{other}`: use .gif, .mp4 or a folder"))),
        None => {
            std::fs::create_dir_all(out).map_err(|e| video_err(e.to_string()))?;
            Sink::Png(out.clone())
        }
    };

    let frames: Vec<usize> = (0..=replay.steps()).step_by(args.every as usize).collect();
    let bar = if std::io::stderr().is_terminal() {
        let style =
            ProgressStyle::with_template("{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} frames, eta {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar());
        ProgressBar::new(frames.len() as u64).with_style(style)
    } else {
        ProgressBar::hidden()
    };
    let mut scene = Scene::default();
    let mut rgb = vec![0u8; w * h * 3];
    // GIF delays are in hundredths of a second.
    let delay = (100 / args.fps).max(1) as u16;
    for (n, &k) in frames.iter().enumerate() {
        replay.scene(k, &mut scene);
        let rgba = renderer.render(&scene);
        match &mut sink {
            Sink::Gif(encoder) => {
                let mut pixels = rgba.to_vec();
                let mut frame = gif::Frame::from_rgba_speed(args.width as u16, args.height as u16, &mut pixels, 30);
                frame.delay = delay;
                encoder.write_frame(&frame).map_err(|e| video_err(e.to_string()))?;
            }
            Sink::Png(dir) => {
                renderer.write_rgb(&mut rgb);
                write_png(&dir.join(format!("frame_{n:05}.png")), args.width, args.height, &rgb)
                    .map_err(|e| video_err(e.to_string()))?;
            }
            Sink::Ffmpeg(child) => {
                renderer.write_rgb(&mut rgb);
                let stdin = child.stdin.as_mut().ok_or_else(|| video_err("ffmpeg has no input".into()))?;
                stdin.write_all(&rgb).map_err(|e| video_err(format!("ffmpeg stopped: {e}")))?;
            }
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    match sink {
        Sink::Gif(encoder) => {
            let mut writer = encoder.into_inner().map_err(|e| video_err(e.to_string()))?;
            writer.flush().map_err(|e| video_err(e.to_string()))?;
        }
        Sink::Png(_) => {}
        Sink::Ffmpeg(mut child) => {
            drop(child.stdin.take());
            let status = child.wait().map_err(|e| video_err(e.to_string()))?;
            if !status.success() {
                return Err(video_err(format!("ffmpeg failed ({status})")));
            }
        }
    }
    eprintln!("wrote {} frames to {}", frames.len(), out.display());
    Ok(())
}

/// Starts `ffmpeg` reading raw RGB frames on stdin and writing H.264 MP4.
fn spawn_ffmpeg(out: &Path, width: u32, height: u32, fps: u32) -> Result<std::process::Child, String> {
    Command::new("ffmpeg")
        .args(["-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s"])
        .arg(format!("{width}x{height}"))
        .args(["-r", &fps.to_string(), "-i", "-", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"])
        .arg(out)
        .stdin(Stdio::piped())
        .spawn()
        .map_err(|e| {
            format!("MP4 needs `ffmpeg` on the PATH ({e}); install it (e.g. `apt-get install ffmpeg`) or write a .gif or a folder of PNGs")
        })
}

/// Writes one RGB PNG.
pub(crate) fn write_png(path: &Path, width: u32, height: u32, rgb: &[u8]) -> std::io::Result<()> {
    let file = File::create(path)?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.write_header().and_then(|mut w| w.write_image_data(rgb)).map_err(std::io::Error::other)
}
