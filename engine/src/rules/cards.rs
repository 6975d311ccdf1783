//! Law 12, disciplinary sanctions: yellow and red cards and sending-offs.
//!
//! - **Law**: a reckless foul is cautioned (yellow card), one with excessive force is a sending-off
//!   offence (red card); a second caution in the match is a sending-off. A sent-off player leaves
//!   the field and is not replaced; if he was the goalkeeper, a team-mate takes his place in goal.
//! - **When it triggers**: a foul (see [`super::fouls`]) with severity above 1.4 (yellow) or 2.0
//!   (red) (docs/grf-compatibility.md#laws).
//! - **Restart**: the foul's free kick or penalty kick. A sent-off player is inactive at once
//!   (`active = False` in observations), stands off the field by the nearer touchline and takes no
//!   further part. A team's last active player is never sent off. When the keeper is sent off,
//!   the first active team-mate (in scenario order) becomes the goalkeeper: he takes the GK role
//!   and the keeper's place in the formation.
//! - **GRF behaviour**: two yellows or a red send the player off 6 s later, never the last
//!   active player of a team; a sent-off GK's formation entry goes to the first active player
//!   (docs/grf-compatibility.md#laws). Observations show `yellow_card` for any caution.
//! - **Differences**: the player leaves at once instead of 6 s later.

use glam::Vec2;

use crate::game::Match;
use crate::geometry::pitch::HALF_WIDTH;
use crate::player::Role;
use crate::stats::Event;

/// Severity above which a foul is cautioned (docs/grf-compatibility.md#laws).
pub const YELLOW_SEVERITY: f32 = 1.4;
/// Severity above which a foul is a sending-off (docs/grf-compatibility.md#laws).
pub const RED_SEVERITY: f32 = 2.0;
/// How far outside the touchline a sent-off player stands (m).
const OFF_FIELD: f32 = 3.0;

/// A card the referee shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Card {
    /// A caution; the second in a match sends the player off.
    Yellow,
    /// A sending-off.
    Red,
}

/// Shows `card` to `g` (global index), with the consequences of the Law (two yellows = red).
pub(crate) fn show(m: &mut Match, g: usize, card: Card) {
    judge(m, g, if card == Card::Red { RED_SEVERITY + 1.0 } else { YELLOW_SEVERITY + 0.1 });
}

/// Shows the card a foul of `severity` by `g` (global index) deserves, if any.
pub(crate) fn judge(m: &mut Match, g: usize, severity: f32) {
    let (side, index) = (m.players[g].side, m.players[g].index);
    if severity > RED_SEVERITY {
        m.record(Event::RedCard { side, player: index });
        send_off(m, g);
    } else if severity > YELLOW_SEVERITY {
        m.players[g].cards += 1;
        m.record(Event::YellowCard { side, player: index });
        if m.players[g].cards >= 2 {
            m.record(Event::RedCard { side, player: index });
            send_off(m, g);
        }
    }
}

/// Sends `g` (global index) off, unless he is his team's last active player; a sent-off keeper is
/// replaced in goal by the first active team-mate.
pub(crate) fn send_off(m: &mut Match, g: usize) {
    let side = m.players[g].side;
    let range = m.ranges[side.index()].clone();
    let active = range.clone().filter(|&i| m.players[i].active).count();
    if active <= 1 || !m.players[g].active {
        return;
    }
    let was_keeper = m.players[g].is_keeper();
    {
        let p = &mut m.players[g];
        p.halt();
        p.active = false;
        p.position = Vec2::new(p.position.x, (HALF_WIDTH + OFF_FIELD).copysign(p.position.y));
    }
    if m.owner == Some(g) {
        m.owner = None;
    }
    if m.taker == Some(g) {
        m.taker = None;
    }
    if was_keeper && let Some(new) = range.clone().find(|&i| m.players[i].active) {
        let (old_i, new_i) = (m.players[g].index, m.players[new].index);
        // The new keeper takes the GK role and the keeper's place in the formation; the sent-off
        // player keeps the outfield role for the records.
        let outfield_role = m.players[new].role;
        m.players[new].role = Role::GK;
        m.players[g].role = outfield_role;
        m.players[new].home = m.players[g].home;
        let formation = &mut m.formations[side.index()];
        let (keeper_entry, outfield_entry) = (formation[old_i], formation[new_i]);
        formation[new_i] = keeper_entry;
        formation[old_i] = outfield_entry;
    }
}
