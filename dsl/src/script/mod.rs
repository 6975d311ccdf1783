//! Reward terms and end conditions written in [rhai](https://rhai.rs), run by the env through the
//! engine's [`Hooks`](touchline_engine::Hooks) trait.
//!
//! A scenario names scripts (`reward script "shaping/possession.rhai" weight 0.1`,
//! `end when script "ends/ball_lost.rhai"`; paths relative to the scenario file). Each script is
//! compiled once, at load ([`Scripts::compile`]), and its hooks are called by name:
//!
//! - a **reward script** defines `fn reward(s)`, called after every step once per team that has
//!   agents, in that team's frame. It returns a number (paid to each of the team's agents) or an
//!   array with one number per agent (in the order of `s.controlled`). The scenario's weight
//!   multiplies it.
//! - an **end script** defines `fn end(s)`, called after every step in the left team's frame; it
//!   returns `true` to end (terminate) the episode.
//! - a **behaviour script** (`CM at (…) does script "run_and_shoot.rhai"`) defines `fn act(s, me)`,
//!   called before every step for each player whose behaviour stage it is (and whom no agent
//!   drives), in that player's team's frame; `me` is his index in his team (`s.left_team[me]` is
//!   where he stands). It returns an action: its GRF name (`"shot"`, `"top_right"`, `"sprint"`,
//!   …) or its index in the default 19-action set. The action is applied as an agent's, with a
//!   sticky gamepad of the player's own; `builtin_ai` is not available (the player stands). One
//!   `memory` per file, shared by every player running it (key it by `me`). A set piece the
//!   player is to take is taken by the built-in AI.
//! - any may define `fn reset(s)`, called at the start of each episode (e.g. to fill `memory`).
//!
//! `s` is the read-only state (the getters are in the table below: ball, players,
//! score, game mode, steps left, the agents' players and actions, `s.prev` the previous step).
//! `memory` is an object map each script keeps for the episode (emptied at reset, saved in env
//! snapshots), visible inside the hook functions (pass it to helper functions as an argument).
//! The top level of a script may define `fn`s and `const`s only.
//!
//! ```rhai
//! // A possession bonus: 0.001 per step the team has the ball.
//! fn reward(s) {
//!     if s.ball_owned_team == 0 { 0.001 } else { 0.0 }
//! }
//! ```
//!
//! Sandbox ([`Limits`]): each call has an operation budget (built-ins on collections charged by
//! the size of what they go through, so that the budget bounds time: about 10 ms a call in the
//! worst cases we could write), a call-depth limit and size limits on strings, arrays and maps;
//! variables must be declared (strict variables, checked when the script compiles); there is no
//! `import`, no `eval`, no clock, no `sleep` (a call to either is refused when the script
//! compiles, `tl::S008`), no randomness and no file or network access. Script files are regular
//! `.rhai` files of at most [`MAX_SCRIPT_BYTES`]. `print` and `debug` lines go to the env's log
//! ([`Env::hook_log`](touchline_engine::Env::hook_log)). The limits, their values and the
//! measured worst cases are tabled in `grammar/scripts.md`.
//!
//! Errors are [`ScriptError`] diagnostics `tl::S001` … `tl::S010` (`tl::S007` is the watcher's). When a hook fails during a
//! step, [`ErrorPolicy`] decides: fail the step (the default), or pay zero for that term, log
//! the error and count it in `StepInfo::script_errors`.
//!
//! ## State API (`s`)
//!
//! Every property of `s` ([`STATE_PROPERTIES`]), with its type, unit, frame and range, a worked
//! example per hook and the codes are in the scripts reference, `grammar/scripts.md`, whose
//! examples `dsl/tests/script_reference.rs` compiles and plays. Frame: the team's own (its goal at
//! x = -1), GRF-normalised like the observation. A property the state does not have is refused when
//! the script compiles (`tl::S010`, with the closest real names).
//!
//! Function: `f32(x)` rounds a float to single precision, as the engine computes.

mod api;
mod cost;
mod engine;
mod error;
mod file;
mod hooks;
mod memory;
mod properties;
mod refused;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use miette::{Diagnostic, NamedSource};
use rhai::{AST, Dynamic, Engine, Map, Scope};
use thiserror::Error;
use touchline_engine::Scenario;
use touchline_engine::scenario::{EndCondition, RewardKind};

