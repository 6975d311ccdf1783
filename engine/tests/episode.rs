//! The episode loop against GRF's figures (docs/grf-compatibility.md#sticky-actions, #rewards,
//! #episode-length): steps_left, termination and truncation, sticky actions seen in each controller's frame,
//! Scoring and Checkpoint rewards, controlled-player switching, and errors.

mod common;

use touchline_engine::{Action, EngineError, Env, EnvConfig, Event, GameMode, Side};

#[test]
fn steps_left_and_the_time_limit_follow_grf() {
    // A 10-step game ends after 11 steps (docs/grf-compatibility.md#episode-length: the second-half test).
    let mut env = Env::new(common::empty_pitch(10), 0).unwrap();
    assert_eq!(env.observations()[0].steps_left, 11);
    assert_eq!(env.info().steps_left, 11);
    for k in 1..=11 {
        let out = env.step(&[Action::Idle]).unwrap();
        assert_eq!(env.observations()[0].steps_left, 11 - k);
        assert_eq!(out.truncated, k == 11, "step {k}");
        assert!(!out.terminated);
    }
    assert!(env.is_done());
    assert_eq!(env.step(&[Action::Idle]), Err(EngineError::EpisodeOver));
    // A reset starts again.
    env.reset().unwrap();
    assert_eq!(env.observations()[0].steps_left, 11);
    assert!(env.step(&[Action::Idle]).is_ok());
}

#[test]
fn academy_drills_start_with_401_steps_left() {
    let env = common::env("academy_empty_goal", 0);
    assert_eq!(env.observations()[0].steps_left, 401);
    let env = common::env("11_vs_11_stochastic", 0);
    assert_eq!(env.observations()[0].steps_left, 3001);
}

#[test]
fn bad_actions_are_errors_not_panics() {
    let mut env = common::env("academy_empty_goal_close", 0);
    assert_eq!(env.step(&[]), Err(EngineError::ActionCount { expected: 1, got: 0 }));
    assert!(matches!(env.step_indices(&[19]), Err(EngineError::UnknownAction { index: 19, .. })));
    assert!(env.step_indices(&[5]).is_ok());
    let config = EnvConfig { left_agents: 3, ..EnvConfig::default() };
    assert!(matches!(
        Env::with_config(common::scenario("academy_empty_goal"), config, 0),
        Err(EngineError::InvalidConfig { .. })
    ));
}

