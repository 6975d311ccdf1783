//! What `Env` and `VectorEnv` share: an engine `Env` plus its observation encoder and frame
//! stacks, with every buffer allocated once.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use touchline_engine::obs::{FrameStack, encode_simple115, encode_simple115v2, encode_smm};
use touchline_engine::{ActionSet, EngineError, Env, EnvConfig, Scenario, Snapshot, StepInfo, StepOutcome};
use touchline_render::{PixelsEncoder, PixelsKind};

/// Frames kept by `stacked=True` (GRF's FrameStack(4), docs/grf-compatibility.md#frame-stacking).
const STACK: usize = 4;

/// How observations are encoded (docs/grf-compatibility.md#representations).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Representation {
    /// GRF's dict of arrays (no array encoding).
    Raw,
    /// float32 (115,), legacy padding.
    Simple115,
    /// float32 (115,), fixed positions.
    Simple115v2,
    /// uint8 (H, W, 4) Super Mini Map.
    Smm { width: usize, height: usize },
    /// uint8 (H, W, 3) RGB or (H, W, 1) grey rendered frames (touchline-render).
    Pixels { width: usize, height: usize, gray: bool },
}

impl Representation {
    pub(crate) fn parse(name: &str, channel_dimensions: (usize, usize)) -> PyResult<Representation> {
        let (width, height) = channel_dimensions;
        match name {
            "raw" => Ok(Representation::Raw),
            "simple115" => Ok(Representation::Simple115),
            "simple115v2" => Ok(Representation::Simple115v2),
            "extracted" | "smm" | "pixels" | "pixels_gray" => {
                if width == 0 || height == 0 || width > 4096 || height > 4096 {
                    return Err(PyValueError::new_err(format!(
                        "channel_dimensions must be (width, height) between 1 and 4096, got ({width}, {height})"
                    )));
                }
                Ok(match name {
                    "pixels" => Representation::Pixels { width, height, gray: false },
                    "pixels_gray" => Representation::Pixels { width, height, gray: true },
                    _ => Representation::Smm { width, height },
                })
            }
            other => Err(PyValueError::new_err(format!(
                "unknown representation {other:?}: expected \"raw\", \"simple115\", \"simple115v2\", \"extracted\", \"pixels\" or \"pixels_gray\""
            ))),
        }
    }

    /// One frame's shape and its last-axis size (channels).
    fn frame(self) -> (Vec<usize>, usize) {
        match self {
            Representation::Raw => (Vec::new(), 0),
            Representation::Simple115 | Representation::Simple115v2 => (vec![115], 115),
            Representation::Smm { width, height } => (vec![height, width, 4], 4),
            Representation::Pixels { width, height, gray } => {
                let c = if gray { 1 } else { 3 };
                (vec![height, width, c], c)
            }
        }
    }
}

/// The Python `touchline.EnvOptions` (python/touchline/options.py), read field by field: how an
/// env is made, as one value. The Python side has checked and normalised every field already;
/// [`EnvArgs::parse`] checks them again, so that the extension's own `Env` and `VectorEnv` refuse
/// a bad value whatever object they are given.
#[derive(Clone, Debug, FromPyObject)]
pub(crate) struct EnvOptions {
    /// "raw", "simple115", "simple115v2", "extracted" (or "smm"), "pixels" or "pixels_gray".
    #[pyo3(attribute)]
    pub(crate) representation: String,
    /// "scoring" or "scoring,checkpoints".
    #[pyo3(attribute)]
    pub(crate) rewards: String,
    /// Stack the last 4 observations along the last axis.
    #[pyo3(attribute)]
    pub(crate) stacked: bool,
    /// Left-team players the agent controls.
    #[pyo3(attribute("number_of_left_players_agent_controls"))]
    pub(crate) left_agents: usize,
    /// Right-team players the agent controls.
    #[pyo3(attribute("number_of_right_players_agent_controls"))]
    pub(crate) right_agents: usize,
    /// (width, height) of image observations, pixels.
    #[pyo3(attribute)]
    pub(crate) channel_dimensions: (usize, usize),
    /// "default" or "v2".
    #[pyo3(attribute)]
    pub(crate) action_set: String,
    /// Hot reload of the scenario file.
    #[pyo3(attribute)]
    pub(crate) watch: bool,
}

