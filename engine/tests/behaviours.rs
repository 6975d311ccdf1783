//! Native behaviours do what they say: scenarios built in Rust, played through the env with no
//! agents (or one, for the override), checked on positions, events and possession.

use glam::Vec2;
use touchline_engine::geometry::coords::obs_to_world;
use touchline_engine::scenario::{Behaviour, Comparison, Condition, PassKind, Stage, Target};
use touchline_engine::{Action, Env, EnvConfig, Event, GameMode, Match, PlayerEntry, Role, Scenario, Side};

fn stage(behaviour: Behaviour) -> Stage {
    Stage { behaviour, until: None }
}

fn with(mut entry: PlayerEntry, stages: Vec<Stage>) -> PlayerEntry {
    entry.behaviour = stages;
    entry
}

fn lazy(mut entry: PlayerEntry) -> PlayerEntry {
    entry.lazy = true;
    entry
}

fn keeper() -> PlayerEntry {
    lazy(PlayerEntry::new(Role::GK, -1.0, 0.0))
}

fn scenario(left: Vec<PlayerEntry>, right: Vec<PlayerEntry>, ball: [f32; 2]) -> Scenario {
    Scenario { left_team: left, right_team: right, ball_position: ball, game_duration: 400, ..Scenario::default() }
}

/// An env with no agents: everyone is played by behaviours or the built-in AI.
fn env(s: Scenario, seed: u64) -> Env {
    Env::with_config(s, EnvConfig { left_agents: 0, ..EnvConfig::default() }, seed).unwrap()
}

fn player(env: &Env, side: Side, i: usize) -> Vec2 {
    env.game().team(side)[i].position
}

/// A point of a team's frame (normalised observation units) in metres, global frame.
fn at(side: Side, x: f32, y: f32) -> Vec2 {
    obs_to_world(x, y) * side.attack_sign()
}

#[test]
fn move_to_arrives_and_finishes() {
    let s = scenario(
        vec![
            keeper(),
            with(PlayerEntry::new(Role::CB, -0.5, 0.0), vec![stage(Behaviour::MoveTo { point: [0.0, 0.2] })]),
        ],
        vec![
            keeper(),
            with(PlayerEntry::new(Role::CB, -0.5, 0.0), vec![stage(Behaviour::MoveTo { point: [0.1, -0.2] })]),
        ],
        [0.0, 0.38],
    );
    let mut env = env(s, 1);
    for _ in 0..120 {
        env.step(&[]).unwrap();
    }
    assert!(player(&env, Side::Left, 1).distance(at(Side::Left, 0.0, 0.2)) < 0.6);
    assert!(player(&env, Side::Right, 1).distance(at(Side::Right, 0.1, -0.2)) < 0.6);
    assert_eq!(env.game().behaviour_stage(Side::Left, 1), Some((0, true)));
    assert_eq!(env.game().behaviour_stage(Side::Left, 0), None);
}

#[test]
fn dribble_to_then_shoot_shoots() {
    let dribbler = with(
        PlayerEntry::new(Role::CF, 0.45, 0.0),
        vec![stage(Behaviour::DribbleTo { point: [0.75, 0.05], shoot: true })],
    );
    let s = scenario(vec![keeper(), dribbler], vec![keeper()], [0.46, 0.0]);
    for seed in 0..3 {
        let mut env = env(s.clone(), seed);
        let mut shot = false;
        for _ in 0..150 {
            env.step(&[]).unwrap();
            shot |= env.game().events().iter().any(|e| matches!(e, Event::Shot { side: Side::Left, player: 1, .. }));
            if shot {
                break;
            }
        }
        assert!(shot, "seed {seed}: no shot");
        let x = player(&env, Side::Left, 1).x;
        assert!(x > at(Side::Left, 0.75, 0.0).x - 2.5, "seed {seed}: shot from x = {x}");
        assert_eq!(env.game().behaviour_stage(Side::Left, 1), Some((0, true)));
    }
}