#[test]
fn sticky_actions_are_seen_in_each_controllers_frame() {
    // GRF test___control_all_players: 1 + 1 agents, actions [left, right].
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let mut env = Env::with_config(common::scenario("11_vs_11_stochastic"), config, 0).unwrap();
    assert_eq!(env.observations()[0].sticky_actions, [0; 10]);
    env.step(&[Action::Idle, Action::Idle]).unwrap();
    env.step(&[Action::Left, Action::Right]).unwrap();
    assert_eq!(env.observations()[0].sticky_actions[0], 1);
    assert_eq!(env.observations()[1].sticky_actions[4], 1);
    env.step(&[Action::Sprint, Action::Dribble]).unwrap();
    assert_eq!(env.observations()[0].sticky_actions, [1, 0, 0, 0, 0, 0, 0, 0, 1, 0]);
    assert_eq!(env.observations()[1].sticky_actions, [0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
    env.step(&[Action::ReleaseDirection, Action::ReleaseDribble]).unwrap();
    assert_eq!(env.observations()[0].sticky_actions, [0, 0, 0, 0, 0, 0, 0, 0, 1, 0]);
    assert_eq!(env.observations()[1].sticky_actions[..8], [0, 0, 0, 0, 1, 0, 0, 0]);
    // The right controller's "right" runs towards the left goal in the global frame.
    let right_active = env.observations()[1].active as usize;
    let v = env.game().team(touchline_engine::Side::Right)[right_active].velocity;
    assert!(v.x < -1.0, "velocity {v}");
}

#[test]
fn a_right_controller_sees_the_pitch_turned_by_180_degrees() {
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let mut env = Env::with_config(common::scenario("11_vs_11_stochastic"), config, 4).unwrap();
    for _ in 0..30 {
        env.step(&[Action::Right, Action::Right]).unwrap();
    }
    let (l, r) = (&env.observations()[0], &env.observations()[1]);
    for (a, b) in l.left_team.iter().zip(&r.right_team) {
        assert_eq!([a[0], a[1]], [-b[0], -b[1]]);
    }
    for (a, b) in l.right_team.iter().zip(&r.left_team) {
        assert_eq!([a[0], a[1]], [-b[0], -b[1]]);
    }
    assert_eq!([l.ball[0], l.ball[1], l.ball[2]], [-r.ball[0], -r.ball[1], r.ball[2]]);
    assert_eq!(l.score, [r.score[1], r.score[0]]);
    if l.ball_owned_team >= 0 {
        assert_eq!(l.ball_owned_team, 1 - r.ball_owned_team);
    }
}

#[test]
fn a_goal_is_worth_exactly_two_with_checkpoints() {
    let mut env = common::env_with_checkpoints("academy_empty_goal_close", 0);
    let mut rewards = Vec::new();
    let (_, total) = common::play(&mut env, |k, _| if k < 8 { Action::Right } else { Action::Shot });
    rewards.push(total);
    assert_eq!(env.info().score, [1, 0]);
    assert!((total - 2.0).abs() < 1e-4, "total {total}");
    assert_eq!(env.info().score_reward, 1.0);
}

#[test]
fn checkpoints_pay_as_the_ball_is_carried_towards_goal() {
    // GRF test_get_state_wrapper: in academy_empty_goal, stepping right, the reward sum reaches
    // 0.9 in 0.1 increments before the goal.
    let mut env = common::env_with_checkpoints("academy_empty_goal", 0);
    let mut sum = 0.0f32;
    let mut steps = 0;
    while sum < 0.85 {
        let out = env.step(&[Action::Right]).unwrap();
        let r = env.rewards()[0];
        assert!(r.abs() < 1e-6 || (r - 0.1).abs() < 1e-4 || (r - 0.2).abs() < 1e-4, "reward {r}");
        sum += r;
        steps += 1;
        assert!(!out.terminated && steps < 200, "ended before 0.9: sum {sum}");
    }
    assert!((sum - 0.9).abs() < 0.01, "sum {sum}");
    assert_eq!(env.info().score, [0, 0]);
}

#[test]
fn running_right_scores_in_the_empty_goal() {
    // GRF test_score_empty_goal: ball and controlled player never fall back by more than 0.01 per
    // step, and the episode ends with reward 1.
    let mut env = common::env("academy_empty_goal", 0);
    let mut last = (env.observations()[0].ball[0], env.observations()[0].left_team[1][0]);
    for step in 0..120 {
        let out = env.step(&[Action::Right]).unwrap();
        let o = &env.observations()[0];
        let now = (o.ball[0], o.left_team[o.active as usize][0]);
        if !out.terminated {
            assert!(now.0 >= last.0 - 0.01 && now.1 >= last.1 - 0.01, "step {step}: {last:?} -> {now:?}");
        }
        last = now;
        if out.terminated {
            assert_eq!(env.rewards()[0], 1.0);
            return;
        }
    }
    panic!("no goal in 120 steps");
}

#[test]
fn out_of_play_ends_an_academy_episode() {
    // Run the ball over the bottom touchline.
    let mut env = common::env("academy_empty_goal_close", 0);
    let (steps, reward) = common::play(&mut env, |_, _| Action::Bottom);
    assert!(steps < 100);
    assert_eq!(reward, 0.0);
    assert_eq!(env.info().game_mode, GameMode::ThrowIn);
}

#[test]
fn single_agent_control_goes_to_the_keeper_only_with_a_pass_meant_for_him() {
    let mut env = common::env("11_vs_11_easy_stochastic", 2);
    let mut policy = common::RandomPolicy::new(9);
    let mut switches = 0;
    let mut last = env.observations()[0].active;
    for _ in 0..1500 {
        let out = env.step(&[policy.action(env.action_set())]).unwrap();
        let o = &env.observations()[0];
        if o.active == 0 && last != 0 {
            let to_keeper =
                env.game().events().iter().any(|e| matches!(e, Event::Pass { side: Side::Left, to: Some(0), .. }));
            assert!(to_keeper, "the keeper (index 0) was selected without a pass meant for him");
        }
        assert_eq!(o.designated, o.active);
        if o.active != last {
            switches += 1;
        }
        last = o.active;
        // The carrier the engine gave the ball to. (The observation also names as owner the last
        // toucher while the loose ball is at his feet, GRF's possession test; control may stay
        // with the team-mate quickest to it until someone takes it.)
        if let Some((Side::Left, carrier)) = env.game().owner()
            && carrier != 0
        {
            assert_eq!(o.active as usize, carrier, "control goes to our ball carrier");
        }
        if out.truncated {
            break;
        }
    }
    assert!(switches > 5, "control should follow the ball ({switches} switches)");
}

#[test]
fn a_pass_hands_control_to_the_team_mate_it_is_meant_for_the_keeper_too() {
    // academy_empty_goal: our CB on the centre spot, our keeper the only team-mate. GRF 2.10
    // (measured): the pass goes back to the keeper and control goes with it as it is played.
    let mut env = common::env("academy_empty_goal", 1);
    for _ in 0..5 {
        env.step(&[Action::Idle]).unwrap();
    }
    for step in 0..20 {
        env.step(&[Action::ShortPass]).unwrap();
        let passed = env.game().events().iter().any(|e| matches!(e, Event::Pass { side: Side::Left, to: Some(0), .. }));
        assert_eq!(env.observations()[0].active == 0, passed, "step {step}: control goes with the pass, not before");
        if passed {
            return;
        }
    }
    panic!("no pass in 20 steps");
}

#[test]
fn the_agents_player_first_to_a_loose_ball_runs_to_it_whatever_his_stick_says() {
    // academy_empty_goal: our CB shoots from the centre spot and then holds the stick towards his
    // own goal. He is the first to the ball, so GRF's magnet runs him after it (GRF 2.10,
    // measured: after a shot that stops short of the line he runs 45 m after it).
    let mut env = common::env("academy_empty_goal", 1);
    for _ in 0..5 {
        env.step(&[Action::Idle]).unwrap();
    }
    env.step(&[Action::Shot]).unwrap();
    let x = env.observations()[0].left_team[1][0];
    for _ in 0..20 {
        env.step(&[Action::Left]).unwrap();
    }
    let o = &env.observations()[0];
    assert_eq!(o.ball_owned_team, -1);
    assert!(o.left_team[1][0] > x + 0.1, "he runs after the ball: x {x} -> {}", o.left_team[1][0]);
}

#[test]
fn every_controllable_player_has_a_fixed_controller_when_all_are_controlled() {
    let config = EnvConfig { left_agents: 11, ..EnvConfig::default() };
    let mut env = Env::with_config(common::scenario("11_vs_11_stochastic"), config, 0).unwrap();
    assert_eq!(env.num_controllers(), 11);
    let expected: Vec<usize> = (0..11).collect();
    for _ in 0..50 {
        env.step(&[Action::Right; 11]).unwrap();
        assert_eq!(env.controlled_players(), &expected[..]);
        for (i, o) in env.observations().iter().enumerate() {
            assert_eq!(o.active, i as i32);
        }
    }
}

#[test]
fn a_player_control_switches_away_from_goes_back_to_the_ai() {
    // One left agent in a full match: control follows the ball (GRF), and the player it leaves is
    // played by the built-in AI again instead of running on with the agent's last input.
    let mut env = Env::new(common::scenario("11_vs_11_stochastic"), 0).unwrap();
    let mut switches = 0;
    for _ in 0..600 {
        let before = env.controlled_players()[0];
        env.step(&[Action::TopRight]).unwrap();
        let now = env.controlled_players()[0];
        if now != before {
            switches += 1;
            // The next step releases the player left behind (and drives `now`).
            env.step(&[Action::TopRight]).unwrap();
            let game = env.game();
            for i in (0..game.team(Side::Left).len()).filter(|&i| i != now) {
                assert!(!game.is_agent_driven(Side::Left, i), "left player {i} still follows the agent");
            }
        }
        if env.is_done() {
            break;
        }
    }
    assert!(switches > 0, "control never switched");
}

#[test]
fn builtin_ai_hands_the_player_to_the_ai_until_another_action() {
    let config = EnvConfig { action_set: touchline_engine::ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(common::scenario("academy_empty_goal_close"), config, 0).unwrap();
    // Built-in AI scores in the empty goal.
    let (steps, reward) = common::play(&mut env, |_, _| Action::BuiltinAi);
    assert_eq!(reward, 1.0, "after {steps} steps");
    assert_eq!(env.step_indices(&[19]), Err(EngineError::EpisodeOver));
}

#[test]
fn an_agent_that_stalls_at_a_set_piece_is_made_to_play_it() {
    // GRF's anti-stalling rule (docs/grf-compatibility.md#action-effects): after 20 steps waiting, the
    // agent's action becomes short_pass, so a throw-in that the agent's player takes is played at last.
    let mut env = Env::new(common::scenario("11_vs_11_stochastic"), 2).unwrap();
    env.game_mut().place_ball(
        glam::Vec3::new(-20.0, -35.9, 0.11),
        glam::Vec3::new(0.0, -5.0, 0.0),
        Some((touchline_engine::Side::Right, 4)),
    );
    env.step(&[Action::Idle]).unwrap();
    assert_eq!(env.info().game_mode, GameMode::ThrowIn);
    let o = &env.observations()[0];
    assert_eq!(o.ball_owned_team, 0);
    assert_eq!(o.active, o.ball_owned_player, "our agent takes the throw-in");
    let mut waited = 1;
    while env.info().game_mode == GameMode::ThrowIn {
        env.step(&[Action::Idle]).unwrap();
        waited += 1;
        assert!(waited <= 24, "still waiting after {waited} steps");
    }
    // The forced short pass is pressed at the 21st step; the throw goes when the button is
    // released at the next step, after the taker's wind-up.
    assert!((22..=24).contains(&waited), "the throw-in is taken {waited} steps in, not just after the forced pass");
}

#[test]
fn the_taker_of_a_placed_ball_is_not_made_to_run_and_keeps_no_held_direction() {
    // GRF's anti-stalling rule makes the agent's ball owner run, reading the owner off the
    // observation; a ball placed for a free kick is nobody's there (docs/grf-compatibility.md#raw-observation).
    // So an idle agent's taker plays the forced short pass and the controller holds no direction
    // afterwards: were he made to run, the held "right" would drive every later carrier at goal.
    use touchline_engine::scenario::StartRestart;
    use touchline_engine::{PlayerEntry, Role, Scenario};
    let s = Scenario {
        name: "free_kick_drill".into(),
        game_duration: 200,
        left_team: vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            PlayerEntry::new(Role::CB, -0.5, 0.0),
            PlayerEntry::new(Role::CM, -0.2, 0.1),
        ],
        right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CF, 0.3, 0.0)],
        start_with: Some(StartRestart { mode: GameMode::FreeKick, team: Side::Left, at: Some([-0.5, 0.0]) }),
        ..Scenario::default()
    };
    for seed in 0..3 {
        let mut env = Env::new(s.clone(), seed).unwrap();
        let mut steps = 0;
        while env.info().game_mode == GameMode::FreeKick {
            env.step(&[Action::Idle]).unwrap();
            steps += 1;
            let o = &env.observations()[0];
            assert_eq!(o.sticky_actions, [0; 10], "seed {seed}: a direction held at step {steps}");
            assert!(steps <= 30, "seed {seed}: the free kick is still not taken");
        }
        assert!(steps > 20, "seed {seed}: taken at step {steps}, before the forced pass");
        for _ in 0..20 {
            env.step(&[Action::Idle]).unwrap();
            assert_eq!(
                env.observations()[0].sticky_actions,
                [0; 10],
                "seed {seed}: a direction held after the restart"
            );
        }
    }
}

