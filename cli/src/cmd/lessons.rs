//! `touchline run --curriculum`: progress through a scenario's lessons, one row a lesson (name,
//! episodes played, the window's metrics, the episode it advanced at).

use std::io::{self, Write};

use serde::Serialize;
use touchline_engine::Env;
use touchline_engine::scenario::Metric;

/// One lesson's progress.
#[derive(Debug, Serialize)]
pub(crate) struct LessonRow {
    /// 0-based lesson index.
    pub(crate) lesson: usize,
    /// The lesson's name.
    pub(crate) name: String,
    /// 0-based index of the first episode played in the lesson.
    pub(crate) first_episode: u64,
    /// Episodes finished in the lesson.
    pub(crate) episodes: u64,
    /// Mean episode return over the lesson's window after its last episode.
    pub(crate) mean_reward: Option<f64>,
    /// Mean score difference (left minus right) over the window.
    pub(crate) mean_score: Option<f64>,
    /// Fraction of the window's episodes the left team won.
    pub(crate) success_rate: Option<f64>,
    /// The episode after which the env moved to the next lesson; `None` for the lesson played
    /// at the end.
    pub(crate) advanced_after: Option<u64>,
}

/// The rows of the lessons played so far.
#[derive(Debug, Default, Serialize)]
pub(crate) struct LessonLog {
    /// Number of lessons of the curriculum.
    pub(crate) lessons: usize,
    /// One row a lesson played, in order.
    pub(crate) rows: Vec<LessonRow>,
}

impl LessonLog {
    /// A log starting at the env's current lesson; `None` without a curriculum.
    pub(crate) fn new(env: &Env) -> Option<LessonLog> {
        let progress = env.curriculum_progress()?;
        let mut log = LessonLog { lessons: progress.lessons, rows: Vec::new() };
        log.open(env, 0);
        Some(log)
    }

    fn open(&mut self, env: &Env, first_episode: u64) {
        if let Some((lesson, name)) = env.lesson() {
            self.rows.push(LessonRow {
                lesson,
                name: name.to_owned(),
                first_episode,
                episodes: 0,
                mean_reward: None,
                mean_score: None,
                success_rate: None,
                advanced_after: None,
            });
        }
    }

    /// Records the episode that just ended (before the env is reset).
    pub(crate) fn episode_done(&mut self, env: &Env) {
        let Some(row) = self.rows.last_mut() else { return };
        row.episodes = env.curriculum_progress().map_or(row.episodes, |p| p.episodes);
        row.mean_reward = env.lesson_metric(Metric::MeanReward);
        row.mean_score = env.lesson_metric(Metric::MeanScore);
        row.success_rate = env.lesson_metric(Metric::SuccessRate);
    }

    /// After a reset into episode `episode`: when the lesson changed, closes the previous row and
    /// returns the line announcing it.
    pub(crate) fn after_reset(&mut self, env: &Env, episode: u64) -> Option<String> {
        let (lesson, name) = env.lesson()?;
        let previous = self.rows.last_mut()?;
        if previous.lesson == lesson {
            return None;
        }
        previous.advanced_after = episode.checked_sub(1);
        let line = format!(
            "lesson   {} `{}` -> {}/{} `{name}` after {} episode{} ({})",
            previous.lesson + 1,
            previous.name,
            lesson + 1,
            self.lessons,
            previous.episodes,
            if previous.episodes == 1 { "" } else { "s" },
            metrics(previous),
        );
        self.open(env, episode);
        Some(line)
    }

    /// The summary table: one line a lesson played.
    pub(crate) fn write(&self, out: &mut impl Write) -> io::Result<()> {
        writeln!(out, "lessons ({} in the curriculum):", self.lessons)?;
        for r in &self.rows {
            let end = match r.advanced_after {
                Some(e) => format!("advanced after episode {e}"),
                None => "playing".to_owned(),
            };
            writeln!(
                out,
                "  {}/{} {:<16} episodes {:>5} (from {:>5})  {}  {end}",
                r.lesson + 1,
                self.lessons,
                r.name,
                r.episodes,
                r.first_episode,
                metrics(r),
            )?;
        }
        Ok(())
    }
}

fn metrics(r: &LessonRow) -> String {
    let show = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v:.3}"));
    format!(
        "mean_reward {} mean_score {} success_rate {}",
        show(r.mean_reward),
        show(r.mean_score),
        show(r.success_rate)
    )
}