impl EnvOptions {
    /// Reads `options`, a `touchline.EnvOptions` or any object with its attributes.
    ///
    /// # Errors
    /// `TypeError` naming what is missing or of the wrong type.
    pub(crate) fn read(options: &Bound<'_, PyAny>) -> PyResult<EnvOptions> {
        options.extract::<EnvOptions>().map_err(|e| {
            PyTypeError::new_err(format!(
                "options must be a touchline.EnvOptions (or have its attributes), got {}: {}",
                options.get_type().name().map_or_else(|_| "?".to_owned(), |n| n.to_string()),
                e.value(options.py())
            ))
        })
    }
}

/// Constructor arguments shared by `Env` and `VectorEnv`.
#[derive(Clone, Debug)]
pub(crate) struct EnvArgs {
    pub(crate) scenario: Scenario,
    /// The scenario's scripts, compiled once and shared by every env built from these arguments.
    pub(crate) scripts: touchline_dsl::script::Scripts,
    pub(crate) representation: Representation,
    pub(crate) config: EnvConfig,
    pub(crate) stacked: bool,
    /// With `watch=True`: the watched source every env made from these arguments follows.
    pub(crate) watch: Option<std::sync::Arc<crate::watch::Watch>>,
}

impl EnvArgs {
    /// Loads `scenario` (with its scripts) and checks `options`.
    ///
    /// # Errors
    /// `ScenarioError` when the scenario or its scripts do not load; `ValueError` for a bad option.
    pub(crate) fn parse(py: Python<'_>, scenario: &str, options: &EnvOptions) -> PyResult<EnvArgs> {
        let EnvOptions {
            representation,
            rewards,
            stacked,
            left_agents,
            right_agents,
            channel_dimensions,
            action_set,
            watch,
        } = options.clone();
        let spec = scenario;
        let (scenario, scripts, watch) = if watch {
            let watch = crate::watch::Watch::start(py, spec)?;
            let build = watch.watched.current();
            (build.scenario.clone(), build.scripts.clone(), Some(watch))
        } else {
            let scenario = touchline_dsl::load(spec).map_err(|e| crate::errors::scenario_error(py, &e))?;
            let scripts = touchline_dsl::script::Scripts::compile(
                &scenario,
                &touchline_dsl::script_dir(spec),
                touchline_dsl::script::ScriptOptions::default(),
            )
            .map_err(|e| crate::errors::script_errors(py, &e))?;
            (scenario, scripts, None)
        };
        let representation = Representation::parse(&representation, channel_dimensions)?;
        let mut checkpoints = false;
        let mut scoring = false;
        for term in rewards.split(',').map(str::trim).filter(|t| !t.is_empty()) {
            match term {
                "scoring" => scoring = true,
                "checkpoints" => checkpoints = true,
                other => {
                    return Err(PyValueError::new_err(format!(
                        "unknown reward {other:?}: expected \"scoring\" or \"scoring,checkpoints\""
                    )));
                }
            }
        }
        if !scoring {
            return Err(PyValueError::new_err("rewards must include \"scoring\" (as in GRF)"));
        }
        let action_set = match action_set.as_str() {
            "default" => ActionSet::Default,
            "v2" => ActionSet::V2,
            other => {
                return Err(PyValueError::new_err(format!(
                    "unknown action_set {other:?}: expected \"default\" or \"v2\""
                )));
            }
        };
        if representation == Representation::Raw && stacked {
            return Err(PyValueError::new_err("stacked=True needs an array representation, not \"raw\""));
        }
        Ok(EnvArgs {
            scenario,
            scripts,
            representation,
            config: EnvConfig { left_agents, right_agents, action_set, checkpoints },
            stacked,
            watch,
        })
    }
}

