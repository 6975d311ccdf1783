//! How the ball is won and how keepers play, against GRF's measured behaviour (issue 15): a
//! defender at a carrier's back does not get to the ball; a keeper with no team-mate covering rushes
//! out at a carrier; in his own area he takes a dribbled ball with his hands, nobody may challenge
//! him while he holds it, and, alone, he clears it the way he faces; two bodies on one spot part
//! instead of drifting along together; a keeper meets a contested loose ball with a first-time
//! clearance and an uncontested one with a first-time pass upfield; an agent walking away from the
//! ball takes it with him; a defender racing back at an idle carrier takes the ball as soon as
//! GRF's does.

mod common;

use touchline_engine::{Action, GameMode, Side};

#[test]
fn defenders_at_a_standing_carriers_back_do_not_get_to_the_ball() {
    // academy_run_to_score: five defenders chase our idle CB from behind. GRF: 80 % of idle
    // episodes keep the ball for all 400 steps.
    let mut kept = 0;
    for seed in 0..6 {
        let mut env = common::env("academy_run_to_score", seed);
        for _ in 0..100 {
            let out = env.step(&[Action::Idle]).unwrap();
            if out.terminated || out.truncated {
                break;
            }
        }
        if env.game().owner().map(|(side, _)| side) == Some(Side::Left) {
            kept += 1;
        }
    }
    assert!(kept >= 4, "kept the ball for 100 steps in {kept} of 6 episodes");
}

#[test]
fn a_goal_side_defender_does_not_dive_in_on_a_carrier_out_of_shooting_range() {
    // academy_pass_and_shoot_with_keeper: our idle CM has the ball wide, about 28 m from goal. GRF:
    // the centre back, goal-side, does not dive in (he marks a man, and no hunter comes), and no
    // idle episode loses the ball in 401 steps (50 of 50). He used to dive in and win it within
    // 64 steps in 45 of 50.
    for seed in 0..4 {
        let mut env = common::env("academy_pass_and_shoot_with_keeper", seed);
        let mut gaps = Vec::new();
        for _ in 0..300 {
            let out = env.step(&[Action::Idle]).unwrap();
            assert!(!out.terminated && !out.truncated, "seed {seed}: the episode ended");
            let carrier = env.game().team(Side::Left)[2].position;
            gaps.push(env.game().team(Side::Right)[1].position.distance(carrier));
        }
        assert_eq!(env.game().owner(), Some((Side::Left, 2)), "seed {seed}: our CM still has the ball");
        gaps.sort_by(f32::total_cmp);
        let close = gaps[gaps.len() / 10];
        assert!(close > 2.5, "seed {seed}: the centre back came within {close:.1} m in a tenth of the steps");
    }
}

#[test]
fn a_keeper_with_no_team_mate_rushes_out_and_clears_the_way_he_faces() {
    // academy_empty_goal_close: the right keeper starts at OUR goal (GRF's layout). GRF: he sprints
    // up the pitch, takes the ball from our idle CB inside his own area at about step 134, and his
    // clearance along the way he ran goes over his own goal line: a corner for us at about 151, in
    // 50 of 50 idle episodes. Our CB, standing at his side, may not challenge him while he holds
    // the ball in his hands (Law 12), so no episode ends with the ball back at our CB's feet.
    for seed in 0..8 {
        let mut env = common::env("academy_empty_goal_close", seed);
        let start = env.game().team(Side::Right)[0].position.x;
        let mut held = false;
        let mut steps = 0;
        loop {
            let out = env.step(&[Action::Idle]).unwrap();
            steps += 1;
            held |= env.game().owner() == Some((Side::Right, 0));
            if out.terminated || out.truncated {
                break;
            }
        }
        let keeper = env.game().team(Side::Right)[0].position.x;
        assert!(keeper - start > 80.0, "seed {seed}: the keeper went from x = {start} to {keeper}");
        assert!(held, "seed {seed}: the keeper took the ball");
        assert!((120..200).contains(&steps), "seed {seed}: ended after {steps} steps");
        assert_eq!(env.info().score, [0, 0]);
        assert_ne!(env.info().game_mode, GameMode::Normal, "seed {seed}: the episode ends with the ball out of play");
    }
}

