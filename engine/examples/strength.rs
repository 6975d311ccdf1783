//! The θ experiment (issue 7): full 11-v-11 matches with the built-in AI on all 22 players, the
//! left team at θ = 1.0 against the right team at θ = 0.05, 0.3, 0.6 and 0.95, plus equal-θ
//! pairings for symmetry. Prints, per pairing, the mean goal difference (left − right) with its
//! standard error, mean goals, possession and the other match statistics.
//!
//! Run: `cargo run --release -p touchline-engine --example strength -- [MATCHES] [PAIRING...]`
//! (default 50 matches per pairing; a pairing is `LEFT:RIGHT`, e.g. `1.0:0.05`).

use touchline_engine::{Action, ActionSet, Env, EnvConfig, MatchStats, Scenario};

/// 11_vs_11_stochastic at the given difficulties. Its two formations differ (the kickoff set and
/// the receiving set); odd seeds give the kickoff set to the right team, as GRF's odd episodes do,
/// so that neither side keeps a formation's advantage.
fn scenario(left: f32, right: f32, seed: u64) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/11_vs_11_stochastic.json", env!("CARGO_MANIFEST_DIR"));
    let mut s: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
    s.left_team_difficulty = left;
    s.right_team_difficulty = right;
    if seed % 2 == 1 {
        std::mem::swap(&mut s.left_team, &mut s.right_team);
    }
    s
}

/// Plays one full match; returns its statistics.
fn play(left: f32, right: f32, seed: u64) -> MatchStats {
    let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario(left, right, seed), config, seed).expect("env");
    loop {
        let out = env.step(&[Action::BuiltinAi]).expect("step");
        if out.terminated || out.truncated {
            return *env.game().stats();
        }
    }
}

fn main() {
    let mut args = std::env::args().skip(1);
    let matches: u64 = args.next().and_then(|a| a.parse().ok()).unwrap_or(50);
    let mut pairings: Vec<(f32, f32)> = args
        .filter_map(|a| {
            let (l, r) = a.split_once(':')?;
            Some((l.parse().ok()?, r.parse().ok()?))
        })
        .collect();
    if pairings.is_empty() {
        pairings = vec![(1.0, 0.05), (1.0, 0.3), (1.0, 0.6), (1.0, 0.95), (0.6, 0.6), (0.95, 0.95)];
    }
    println!(
        "{:>5} {:>5} {:>7} {:>6} {:>6} {:>6} {:>6} {:>7} {:>7} {:>6} {:>5} {:>5} {:>5} {:>5} {:>5}",
        "left",
        "right",
        "matches",
        "GD",
        "±se",
        "goals",
        "poss%",
        "shots",
        "passes",
        "compl",
        "fouls",
        "cards",
        "offs",
        "corn",
        "throw"
    );
    for (left, right) in pairings {
        let mut diffs = Vec::new();
        let (mut goals, mut poss, mut shots, mut passes, mut completed) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let (mut fouls, mut cards, mut offsides, mut corners, mut throws) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for seed in 0..matches {
            let s = play(left, right, seed);
            if std::env::var_os("STRENGTH_VERBOSE").is_some() {
                let [l, r] = s.teams;
                println!(
                    "  seed {seed}: {}-{}, possession {:.1} %",
                    l.goals,
                    r.goals,
                    s.possession_percent(touchline_engine::Side::Left)
                );
            }
            let [l, r] = s.teams;
            diffs.push(f64::from(l.goals) - f64::from(r.goals));
            goals += f64::from(l.goals + r.goals);
            poss += s.possession_percent(touchline_engine::Side::Left);
            shots += f64::from(l.shots + r.shots);
            passes += f64::from(l.passes + r.passes);
            completed += f64::from(l.passes_completed + r.passes_completed);
            fouls += f64::from(l.fouls + r.fouls);
            cards += f64::from(l.yellow_cards + r.yellow_cards + l.red_cards + r.red_cards);
            offsides += f64::from(l.offsides + r.offsides);
            corners += f64::from(l.corners + r.corners);
            throws += f64::from(l.throw_ins + r.throw_ins);
        }
        let n = matches as f64;
        let mean = diffs.iter().sum::<f64>() / n;
        let var = diffs.iter().map(|d| (d - mean) * (d - mean)).sum::<f64>() / (n - 1.0).max(1.0);
        println!(
            "{left:>5.2} {right:>5.2} {matches:>7} {mean:>+6.2} {:>6.2} {:>6.2} {:>6.1} {:>7.1} {:>7.1} {:>6.1} {:>5.2} {:>5.2} {:>5.2} {:>5.2} {:>5.2}",
            (var / n).sqrt(),
            goals / n,
            poss / n,
            shots / n,
            passes / n,
            completed / n,
            fouls / n,
            cards / n,
            offsides / n,
            corners / n,
            throws / n,
        );
    }
}
