//! [`ScriptHooks`]: one env's running scripts, implementing the engine's [`Hooks`].

use std::fmt;
use std::sync::Arc;

use rhai::{CallFnOptions, Dynamic, Engine, EvalAltResult, Map, Scope};
use touchline_engine::{Action, ActionSet, EngineError, HookOutcome, HookView, Hooks, Side};

use super::api::{State, TeamState};
use super::engine::{self, Meter, PrintSink};
use super::error::{self, ScriptError};
use super::memory::{self, Value};
use super::{ErrorPolicy, Role, Script, ScriptSet, base_scope};

/// The scripts of one env: a sandboxed engine, each script's scope (its `memory` and constants)
/// and the last two team views. Built by [`Scripts::hooks`](super::Scripts::hooks).
pub struct ScriptHooks {
    set: Arc<ScriptSet>,
    engine: Engine,
    sink: PrintSink,
    /// What the call under way has spent besides rhai's operations (built-ins on collections).
    meter: Arc<Meter>,
    scopes: Vec<Scope<'static>>,
    /// The views after the last reset or step, left and right.
    now: [Arc<TeamState>; 2],
    /// The views one step earlier (`None` at reset).
    prev: [Option<Arc<TeamState>>; 2],
    log: Vec<String>,
    /// Behaviour scripts ran for the step under way (their log lines stay for the step's log).
    acted: bool,
    /// Behaviour-script failures absorbed for the step under way (counted in its outcome).
    act_errors: u32,
}

impl fmt::Debug for ScriptHooks {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let paths: Vec<&str> = self.set.scripts.iter().map(|s| s.path.as_str()).collect();
        f.debug_struct("ScriptHooks").field("scripts", &paths).finish_non_exhaustive()
    }
}

/// What a hook call returned.
enum Returned {
    Paid,
    End(bool),
}

impl ScriptHooks {
    pub(crate) fn new(set: Arc<ScriptSet>) -> ScriptHooks {
        let sink = PrintSink::default();
        let meter = Arc::new(Meter::default());
        let engine = engine::sandboxed(&set.options.limits, true, &sink, &meter);
        let scopes = set.scripts.iter().map(base_scope).collect();
        ScriptHooks {
            set,
            engine,
            sink,
            meter,
            scopes,
            now: [Arc::default(), Arc::default()],
            prev: [None, None],
            log: Vec::new(),
            acted: false,
            act_errors: 0,
        }
    }

    /// A copy with its own engine and the same scripts, memory and views.
    pub(crate) fn clone_of(&self) -> ScriptHooks {
        let mut copy = ScriptHooks::new(Arc::clone(&self.set));
        copy.scopes.clone_from(&self.scopes);
        copy.now = [Arc::new((*self.now[0]).clone()), Arc::new((*self.now[1]).clone())];
        copy.prev = self.prev.clone();
        copy
    }

    /// The views this step needs: each side with agents, the left side for end scripts, both
    /// for behaviour scripts (whose players may be on either side).
    fn sides(&self, view: &HookView<'_>) -> [bool; 2] {
        let ends = self.set.scripts.iter().any(|s| s.role == Role::End);
        let acts = self.set.scripts.iter().any(|s| s.role == Role::Behaviour);
        [view.left_controllers > 0 || ends || acts, view.observations.len() > view.left_controllers || acts]
    }

    /// Moves the current views to `prev` (when `step`) and fills the new ones from `view`, reusing
    /// the old buffers when no script kept a reference to them.
    fn refresh(&mut self, view: &HookView<'_>, step: bool) {
        let sides = self.sides(view);
        for (k, side) in Side::BOTH.into_iter().enumerate() {
            if !sides[k] {
                continue;
            }
            if step {
                let recycled = self.prev[k].take().unwrap_or_default();
                self.prev[k] = Some(std::mem::replace(&mut self.now[k], recycled));
            } else {
                self.prev[k] = None;
            }
            Arc::make_mut(&mut self.now[k]).fill(view, side);
        }
    }

    fn state(&self, k: usize) -> State {
        State { now: Arc::clone(&self.now[k]), prev: self.prev[k].clone() }
    }