pub use api::STATE_PROPERTIES;
pub use engine::Limits;
pub use error::ScriptError;
pub use file::MAX_SCRIPT_BYTES;
pub use hooks::ScriptHooks;

/// What a failing hook does to the step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ErrorPolicy {
    /// The step fails with the diagnostic ([`EngineError::Script`](touchline_engine::EngineError::Script)),
    /// and the episode is over.
    #[default]
    Raise,
    /// The term pays zero (an end script does not end the episode), the diagnostic goes to the log
    /// and `StepInfo::script_errors` counts it.
    Warn,
}

/// How scripts run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ScriptOptions {
    /// Limits of each hook call.
    pub limits: Limits,
    /// What a failing hook does.
    pub on_error: ErrorPolicy,
}

/// Every load error of a scenario's scripts, reported at once.
#[derive(Debug, Error, Diagnostic)]
#[error("{} script error{} in the scenario", errors.len(), if errors.len() == 1 { "" } else { "s" })]
pub struct ScriptErrors {
    /// One diagnostic per problem.
    #[related]
    pub errors: Vec<ScriptError>,
}

/// What a script is for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Role {
    Reward {
        weight: f32,
    },
    End,
    /// A player's behaviour (`does script "x.rhai"`): `fn act(s, me)` returns an action.
    Behaviour,
}

impl Role {
    fn hook(self) -> &'static str {
        match self {
            Role::Reward { .. } => "reward",
            Role::End => "end",
            Role::Behaviour => "act",
        }
    }

    /// Parameters the hook takes: the state, and for `act` the player's index.
    fn arity(self) -> usize {
        match self {
            Role::Behaviour => 2,
            _ => 1,
        }
    }
}

/// One compiled script.
#[derive(Debug)]
pub(crate) struct Script {
    /// The path as the scenario wrote it.
    pub(crate) path: String,
    pub(crate) text: String,
    pub(crate) ast: AST,
    /// The top level's constants, put in each call's scope.
    pub(crate) constants: Vec<(String, Dynamic)>,
    pub(crate) role: Role,
    pub(crate) has_reset: bool,
}

impl Script {
    pub(crate) fn source(&self) -> NamedSource<String> {
        NamedSource::new(&self.path, self.text.clone()).with_language("rhai")
    }
}

#[derive(Debug)]
pub(crate) struct ScriptSet {
    pub(crate) scripts: Vec<Script>,
    pub(crate) options: ScriptOptions,
    pub(crate) files: Vec<PathBuf>,
}

/// A scenario's scripts, compiled once; cheap to clone and shared by every env built from it
/// (each env gets its own [`ScriptHooks`] with its own `memory`).
#[derive(Clone, Debug)]
pub struct Scripts {
    pub(crate) set: Arc<ScriptSet>,
}

impl Scripts {
    /// Reads and compiles every script `scenario` names (reward terms, then end conditions), with
    /// paths relative to `dir` (the scenario file's folder).
    ///
    /// # Errors
    /// Every problem at once: unreadable files (`tl::S001`), syntax (`tl::S002`), a missing or
    /// wrong hook (`tl::S003`), a top level that is not only `fn`s and `const`s (`tl::S004`).
    pub fn compile(scenario: &Scenario, dir: &Path, options: ScriptOptions) -> Result<Scripts, ScriptErrors> {
        Scripts::compile_with(scenario, options, |path| {
            let file = dir.join(path);
            let text = file::read_script(&file)
                .map_err(|source| ScriptError::Unreadable { path: file.display().to_string(), source });
            (Some(file), text)
        })
    }

