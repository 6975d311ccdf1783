//! Match statistics as `touchline run --stats` prints them: one block per episode and the mean
//! over all episodes, each figure as `left / right`.

use std::io::{self, Write};

use serde::Serialize;
use touchline_engine::{MatchStats, Side, TeamStats};

/// One episode's statistics (or a mean of several), `[left, right]` per figure.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub(crate) struct StatsLine {
    goals: [f64; 2],
    shots: [f64; 2],
    shots_on_target: [f64; 2],
    passes: [f64; 2],
    passes_completed: [f64; 2],
    /// Percent of the time with the ball.
    possession: [f64; 2],
    fouls: [f64; 2],
    yellow_cards: [f64; 2],
    red_cards: [f64; 2],
    offsides: [f64; 2],
    corners: [f64; 2],
    throw_ins: [f64; 2],
    goal_kicks: [f64; 2],
    free_kicks: [f64; 2],
    penalties: [f64; 2],
}

impl From<&MatchStats> for StatsLine {
    fn from(s: &MatchStats) -> StatsLine {
        let pair = |f: fn(&TeamStats) -> u32| [f64::from(f(&s.teams[0])), f64::from(f(&s.teams[1]))];
        StatsLine {
            goals: pair(|t| t.goals),
            shots: pair(|t| t.shots),
            shots_on_target: pair(|t| t.shots_on_target),
            passes: pair(|t| t.passes),
            passes_completed: pair(|t| t.passes_completed),
            possession: [s.possession_percent(Side::Left), s.possession_percent(Side::Right)],
            fouls: pair(|t| t.fouls),
            yellow_cards: pair(|t| t.yellow_cards),
            red_cards: pair(|t| t.red_cards),
            offsides: pair(|t| t.offsides),
            corners: pair(|t| t.corners),
            throw_ins: pair(|t| t.throw_ins),
            goal_kicks: pair(|t| t.goal_kicks),
            free_kicks: pair(|t| t.free_kicks),
            penalties: pair(|t| t.penalties),
        }
    }
}

impl StatsLine {
    fn fields_mut(&mut self) -> [&mut [f64; 2]; 15] {
        [
            &mut self.goals,
            &mut self.shots,
            &mut self.shots_on_target,
            &mut self.passes,
            &mut self.passes_completed,
            &mut self.possession,
            &mut self.fouls,
            &mut self.yellow_cards,
            &mut self.red_cards,
            &mut self.offsides,
            &mut self.corners,
            &mut self.throw_ins,
            &mut self.goal_kicks,
            &mut self.free_kicks,
            &mut self.penalties,
        ]
    }

    /// The mean of `lines`; `None` when there are none.
    pub(crate) fn mean<'a>(lines: impl Iterator<Item = &'a StatsLine>) -> Option<StatsLine> {
        let mut sum = StatsLine::default();
        let mut n = 0usize;
        for line in lines {
            let mut line = line.clone();
            for (total, value) in sum.fields_mut().into_iter().zip(line.fields_mut()) {
                total[0] += value[0];
                total[1] += value[1];
            }
            n += 1;
        }
        if n == 0 {
            return None;
        }
        for field in sum.fields_mut() {
            field[0] /= n as f64;
            field[1] /= n as f64;
        }
        Some(sum)
    }

    /// Writes the block, each line starting with `indent`.
    pub(crate) fn write(&self, out: &mut impl Write, indent: &str) -> io::Result<()> {
        let rows: [(&str, &[f64; 2]); 15] = [
            ("goals", &self.goals),
            ("shots", &self.shots),
            ("on target", &self.shots_on_target),
            ("passes", &self.passes),
            ("completed", &self.passes_completed),
            ("possession %", &self.possession),
            ("fouls", &self.fouls),
            ("yellow cards", &self.yellow_cards),
            ("red cards", &self.red_cards),
            ("offsides", &self.offsides),
            ("corners", &self.corners),
            ("throw-ins", &self.throw_ins),
            ("goal kicks", &self.goal_kicks),
            ("free kicks", &self.free_kicks),
            ("penalties", &self.penalties),
        ];
        for (name, [l, r]) in rows {
            writeln!(out, "{indent}  {name:<14}{:>7} / {}", number(*l), number(*r))?;
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
        assert_eq!(a.possession, [75.0, 25.0]);
        let b = StatsLine::default();
        let m = StatsLine::mean([a, b].iter()).unwrap();
        assert_eq!(m.goals, [1.0, 0.0]);
        assert_eq!(m.passes, [0.0, 5.0]);
        assert!(StatsLine::mean(std::iter::empty()).is_none());
        let mut text = Vec::new();
        m.write(&mut text, "").unwrap();
        let text = String::from_utf8(text).unwrap();
        assert!(text.contains("goals               1 / 0"), "{text}");
    }
}
