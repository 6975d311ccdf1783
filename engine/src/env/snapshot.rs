//! Snapshots of an episode: the whole dynamic state of an [`Env`] (match, controllers, sticky
//! actions, reward and end-condition bookkeeping, RNG, episode counters) and nothing else, so that
//! restoring it and replaying the same actions gives the same trajectory bit for bit. In memory a
//! snapshot is a plain copy; [`Snapshot::to_bytes`] gives a compact, versioned, checksummed form
//! that loads in another process.

use serde::{Deserialize, Serialize};

use super::end::EndTracker;
use super::{Controller, Env, StepInfo};
use crate::error::EngineError;
use crate::game::Match;
use crate::obs::RawObservation;
use crate::reward::{CheckpointTracker, EventProgress};

/// Bytes every serialised snapshot starts with.
const MAGIC: &[u8; 6] = b"TLSNAP";
/// Header: magic, format version (u16), scenario fingerprint (u64), payload checksum (u64).
const HEADER: usize = 6 + 2 + 8 + 8;

/// What the payload holds, in this order: scenario name, state, hooks' state, and the extra
/// bytes of [`Snapshot::to_bytes_with`].
type Payload = (String, EnvState, Vec<u8>, Vec<u8>);

/// Everything in an [`Env`] that changes while it plays.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct EnvState {
    pub(super) seed: u64,
    /// 0-based episode index since the last seeding.
    pub(super) episode: u64,
    /// No step taken since the episode started (a reset then restarts the same episode).
    pub(super) fresh: bool,
    pub(super) game: Match,
    pub(super) controllers: Vec<Controller>,
    /// Player (index in team) driven by each controller, left controllers first.
    pub(super) controlled: Vec<usize>,
    pub(super) observations: Vec<RawObservation>,
    pub(super) rewards: Vec<f32>,
    pub(super) checkpoints: Vec<CheckpointTracker>,
    /// Event-reward progress, controller-major: the terms of controller `i` are
    /// `events[i * terms .. (i + 1) * terms]`.
    pub(super) events: Vec<EventProgress>,
    /// The ball's (x, y) in each controller's team frame when the step began (for `ball enters`).
    pub(super) previous_ball: Vec<[f32; 2]>,
    pub(super) end: EndTracker,
    pub(super) info: StepInfo,
    pub(super) steps: u32,
    pub(super) done: bool,
    pub(super) score_diff: i32,
    /// GRF's anti-stalling counter: steps in a row that ended with a set piece pending.
    pub(super) waiting_for_game: u32,
    /// The hooks failed at the last reset, which returned this error; every step of the episode
    /// returns it again (transient: not saved).
    #[serde(skip)]
    pub(super) hook_error: Option<EngineError>,
    /// Progress through the curriculum (empty without one).
    pub(super) lessons: super::lessons::LessonProgress,
}

/// A saved moment of an episode; see [`Env::snapshot`] and [`Env::restore`].
#[derive(Clone, Debug)]
pub struct Snapshot {
    fingerprint: u64,
    scenario: String,
    state: Box<EnvState>,
    /// The hooks' state ([`super::Hooks::save`]); empty without hooks.
    hooks: Vec<u8>,
}