#[test]
fn pass_to_reaches_the_team_mate() {
    let passer =
        with(PlayerEntry::new(Role::CM, 0.0, 0.0), vec![stage(Behaviour::PassTo { player: 2, kind: PassKind::Short })]);
    // The receiver plays for the ball as the built-in AI does: GRF's pass over 18 m leaves at
    // 22 m/s, too fast for a man standing still to trap.
    let receiver = with(PlayerEntry::new(Role::CF, 0.25, 0.15), vec![stage(Behaviour::Builtin { difficulty: None })]);
    let decoy = with(PlayerEntry::new(Role::LM, 0.1, -0.3), vec![stage(Behaviour::Idle)]);
    let s = Scenario {
        deterministic: true,
        ..scenario(vec![keeper(), passer, receiver, decoy], vec![keeper()], [0.01, 0.0])
    };
    let mut env = env(s, 0);
    let (mut passed, mut received) = (false, false);
    for _ in 0..80 {
        env.step(&[]).unwrap();
        passed |= env.game().events().iter().any(|e| matches!(e, Event::Pass { side: Side::Left, player: 1, .. }));
        if passed && env.game().owner() == Some((Side::Left, 2)) {
            received = true;
            break;
        }
    }
    assert!(passed && received, "passed {passed}, received {received}");
}

#[test]
fn follow_keeps_close() {
    // The leader runs across the pitch; the follower (the faster team, θ 1) stays with him.
    let leader = with(PlayerEntry::new(Role::CF, -0.1, 0.0), vec![stage(Behaviour::MoveTo { point: [0.6, 0.3] })]);
    let follower = with(PlayerEntry::new(Role::CB, 0.05, 0.02), vec![stage(Behaviour::Follow(Target::Right(1)))]);
    let s = scenario(vec![keeper(), follower], vec![keeper(), leader], [0.0, -0.4]);
    let mut env = env(s, 3);
    for k in 0..100 {
        env.step(&[]).unwrap();
        let d = player(&env, Side::Left, 1).distance(player(&env, Side::Right, 1));
        assert!(d < 4.0, "step {k}: {d} m behind");
    }
}

#[test]
fn mark_stays_goal_side() {
    // The right forward runs at the left goal; the left marker keeps between him and it.
    let man = with(PlayerEntry::new(Role::CF, -0.1, 0.1), vec![stage(Behaviour::MoveTo { point: [0.75, -0.1] })]);
    let marker = with(PlayerEntry::new(Role::CB, -0.45, -0.05), vec![stage(Behaviour::Mark(Target::Right(1)))]);
    let s = scenario(vec![keeper(), marker], vec![keeper(), man], [0.0, 0.4]);
    let mut env = env(s, 2);
    for k in 0..90 {
        env.step(&[]).unwrap();
        let (m, o) = (player(&env, Side::Left, 1), player(&env, Side::Right, 1));
        // Once he has met his man (they run at each other at first).
        if k >= 40 {
            // Goal-side: nearer the left goal (x = -55) than his man, and close.
            assert!(m.x < o.x, "step {k}: marker {m} not goal-side of {o}");
            assert!(m.distance(o) < 4.0, "step {k}: marker {m} far from {o}");
        }
    }
}

#[test]
fn press_wins_the_ball_from_a_lazy_carrier() {
    let carrier = lazy(PlayerEntry::new(Role::CF, 0.0, 0.0));
    let presser = with(PlayerEntry::new(Role::CB, -0.3, 0.1), vec![stage(Behaviour::Press)]);
    // The ball at the right forward's feet (right frame x = 0 is global 0).
    let s = scenario(vec![keeper(), presser], vec![keeper(), carrier], [-0.01, 0.0]);
    let mut won = 0;
    for seed in 0..8 {
        let mut env = env(s.clone(), seed);
        for _ in 0..150 {
            env.step(&[]).unwrap();
            if env.game().owner() == Some((Side::Left, 1)) {
                won += 1;
                break;
            }
        }
    }
    assert!(won >= 2, "the presser won the ball in {won} of 8 seeds");
}

#[test]
fn hold_position_returns_after_being_displaced() {
    let holder = with(PlayerEntry::new(Role::CB, -0.5, 0.1), vec![stage(Behaviour::HoldPosition)]);
    let s = scenario(vec![keeper(), holder], vec![keeper()], [0.3, -0.3]);
    let mut env = env(s, 4);
    let home = player(&env, Side::Left, 1);
    for _ in 0..10 {
        env.step(&[]).unwrap();
    }
    assert!(player(&env, Side::Left, 1).distance(home) < 0.2);
    env.game_mut().place_player(Side::Left, 1, home + Vec2::new(9.0, -4.0));
    for _ in 0..50 {
        env.step(&[]).unwrap();
    }
    assert!(player(&env, Side::Left, 1).distance(home) < 0.3, "{} vs {home}", player(&env, Side::Left, 1));
}

