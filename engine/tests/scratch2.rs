mod common;
use touchline_engine::Action;

#[test]
fn trace() {
    let mut env = common::builtin_env("11_vs_11_easy_stochastic", 0);
    for k in 0..300 {
        env.step(&[Action::BuiltinAi]).unwrap();
        if k % 3 != 0 {
            continue;
        }
        let g = env.game();
        let b = g.ball();
        let mut near: Vec<(f32, String)> = g
            .players()
            .iter()
            .map(|p| (p.position.distance(b.xy()), format!("{:?}{}{}", p.side, p.index, p.role)))
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        println!(
            "{k:4} owner {:?} ball ({:6.1},{:6.1},{:4.2}) v ({:5.1},{:5.1},{:5.1}) mode {:?} near {:?}",
            g.owner(),
            b.position.x,
            b.position.y,
            b.position.z,
            b.velocity.x,
            b.velocity.y,
            b.velocity.z,
            g.mode(),
            &near[..3].iter().map(|(d, n)| format!("{n}:{d:.1}")).collect::<Vec<_>>()
        );
    }
}