/// FNV-1a over bytes: a fingerprint and checksum that is the same on every platform.
fn fnv(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

impl Snapshot {
    /// Version of the byte format written by [`Snapshot::to_bytes`]; bumped whenever the state's
    /// layout changes. Reading another version is an error. Version 9 carries extra bytes (the
    /// Python env's frame stacks) inside the checksummed payload; version 10 adds each player's
    /// queued first-time shot and blocked ball control (an agent's buttons at a loose ball);
    /// version 11 the end conditions' memory of a live shot and of the last game mode (`save`,
    /// `restart_taken`); version 12 each player's run when he asked for the kick he winds up
    /// (a shot's difficulty depends on it); version 13 drops the blocked ball control (a pass
    /// asked for at a loose ball is queued like a shot); version 14 the tick of the last touch of
    /// the ball (a player's body blocks a fast ball only just after an opponent's touch); version
    /// 15 the magnet's last answer and its tick, and the team-mate each pass event is meant for;
    /// version 16 the magnet's answer for each team, with how hard it pulls; version 17 the tick of
    /// each AI player's last decision (a player far from the ball decides less often); version 18
    /// each player's facing when he asked for the kick he winds up (a pass played round from a
    /// stand is the weaker).
    pub const FORMAT_VERSION: u16 = 18;

    /// Name of the scenario the snapshot was taken on.
    pub fn scenario(&self) -> &str {
        &self.scenario
    }

    /// The serialised form: a 24-byte header (magic `TLSNAP`, format version, scenario
    /// fingerprint, checksum) and the state in postcard's compact encoding. About 5–8 KiB for a
    /// full 11-v-11 match.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.to_bytes_with(&[])
    }

    /// [`Snapshot::to_bytes`] with `extra` bytes of the caller's own (the Python env's frame
    /// stacks) inside the payload, under the same checksum; [`Snapshot::from_bytes_with`] gives
    /// them back and [`Snapshot::from_bytes`] skips them.
    pub fn to_bytes_with(&self, extra: &[u8]) -> Vec<u8> {
        let payload = postcard::to_allocvec(&(&self.scenario, &*self.state, &self.hooks, extra)).unwrap_or_default();
        let mut out = Vec::with_capacity(HEADER + payload.len());
        out.extend_from_slice(MAGIC);
        out.extend_from_slice(&Self::FORMAT_VERSION.to_le_bytes());
        out.extend_from_slice(&self.fingerprint.to_le_bytes());
        out.extend_from_slice(&fnv(&payload).to_le_bytes());
        out.extend_from_slice(&payload);
        out
    }

    /// Reads bytes written by [`Snapshot::to_bytes`] or [`Snapshot::to_bytes_with`] (the extra
    /// bytes are skipped).
    ///
    /// # Errors
    /// [`EngineError::InvalidSnapshot`] for anything else: wrong magic, another format version,
    /// a checksum mismatch (corruption), truncation or undecodable contents. Whether the
    /// contents fit an env is checked by [`Env::restore`].
    pub fn from_bytes(bytes: &[u8]) -> Result<Snapshot, EngineError> {
        Self::from_bytes_with(bytes).map(|(snapshot, _)| snapshot)
    }

    /// Reads bytes written by [`Snapshot::to_bytes_with`]: the snapshot and the extra bytes.
    ///
    /// # Errors
    /// As [`Snapshot::from_bytes`].
    pub fn from_bytes_with(bytes: &[u8]) -> Result<(Snapshot, Vec<u8>), EngineError> {
        let bad = |reason: String| EngineError::InvalidSnapshot { reason };
        if bytes.len() < HEADER || &bytes[..6] != MAGIC {
            return Err(bad("it does not start with a touchline snapshot header".into()));
        }
        let word = |at: usize| {
            let mut b = [0u8; 8];
            b.copy_from_slice(&bytes[at..at + 8]);
            u64::from_le_bytes(b)
        };
        let version = u16::from_le_bytes([bytes[6], bytes[7]]);
        if version != Self::FORMAT_VERSION {
            return Err(bad(format!(
                "format version {version}; this touchline reads version {}",
                Self::FORMAT_VERSION
            )));
        }
        let (fingerprint, checksum) = (word(8), word(16));
        let payload = &bytes[HEADER..];
        if fnv(payload) != checksum {
            return Err(bad("the checksum does not match: the bytes are truncated or corrupted".into()));
        }
        let (scenario, state, hooks, extra): Payload =
            postcard::from_bytes(payload).map_err(|e| bad(format!("cannot decode the state: {e}")))?;
        Ok((Snapshot { fingerprint, scenario, state: Box::new(state), hooks }, extra))
    }
}

