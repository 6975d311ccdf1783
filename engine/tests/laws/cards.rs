//! Law 12, cards and sending-offs (docs/grf-compatibility.md#laws): two yellows make a red; a sent-off player is
//! inactive and off the field; a team's last active player stays on; a sent-off keeper is
//! replaced in goal by the first active team-mate, who takes the GK role.

use touchline_engine::rules::cards::Card;
use touchline_engine::{Action, Env, Event, Role, Side};

use super::common;

fn full_match() -> Env {
    Env::new(common::scenario("11_vs_11_stochastic"), 2).unwrap()
}

#[test]
fn two_yellows_are_a_red_and_the_player_leaves() {
    let mut env = full_match();
    env.game_mut().show_card(Side::Right, 4, Card::Yellow);
    assert!(env.game().team(Side::Right)[4].active);
    env.step(&[Action::Idle]).unwrap();
    assert!(env.observations()[0].right_team_yellow_card[4]);
    env.game_mut().show_card(Side::Right, 4, Card::Yellow);
    let p = &env.game().team(Side::Right)[4];
    assert!(!p.active && p.position.y.abs() > 36.0, "{p:?}");
    let stats = env.game().stats().teams[1];
    assert_eq!((stats.yellow_cards, stats.red_cards), (2, 1));
    assert!(env.game().events().iter().any(|e| matches!(e, Event::RedCard { side: Side::Right, player: 4 })));
    // He takes no further part: he stays off the field through play and restarts.
    for _ in 0..300 {
        env.step(&[Action::Idle]).unwrap();
        let p = &env.game().team(Side::Right)[4];
        assert!(!p.active && p.position.y.abs() > 36.0);
        assert_ne!(env.game().owner(), Some((Side::Right, 4)));
    }
    assert!(!env.observations()[0].right_team_active[4]);
}

#[test]
fn a_sent_off_keeper_is_replaced_in_goal() {
    let mut env = full_match();
    env.game_mut().show_card(Side::Left, 0, Card::Red);
    let team = env.game().team(Side::Left);
    assert!(!team[0].active);
    assert_eq!(team[1].role, Role::GK, "the first active player takes the keeper's role");
    assert_eq!(team.iter().filter(|p| p.active && p.role == Role::GK).count(), 1);
    for _ in 0..200 {
        env.step(&[Action::Idle]).unwrap();
    }
    let o = &env.observations()[0];
    assert_eq!(o.left_team_roles[1], Role::GK as u8);
    assert!(!o.left_team_active[0]);
}

#[test]
fn the_last_active_player_is_never_sent_off() {
    let mut env = Env::new(common::empty_pitch(100), 0).unwrap();
    env.game_mut().show_card(Side::Right, 0, Card::Red);
    assert!(env.game().team(Side::Right)[0].active, "the right team's only player stays on");
    env.game_mut().show_card(Side::Left, 1, Card::Red);
    assert!(!env.game().team(Side::Left)[1].active);
    env.game_mut().show_card(Side::Left, 0, Card::Red);
    assert!(env.game().team(Side::Left)[0].active, "now the left keeper is the last one");
}
