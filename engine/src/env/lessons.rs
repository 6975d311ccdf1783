//! An env's progress through a curriculum: the lesson it plays, the results of the episodes
//! finished in that lesson (a moving window) and the return of the episode under way. Part of
//! the env's state, so that snapshots keep it.

use serde::{Deserialize, Serialize};

use crate::scenario::{Criterion, EpisodeResult};

/// Lesson index and the window of finished episodes.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub(crate) struct LessonProgress {
    /// The lesson played, 0-based.
    pub(crate) lesson: usize,
    /// A ring of the last results, as long as the largest window of any lesson (allocated when
    /// the env is built, so that recording a result never allocates).
    results: Vec<EpisodeResult>,
    /// The slot the next result goes to.
    next: usize,
    /// Results in the ring (at most its length).
    len: usize,
    /// Episodes finished in this lesson.
    pub(crate) episodes: u64,
    /// The return of the episode under way so far.
    episode_return: f32,
}

impl LessonProgress {
    /// Progress at the first lesson, with room for windows of up to `capacity` episodes.
    pub(crate) fn new(capacity: usize) -> LessonProgress {
        LessonProgress { results: vec![EpisodeResult::default(); capacity], ..LessonProgress::default() }
    }

    /// Makes room for windows of `capacity` episodes (a curriculum replaced by hot reload),
    /// keeping the lesson and forgetting the window.
    pub(crate) fn resize(&mut self, capacity: usize) {
        if capacity != self.results.len() {
            self.results = vec![EpisodeResult::default(); capacity];
            self.next = 0;
            self.len = 0;
        }
    }

    /// Room in the window ring (the largest window of any lesson).
    pub(crate) fn capacity(&self) -> usize {
        self.results.len()
    }

    /// Checks restored progress against an env of `lessons` lessons (1 without a curriculum)
    /// whose ring holds `capacity` results.
    pub(crate) fn check(&self, lessons: usize, capacity: usize) -> Result<(), String> {
        if self.lesson >= lessons {
            return Err(format!("the curriculum is at lesson {} of {lessons}", self.lesson));
        }
        let cap = self.results.len();
        if cap != capacity || self.len > cap || (cap > 0 && self.next >= cap) || (cap == 0 && self.next != 0) {
            return Err(format!(
                "the lesson window ({} of {cap}, next {}) does not fit {capacity}",
                self.len, self.next
            ));
        }
        if !self.episode_return.is_finite() || self.results.iter().any(|r| !r.reward.is_finite()) {
            return Err("a lesson's episode return is not finite".into());
        }
        Ok(())
    }

    /// A new episode starts.
    pub(crate) fn start_episode(&mut self) {
        self.episode_return = 0.0;
    }

    /// Adds a step's reward to the episode's return.
    pub(crate) fn add_reward(&mut self, reward: f32) {
        self.episode_return += reward;
    }

    /// The episode ended with `score_diff` (left minus right): its result enters the window.
    pub(crate) fn finish_episode(&mut self, score_diff: i32) {
        self.episodes += 1;
        let cap = self.results.len();
        if cap == 0 {
            return;
        }
        self.results[self.next] = EpisodeResult { reward: self.episode_return, score_diff };
        self.next = (self.next + 1) % cap;
        self.len = (self.len + 1).min(cap);
    }

    /// The last `window` results (fewer when fewer were recorded), newest first.
    pub(crate) fn window(&self, window: usize) -> impl Iterator<Item = &EpisodeResult> + Clone {
        let cap = self.results.len();
        let n = window.min(self.len);
        (0..n).map(move |j| &self.results[(self.next + cap - 1 - j) % cap])
    }

    /// Whether `criterion` holds over its window.
    pub(crate) fn met(&self, criterion: &Criterion) -> bool {
        criterion.met(self.window(criterion.window as usize))
    }

    /// Moves to the next lesson with an empty window.
    pub(crate) fn advance(&mut self) {
        self.lesson += 1;
        self.next = 0;
        self.len = 0;
        self.episodes = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{Metric, Threshold};

    #[test]
    fn the_window_keeps_the_newest_results() {
        let mut p = LessonProgress::new(3);
        for diff in [1, 0, 0, 1, 1] {
            p.start_episode();
            p.add_reward(diff as f32);
            p.finish_episode(diff);
        }
        let diffs: Vec<i32> = p.window(3).map(|r| r.score_diff).collect();
        assert_eq!(diffs, [1, 1, 0]);
        assert_eq!(p.window(2).count(), 2);
        let c = Criterion {
            window: 3,
            min_episodes: 3,
            thresholds: vec![Threshold { metric: Metric::SuccessRate, at_least: true, value: 0.6 }],
        };
        assert!(p.met(&c));
        p.advance();
        assert_eq!((p.lesson, p.window(3).count(), p.episodes), (1, 0, 0));
        assert!(!p.met(&c));
    }
}