/// Observation output buffers.
pub(crate) enum ObsOut<'a> {
    F32(&'a mut [f32]),
    U8(&'a mut [u8]),
}

/// What a vector env does with a match whose episode just ended: Gymnasium's `AutoresetMode`
/// (<https://farama.org/Vector-Autoreset-Mode>).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Autoreset {
    /// The step that ends an episode returns its last observation; the next step ignores the
    /// match's action and resets it (reward 0, not terminated or truncated).
    NextStep,
    /// The step that ends an episode resets the match at once and returns the next episode's
    /// first observation; the last one goes in `final_obs`.
    SameStep,
    /// The match stays ended until the caller resets it (`reset_mask`); stepping it is an error.
    Disabled,
}

impl Autoreset {
    /// Parses Gymnasium's `AutoresetMode` values: "NextStep", "SameStep", "Disabled".
    pub(crate) fn parse(name: &str) -> PyResult<Autoreset> {
        match name {
            "NextStep" => Ok(Autoreset::NextStep),
            "SameStep" => Ok(Autoreset::SameStep),
            "Disabled" => Ok(Autoreset::Disabled),
            other => Err(pyo3::exceptions::PyValueError::new_err(format!(
                "unknown autoreset mode {other:?}; expected \"NextStep\", \"SameStep\" or \"Disabled\""
            ))),
        }
    }
}

/// An engine env with its encoder.
pub(crate) struct EnvCore {
    pub(crate) env: Env,
    pub(crate) representation: Representation,
    stacked: bool,
    frame_len: usize,
    stacks_f32: Vec<FrameStack<f32>>,
    stacks_u8: Vec<FrameStack<u8>>,
    frame_u8: Vec<u8>,
    /// The renderer of the pixels representations (the pitch painted once).
    pixels: Option<PixelsEncoder>,
    /// The info of the last step that ended an episode (a vector env resets at once, and its
    /// `final_info` still reports the finished episode's score).
    pub(crate) final_info: StepInfo,
    /// The scenario version of the step that ended the last episode.
    pub(crate) final_version: u64,
    /// The last step ended the episode and the match has not been reset since (vector envs in
    /// [`Autoreset::NextStep`] and [`Autoreset::Disabled`]).
    pub(crate) ended: bool,
    /// With `watch=True`: which version of the scenario the match plays.
    pub(crate) playing: Option<touchline_dsl::watch::Playing>,
}

impl EnvCore {
    pub(crate) fn new(args: &EnvArgs, seed: u64) -> Result<EnvCore, EngineError> {
        let (env, playing) = match &args.watch {
            Some(watch) => {
                let (env, playing) = watch.watched.env_playing(args.config, seed)?;
                (env, Some(playing))
            }
            None => (touchline_dsl::attach(&args.scripts, args.scenario.clone(), args.config, seed)?, None),
        };
        let (shape, channels) = args.representation.frame();
        let frame_len: usize = if shape.is_empty() { 0 } else { shape.iter().product() };
        let m = env.num_controllers();
        let (stacks_f32, stacks_u8) = match (args.stacked, args.representation) {
            (false, _) | (_, Representation::Raw) => (Vec::new(), Vec::new()),
            (true, Representation::Smm { .. } | Representation::Pixels { .. }) => {
                (Vec::new(), (0..m).map(|_| FrameStack::new(frame_len, channels, STACK)).collect())
            }
            (true, _) => ((0..m).map(|_| FrameStack::new(frame_len, channels, STACK)).collect(), Vec::new()),
        };
        Ok(EnvCore {
            env,
            representation: args.representation,
            stacked: args.stacked,
            frame_len,
            stacks_f32,
            stacks_u8,
            frame_u8: vec![0; frame_len],
            final_info: StepInfo::default(),
            final_version: 0,
            ended: false,
            playing,
            pixels: match args.representation {
                Representation::Pixels { width, height, gray } => {
                    let kind = if gray { PixelsKind::Gray } else { PixelsKind::Rgb };
                    // Sizes were checked when the arguments were parsed.
                    PixelsEncoder::new(width, height, kind).ok()
                }
                _ => None,
            },
        })
    }