#[test]
fn two_keepers_on_one_spot_part_instead_of_drifting_together() {
    // academy_empty_goal: both keepers start on our goal line. Ours stands 30 % of the way out to
    // the ball, as GRF's keeper does with his team on the ball; theirs rushes on past him.
    let mut env = common::env("academy_empty_goal", 1);
    for _ in 0..60 {
        env.step(&[Action::Idle]).unwrap();
    }
    let ours = env.game().team(Side::Left)[0].position.x;
    let theirs = env.game().team(Side::Right)[0].position.x;
    assert!(ours < -30.0, "our keeper drifted to x = {ours}");
    assert!(theirs > ours + 15.0, "their keeper is at x = {theirs}, ours at {ours}");
}

#[test]
fn an_agents_player_walking_away_from_the_ball_takes_it_with_him() {
    // academy_empty_goal: the ball lies a metre in front of our CB. GRF (measured, 2.10.2): holding
    // left, bottom-left or top-left from the first step, he still gathers it (owner by step 10) and
    // dribbles it the way he goes; he never leaves it for the opponents' keeper.
    for action in [Action::Left, Action::BottomLeft, Action::TopLeft] {
        let mut env = common::env("academy_empty_goal", 0);
        for _ in 0..10 {
            env.step(&[action]).unwrap();
        }
        let o = &env.observations()[0];
        assert_eq!((o.ball_owned_team, o.ball_owned_player), (0, 1), "{action:?}: nobody took the ball");
        for _ in 0..20 {
            env.step(&[action]).unwrap();
        }
        let o = &env.observations()[0];
        assert!(o.ball[0] < -0.05, "{action:?}: the ball stayed at x = {}", o.ball[0]);
    }
}

#[test]
fn a_long_pass_back_in_academy_empty_goal_reaches_our_keeper() {
    // GRF 2.10.2, measured (seeds 0-5, idle 5 or 7 steps, then one long pass, then idle): our CB
    // has the ball from step 3-5, the pass goes back to our keeper, the only team-mate, and our
    // keeper takes it at step 42-47 in all 12 runs; the opponents' keeper, rushing out from our
    // goal, never gets it.
    for (seed, idle) in [(0, 5), (3, 5), (3, 7), (5, 7)] {
        let mut env = common::env("academy_empty_goal", seed);
        for _ in 0..idle {
            env.step(&[Action::Idle]).unwrap();
        }
        env.step(&[Action::LongPass]).unwrap();
        let mut keeper_has_it = false;
        for step in 0..60 {
            let out = env.step(&[Action::Idle]).unwrap();
            let o = &env.observations()[0];
            assert!(
                o.ball_owned_team != 1 || out.terminated,
                "seed {seed}, step {step}: the opponents' keeper took it"
            );
            keeper_has_it |= (o.ball_owned_team, o.ball_owned_player) == (0, 0);
            if keeper_has_it || out.terminated || out.truncated {
                break;
            }
        }
        assert!(keeper_has_it, "seed {seed}, idle {idle}: our keeper never had the pass back");
    }
}

#[test]
fn a_keeper_first_to_a_contested_loose_ball_outside_his_area_clears_it_first_time() {
    // academy_empty_goal: the opponents' keeper starts at our goal, outside his own area. A loose
    // ball rolls towards him 8 m ahead of him, our CB chasing it 8 m behind: GRF's keeper plays a
    // contested ball he cannot hold first time, high and away ("panic pass"), and never shows as
    // its owner.
    let mut env = common::env("academy_empty_goal", 3);
    let game = env.game_mut();
    game.place_player(Side::Right, 0, glam::Vec2::new(-38.0, 0.0));
    game.place_player(Side::Left, 1, glam::Vec2::new(-22.0, 0.0));
    game.place_ball(glam::Vec3::new(-30.0, 0.0, 0.11), glam::Vec3::new(-3.0, 0.0, 0.0), Some((Side::Left, 1)));
    let mut highest = 0.0f32;
    for tick in 0..300 {
        game.tick();
        assert!(
            game.owner().is_none_or(|(side, _)| side == Side::Left),
            "tick {tick}: the opponents' keeper took the ball"
        );
        highest = highest.max(game.ball().position.z);
    }
    assert!(highest > 3.0, "cleared high: {highest}");
}