    /// Compiles every script `scenario` names from texts held in memory (`sources`: the path as
    /// the scenario names it, and the text), for instance the scripts a replay carries.
    ///
    /// # Errors
    /// As [`Scripts::compile`]; a script missing from `sources` is `tl::S001` (unreadable).
    pub fn from_sources<'a>(
        scenario: &Scenario,
        sources: impl IntoIterator<Item = (&'a str, &'a str)>,
        options: ScriptOptions,
    ) -> Result<Scripts, ScriptErrors> {
        let sources: Vec<(&str, &str)> = sources.into_iter().collect();
        Scripts::compile_with(scenario, options, |path| {
            let text = sources.iter().find(|(p, _)| *p == path).map(|(_, t)| (*t).to_owned()).ok_or_else(|| {
                ScriptError::Unreadable {
                    path: path.to_owned(),
                    source: std::io::Error::new(std::io::ErrorKind::NotFound, "its text was not given"),
                }
            });
            (None, text)
        })
    }

    /// The path (as the scenario names it) and text of every script, in the order compiled.
    pub fn sources(&self) -> impl Iterator<Item = (&str, &str)> {
        self.set.scripts.iter().map(|s| (s.path.as_str(), s.text.as_str()))
    }

    /// Compiles the scripts `scenario` names, reading each one's text with `read` (given the path
    /// as the scenario names it; returns the resolved file, if any, and the text).
    fn compile_with(
        scenario: &Scenario,
        options: ScriptOptions,
        mut read: impl FnMut(&str) -> (Option<PathBuf>, Result<String, ScriptError>),
    ) -> Result<Scripts, ScriptErrors> {
        // With a curriculum the env plays the lessons, which all run the same scripts (checked
        // when compiling): the first lesson's are the ones to load.
        let scenario = scenario.curriculum.as_ref().and_then(|c| c.lessons.first()).map_or(scenario, |l| &l.scenario);
        let mut wanted = Vec::new();
        for term in &scenario.rewards {
            if let RewardKind::Script { path } = &term.reward {
                wanted.push((path.clone(), Role::Reward { weight: term.weight }));
            }
        }
        for end in &scenario.end_when {
            if let EndCondition::Script { path } = end {
                wanted.push((path.clone(), Role::End));
            }
        }
        // One compiled script (and one `memory`) per behaviour file, however many players use it.
        for path in scenario.script_behaviours() {
            if !wanted.iter().any(|(p, role)| p == path && *role == Role::Behaviour) {
                wanted.push((path.to_owned(), Role::Behaviour));
            }
        }
        let mut scripts = Vec::new();
        let mut errors = Vec::new();
        let mut files = Vec::new();
        for (path, role) in wanted {
            let (file, text) = read(&path);
            files.extend(file);
            let text = match text {
                Ok(text) => text,
                Err(e) => {
                    errors.push(e);
                    continue;
                }
            };
            match compile_text(&path, text, role, &options) {
                Ok(script) => scripts.push(script),
                Err(e) => errors.push(*e),
            }
        }
        if errors.is_empty() {
            Ok(Scripts { set: Arc::new(ScriptSet { scripts, options, files }) })
        } else {
            Err(ScriptErrors { errors })
        }
    }

    /// Compiles one script from text (`path` names it in diagnostics): a reward script with
    /// `weight` when `weight` is `Some`, else an end script. For tests, benchmarks and tools.
    ///
    /// # Errors
    /// As [`Scripts::compile`].
    pub fn from_text(
        path: &str,
        text: &str,
        weight: Option<f32>,
        options: ScriptOptions,
    ) -> Result<Scripts, Box<ScriptError>> {
        let role = weight.map_or(Role::End, |weight| Role::Reward { weight });
        let script = compile_text(path, text.to_owned(), role, &options)?;
        Ok(Scripts { set: Arc::new(ScriptSet { scripts: vec![script], options, files: Vec::new() }) })
    }

    /// Whether there are no scripts.
    pub fn is_empty(&self) -> bool {
        self.set.scripts.is_empty()
    }

    /// The script files read (resolved paths), for watching.
    pub fn files(&self) -> &[PathBuf] {
        &self.set.files
    }

    /// Fresh hooks for one env (empty `memory`).
    pub fn hooks(&self) -> ScriptHooks {
        ScriptHooks::new(Arc::clone(&self.set))
    }

    /// Fresh hooks for one env as the engine takes them, or `None` when there are no scripts
    /// (as [`crate::attach`] chooses between `Env::with_hooks` and `Env::with_config`).
    pub fn engine_hooks(&self) -> Option<Box<dyn touchline_engine::Hooks>> {
        (!self.is_empty()).then(|| Box::new(self.hooks()) as Box<dyn touchline_engine::Hooks>)
    }
}

/// The scope every hook call sees: `memory`, then the script's constants.
pub(crate) fn base_scope(script: &Script) -> Scope<'static> {
    let mut scope = Scope::new();
    scope.push("memory", Map::new());
    for (name, value) in &script.constants {
        scope.push_constant_dynamic(name.clone(), value.clone());
    }
    scope
}

