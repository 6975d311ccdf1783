//! The colours of a frame (RGB). Teams are red (left) and blue (right) as in GRF's 2-D videos
//! (docs/grf-compatibility.md#replays), goalkeepers in lighter shades of their team's colour so that they stand out.

/// Outside the rim.
pub(crate) const SURROUND: [u8; 3] = [28, 74, 36];
/// Grass.
pub(crate) const GRASS: [u8; 3] = [52, 128, 60];
/// Every other mowing stripe.
pub(crate) const GRASS_STRIPE: [u8; 3] = [60, 140, 68];
/// The nets behind the goal lines.
pub(crate) const NET: [u8; 3] = [190, 200, 192];
/// Pitch markings.
pub(crate) const LINE: [u8; 3] = [240, 244, 240];
/// Shirts: left outfield, left goalkeeper, right outfield, right goalkeeper.
pub(crate) const LEFT: [u8; 3] = [214, 48, 40];
pub(crate) const LEFT_KEEPER: [u8; 3] = [250, 150, 60];
pub(crate) const RIGHT: [u8; 3] = [40, 96, 214];
pub(crate) const RIGHT_KEEPER: [u8; 3] = [90, 210, 230];
/// Shirt numbers and the ball.
pub(crate) const WHITE: [u8; 3] = [255, 255, 255];
/// The outline of players and ball.
pub(crate) const OUTLINE: [u8; 3] = [20, 20, 20];
/// The ring round agent-driven players.
pub(crate) const CONTROLLED: [u8; 3] = [255, 230, 0];
/// The ball's shadow (drawn at [`SHADOW_ALPHA`]).
pub(crate) const SHADOW: [u8; 3] = [0, 0, 0];
/// Opacity of the ball's shadow.
pub(crate) const SHADOW_ALPHA: f32 = 0.4;
/// The scoreboard band and its text.
pub(crate) const BOARD: [u8; 3] = [16, 20, 28];
pub(crate) const BOARD_TEXT: [u8; 3] = [235, 235, 235];
pub(crate) const BOARD_MODE: [u8; 3] = [255, 210, 80];