#[test]
fn idle_stands() {
    let idler = with(PlayerEntry::new(Role::CB, -0.5, 0.1), vec![stage(Behaviour::Idle)]);
    let runner = with(PlayerEntry::new(Role::CF, -0.2, 0.0), vec![stage(Behaviour::Follow(Target::Ball))]);
    let s = scenario(vec![keeper(), idler, runner], vec![keeper()], [0.2, -0.2]);
    let mut env = env(s, 5);
    let start = player(&env, Side::Left, 1);
    for _ in 0..60 {
        env.step(&[]).unwrap();
    }
    assert_eq!(player(&env, Side::Left, 1), start);
    assert!(player(&env, Side::Left, 2).distance(env.game().ball().xy()) < 2.5);
}

#[test]
fn builtin_plays_at_its_own_theta() {
    let make = |theta: Option<f32>| {
        let cf = with(PlayerEntry::new(Role::CF, 0.3, 0.0), vec![stage(Behaviour::Builtin { difficulty: theta })]);
        Scenario {
            left_team_difficulty: 1.0,
            ..scenario(vec![keeper(), cf], vec![PlayerEntry::new(Role::GK, -1.0, 0.0)], [0.32, 0.0])
        }
    };
    let team = env(make(None), 1);
    let slow = env(make(Some(0.0)), 1);
    let (fast_speed, slow_speed) =
        (team.game().team(Side::Left)[1].max_speed, slow.game().team(Side::Left)[1].max_speed);
    assert!(slow_speed < fast_speed, "θ 0 top speed {slow_speed} vs the team's {fast_speed}");
    // Handed to the AI, the forward plays: he takes the ball on and shoots within the episode
    // (400 steps; at θ 0 the keeper comes out and wins his first run).
    for mut env in [team, slow] {
        let mut shots = 0;
        for _ in 0..1000 {
            if env.step(&[]).unwrap().truncated {
                break;
            }
            shots += env.game().events().iter().filter(|e| matches!(e, Event::Shot { side: Side::Left, .. })).count();
        }
        assert!(shots > 0);
    }
}

#[test]
fn builtin_without_theta_everywhere_is_the_built_in_ai_bit_for_bit() {
    let base = scenario(
        vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            PlayerEntry::new(Role::CB, -0.5, 0.1),
            PlayerEntry::new(Role::CF, 0.0, 0.0),
        ],
        vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            PlayerEntry::new(Role::CB, -0.5, -0.1),
            PlayerEntry::new(Role::CM, -0.1, 0.0),
        ],
        [0.0, 0.0],
    );
    let mut handed = base.clone();
    for p in handed.left_team.iter_mut().chain(&mut handed.right_team) {
        p.behaviour = vec![stage(Behaviour::Builtin { difficulty: None })];
    }
    let (mut a, mut b) = (env(base, 9), env(handed, 9));
    for _ in 0..300 {
        let (x, y) = (a.step(&[]).unwrap(), b.step(&[]).unwrap());
        assert_eq!(x, y);
        assert_eq!(a.game().state_hash(), b.game().state_hash());
        if x.terminated || x.truncated {
            break;
        }
    }
}

#[test]
fn until_steps_switches_at_the_right_step() {
    let s = scenario(
        vec![
            keeper(),
            with(
                PlayerEntry::new(Role::CB, -0.5, 0.0),
                vec![
                    Stage {
                        behaviour: Behaviour::Idle,
                        until: Some(Condition::Steps { op: Comparison::Ge, steps: 20 }),
                    },
                    stage(Behaviour::MoveTo { point: [0.0, 0.0] }),
                ],
            ),
        ],
        vec![keeper()],
        [0.3, 0.3],
    );
    let mut env = env(s, 1);
    let start = player(&env, Side::Left, 1);
    for _ in 0..20 {
        env.step(&[]).unwrap();
    }
    assert_eq!(env.game().behaviour_stage(Side::Left, 1), Some((0, false)));
    assert_eq!(player(&env, Side::Left, 1), start);
    env.step(&[]).unwrap();
    assert_eq!(env.game().behaviour_stage(Side::Left, 1), Some((1, false)));
    assert!(env.game().team(Side::Left)[1].velocity.x > 0.3);
}

