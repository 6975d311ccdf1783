//! How the ball is won and how keepers play, against GRF's measured behaviour (issue 15): a
//! defender at a carrier's back does not get to the ball; a keeper with no team-mate covering rushes
//! out at a carrier; in his own area he takes a dribbled ball with his hands and, alone, clears it
//! the way he faces; two bodies on one spot part instead of drifting along together.

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
fn a_keeper_with_no_team_mate_rushes_out_and_clears_the_way_he_faces() {
    // academy_empty_goal_close: the right keeper starts at OUR goal (GRF's layout). GRF: he sprints
    // up the pitch, takes the ball from our idle CB inside his own area at about step 134, and his
    // clearance along the way he ran goes over his own goal line: a corner for us at about 151.
    let mut env = common::env("academy_empty_goal_close", 2);
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
    assert!(keeper - start > 80.0, "the keeper went from x = {start} to {keeper}");
    assert!(held, "the keeper took the ball");
    assert!((120..200).contains(&steps), "ended after {steps} steps");
    assert_eq!(env.info().score, [0, 0]);
    assert_ne!(env.info().game_mode, GameMode::Normal, "the episode ends with the ball out of play");
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
