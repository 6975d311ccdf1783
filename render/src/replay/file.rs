//! The replay file's header and compressed payload (the format table is in the parent module).

use std::io::{Read, Write};

use flate2::Compression;
use flate2::read::ZlibDecoder;
use flate2::write::ZlibEncoder;
use serde::ser::{Serialize, SerializeSeq, SerializeStruct, Serializer};
use thiserror::Error;
use touchline_engine::EngineError;

use super::{Frame, Replay};

/// Bytes every replay file starts with.
pub const MAGIC: &[u8; 8] = b"TLREPLAY";
/// Version of the format written; bumped whenever [`Replay`]'s layout changes. Version 2 added the
/// scripts' text and the recorder's per-step values; version 1 files are still read (with neither).
/// Reading any other version is an error.
pub const FORMAT_VERSION: u16 = 2;
/// The oldest version read.
const OLDEST_VERSION: u16 = 1;
/// Header size in bytes.
const HEADER: usize = 8 + 2 + 8 + 8;
/// Largest decompressed payload accepted (bytes): a 3000-step 11-v-11 episode is about 0.4 MB, so
/// 256 MB leaves room for very long episodes while stopping decompression bombs.
const MAX_DECOMPRESSED: u64 = 256 << 20;

/// Why a replay cannot be read or played.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ReplayError {
    /// The bytes do not start with a replay header.
    #[error("not a touchline replay (it does not start with the `TLREPLAY` header)")]
    NotAReplay,
    /// Written by another format version.
    #[error("replay format version {found}; this touchline reads versions {OLDEST_VERSION} to {FORMAT_VERSION}")]
    Version {
        /// The file's version.
        found: u16,
    },
    /// Fewer bytes than the header announces.
    #[error("the replay is truncated: {got} of {expected} bytes")]
    Truncated {
        /// Bytes the header announces (header included).
        expected: u64,
        /// Bytes present.
        got: u64,
    },
    /// The checksum does not match the payload.
    #[error("the replay is corrupted: its checksum does not match its contents")]
    Checksum,
    /// The payload does not decompress or decode.
    #[error("the replay cannot be decoded: {reason}")]
    Decode {
        /// What failed.
        reason: String,
    },
    /// The decoded parts disagree (see [`Replay::check`]).
    #[error("the replay is inconsistent: {reason}")]
    Inconsistent {
        /// The first disagreement.
        reason: String,
    },
    /// The start snapshot does not load.
    #[error("the replay's start state cannot be restored")]
    Start(#[source] EngineError),
    /// The engine refused the scenario, configuration or a step.
    #[error("the engine refused the replay")]
    Engine(#[from] EngineError),
    /// Re-simulation gave another state than the one stored.
    #[error(
        "the replay does not reproduce: frame {frame} differs (stored state hash {stored:08x}, re-simulated {replayed:08x}); \
         it was probably recorded with another version of the engine"
    )]
    Diverged {
        /// The first frame that differs (0 = the start).
        frame: usize,
        /// Hash stored in the replay.
        stored: u32,
        /// Hash of the re-simulated state.
        replayed: u32,
    },
}