    /// Calls behaviour script `i`'s `act` for side `k`'s player `me` and reads its action.
    fn act(&mut self, i: usize, k: usize, me: usize, step: u32) -> Result<Action, Box<ScriptError>> {
        let state = self.state(k);
        let options = CallFnOptions::new().eval_ast(false).rewind_scope(true);
        let ast = &self.set.scripts[i].ast;
        self.meter.start();
        let value = self
            .engine
            .call_fn_with_options::<Dynamic>(options, &mut self.scopes[i], ast, "act", (state, me as rhai::INT))
            // `act` runs before the step it chooses for: that step's number is one more than
            // the steps taken.
            .map_err(|e| Box::new(Self::runtime_error(&self.set.scripts[i], "act", step + 1, &e)))?;
        let set = ActionSet::Default.actions();
        let action = if let Ok(index) = value.as_int() {
            usize::try_from(index).ok().and_then(|i| set.get(i).copied())
        } else if let Some(name) = value.read_lock::<rhai::ImmutableString>() {
            set.iter().copied().find(|a| a.name() == name.as_str())
        } else {
            None
        };
        action.ok_or_else(|| {
            let expected = "an action name (\"shot\", \"right\", \"sprint\", …) or an index 0–18 of the default set";
            Box::new(Self::return_error(&self.set.scripts[i], "act", &value, expected))
        })
    }

    /// Calls `hook` of script `i` with side `k`'s view.
    fn call(&mut self, i: usize, hook: &'static str, k: usize) -> Result<Dynamic, Box<EvalAltResult>> {
        let state = self.state(k);
        let options = CallFnOptions::new().eval_ast(false).rewind_scope(true);
        let ast = &self.set.scripts[i].ast;
        self.meter.start();
        self.engine.call_fn_with_options(options, &mut self.scopes[i], ast, hook, (state,))
    }

    fn runtime_error(script: &Script, hook: &'static str, step: u32, e: &EvalAltResult) -> ScriptError {
        let (message, help) = failure(e);
        // The innermost position: where in a helper the failure happened, not the call to it.
        let pos = if e.unwrap_inner().position().is_none() { e.position() } else { e.unwrap_inner().position() };
        let limit =
            matches!(e.unwrap_inner(), EvalAltResult::ErrorTooManyOperations(_) | EvalAltResult::ErrorTerminated(..));
        let span = if !pos.is_none() {
            error::span_at(&script.text, pos)
        } else if let Some(span) = limit.then(|| error::span_of_first_loop(&script.ast, &script.text, hook)).flatten() {
            span
        } else {
            error::span_of_fn(&script.text, hook)
        };
        ScriptError::Runtime { path: script.path.clone(), hook, step, message, src: script.source(), span, help }
    }

    fn return_error(script: &Script, hook: &'static str, got: &Dynamic, expected: &str) -> ScriptError {
        ScriptError::ReturnType {
            path: script.path.clone(),
            hook,
            got: format!("{} `{got}`", got.type_name()),
            expected: expected.to_owned(),
            src: script.source(),
            span: error::span_of_fn(&script.text, hook),
            help: format!(
                "the value of a function is its last expression, or what `return` gives: every branch of \
                 `fn {hook}` must end in such a value (an `if` without `else` gives `()`)"
            ),
        }
    }

    /// Applies the error policy to a failed hook: an engine error to fail the step, or a logged,
    /// counted warning.
    fn fail(&mut self, error: &ScriptError, errors: &mut u32) -> Result<(), EngineError> {
        let message = crate::render_plain(error);
        match self.set.options.on_error {
            ErrorPolicy::Raise => {
                let code = miette::Diagnostic::code(error).map_or_else(|| "tl::S005".to_owned(), |c| c.to_string());
                Err(EngineError::Script { message, code })
            }
            ErrorPolicy::Warn => {
                *errors += 1;
                self.log.push(message);
                Ok(())
            }
        }
    }

    /// Runs script `i`'s step hook for side `k`, writing its weighted reward into the side's slots of
    /// `rewards`; returns whether it ends the episode.
    fn run(
        &mut self,
        i: usize,
        k: usize,
        view: &HookView<'_>,
        rewards: &mut [f32],
    ) -> Result<Returned, Box<ScriptError>> {
        let script = &self.set.scripts[i];
        let (role, hook) = (script.role, script.role.hook());
        let value =
            self.call(i, hook, k).map_err(|e| Self::runtime_error(&self.set.scripts[i], hook, view.steps, &e))?;
        let script = &self.set.scripts[i];
        match role {
            Role::End => match value.as_bool() {
                Ok(end) => Ok(Returned::End(end)),
                Err(_) => Err(Box::new(Self::return_error(script, hook, &value, "a bool (true ends the episode)"))),
            },
            // Behaviour scripts are not step hooks (`step` skips them); nothing to pay.
            Role::Behaviour => Ok(Returned::Paid),
            Role::Reward { weight } => {
                let (start, len) = if k == 0 {
                    (0, view.left_controllers)
                } else {
                    (view.left_controllers, view.observations.len() - view.left_controllers)
                };
                let slots = &mut rewards[start..start + len];
                let expected = "a number, or an array with one number per agent (`s.controlled`)";
                if let Some(r) = number(&value) {
                    pay(slots, std::iter::repeat(r), weight).map_err(|m| not_finite(script, view.steps, &m))?;
                    return Ok(Returned::Paid);
                }
                let Some(array) = value.read_lock::<rhai::Array>() else {
                    return Err(Box::new(Self::return_error(script, hook, &value, expected)));
                };
                let per_agent: Option<Vec<f32>> = array.iter().map(number).collect();
                match per_agent {
                    Some(values) if values.len() == len => {
                        pay(slots, values.into_iter(), weight).map_err(|m| not_finite(script, view.steps, &m))?;
                        Ok(Returned::Paid)
                    }
                    _ => Err(Box::new(Self::return_error(
                        script,
                        hook,
                        &value,
                        &format!("{expected}; {len} agent(s) here"),
                    ))),
                }
            }
        }
    }