/// A right-team centre back alone with the ball in our half, running at our keeper; our only
/// outfield player stands idle far away, so nobody covers and the keeper comes out.
fn centre_back_through_on_goal() -> touchline_engine::Scenario {
    use touchline_engine::{PlayerEntry, Role, Scenario};
    let mut far = PlayerEntry::new(Role::CM, 0.8, 0.4);
    far.lazy = true;
    let mut right_gk = PlayerEntry::new(Role::GK, -1.0, 0.0);
    right_gk.lazy = true;
    Scenario {
        name: "centre_back_through_on_goal".into(),
        game_duration: 300,
        end_episode_on_score: true,
        end_episode_on_possession_change: true,
        end_episode_on_out_of_play: true,
        left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), far],
        // In the right team's own frame: 20 m into our half, off centre.
        right_team: vec![right_gk, PlayerEntry::new(Role::CB, 0.4, 0.1)],
        ball_position: [-0.41, -0.1],
        ..Scenario::default()
    }
}

#[test]
fn a_centre_back_through_on_goal_does_not_beat_the_keeper() {
    // GRF: a centre back who wins the ball in the pass-and-shoot drills scores in about 5 % of
    // random episodes (0.045 and 0.06). His AI shoots only within about 12.7 m of the spot 7 m
    // out with a lane to goal, and our keeper, rushing out, takes the ball at his feet in the
    // area. Before both, he dribbled at the keeper, who ran alongside him, and scored in a
    // quarter of the episodes.
    let mut conceded = 0;
    for seed in 0..10 {
        let mut env = touchline_engine::Env::new(centre_back_through_on_goal(), seed).unwrap();
        let _ = common::play(&mut env, |_, _| Action::Idle);
        conceded += env.game().score()[1];
    }
    assert!(conceded <= 1, "the centre back scored {conceded} times in 10");
}

/// A hard pass of the left team's at hip height, struck `gap` m in front of a standing right
/// centre back and straight at him: the ball (position and velocity) once 80 ticks have passed,
/// and who has it.
fn hard_pass_at_a_standing_defender(gap: f32) -> (touchline_engine::physics::Ball, Option<(Side, usize)>) {
    use touchline_engine::{PlayerEntry, Role};
    let mut scenario = common::empty_pitch(400);
    let mut cb = PlayerEntry::new(Role::CB, 0.5, 0.2);
    cb.lazy = true;
    scenario.right_team.push(cb);
    let mut env = touchline_engine::Env::new(scenario, 0).unwrap();
    let game = env.game_mut();
    game.place_player(Side::Right, 1, glam::Vec2::new(0.0, -20.0));
    game.place_ball(glam::Vec3::new(-gap, -20.0, 0.6), glam::Vec3::new(25.0, 0.0, 2.5), Some((Side::Left, 1)));
    for _ in 0..80 {
        game.tick();
    }
    (*game.ball(), game.owner())
}

#[test]
fn a_hard_pass_goes_through_a_defender_it_reaches_late_and_meets_one_it_reaches_at_once() {
    // GRF: a ball too fast to control (over 15 m/s relative) meets a player's body only in the
    // 200 ms after an opponent touched it; later it runs on past him (academy_run_to_score: a
    // back pass to the keeper is not cut out by the defenders chasing the carrier).
    let (late, owner) = hard_pass_at_a_standing_defender(12.0);
    assert_eq!(owner, None, "the defender 12 m away took the pass");
    assert!(
        late.position.x > 2.0 && late.velocity.x > 8.0,
        "the pass struck 12 m from the defender did not run on past him: {late:?}"
    );
    let (soon, owner) = hard_pass_at_a_standing_defender(1.5);
    assert!(
        owner.is_some_and(|(side, _)| side == Side::Right) || soon.velocity.x < 10.0,
        "the pass struck 1.5 m from the defender ran on past him: {soon:?}"
    );
}

