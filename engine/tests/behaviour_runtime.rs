//! The machinery around behaviours: `end when` conditions, validation, determinism and
//! snapshots of behaviour state, and script behaviours through the env's hooks.

use touchline_engine::scenario::{
    Behaviour, Comparison, Condition, EndCondition, Owner, PassKind, Region, Stage, Target,
};
use touchline_engine::{
    Action, EngineError, Env, EnvConfig, HookOutcome, HookView, Hooks, PlayerEntry, Role, Scenario, Side, Snapshot,
};

fn stage(behaviour: Behaviour) -> Stage {
    Stage { behaviour, until: None }
}

fn with(mut entry: PlayerEntry, stages: Vec<Stage>) -> PlayerEntry {
    entry.behaviour = stages;
    entry
}

fn keeper() -> PlayerEntry {
    PlayerEntry { lazy: true, ..PlayerEntry::new(Role::GK, -1.0, 0.0) }
}

fn config() -> EnvConfig {
    EnvConfig { left_agents: 0, ..EnvConfig::default() }
}

/// A small game where every outfield player has a behaviour: a dribbler who then passes, a
/// presser, a marker, a holder.
fn busy() -> Scenario {
    Scenario {
        left_team: vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            with(
                PlayerEntry::new(Role::CF, 0.0, 0.0),
                vec![
                    Stage {
                        behaviour: Behaviour::DribbleTo { point: [0.5, 0.1], shoot: false },
                        until: Some(Condition::Any(vec![
                            Condition::Done,
                            Condition::Steps { op: Comparison::Ge, steps: 60 },
                        ])),
                    },
                    stage(Behaviour::PassTo { player: 2, kind: PassKind::Long }),
                    stage(Behaviour::Follow(Target::Ball)),
                ],
            ),
            with(PlayerEntry::new(Role::LM, 0.2, -0.3), vec![stage(Behaviour::HoldPosition)]),
        ],
        right_team: vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            with(PlayerEntry::new(Role::CM, -0.2, 0.0), vec![stage(Behaviour::Press)]),
            with(PlayerEntry::new(Role::CB, -0.5, 0.2), vec![stage(Behaviour::Mark(Target::Left(2)))]),
        ],
        ball_position: [0.01, 0.0],
        game_duration: 300,
        ..Scenario::default()
    }
}

fn hashes(mut env: Env, steps: usize) -> Vec<u64> {
    let mut out = Vec::new();
    for _ in 0..steps {
        let o = env.step(&[]).unwrap();
        out.push(env.game().state_hash());
        if o.terminated || o.truncated {
            env.reset().unwrap();
        }
    }
    out
}

#[test]
fn same_seed_same_trajectory_with_behaviours() {
    let a = hashes(Env::with_config(busy(), config(), 11).unwrap(), 400);
    let b = hashes(Env::with_config(busy(), config(), 11).unwrap(), 400);
    assert_eq!(a, b);
    let c = hashes(Env::with_config(busy(), config(), 12).unwrap(), 400);
    assert_ne!(a, c);
}

#[test]
fn snapshots_keep_the_behaviour_state() {
    let mut env = Env::with_config(busy(), config(), 3).unwrap();
    for _ in 0..70 {
        env.step(&[]).unwrap();
    }
    let stage = env.game().behaviour_stage(Side::Left, 1);
    let bytes = env.snapshot().to_bytes();
    let after: Vec<u64> = (0..100)
        .map(|_| {
            env.step(&[]).unwrap();
            env.game().state_hash()
        })
        .collect();
    let mut other = Env::with_config(busy(), config(), 99).unwrap();
    other.restore(&Snapshot::from_bytes(&bytes).unwrap()).unwrap();
    assert_eq!(other.game().behaviour_stage(Side::Left, 1), stage);
    for (k, h) in after.iter().enumerate() {
        other.step(&[]).unwrap();
        assert_eq!(other.game().state_hash(), *h, "step {k} after the restore");
    }
}

#[test]
fn end_when_conditions_terminate() {
    // Ends when the presser has the ball or the dribbler reaches the right third.
    let when = Condition::Any(vec![
        Condition::Owner(Owner::Team(Side::Right)),
        Condition::In { what: Target::Left(1), region: Region::Rect { x: [0.33, 1.0], y: [-0.42, 0.42] } },
    ]);
    let s = Scenario { end_when: vec![EndCondition::When(when)], ..busy() };
    let mut env = Env::with_config(s, config(), 5).unwrap();
    for k in 0..300 {
        let out = env.step(&[]).unwrap();
        let g = env.game();
        let holds = g.owner().is_some_and(|o| o.0 == Side::Right)
            || touchline_engine::geometry::coords::world_to_obs(g.team(Side::Left)[1].position)[0] >= 0.33;
        assert_eq!(out.terminated, holds, "step {k}");
        if out.terminated {
            return;
        }
    }
    panic!("never terminated");
}