/// FNV-1a 64 over bytes.
fn fnv(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

impl Replay {
    /// The file form: a 26-byte header (magic `TLREPLAY`, version, payload length, FNV-1a
    /// checksum) and the replay in postcard's encoding, zlib-compressed. About 150 KB for a
    /// 3000-step 11-v-11 match.
    pub fn to_bytes(&self) -> Vec<u8> {
        // Positions are stored as differences from the previous frame (a few centimetres, one or
        // two bytes each in postcard's varints), computed while serialising. Serialising plain
        // data into a Vec and compressing into a Vec cannot fail.
        let stored = Stored {
            scenario: serde_json::to_string(&self.scenario).unwrap_or_default(),
            config: &self.config,
            start: &self.start,
            first_step: self.first_step,
            roster: &self.roster,
            actions: &self.actions,
            controllers: self.controllers,
            frames: DeltaFrames(&self.frames),
            scripts: &self.scripts,
            values: &self.values,
        };
        let estimate = 256 + self.frames.len() * (self.roster.len() * 3 + 24) + self.actions.len();
        let raw = postcard::to_extend(&stored, Vec::with_capacity(estimate)).unwrap_or_default();
        // zlib's fastest level: recording must stay cheap (it runs at the end of every episode).
        let mut z = ZlibEncoder::new(Vec::with_capacity(raw.len() / 2 + 64), Compression::fast());
        let _ = z.write_all(&raw);
        let payload = z.finish().unwrap_or_default();
        let mut out = Vec::with_capacity(HEADER + payload.len());
        out.extend_from_slice(MAGIC);
        out.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
        out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
        out.extend_from_slice(&fnv(&payload).to_le_bytes());
        out.extend_from_slice(&payload);
        out
    }

    /// Writes the file form to `path` whole or not at all: into a temporary file in the same
    /// folder, then renamed over `path` (so that a reader never sees half a replay).
    ///
    /// # Errors
    /// The operating system's error when the folder cannot be written.
    pub fn save(&self, path: &std::path::Path) -> std::io::Result<()> {
        let dir = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => std::path::Path::new("."),
        };
        let mut file = tempfile::NamedTempFile::new_in(dir)?;
        file.write_all(&self.to_bytes())?;
        file.as_file().sync_all()?;
        file.persist(path).map(|_| ()).map_err(|e| e.error)
    }

    /// Reads the file form.
    ///
    /// # Errors
    /// A [`ReplayError`] naming the first check that fails (see the module documentation).
    pub fn from_bytes(bytes: &[u8]) -> Result<Replay, ReplayError> {
        if bytes.len() < MAGIC.len() || &bytes[..MAGIC.len()] != MAGIC {
            return Err(ReplayError::NotAReplay);
        }
        if bytes.len() < HEADER {
            return Err(ReplayError::Truncated { expected: HEADER as u64, got: bytes.len() as u64 });
        }
        let version = u16::from_le_bytes([bytes[8], bytes[9]]);
        if !(OLDEST_VERSION..=FORMAT_VERSION).contains(&version) {
            return Err(ReplayError::Version { found: version });
        }
        let word = |at: usize| {
            let mut b = [0u8; 8];
            b.copy_from_slice(&bytes[at..at + 8]);
            u64::from_le_bytes(b)
        };
        let (len, checksum) = (word(10), word(18));
        let payload = &bytes[HEADER..];
        let expected = (HEADER as u64).saturating_add(len);
        if (payload.len() as u64) < len {
            return Err(ReplayError::Truncated { expected, got: bytes.len() as u64 });
        }
        if payload.len() as u64 > len {
            return Err(ReplayError::Decode {
                reason: format!("{} bytes after the payload", payload.len() as u64 - len),
            });
        }
        if fnv(payload) != checksum {
            return Err(ReplayError::Checksum);
        }
        let mut raw = Vec::new();
        ZlibDecoder::new(payload)
            .take(MAX_DECOMPRESSED + 1)
            .read_to_end(&mut raw)
            .map_err(|e| ReplayError::Decode { reason: format!("decompression failed: {e}") })?;
        if raw.len() as u64 > MAX_DECOMPRESSED {
            return Err(ReplayError::Decode {
                reason: format!("it decompresses to more than {MAX_DECOMPRESSED} bytes"),
            });
        }
        let postcard_error = |e: postcard::Error| ReplayError::Decode { reason: format!("postcard: {e}") };
        let read: Loaded = if version == 1 {
            let v1: LoadedV1 = postcard::from_bytes(&raw).map_err(postcard_error)?;
            Loaded {
                scenario: v1.scenario,
                config: v1.config,
                start: v1.start,
                first_step: v1.first_step,
                roster: v1.roster,
                actions: v1.actions,
                controllers: v1.controllers,
                frames: v1.frames,
                scripts: Vec::new(),
                values: Vec::new(),
            }
        } else {
            postcard::from_bytes(&raw).map_err(postcard_error)?
        };
        let scenario = serde_json::from_str(&read.scenario)
            .map_err(|e| ReplayError::Decode { reason: format!("the scenario: {e}") })?;
        let mut replay = Replay {
            scenario,
            config: read.config,
            start: read.start,
            first_step: read.first_step,
            roster: read.roster,
            actions: read.actions,
            controllers: read.controllers,
            frames: read.frames,
            scripts: read.scripts,
            values: read.values,
        };
        replay.check()?;
        delta_decode(&mut replay.frames);
        Ok(replay)
    }
}