#[test]
fn a_keeper_waits_ten_metres_out_while_the_ball_is_in_the_other_half() {
    // GRF 2.10's keeper works out his place between ball and goal only while the ball (0.6 s
    // ahead) is in his half; otherwise he stands 10 m in front of the centre of his goal. Our
    // keeper, with our team on the ball deep in their half, stood 30 % of the way out to it
    // before (about 25 m out with the ball 30 m into their half).
    let mut env = common::builtin_env("11_vs_11_stochastic", 4);
    let mut deep_for = 0;
    let mut checked = 0;
    for step in 0..1500 {
        env.step(&[Action::BuiltinAi]).unwrap();
        let game = env.game();
        // Deep and staying there: a ball cleared back towards our half at speed is in our half by
        // the time he looks ahead (0.6 s plus a fifth of his time to it), and he rightly drops.
        let ball = game.ball();
        let staying = ball.position.x > 25.0 && ball.velocity.x > -5.0;
        deep_for = if staying && game.mode() == GameMode::Normal { deep_for + 1 } else { 0 };
        if deep_for >= 20 {
            let keeper = game.team(Side::Left)[0].position;
            assert!(
                keeper.distance(glam::Vec2::new(-45.0, 0.0)) < 1.5,
                "step {step}: ball at x = {:.0}, our keeper at {keeper}",
                game.ball().position.x
            );
            checked += 1;
        }
    }
    assert!(checked > 20, "the ball was deep in their half for {checked} steps only");
}

/// A built-in 11_vs_11_stochastic match (engine seed 1) with each team's ten outfield players in
/// a line across the pitch, 6 m apart, theirs at x = `right_x` and ours at `left_x` (m).
fn outfield_lines(right_x: f32, left_x: f32) -> touchline_engine::Env {
    let mut env = common::builtin_env("11_vs_11_stochastic", 1);
    let game = env.game_mut();
    for i in 1..11 {
        game.place_player(Side::Right, i, glam::Vec2::new(right_x, -30.0 + 6.0 * i as f32));
        game.place_player(Side::Left, i, glam::Vec2::new(left_x, -30.0 + 6.0 * i as f32));
    }
    env
}

/// Ticks `game` until their keeper first touches the ball (at most 300 ticks) and returns the
/// ball's velocity (m/s) as it leaves that touch; panics if he never touches it or if he ever
/// has it at his feet or in his hands first.
fn their_keepers_first_touch(game: &mut touchline_engine::Match) -> glam::Vec3 {
    for tick in 0..300 {
        game.tick();
        assert_ne!(game.owner(), Some((Side::Right, 0)), "tick {tick}: their keeper had the ball");
        if game.last_touch() == Some((Side::Right, 0)) {
            return game.ball().velocity;
        }
    }
    panic!("their keeper never touched the ball");
}

#[test]
fn a_keeper_runs_for_a_loose_ball_he_is_clearly_first_to_outside_his_area() {
    // GRF's team AI sends the quickest of all 22 to a loose ball, keeper or not. A slow ball lies
    // 15 m in front of their keeper, outside his area; his team-mates are 25 m from it, ours 40 m:
    // he goes and gets it (before, he stayed on his line while a team-mate was quicker to the
    // ball than any of ours).
    let mut env = outfield_lines(0.0, -15.0);
    let game = env.game_mut();
    game.place_player(Side::Right, 0, glam::Vec2::new(40.0, 0.0));
    game.place_ball(glam::Vec3::new(25.0, 0.0, 0.11), glam::Vec3::ZERO, None);
    let mut nearest = f32::INFINITY;
    for _ in 0..300 {
        game.tick();
        let keeper = game.team(Side::Right)[0].position;
        nearest = nearest.min(keeper.distance(game.ball().xy()));
    }
    assert!(nearest < 1.0, "their keeper came no nearer the ball than {nearest:.1} m");
}