/// Compiles `text`: a first, non-strict pass runs the top level to collect its constants; the
/// second pass compiles strictly with `memory` and those constants declared.
fn compile_text(path: &str, text: String, role: Role, options: &ScriptOptions) -> Result<Script, Box<ScriptError>> {
    let sink = engine::PrintSink::default();
    let meter = Arc::new(engine::Meter::default());
    let src = || NamedSource::new(path, text.clone()).with_language("rhai");
    let syntax = |e: rhai::ParseError| {
        Box::new(ScriptError::Syntax {
            path: path.to_owned(),
            message: e.err_type().to_string(),
            src: src(),
            span: error::span_at(&text, e.position()),
        })
    };
    let loose = engine::sandboxed(&options.limits, false, &sink, &meter);
    let first = loose.compile(&text).map_err(syntax)?;
    // Before the top level runs: it runs now, and a `sleep` there would hang the compile.
    if let Some(refusal) = refused::first_refused(&first) {
        return Err(Box::new(ScriptError::Refused {
            path: path.to_owned(),
            name: refusal.name,
            src: src(),
            span: error::span_at(&text, refusal.position),
            help: refusal.why.to_owned(),
        }));
    }
    if let Some(unknown) = properties::first_unknown(&first) {
        let at = error::span_at(&text, unknown.position).offset();
        return Err(Box::new(ScriptError::UnknownProperty {
            path: path.to_owned(),
            help: properties::help(&unknown.name),
            span: (at, unknown.name.len()).into(),
            name: unknown.name,
            src: src(),
        }));
    }
    let mut top = Scope::new();
    top.push("memory", Map::new());
    meter.start();
    if let Err(e) = loose.run_ast_with_scope(&mut top, &first) {
        return Err(Box::new(ScriptError::TopLevel {
            path: path.to_owned(),
            message: format!("the top level fails: {}", hooks::failure(&e).0),
            src: src(),
            span: error::span_at(&text, e.position()),
        }));
    }
    let mut constants = Vec::new();
    for (name, constant, value) in top.iter() {
        if name == "memory" {
            continue;
        }
        if !constant {
            // The declaration, not a mention in a comment: `let` first on its line.
            let declaration = format!("let {name}");
            let at = text
                .match_indices(&declaration)
                .map(|(at, _)| at)
                .find(|&at| text[..at].rsplit('\n').next().is_some_and(|before| before.trim().is_empty()))
                .unwrap_or(0);
            return Err(Box::new(ScriptError::TopLevel {
                path: path.to_owned(),
                message: format!("`let {name}` at the top level would keep state across episodes"),
                src: src(),
                span: (at, 4 + name.len()).into(),
            }));
        }
        constants.push((name.to_owned(), value));
    }
    let strict: Engine = engine::sandboxed(&options.limits, true, &sink, &meter);
    let mut scope = Scope::new();
    scope.push("memory", Map::new());
    for (name, value) in &constants {
        scope.push_constant_dynamic(name.clone(), value.clone());
    }
    let ast = strict.compile_with_scope(&scope, &text).map_err(syntax)?;
    let hook = role.hook();
    let arity =
        |name: &str| ast.iter_functions().filter(|f| f.name == name).map(|f| f.params.len()).collect::<Vec<_>>();
    let found = arity(hook);
    if !found.contains(&role.arity()) {
        let help = match found.first() {
            Some(n) if role == Role::Behaviour => format!(
                "`act` takes {n} parameters; it must take two, the state and the player's index: `fn act(s, me) {{ … }}`"
            ),
            Some(n) => format!("`{hook}` takes {n} parameters; it must take one, the state: `fn {hook}(s) {{ … }}`"),
            None if role == Role::Behaviour => "a behaviour script defines `fn act(s, me)` returning an action \
                                                 name (\"shot\", \"right\", …) or its index in the default set"
                .to_owned(),
            None if matches!(role, Role::Reward { .. }) => {
                "a reward script defines `fn reward(s)` returning a number, or an array with one number per agent"
                    .to_owned()
            }
            None => "an end-condition script defines `fn end(s)` returning true to end the episode".to_owned(),
        };
        return Err(Box::new(ScriptError::MissingHook { path: path.to_owned(), hook, help }));
    }
    let resets = arity("reset");
    if !resets.is_empty() && !resets.contains(&1) {
        return Err(Box::new(ScriptError::MissingHook {
            path: path.to_owned(),
            hook: "reset",
            help: "`reset` must take one parameter, the state: `fn reset(s) { … }`".to_owned(),
        }));
    }
    Ok(Script { path: path.to_owned(), text, ast, constants, role, has_reset: !resets.is_empty() })
}