    fn drain_prints(&mut self) {
        let mut lines = self.sink.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        self.log.append(&mut lines);
    }
}

/// What a failed call says: the message and, for exhausted limits, how to stay within them.
pub(crate) fn failure(e: &EvalAltResult) -> (String, Option<String>) {
    let budget = || {
        Some(
            "each hook call may run a limited number of operations, a built-in on a collection counting \
             one per element it holds (ScriptOptions::limits)"
                .to_owned(),
        )
    };
    match e.unwrap_inner() {
        EvalAltResult::ErrorTooManyOperations(_) => {
            ("the operation limit was reached (an endless loop?)".to_owned(), budget())
        }
        EvalAltResult::ErrorTerminated(why, _) if why.to_string() == engine::OUT_OF_TIME => (
            format!("the hook ran for over {} s and was stopped", engine::TIME_GUARD.as_secs_f32()),
            Some("a hook call must finish well within its operation budget; this one did not".to_owned()),
        ),
        EvalAltResult::ErrorTerminated(..) => {
            ("the operation limit was reached (an endless loop, or large collections?)".to_owned(), budget())
        }
        EvalAltResult::ErrorDataTooLarge(what, _) => (
            format!("{what} is over its limit"),
            Some("strings, arrays and maps are limited in size (ScriptOptions::limits)".to_owned()),
        ),
        EvalAltResult::ErrorStackOverflow(_) => {
            ("the call-depth limit was reached (endless recursion?)".to_owned(), None)
        }
        EvalAltResult::ErrorVariableNotFound(name, _) if name == "memory" => (
            "`memory` is not visible in helper functions".to_owned(),
            Some("pass `memory` to the helper as an argument, or call it as `helper!(…)`".to_owned()),
        ),
        EvalAltResult::ErrorDotExpr(message, _) => match super::properties::unknown_at_run_time(message) {
            Some((message, help)) => (message, Some(help)),
            None => (without_position(&e.to_string()), None),
        },
        EvalAltResult::ErrorRuntime(value, _) => (
            format!("the script threw {}", if value.is_string() { format!("\"{value}\"") } else { value.to_string() }),
            Some("`throw` in a hook fails the step (ErrorPolicy::Raise, the default); with ErrorPolicy::Warn the term pays 0 and the error is logged".to_owned()),
        ),
        _ => (
            without_position(&e.to_string()),
            Some(
                "a hook that fails ends the step with this error (ErrorPolicy::Raise, the default); with \
                 ErrorPolicy::Warn the term pays 0 and the error is logged"
                    .to_owned(),
            ),
        ),
    }
}

/// rhai's message without its " (line 2, position 23)" suffix: the label shows where.
fn without_position(message: &str) -> String {
    match message.rfind(" (line ") {
        Some(at) if message.ends_with(')') => message[..at].to_owned(),
        _ => message.to_owned(),
    }
}

/// Adds `weight × r` to each slot, all or none: an error naming the product when a sum would not
/// be finite (a script's 3e38 times `weight 10` is inf), so that no inf or NaN is ever paid and,
/// under the warn policy, the term pays zero.
fn pay(slots: &mut [f32], values: impl Iterator<Item = f32> + Clone, weight: f32) -> Result<(), String> {
    for (slot, r) in slots.iter().zip(values.clone()) {
        if !(slot + weight * r).is_finite() {
            return Err(format!("weight {weight} × the script's {r} = {}", weight * r));
        }
    }
    for (slot, r) in slots.iter_mut().zip(values) {
        *slot += weight * r;
    }
    Ok(())
}

fn not_finite(script: &Script, step: u32, message: &str) -> Box<ScriptError> {
    Box::new(ScriptError::NotFinite { path: script.path.clone(), step, message: message.to_owned() })
}