#[test]
fn a_keeper_who_decides_to_clear_first_time_clears_though_he_has_time_by_the_touch() {
    // GRF's keeper picks his first-time clearance about a second from the ball, while the
    // opponent chasing it is near enough to make him panic, and the kick animation then plays
    // out. A pass runs at 6 m/s towards their keeper, who stands 6 m outside his area, with our
    // forward 5 m behind it: deciding again on the last tick, when he is on the ball and the
    // forward still about a second off, he stopped it instead.
    let mut env = outfield_lines(-10.0, -30.0);
    let game = env.game_mut();
    game.place_player(Side::Left, 10, glam::Vec2::new(17.0, 0.0));
    game.place_player(Side::Right, 0, glam::Vec2::new(30.0, 0.0));
    game.place_ball(glam::Vec3::new(22.0, 0.0, 0.11), glam::Vec3::new(6.0, 0.0, 0.0), Some((Side::Left, 10)));
    let speed = their_keepers_first_touch(game).length();
    assert!(speed > 15.0, "the clearance left at {speed:.1} m/s");
}

#[test]
fn a_keeper_coming_out_for_an_uncontested_ball_plays_it_first_time_upfield() {
    // academy_run_to_score_with_keeper's random agent shoots from halfway and the ball rolls into
    // their area with nobody of ours near. GRF's keeper runs out and passes it first time,
    // 25-31 m/s, to a team-mate upfield, and never shows as its owner (40 episodes, none ended
    // with him holding the ball): with no opponent near as quick to it (a possession amount of
    // 3.4 or more) he does not ask for his hands.
    let mut env = outfield_lines(5.0, -20.0);
    let game = env.game_mut();
    game.place_player(Side::Right, 0, glam::Vec2::new(50.0, 0.0));
    game.place_ball(glam::Vec3::new(28.0, 2.0, 0.11), glam::Vec3::new(9.0, 0.0, 0.0), Some((Side::Left, 10)));
    let v = their_keepers_first_touch(game);
    assert!(v.truncate().length() > 15.0 && v.x < 0.0, "played upfield first time: {v}");
}

/// The step at which an idle episode of `scenario` with engine seed `seed` ends, and whether it
/// ends with the opponents on the ball.
fn idle_episode_end(scenario: &str, seed: u64) -> (usize, bool) {
    let mut env = common::env(scenario, seed);
    for step in 1..=401 {
        let out = env.step(&[Action::Idle]).unwrap();
        if out.terminated || out.truncated {
            let theirs = env.game().observed_owner().is_some_and(|(side, _)| side == Side::Right);
            return (step, theirs);
        }
    }
    (401, false)
}

#[test]
fn a_defender_racing_back_takes_the_ball_off_an_idle_carrier_as_grfs_does() {
    // academy_counterattack_hard: our idle carrier has the ball; a defender races back at him.
    // GRF: every idle episode ends on a lost ball, after 53.9 steps on average (± 1.9). The
    // hunter runs at the ball, not goal-side of the carrier, and his knock is not his until his
    // tackle ends; aimed goal-side, touchline's hunter met the carrier's shoulder away from the
    // ball and the episodes ran to about 63 steps.
    let ends: Vec<(usize, bool)> = (0..8).map(|seed| idle_episode_end("academy_counterattack_hard", seed)).collect();
    assert!(ends.iter().all(|&(_, theirs)| theirs), "every episode ends on a lost ball: {ends:?}");
    let mean = ends.iter().map(|&(step, _)| step as f32).sum::<f32>() / ends.len() as f32;
    assert!(mean < 60.0, "ended after {mean:.1} steps on average: {ends:?}");
}
