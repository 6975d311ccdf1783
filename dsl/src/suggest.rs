//! "Did you mean …?" suggestions for misspelt names.

/// Levenshtein edit distance between `a` and `b`, counted in `char`s (insertions, deletions and
/// substitutions each cost 1).
pub(crate) fn levenshtein(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    // `row[j]` is the distance between the prefix of `a` seen so far and `b[..j]`.
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substitute = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substitute.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

/// The candidates closest to `query`, in the candidates' order.
///
/// A candidate is close when its edit distance (ignoring ASCII case) is at most a third of the
/// query's length (and at least 1 edit is always allowed); all candidates at the smallest such
/// distance are returned. When none is close, the candidates that contain the query (ignoring ASCII
/// case) are returned instead, e.g. `corner` gives `academy_corner`. Empty when nothing fits.
pub(crate) fn closest<'a>(query: &str, candidates: &[&'a str]) -> Vec<&'a str> {
    let query = query.to_ascii_lowercase();
    let limit = (query.chars().count() / 3).max(1);
    let scored: Vec<(usize, &'a str)> =
        candidates.iter().map(|c| (levenshtein(&query, &c.to_ascii_lowercase()), *c)).collect();
    if let Some(best) = scored.iter().map(|(d, _)| *d).min().filter(|d| *d <= limit) {
        return scored.into_iter().filter(|(d, _)| *d == best).map(|(_, c)| c).collect();
    }
    if query.is_empty() {
        return Vec::new();
    }
    candidates.iter().copied().filter(|c| c.to_ascii_lowercase().contains(&query)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_basics() {
        assert_eq!(levenshtein("", ""), 0);
        assert_eq!(levenshtein("abc", ""), 3);
        assert_eq!(levenshtein("", "abc"), 3);
        assert_eq!(levenshtein("kitten", "sitting"), 3);
        assert_eq!(levenshtein("flaw", "lawn"), 2);
        assert_eq!(levenshtein("goal", "gaol"), 2);
        assert_eq!(levenshtein("same", "same"), 0);
        assert_eq!(levenshtein("ä", "a"), 1, "counts chars, not bytes");
    }

    #[test]
    fn distance_is_symmetric() {
        let words = ["academy_corner", "corner", "5_vs_5", "1_vs_1_easy", ""];
        for a in words {
            for b in words {
                assert_eq!(levenshtein(a, b), levenshtein(b, a), "{a} / {b}");
            }
        }
    }

    const NAMES: &[&str] = &[
        "1_vs_1_easy",
        "5_vs_5",
        "academy_corner",
        "academy_empty_goal",
        "academy_empty_goal_close",
        "academy_run_to_score",
        "academy_run_to_score_with_keeper",
    ];

    #[test]
    fn suggests_the_nearest_name() {
        assert_eq!(closest("academy_empty_gaol", NAMES), ["academy_empty_goal"]);
        assert_eq!(closest("academy_empty_goal_clos", NAMES), ["academy_empty_goal_close"]);
        assert_eq!(closest("ACADEMY_CORNER", NAMES), ["academy_corner"]);
        assert_eq!(closest("5_vs_6", NAMES), ["5_vs_5"]);
    }

    #[test]
    fn ties_are_all_returned() {
        assert_eq!(closest("b", &["a", "c", "dd"]), ["a", "c"]);
    }

    #[test]
    fn falls_back_to_substrings() {
        assert_eq!(closest("corner", NAMES), ["academy_corner"]);
        assert_eq!(closest("run_to_score", NAMES), ["academy_run_to_score", "academy_run_to_score_with_keeper"]);
    }

    #[test]
    fn nothing_close() {
        assert!(closest("penalty_shootout", NAMES).is_empty());
        assert!(closest("", NAMES).is_empty());
    }
}
