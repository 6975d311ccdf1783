//! Match statistics as `touchline run --stats` prints them: one block per episode and the mean
//! over all episodes, each figure as `left / right`.

use std::io::{self, Write};

use serde::ser::{Serialize, SerializeMap, Serializer};
use touchline_engine::{MatchStats, Side, TeamStats};

/// How one figure is read from a team's statistics (possession, a share of both teams' time, is
/// the one figure that is not).
type Count = fn(&TeamStats) -> u32;

/// Every figure: JSON key, printed label and how to count it (`None`: possession %).
const ROWS: [(&str, &str, Option<Count>); 18] = [
    ("goals", "goals", Some(|t| t.goals)),
    ("shots", "shots", Some(|t| t.shots)),
    ("shots_on_target", "on target", Some(|t| t.shots_on_target)),
    ("passes", "passes", Some(|t| t.passes)),
    ("passes_completed", "completed", Some(|t| t.passes_completed)),
    ("passes_intercepted", "intercepted", Some(|t| t.passes_intercepted)),
    ("possession", "possession %", None),
    ("possessions_won", "balls won", Some(|t| t.possessions_won)),
    ("out_of_play", "out of play", Some(|t| t.out_of_play)),
    ("fouls", "fouls", Some(|t| t.fouls)),
    ("yellow_cards", "yellow cards", Some(|t| t.yellow_cards)),
    ("red_cards", "red cards", Some(|t| t.red_cards)),
    ("offsides", "offsides", Some(|t| t.offsides)),
    ("corners", "corners", Some(|t| t.corners)),
    ("throw_ins", "throw-ins", Some(|t| t.throw_ins)),
    ("goal_kicks", "goal kicks", Some(|t| t.goal_kicks)),
    ("free_kicks", "free kicks", Some(|t| t.free_kicks)),
    ("penalties", "penalties", Some(|t| t.penalties)),
];

/// One episode's statistics (or a mean of several), `[left, right]` per figure of [`ROWS`].
/// JSON: an object with one `[left, right]` array per key, in [`ROWS`] order.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct StatsLine {
    values: [[f64; 2]; ROWS.len()],
}

impl From<&MatchStats> for StatsLine {
    fn from(s: &MatchStats) -> StatsLine {
        let mut values = [[0.0; 2]; ROWS.len()];
        for (v, (_, _, count)) in values.iter_mut().zip(ROWS) {
            *v = match count {
                Some(count) => [f64::from(count(&s.teams[0])), f64::from(count(&s.teams[1]))],
                None => [s.possession_percent(Side::Left), s.possession_percent(Side::Right)],
            };
        }
        StatsLine { values }
    }
}

impl Serialize for StatsLine {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(ROWS.len()))?;
        for ((key, _, _), v) in ROWS.iter().zip(&self.values) {
            map.serialize_entry(key, v)?;
        }
        map.end()
    }
}

impl StatsLine {
    /// The figure stored under JSON key `key`.
    #[cfg(test)]
    fn get(&self, key: &str) -> [f64; 2] {
        let i = ROWS.iter().position(|(k, _, _)| *k == key).expect("a known key");
        self.values[i]
    }

    /// The mean of `lines`; `None` when there are none.
    pub(crate) fn mean<'a>(lines: impl Iterator<Item = &'a StatsLine>) -> Option<StatsLine> {
        let mut sum = StatsLine::default();
        let mut n = 0usize;
        for line in lines {
            for (total, value) in sum.values.iter_mut().zip(&line.values) {
                total[0] += value[0];
                total[1] += value[1];
            }
            n += 1;
        }
        if n == 0 {
            return None;
        }
        for field in &mut sum.values {
            field[0] /= n as f64;
            field[1] /= n as f64;
        }
        Some(sum)
    }

    /// Writes the block, each line starting with `indent`.
    pub(crate) fn write(&self, out: &mut impl Write, indent: &str) -> io::Result<()> {
        for ((_, label, _), [l, r]) in ROWS.iter().zip(&self.values) {
            writeln!(out, "{indent}  {label:<14}{:>7} / {}", number(*l), number(*r))?;
        }
        Ok(())
    }
}

/// Whole numbers without decimals, others with one (possession) or two.
fn number(x: f64) -> String {
    if x.fract() == 0.0 { format!("{x:.0}") } else { format!("{x:.2}") }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn means_and_printing() {
        let mut s = MatchStats::default();
        s.teams[0].goals = 2;
        s.teams[1].passes = 10;
        s.teams[0].possession_ticks = 3;
        s.teams[1].possession_ticks = 1;
        let a = StatsLine::from(&s);
        assert_eq!(a.get("possession"), [75.0, 25.0]);
        let b = StatsLine::default();
        let m = StatsLine::mean([a, b].iter()).unwrap();
        assert_eq!(m.get("goals"), [1.0, 0.0]);
        assert_eq!(m.get("passes"), [0.0, 5.0]);
        let json = serde_json::to_value(&m).unwrap();
        assert_eq!(json["passes"], serde_json::json!([0.0, 5.0]));
        assert_eq!(json.as_object().unwrap().len(), ROWS.len());
        assert!(StatsLine::mean(std::iter::empty()).is_none());
        let mut text = Vec::new();
        m.write(&mut text, "").unwrap();
        let text = String::from_utf8(text).unwrap();
        assert!(text.contains("goals               1 / 0"), "{text}");
    }
}