/// A finite number from an int or a float.
fn number(d: &Dynamic) -> Option<f32> {
    let v = match (d.as_float(), d.as_int()) {
        (Ok(f), _) => f as f32,
        (_, Ok(i)) => i as f32,
        _ => return None,
    };
    v.is_finite().then_some(v)
}

impl Hooks for ScriptHooks {
    fn reset(&mut self, view: &HookView<'_>) -> Result<(), EngineError> {
        self.log.clear();
        self.acted = false;
        self.act_errors = 0;
        self.refresh(view, false);
        let mut errors = 0;
        for i in 0..self.set.scripts.len() {
            self.scopes[i].set_value("memory", Map::new());
            if !self.set.scripts[i].has_reset {
                continue;
            }
            if let Err(e) = self.call(i, "reset", 0) {
                let error = Self::runtime_error(&self.set.scripts[i], "reset", 0, &e);
                self.drain_prints();
                self.fail(&error, &mut errors)?;
            }
        }
        self.drain_prints();
        Ok(())
    }

    fn step(&mut self, view: &HookView<'_>, rewards: &mut [f32]) -> Result<HookOutcome, EngineError> {
        // Behaviour scripts ran before this step's ticks: their lines belong to this step.
        if !std::mem::take(&mut self.acted) {
            self.log.clear();
        }
        self.refresh(view, true);
        let sides = self.sides(view);
        let mut outcome = HookOutcome { errors: std::mem::take(&mut self.act_errors), ..HookOutcome::default() };
        for i in 0..self.set.scripts.len() {
            if self.set.scripts[i].role == Role::Behaviour {
                continue;
            }
            let reward = matches!(self.set.scripts[i].role, Role::Reward { .. });
            for (k, &needed) in sides.iter().enumerate() {
                // Rewards go to each team with agents; end scripts look from the left.
                let wanted = if reward { needed && (k == 1 || view.left_controllers > 0) } else { k == 0 };
                if !wanted {
                    continue;
                }
                match self.run(i, k, view, rewards) {
                    Ok(Returned::End(end)) => outcome.end |= end,
                    Ok(Returned::Paid) => {}
                    Err(error) => {
                        self.drain_prints();
                        self.fail(&error, &mut outcome.errors)?;
                    }
                }
            }
        }
        self.drain_prints();
        Ok(outcome)
    }

    fn behaviour_action(
        &mut self,
        view: &HookView<'_>,
        side: Side,
        player: usize,
        path: &str,
    ) -> Result<Action, EngineError> {
        if !std::mem::replace(&mut self.acted, true) {
            self.log.clear();
        }
        let Some(i) = self.set.scripts.iter().position(|s| s.role == Role::Behaviour && s.path == path) else {
            return Err(EngineError::Script {
                message: format!("no behaviour script \"{path}\" was compiled"),
                code: "tl::S000".to_owned(),
            });
        };
        let result = self.act(i, side.index(), player, view.steps);
        self.drain_prints();
        match result {
            Ok(action) => Ok(action),
            Err(error) => {
                let mut errors = 0;
                self.fail(&error, &mut errors)?;
                self.act_errors += errors;
                // Under the warn policy a failing script's player does nothing this step.
                Ok(Action::Idle)
            }
        }
    }

    fn log(&self) -> &[String] {
        &self.log
    }

    fn save(&self) -> Vec<u8> {
        let memories: Vec<Vec<(String, Value)>> = self
            .scopes
            .iter()
            .map(|scope| scope.get_value::<Map>("memory").map(|m| memory::map_entries(&m)).unwrap_or_default())
            .collect();
        postcard::to_allocvec(&(memories, &*self.now[0], &*self.now[1])).unwrap_or_default()
    }

    fn load(&mut self, bytes: &[u8]) -> Result<(), EngineError> {
        let (memories, left, right): (Vec<Vec<(String, Value)>>, TeamState, TeamState) = postcard::from_bytes(bytes)
            .map_err(|e| EngineError::InvalidSnapshot { reason: format!("the scripts' state cannot be read: {e}") })?;
        if memories.len() != self.scopes.len() {
            return Err(EngineError::InvalidSnapshot {
                reason: format!(
                    "the snapshot has {} scripts' memory, this env runs {}",
                    memories.len(),
                    self.scopes.len()
                ),
            });
        }
        for (scope, entries) in self.scopes.iter_mut().zip(&memories) {
            scope.set_value("memory", memory::to_map(entries));
        }
        self.now = [Arc::new(left), Arc::new(right)];
        self.prev = [None, None];
        Ok(())
    }

    fn clone_box(&self) -> Box<dyn Hooks> {
        Box::new(self.clone_of())
    }
}