    /// The version of the scenario played: 0 without `watch=True`, else the watcher's generation
    /// (1 for the file as first loaded, one more for each change that compiled and was taken up).
    pub(crate) fn scenario_version(&self) -> u64 {
        self.playing.as_ref().map_or(0, touchline_dsl::watch::Playing::generation)
    }

    /// Shape of one controller's observation (stacking included).
    pub(crate) fn observation_shape(&self) -> Vec<usize> {
        let (mut shape, _) = self.representation.frame();
        if self.stacked
            && let Some(last) = shape.last_mut()
        {
            *last *= STACK;
        }
        shape
    }

    /// Elements of one controller's observation.
    pub(crate) fn observation_len(&self) -> usize {
        if self.stacked { self.frame_len * STACK } else { self.frame_len }
    }

    pub(crate) fn dtype(&self) -> &'static str {
        match self.representation {
            Representation::Raw => "raw",
            Representation::Smm { .. } | Representation::Pixels { .. } => "uint8",
            _ => "float32",
        }
    }

    /// Starts the next episode (of `seed` when given).
    ///
    /// # Errors
    /// A script's `reset` hook that fails: the episode is over before it began and the match
    /// counts as ended, so that a vector env resets it again (to the following episode) at its
    /// next step instead of stepping a broken episode.
    pub(crate) fn reset(&mut self, seed: Option<u64>) -> Result<(), EngineError> {
        let result = match seed {
            Some(s) => self.env.reset_with_seed(s),
            None => self.env.reset(),
        };
        self.ended = result.is_err();
        result
    }

    /// One match's part of a vector step under `mode`: steps it with `actions` (or, in
    /// [`Autoreset::NextStep`], resets the match the previous step ended) and writes its
    /// rewards, its observations into `obs` and, when [`Autoreset::SameStep`] resets it, the
    /// ended episode's last observations into `finals`. Returns (terminated, truncated).
    pub(crate) fn vector_step(
        &mut self,
        actions: &[u32],
        mode: Autoreset,
        rewards: &mut [f32],
        obs: ObsOut<'_>,
        finals: Option<ObsOut<'_>>,
    ) -> Result<(bool, bool), EngineError> {
        if self.ended && mode == Autoreset::NextStep {
            self.reset(None)?;
            rewards.fill(0.0);
            self.write_observations(obs, true);
            return Ok((false, false));
        }
        if self.ended && mode == Autoreset::SameStep {
            // Only a failed reset leaves a SameStep match ended: try the next episode.
            self.reset(None)?;
        }
        let outcome = self.step(actions)?;
        rewards.copy_from_slice(self.env.rewards());
        let done = outcome.terminated || outcome.truncated;
        if done && mode == Autoreset::SameStep {
            if let Some(finals) = finals {
                self.write_observations(finals, false);
            }
            self.reset(None)?;
            self.write_observations(obs, true);
        } else {
            self.write_observations(obs, false);
            self.ended = done;
        }
        Ok((outcome.terminated, outcome.truncated))
    }

    pub(crate) fn step(&mut self, actions: &[u32]) -> Result<StepOutcome, EngineError> {
        let outcome = self.env.step_indices(actions)?;
        if outcome.terminated || outcome.truncated {
            self.final_info = *self.env.info();
            self.final_version = self.scenario_version();
        }
        Ok(outcome)
    }

    /// Encodes every controller's observation into `out` (M × observation_len). `fresh` means
    /// the first observation of an episode: stacks are refilled with it.
    pub(crate) fn write_observations(&mut self, out: ObsOut<'_>, fresh: bool) {
        let len = self.observation_len();
        match (self.representation, out) {
            (Representation::Raw, _) => {}
            (Representation::Smm { width, height }, ObsOut::U8(out)) => {
                for (i, obs) in self.env.observations().iter().enumerate() {
                    let dst = &mut out[i * len..(i + 1) * len];
                    if self.stacked {
                        encode_smm(obs, width, height, &mut self.frame_u8);
                        let stack = &mut self.stacks_u8[i];
                        if fresh {
                            stack.reset(&self.frame_u8);
                        } else {
                            stack.push(&self.frame_u8);
                        }
                        stack.write_stacked(dst);
                    } else {
                        encode_smm(obs, width, height, dst);
                    }
                }
            }
            (Representation::Pixels { .. }, ObsOut::U8(out)) => {
                let Some(encoder) = self.pixels.as_mut() else { return };
                for i in 0..self.env.num_controllers() {
                    let dst = &mut out[i * len..(i + 1) * len];
                    if self.stacked {
                        encoder.encode(&self.env, i, &mut self.frame_u8);
                        let stack = &mut self.stacks_u8[i];
                        if fresh {
                            stack.reset(&self.frame_u8);
                        } else {
                            stack.push(&self.frame_u8);
                        }
                        stack.write_stacked(dst);
                    } else {
                        encoder.encode(&self.env, i, dst);
                    }
                }
            }
            (repr, ObsOut::F32(out)) => {
                let mut frame = [0.0f32; 115];
                for (i, obs) in self.env.observations().iter().enumerate() {
                    if repr == Representation::Simple115 {
                        encode_simple115(obs, &mut frame);
                    } else {
                        encode_simple115v2(obs, &mut frame);
                    }
                    let dst = &mut out[i * len..(i + 1) * len];
                    if self.stacked {
                        let stack = &mut self.stacks_f32[i];
                        if fresh {
                            stack.reset(&frame);
                        } else {
                            stack.push(&frame);
                        }
                        stack.write_stacked(dst);
                    } else {
                        dst.copy_from_slice(&frame);
                    }
                }
            }
            // The callers allocate the buffer from `dtype()`, so the kinds always match.
            (_, _) => {}
        }
    }
}