#[test]
fn until_distance_switches_on_the_first_tick_it_holds() {
    let near = Condition::Distance { a: Target::Ball, b: Target::Me, op: Comparison::Lt, metres: 3.0 };
    let s = scenario(
        vec![
            keeper(),
            with(
                PlayerEntry::new(Role::CB, -0.5, 0.0),
                vec![Stage { behaviour: Behaviour::Idle, until: Some(near) }, stage(Behaviour::Press)],
            ),
        ],
        vec![keeper()],
        [0.0, 0.0],
    );
    let mut game = Match::new(&s, 0, 1);
    let me = game.team(Side::Left)[1].position;
    game.place_ball(glam::Vec3::new(me.x + 15.0, me.y, 0.11), glam::Vec3::new(-11.0, 0.0, 0.0), None);
    let mut before = game.ball().xy().distance(me);
    for tick in 0..300 {
        game.tick();
        let stage = game.behaviour_stage(Side::Left, 1).unwrap().0;
        let now = game.ball().xy().distance(game.team(Side::Left)[1].position);
        if stage == 1 {
            // The tick that switched started with the ball under 3 m; the one before did not.
            assert!(before < 3.0, "tick {tick}: switched at {before} m");
            return;
        }
        assert!(before >= 3.0, "tick {tick}: not switched at {before} m");
        before = now;
    }
    panic!("never switched");
}

#[test]
fn set_pieces_taken_by_behaviour_players_go_on() {
    // Every right player idles; the ball goes out off the left team: the right team's throw-in
    // is taken by the AI's set-piece logic for the idle taker, and play resumes.
    let right = vec![
        with(PlayerEntry::new(Role::GK, -1.0, 0.0), vec![stage(Behaviour::Idle)]),
        with(PlayerEntry::new(Role::CB, -0.2, -0.3), vec![stage(Behaviour::Idle)]),
        with(PlayerEntry::new(Role::CM, 0.0, 0.1), vec![stage(Behaviour::Idle)]),
    ];
    let s = scenario(vec![keeper(), lazy(PlayerEntry::new(Role::CB, -0.2, 0.0))], right, [0.0, 0.0]);
    let mut env = env(s, 2);
    env.game_mut().place_ball(glam::Vec3::new(5.0, 30.0, 0.11), glam::Vec3::new(0.0, 12.0, 0.0), Some((Side::Left, 1)));
    let mut set_piece = false;
    for _ in 0..200 {
        env.step(&[]).unwrap();
        if env.game().mode() == GameMode::ThrowIn {
            set_piece = true;
        }
        if set_piece && env.game().mode() == GameMode::Normal {
            return;
        }
    }
    panic!("set piece {set_piece}, still {:?}", env.game().mode());
}

#[test]
fn agents_override_behaviours() {
    // The left agent drives the only controllable player, who would otherwise idle.
    let idler = with(PlayerEntry::new(Role::CB, -0.5, 0.0), vec![stage(Behaviour::Idle)]);
    let s = scenario(vec![lazy(PlayerEntry { controllable: false, ..keeper() }), idler], vec![keeper()], [0.5, 0.3]);
    let mut env = Env::new(s, 1).unwrap();
    let start = player(&env, Side::Left, 1);
    for _ in 0..10 {
        env.step(&[Action::Right]).unwrap();
    }
    assert!(player(&env, Side::Left, 1).x > start.x + 3.0);
}

#[test]
fn lazy_wins_over_a_behaviour() {
    let mover = lazy(with(PlayerEntry::new(Role::CB, -0.5, 0.0), vec![stage(Behaviour::MoveTo { point: [0.5, 0.0] })]));
    let s = scenario(vec![keeper(), mover], vec![keeper()], [0.3, 0.3]);
    let mut env = env(s, 1);
    let start = player(&env, Side::Left, 1);
    for _ in 0..30 {
        env.step(&[]).unwrap();
    }
    assert_eq!(player(&env, Side::Left, 1), start);
}