/// How far (m) our CB, an agent's player with his stick idle, moves towards a ball lying between
/// him and an opponent's CB `opponent_x` m from it, in half a second.
fn idle_run_towards_a_loose_ball(opponent_x: f32) -> f32 {
    use touchline_engine::game::PlayerInput;
    use touchline_engine::{Match, PlayerEntry, Role, Scenario};
    let mut left_gk = PlayerEntry::new(Role::GK, -1.0, 0.0);
    left_gk.lazy = true;
    let mut right_gk = PlayerEntry::new(Role::GK, 1.0, 0.0);
    right_gk.lazy = true;
    let s = Scenario {
        name: "loose_ball".into(),
        left_team: vec![left_gk, PlayerEntry::new(Role::CB, -0.5, 0.0)],
        right_team: vec![right_gk, PlayerEntry::new(Role::CB, 0.5, 0.0)],
        ball_position: [0.0, 0.3],
        ..Scenario::default()
    };
    let mut game = Match::new(&s, 0, 1);
    game.place_player(Side::Left, 1, glam::Vec2::new(-10.0, 0.0));
    game.place_player(Side::Right, 1, glam::Vec2::new(opponent_x, 0.0));
    game.place_ball(glam::Vec3::new(0.0, 0.0, 0.11), glam::Vec3::ZERO, None);
    game.set_agent_input(Side::Left, 1, Some(PlayerInput::default()));
    for _ in 0..50 {
        game.tick();
    }
    assert_eq!(game.mode(), GameMode::Normal);
    game.team(Side::Left)[1].position.x + 10.0
}

#[test]
fn the_agents_player_second_to_a_loose_ball_is_pulled_to_it_in_part_only_while_the_race_is_close() {
    // GRF's magnet also pulls his team's first to the ball when an opponent is first, by
    // sqrt(2·(p − 0.5)) for a possession amount p = (t_opponent + 0.2) / (t_his + 0.2) above one
    // half: 10 m from the ball against an opponent 8 m from it (p ≈ 0.83) he sets off with his
    // stick idle; against one 3 m from it (p ≈ 0.4) he stays.
    let close = idle_run_towards_a_loose_ball(8.0);
    let lost = idle_run_towards_a_loose_ball(3.0);
    assert!(close > 0.5, "a close race: he ran {close} m");
    assert!(lost.abs() < 0.1, "a lost race: he moved {lost} m");
}