/// [`Replay`] as written: the same fields in the same order (postcard encodes a struct as its
/// fields in order), the scenario as JSON (its serde form skips default fields, which only a
/// self-describing format can read back), the frames delta-encoded.
#[derive(serde::Serialize)]
struct Stored<'a> {
    scenario: String,
    config: &'a touchline_engine::EnvConfig,
    start: &'a super::Start,
    first_step: u32,
    roster: &'a [super::RosterEntry],
    actions: &'a [touchline_engine::Action],
    controllers: usize,
    frames: DeltaFrames<'a>,
    scripts: &'a [super::ScriptSource],
    values: &'a [super::StepValues],
}

/// [`Stored`] as read back (frames still delta-encoded).
#[derive(serde::Deserialize)]
struct Loaded {
    scenario: String,
    config: touchline_engine::EnvConfig,
    start: super::Start,
    first_step: u32,
    roster: Vec<super::RosterEntry>,
    actions: Vec<touchline_engine::Action>,
    controllers: usize,
    frames: Vec<Frame>,
    scripts: Vec<super::ScriptSource>,
    values: Vec<super::StepValues>,
}

/// Version 1's payload: [`Loaded`] without the scripts and values.
#[derive(serde::Deserialize)]
struct LoadedV1 {
    scenario: String,
    config: touchline_engine::EnvConfig,
    start: super::Start,
    first_step: u32,
    roster: Vec<super::RosterEntry>,
    actions: Vec<touchline_engine::Action>,
    controllers: usize,
    frames: Vec<Frame>,
}

/// Frames with each frame's ball and player positions (after the first frame) replaced by their
/// difference from the previous frame (wrapping, so that decoding restores every value exactly).
struct DeltaFrames<'a>(&'a [Frame]);

/// One frame as [`Frame`] serialises, positions as differences from `prev`.
struct DeltaFrame<'a> {
    frame: &'a Frame,
    prev: Option<&'a Frame>,
}

/// A frame's players, as differences from the previous frame's.
struct DeltaPlayers<'a>(&'a [[i16; 2]], Option<&'a [[i16; 2]]>);

impl Serialize for DeltaFrames<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(self.0.len()))?;
        for (k, frame) in self.0.iter().enumerate() {
            seq.serialize_element(&DeltaFrame { frame, prev: k.checked_sub(1).map(|p| &self.0[p]) })?;
        }
        seq.end()
    }
}

impl Serialize for DeltaFrame<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let f = self.frame;
        let ball = match self.prev {
            Some(p) => [0, 1, 2].map(|i| f.ball[i].wrapping_sub(p.ball[i])),
            None => f.ball,
        };
        let mut st = s.serialize_struct("Frame", 8)?;
        st.serialize_field("ball", &ball)?;
        st.serialize_field("players", &DeltaPlayers(&f.players, self.prev.map(|p| &p.players[..])))?;
        st.serialize_field("on_pitch", &f.on_pitch)?;
        st.serialize_field("owner", &f.owner)?;
        st.serialize_field("controlled", &f.controlled)?;
        st.serialize_field("score", &f.score)?;
        st.serialize_field("mode", &f.mode)?;
        st.serialize_field("hash", &f.hash)?;
        st.end()
    }
}

