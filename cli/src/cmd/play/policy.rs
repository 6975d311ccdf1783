//! [`PolicySocket`]: the opponent's player played by a program (a Python policy) over a local socket.
//!
//! touchline listens on 127.0.0.1; one client at a time connects. After every step (and at the
//! start of every episode) the server writes one JSON line with the player's observation
//! (`simple115v2`, in the player's own frame, as Gymnasium envs give it) and a turn number; the
//! client answers `{"turn": T, "action": A}` with an index into GRF's action set. The match never
//! waits: the answer is used at the next step if it has arrived (100 ms later), else the player
//! idles (keeping what he holds); with no client connected the built-in AI plays him.
//! docs/play-protocol.md has the details.

use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

use serde::{Deserialize, Serialize};
use touchline_engine::obs::{SIMPLE115_LEN, encode_simple115v2};
use touchline_engine::{Action, ActionSet, Env};

/// The link's state, shared with the accepting and reading threads.
#[derive(Default)]
struct Link {
    /// The connected client's stream, to write observations to.
    writer: Option<TcpStream>,
    /// The latest answer: `(turn, action)`.
    reply: Option<(u64, Action)>,
}

/// One observation line.
#[derive(Serialize)]
struct ObservationLine<'a> {
    turn: u64,
    side: &'static str,
    episode: u64,
    step: u32,
    /// The episode has ended: no answer is expected.
    done: bool,
    observation: &'a [f32],
}

/// One answer line.
#[derive(Deserialize)]
struct ActionLine {
    turn: u64,
    action: usize,
}

/// See the module documentation.
pub(crate) struct PolicySocket {
    link: Arc<Mutex<Link>>,
    /// The env controller the policy plays.
    pub(crate) seat: usize,
    /// The turn of the last observation sent.
    turn: u64,
}

fn lock(link: &Mutex<Link>) -> MutexGuard<'_, Link> {
    link.lock().unwrap_or_else(PoisonError::into_inner)
}

impl PolicySocket {
    /// Listens on 127.0.0.1:`port` (0: any free port) for the policy of env controller `seat`;
    /// returns the socket and the port.
    pub(crate) fn listen(port: u16, seat: usize) -> std::io::Result<(PolicySocket, u16)> {
        let listener = TcpListener::bind(("127.0.0.1", port))?;
        let port = listener.local_addr()?.port();
        let link = Arc::new(Mutex::new(Link::default()));
        let accepting = Arc::clone(&link);
        std::thread::spawn(move || {
            for stream in listener.incoming().flatten() {
                accept(&accepting, stream);
            }
        });
        Ok((PolicySocket { link, seat, turn: 0 }, port))
    }

    /// A policy is connected.
    pub(crate) fn connected(&self) -> bool {
        lock(&self.link).writer.is_some()
    }

    /// The action for this step: the answer to the last observation, `idle` if it is late, the
    /// built-in AI with no policy connected.
    pub(crate) fn action(&self) -> Action {
        let link = lock(&self.link);
        match (&link.writer, link.reply) {
            (None, _) => Action::BuiltinAi,
            (Some(_), Some((turn, action))) if turn == self.turn => action,
            (Some(_), _) => Action::Idle,
        }
    }

    /// Sends the policy's observation of `env` (a write that fails drops the client).
    pub(crate) fn observe(&mut self, env: &Env, done: bool) {
        self.turn += 1;
        let mut observation = [0.0; SIMPLE115_LEN];
        encode_simple115v2(&env.observations()[self.seat], &mut observation);
        let side = env.controller_sides().nth(self.seat).map_or("left", |s| s.name());
        let info = env.info();
        let line = ObservationLine {
            turn: self.turn,
            side,
            episode: info.episode,
            step: info.steps,
            done,
            observation: &observation,
        };
        let Ok(mut text) = serde_json::to_string(&line) else { return };
        text.push('\n');
        let mut link = lock(&self.link);
        if let Some(w) = &mut link.writer
            && w.write_all(text.as_bytes()).is_err()
        {
            link.writer = None;
        }
    }
}

/// Takes a client, or turns it away while another is connected.
fn accept(link: &Arc<Mutex<Link>>, mut stream: TcpStream) {
    let Ok(reader) = stream.try_clone() else { return };
    {
        let mut l = lock(link);
        if l.writer.is_some() {
            let _ = stream.write_all(b"{\"error\":\"another policy is connected\"}\n");
            return;
        }
        let _ = stream.set_nodelay(true);
        l.writer = Some(stream);
        l.reply = None;
    }
    let link = Arc::clone(link);
    std::thread::spawn(move || {
        let set = ActionSet::V2.actions();
        for line in BufReader::new(reader).lines() {
            let Ok(line) = line else { break };
            // A line that is not an answer is skipped: the player idles for that step.
            if let Ok(answer) = serde_json::from_str::<ActionLine>(&line)
                && let Some(&action) = set.get(answer.action)
            {
                lock(&link).reply = Some((answer.turn, action));
            }
        }
        lock(&link).writer = None;
    });
}
