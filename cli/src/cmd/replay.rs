//! `touchline replay FILE -o OUT`: draws a replay into a video (MP4 through `ffmpeg` when it is
//! installed), an animated GIF, or a folder of PNG frames; checks first that it re-simulates.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use touchline_dsl::script::{ScriptOptions, Scripts};
use touchline_render::Scene;
use touchline_render::replay::Replay;
use touchline_render::video::{Video, VideoError, VideoOptions};

use crate::CliError;

/// Arguments of `touchline replay`.
#[derive(Debug, Args)]
pub(crate) struct ReplayArgs {
    /// A replay file (`.tlreplay`) written by `touchline run --record` or by Python (`touchline.RecordReplay`).
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

/// Fresh hooks running the scripts `replay` carries (`None` for a scenario without scripts).
pub(crate) fn hooks(replay: &Replay) -> Result<Option<Box<dyn touchline_engine::Hooks>>, CliError> {
    let sources = replay.scripts.iter().map(|s| (s.path.as_str(), s.text.as_str()));
    let scripts = Scripts::from_sources(&replay.scenario, sources, ScriptOptions::default())
        .map_err(|e| CliError::Build(touchline_dsl::BuildError::Scripts(e)))?;
    Ok(scripts.engine_hooks())
}

/// Re-simulates `replay` and fails if it does not reproduce.
pub(crate) fn verify(path: &Path, replay: &Replay) -> Result<(), CliError> {
    replay
        .simulate_with(hooks(replay)?, |_, _| {})
        .map(|_| ())
        .map_err(|source| CliError::Replay { path: path.to_path_buf(), source })
}

/// Runs `touchline replay`.
pub(crate) fn run(args: &ReplayArgs) -> Result<(), CliError> {
    let replay = load(&args.file)?;
    if !args.no_verify {
        verify(&args.file, &replay)?;
    }
    let options = VideoOptions { width: args.width, height: args.height, every: args.every, fps: args.fps };
    let video_err = |e: VideoError| CliError::Video { path: e.path, reason: e.reason };
    let mut video = Video::create(&args.output, options).map_err(video_err)?;
    let frames = video.frames_of(&replay);
    let bar = if std::io::stderr().is_terminal() {
        let style =
            ProgressStyle::with_template("{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} frames, eta {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar());
        ProgressBar::new(frames.len() as u64).with_style(style)
    } else {
        ProgressBar::hidden()
    };
    let mut scene = Scene::default();
    for &k in &frames {
        replay.scene(k, &mut scene);
        video.push(&scene).map_err(video_err)?;
        bar.inc(1);
    }
    bar.finish_and_clear();
    let written = video.finish().map_err(video_err)?;
    eprintln!("wrote {written} frames to {}", args.output.display());
    Ok(())
}
