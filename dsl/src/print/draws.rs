//! Shared draws in printed `.tl`: every [`Sample::Shared`] key becomes a `param drawN = …`
//! declaration that its uses name, so the printed file draws once per reset where the scenario
//! does. A param is one expression read in each use's units, so a key is printable when one
//! expression gives every use its distribution: the same numbers in scenario units, or the same
//! metres. A key no expression fits (only a hand-written JSON can make one) is printed at each use,
//! as its own draw.

use touchline_engine::Scenario;
use touchline_engine::scenario::{Distribution, Sample, Spot};

use crate::compile::{BALL_X_METRES, BALL_Y_METRES, PLAYER_X_METRES, PLAYER_Y_METRES};

/// One use of a shared key: its distribution and the metres per scenario unit of its axis.
struct Use {
    key: u32,
    of: Distribution,
    metres: f64,
}

/// The names of the printable keys and the expressions a body gives them.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Draws {
    /// `(key, name, expression)`, in the order the keys are first used.
    items: Vec<(u32, String, String)>,
}

impl Draws {
    /// The keys used in `scenarios` (the scenario, then its lessons), named `draw1`, `draw2`, … in
    /// order of first use, with the expression the first scenario using a key gives it.
    pub(super) fn declare<'a>(scenarios: impl IntoIterator<Item = &'a Scenario>) -> Draws {
        let mut draws = Draws::default();
        for s in scenarios {
            for (key, expr) in expressions(s) {
                if !draws.items.iter().any(|(k, ..)| *k == key) {
                    let name = format!("draw{}", draws.items.len() + 1);
                    draws.items.push((key, name, expr));
                }
            }
        }
        draws
    }

    /// `(name, expression)` of every key, for the `param` lines.
    pub(super) fn params(&self) -> impl Iterator<Item = (&str, &str)> {
        self.items.iter().map(|(_, name, expr)| (name.as_str(), expr.as_str()))
    }

    /// The draws of a lesson's scenario `s`: the declared names, with `s`'s own expressions, and
    /// the `(name, expression)` assignments a lesson needs where they differ from `self`'s. A key
    /// `s` uses in a way no expression fits is left out, so its uses print on their own.
    pub(super) fn in_lesson(&self, s: &Scenario) -> (Draws, Vec<(String, String)>) {
        let own = expressions(s);
        let mut assign = Vec::new();
        let mut items = Vec::new();
        for (key, name, expr) in &self.items {
            match own.iter().find(|(k, _)| k == key) {
                Some((_, e)) => {
                    if e != expr {
                        assign.push((name.clone(), e.clone()));
                    }
                    items.push((*key, name.clone(), e.clone()));
                }
                // Not used by the lesson (or not printable there): keep the name for the uses
                // the lesson does not print, which are the scenario's own.
                None if !uses(s).iter().any(|u| u.key == *key) => items.push((*key, name.clone(), expr.clone())),
                None => {}
            }
        }
        (Draws { items }, assign)
    }

    /// The name a sample prints as, if it is a printable shared draw.
    pub(super) fn name(&self, sample: &Sample) -> Option<&str> {
        let Sample::Shared(shared) = sample else { return None };
        self.items.iter().find(|(k, ..)| *k == shared.shared).map(|(_, name, _)| name.as_str())
    }
}

/// Every shared use of `s`: the players' points (team frame) and the ball's (global frame).
fn uses(s: &Scenario) -> Vec<Use> {
    let mut out = Vec::new();
    let mut point = |spot: Option<&Spot>, [mx, my]: [f64; 2]| {
        if let Some(Spot::Point { x, y }) = spot {
            for (sample, metres) in [(x, mx), (y, my)] {
                if let Sample::Shared(shared) = sample {
                    out.push(Use { key: shared.shared, of: shared.of.clone(), metres });
                }
            }
        }
    };
    for p in s.left_team.iter().chain(&s.right_team) {
        point(p.random.as_ref(), [PLAYER_X_METRES, PLAYER_Y_METRES]);
    }
    point(s.ball_random.as_ref(), [BALL_X_METRES, BALL_Y_METRES]);
    point(s.odd_episode_ball_random.as_ref(), [BALL_X_METRES, BALL_Y_METRES]);
    out
}

/// The printable keys of `s` with their expressions, in order of first use.
fn expressions(s: &Scenario) -> Vec<(u32, String)> {
    let all = uses(s);
    let mut keys: Vec<u32> = Vec::new();
    for u in &all {
        if !keys.contains(&u.key) {
            keys.push(u.key);
        }
    }
    keys.into_iter()
        .filter_map(|key| {
            let of: Vec<&Use> = all.iter().filter(|u| u.key == key).collect();
            expression(&of).map(|e| (key, e))
        })
        .collect()
}

/// One expression that reads as each use's distribution, if there is one.
fn expression(uses: &[&Use]) -> Option<String> {
    let first = &uses.first()?.of;
    if uses.iter().all(|u| &u.of == first) {
        return Some(text(first, super::number));
    }
    // In metres: each number is the shortest metres that every use reads back as its own value.
    let columns = values(first).len();
    if !uses.iter().all(|u| same_kind(&u.of, first) && values(&u.of).len() == columns) {
        return None;
    }
    let metres: Vec<String> = (0..columns).map(|i| shortest_metres(uses, i)).collect::<Option<_>>()?;
    let mut m = metres.iter();
    Some(text(first, |_| format!("{} m", m.next().map_or("0", String::as_str))))
}

/// The shortest decimal metres that reads back, in every use's units, as the use's `i`-th value
/// (the compiler divides the written metres by the axis's metres per unit, in f64).
fn shortest_metres(uses: &[&Use], i: usize) -> Option<String> {
    let reads_back = |m: f64| uses.iter().all(|u| (m / u.metres) as f32 == values(&u.of)[i]);
    uses.iter().find_map(|candidate| {
        let exact = f64::from(values(&candidate.of)[i]) * candidate.metres;
        (0..=12).find_map(|digits| {
            let written = format!("{exact:.digits$}");
            let value: f64 = written.parse().ok()?;
            reads_back(value).then(|| {
                let trimmed =
                    if written.contains('.') { written.trim_end_matches('0').trim_end_matches('.') } else { &written };
                if trimmed == "-0" { "0".to_owned() } else { trimmed.to_owned() }
            })
        })
    })
}

/// The numbers of a distribution, in order.
fn values(d: &Distribution) -> Vec<f32> {
    match d {
        Distribution::Uniform(a, b) | Distribution::Normal(a, b) => vec![*a, *b],
        Distribution::Choice(vs) => vs.clone(),
    }
}

fn same_kind(a: &Distribution, b: &Distribution) -> bool {
    std::mem::discriminant(a) == std::mem::discriminant(b)
}

/// A distribution's text, each number written by `number` (in order).
pub(super) fn text(d: &Distribution, mut number: impl FnMut(f32) -> String) -> String {
    match d {
        Distribution::Uniform(a, b) => format!("uniform({}, {})", number(*a), number(*b)),
        Distribution::Normal(m, sd) => format!("normal({}, {})", number(*m), number(*sd)),
        Distribution::Choice(vs) => format!("choice[{}]", vs.iter().map(|v| number(*v)).collect::<Vec<_>>().join(", ")),
    }
}