#[test]
fn validation_names_bad_behaviours_and_conditions() {
    let bad = |s: Scenario| Env::with_config(s, config(), 1).unwrap_err().to_string();
    let mut s = busy();
    s.left_team[1].behaviour = vec![stage(Behaviour::PassTo { player: 1, kind: PassKind::Short })];
    assert!(bad(s).contains("cannot pass to himself"));
    let mut s = busy();
    s.left_team[1].behaviour = vec![stage(Behaviour::PassTo { player: 5, kind: PassKind::Short })];
    assert!(bad(s).contains("team-mate 5"));
    let mut s = busy();
    s.right_team[2].behaviour = vec![stage(Behaviour::Mark(Target::Left(3)))];
    assert!(bad(s).contains("left player 3 does not exist"));
    let mut s = busy();
    s.right_team[2].behaviour = vec![stage(Behaviour::Mark(Target::Ball))];
    assert!(bad(s).contains("mark needs a player"));
    let mut s = busy();
    s.left_team[2].behaviour = vec![stage(Behaviour::MoveTo { point: [2.0, 0.0] })];
    assert!(bad(s).contains("off the pitch"));
    let mut s = busy();
    s.left_team[2].behaviour = vec![stage(Behaviour::Builtin { difficulty: Some(1.5) })];
    assert!(bad(s).contains("outside [0, 1]"));
    let mut s = busy();
    s.left_team[2].behaviour = vec![Stage {
        behaviour: Behaviour::Idle,
        until: Some(Condition::In { what: Target::Me, region: Region::Circle { x: 0.0, y: 0.0, r: -1.0 } }),
    }];
    assert!(bad(s).contains("radius"));
    let mut s = busy();
    s.end_when = vec![EndCondition::When(Condition::Distance {
        a: Target::Me,
        b: Target::Ball,
        op: Comparison::Lt,
        metres: 1.0,
    })];
    assert!(bad(s).contains("`me`"));
    let mut s = busy();
    s.end_when = vec![EndCondition::When(Condition::Not(Box::new(Condition::Done)))];
    assert!(bad(s).contains("`done`"));
    let mut s = busy();
    s.end_when = vec![EndCondition::When(Condition::Owner(Owner::Player(Target::Ball)))];
    assert!(bad(s).contains("only a player"));
}

/// Hooks that drive scripted players with a fixed action and count the calls.
#[derive(Clone, Debug, Default)]
struct FixedScript {
    calls: u32,
}

impl Hooks for FixedScript {
    fn reset(&mut self, _view: &HookView<'_>) -> Result<(), EngineError> {
        Ok(())
    }

    fn step(&mut self, _view: &HookView<'_>, _rewards: &mut [f32]) -> Result<HookOutcome, EngineError> {
        Ok(HookOutcome::default())
    }

    fn behaviour_action(
        &mut self,
        _view: &HookView<'_>,
        _side: Side,
        _player: usize,
        path: &str,
    ) -> Result<Action, EngineError> {
        self.calls += 1;
        match path {
            "forward.rhai" => Ok(Action::Right),
            _ => Err(EngineError::InvalidScenario { reason: format!("no script {path}") }),
        }
    }

    fn save(&self) -> Vec<u8> {
        Vec::new()
    }

    fn load(&mut self, _bytes: &[u8]) -> Result<(), EngineError> {
        Ok(())
    }

    fn clone_box(&self) -> Box<dyn Hooks> {
        Box::new(self.clone())
    }
}

#[test]
fn script_behaviours_run_through_the_hooks_in_the_players_frame() {
    let scripted =
        |path: &str| with(PlayerEntry::new(Role::CM, -0.3, 0.0), vec![stage(Behaviour::Script { path: path.into() })]);
    let s = Scenario {
        left_team: vec![keeper(), scripted("forward.rhai")],
        right_team: vec![keeper(), scripted("forward.rhai")],
        ball_position: [0.0, 0.4],
        ..Scenario::default()
    };
    let refused = Env::with_config(s.clone(), config(), 1).unwrap_err().to_string();
    assert!(refused.contains("forward.rhai") && refused.contains("hooks"), "{refused}");
    let mut env = Env::with_hooks(s.clone(), config(), 1, Box::new(FixedScript::default())).unwrap();
    let (l0, r0) = (env.game().team(Side::Left)[1].position, env.game().team(Side::Right)[1].position);
    for _ in 0..20 {
        env.step(&[]).unwrap();
    }
    // `right` in each player's own frame: towards the opponents' goal.
    assert!(env.game().team(Side::Left)[1].position.x > l0.x + 5.0);
    assert!(env.game().team(Side::Right)[1].position.x < r0.x - 5.0);
    // A failing script fails the step and ends the episode.
    let mut broken = s;
    broken.right_team[1].behaviour = vec![stage(Behaviour::Script { path: "missing.rhai".into() })];
    let mut env = Env::with_hooks(broken, config(), 1, Box::new(FixedScript::default())).unwrap();
    assert!(env.step(&[]).unwrap_err().to_string().contains("missing.rhai"));
    assert!(env.is_done());
}