/// The match saved in `bytes` (a serialised [`Snapshot`]), checked to fit `scenario`'s teams.
pub(super) fn start_match(scenario: &crate::Scenario, bytes: &[u8]) -> Result<Match, EngineError> {
    let snapshot = Snapshot::from_bytes(bytes)?;
    let game = snapshot.state.game;
    let saved = [game.players.len().min(game.ranges[0].end), game.players.len().saturating_sub(game.ranges[0].end)];
    let wanted = [scenario.left_team.len(), scenario.right_team.len()];
    if saved != wanted {
        return Err(EngineError::InvalidScenario {
            reason: format!(
                "the saved state has {}v{} players but the scenario's teams have {}v{}",
                saved[0], saved[1], wanted[0], wanted[1]
            ),
        });
    }
    super::restore_check::check_match(&game, wanted)
        .map_err(|reason| EngineError::InvalidSnapshot { reason: format!("the saved match is not valid: {reason}") })?;
    Ok(game)
}

impl Env {
    /// Identifies the scenario and configuration a snapshot belongs to (computed once, in
    /// [`Env::with_config`]).
    pub(crate) fn compute_fingerprint(&self) -> u64 {
        // With a curriculum, the lessons (not the lesson played) identify the env: a snapshot
        // taken in one lesson restores in another.
        let bytes = match &self.curriculum {
            Some(c) => postcard::to_allocvec(&(&**c, &self.config)),
            None => postcard::to_allocvec(&(&self.scenario, &self.config)),
        };
        fnv(&bytes.unwrap_or_default())
    }

    /// Saves the whole dynamic state of the episode.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            fingerprint: self.fingerprint,
            scenario: self.scenario.name.clone(),
            state: Box::new(self.state.clone()),
            hooks: self.hooks.as_ref().map(|h| h.save()).unwrap_or_default(),
        }
    }

    /// Puts the env back in the state of `snapshot`; stepping on with the same actions then
    /// repeats the trajectory that followed it, bit for bit.
    ///
    /// # Errors
    /// [`EngineError::SnapshotScenario`] when the snapshot was taken on another scenario or
    /// configuration; [`EngineError::InvalidSnapshot`] when its contents are out of range (a
    /// position that is not finite, an index past its list: bytes edited with a consistent
    /// checksum); the hooks' errors. The env is unchanged.
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<(), EngineError> {
        if snapshot.fingerprint != self.fingerprint {
            return Err(EngineError::SnapshotScenario {
                snapshot: snapshot.scenario.clone(),
                env: self.scenario.name.clone(),
            });
        }
        self.check_restorable(&snapshot.state)?;
        if let Some(hooks) = self.hooks.as_mut() {
            hooks.load(&snapshot.hooks)?;
        }
        let saved = snapshot.state.lessons.lesson;
        if saved != self.state.lessons.lesson
            && let Some(lesson) = self.curriculum.as_ref().and_then(|c| c.lessons.get(saved))
        {
            // The snapshot plays another lesson: switch to it first (lessons were checked
            // against the env when it was built, so this cannot fail), then take its state.
            let scenario = lesson.scenario.clone();
            self.switch_to(scenario)?;
        }
        self.state.clone_from(&snapshot.state);
        Ok(())
    }

    /// Checks `state` against this env, or against the lesson it plays (a snapshot taken in
    /// another lesson of the curriculum).
    fn check_restorable(&self, state: &EnvState) -> Result<(), EngineError> {
        let invalid =
            |reason: String| EngineError::InvalidSnapshot { reason: format!("the saved state is not valid: {reason}") };
        let lesson = self.curriculum.as_ref().and_then(|c| c.lessons.get(state.lessons.lesson));
        match lesson {
            Some(l) if state.lessons.lesson != self.state.lessons.lesson => {
                state.check_against(self, &l.scenario).map_err(invalid)
            }
            _ => state.check_against(self, &self.scenario).map_err(invalid),
        }
    }
}