impl Serialize for DeltaPlayers<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(self.0.len()))?;
        for (i, p) in self.0.iter().enumerate() {
            let d = match self.1.and_then(|prev| prev.get(i)) {
                Some(q) => [p[0].wrapping_sub(q[0]), p[1].wrapping_sub(q[1])],
                None => *p,
            };
            seq.serialize_element(&d)?;
        }
        seq.end()
    }
}

/// Undoes the delta encoding of [`DeltaFrames`] (frames must have equal player counts:
/// [`Replay::check`] ensures it).
fn delta_decode(frames: &mut [Frame]) {
    for k in 1..frames.len() {
        let (before, after) = frames.split_at_mut(k);
        let (prev, cur) = (&before[k - 1], &mut after[0]);
        for (c, p) in cur.ball.iter_mut().zip(prev.ball) {
            *c = c.wrapping_add(p);
        }
        for (c, p) in cur.players.iter_mut().zip(&prev.players) {
            c[0] = c[0].wrapping_add(p[0]);
            c[1] = c[1].wrapping_add(p[1]);
        }
    }
}

#[cfg(test)]
mod tests {
    use touchline_engine::{Action, Env, Scenario};

    use super::*;
    use crate::replay::{Recorder, StepValues};

    /// Version 1's payload as version 1 wrote it: [`Stored`] without the scripts and values.
    #[derive(serde::Serialize)]
    struct StoredV1<'a> {
        scenario: String,
        config: &'a touchline_engine::EnvConfig,
        start: &'a super::super::Start,
        first_step: u32,
        roster: &'a [super::super::RosterEntry],
        actions: &'a [touchline_engine::Action],
        controllers: usize,
        frames: DeltaFrames<'a>,
    }

    fn recorded() -> Replay {
        let path = format!("{}/../stdlib-scenarios/academy_empty_goal_close.json", env!("CARGO_MANIFEST_DIR"));
        let scenario: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
        let mut env = Env::new(scenario, 1).expect("env");
        let mut recorder = Recorder::start(&env);
        for _ in 0..12 {
            recorder.value("value", 0.5);
            env.step(&[Action::Right]).expect("step");
            recorder.record(&env, &[Action::Right]);
        }
        recorder.finish()
    }

    #[test]
    fn version_1_files_are_still_read() {
        let replay = recorded();
        let stored = StoredV1 {
            scenario: serde_json::to_string(&replay.scenario).expect("json"),
            config: &replay.config,
            start: &replay.start,
            first_step: replay.first_step,
            roster: &replay.roster,
            actions: &replay.actions,
            controllers: replay.controllers,
            frames: DeltaFrames(&replay.frames),
        };
        let raw = postcard::to_allocvec(&stored).expect("postcard");
        let mut z = ZlibEncoder::new(Vec::new(), Compression::fast());
        z.write_all(&raw).expect("compress");
        let payload = z.finish().expect("compress");
        let mut bytes = MAGIC.to_vec();
        bytes.extend_from_slice(&1u16.to_le_bytes());
        bytes.extend_from_slice(&(payload.len() as u64).to_le_bytes());
        bytes.extend_from_slice(&fnv(&payload).to_le_bytes());
        bytes.extend_from_slice(&payload);
        let back = Replay::from_bytes(&bytes).expect("a version 1 file reads");
        assert_eq!(back.frames, replay.frames);
        assert_eq!(back.actions, replay.actions);
        assert!(back.scripts.is_empty() && back.values.is_empty());
        back.simulate(|_, _| {}).expect("it re-simulates");
        // The version written now keeps the values.
        let now = Replay::from_bytes(&replay.to_bytes()).expect("reads");
        assert_eq!(now.values, vec![StepValues { name: "value".into(), values: vec![0.5; 12] }]);
    }
}