impl EnvCore {
    /// The env's snapshot with the frame stacks as its extra bytes, all under its checksum
    /// ([`Snapshot::to_bytes_with`]): what `start from` reads too.
    pub(crate) fn state_bytes(&self) -> Vec<u8> {
        let stacks = postcard::to_allocvec(&(&self.stacks_f32, &self.stacks_u8)).unwrap_or_default();
        self.env.snapshot().to_bytes_with(&stacks)
    }

    /// Restores bytes from [`EnvCore::state_bytes`]; on any error nothing changes.
    pub(crate) fn restore_bytes(&mut self, bytes: &[u8]) -> Result<(), EngineError> {
        let bad = |reason: &str| EngineError::InvalidSnapshot { reason: reason.into() };
        let (snapshot, stacks) = Snapshot::from_bytes_with(bytes)?;
        type Stacks = (Vec<FrameStack<f32>>, Vec<FrameStack<u8>>);
        let (f, u): Stacks = postcard::from_bytes(&stacks).map_err(|_| bad("the frame stacks do not decode"))?;
        let fits = f.len() == self.stacks_f32.len()
            && u.len() == self.stacks_u8.len()
            && f.iter().zip(&self.stacks_f32).all(|(a, b)| b.same_shape(a))
            && u.iter().zip(&self.stacks_u8).all(|(a, b)| b.same_shape(a));
        if !fits {
            return Err(bad("the frame stacks belong to another representation"));
        }
        // Frames of simple115 hold finite values only; a NaN would reach the learner as is.
        if !f.iter().all(FrameStack::is_finite) {
            return Err(bad("the frame stacks hold a value that is not finite"));
        }
        self.env.restore(&snapshot)?;
        self.stacks_f32 = f;
        self.stacks_u8 = u;
        Ok(())
    }
}
