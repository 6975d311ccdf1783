//! [`Origins`]: where each part of the merged scenario was written, so that a check made after
//! merging (team sizes, positions, `require`) can point at the line that caused it.

use crate::diagnostic::Source;
use crate::syntax::Span;

/// Where a part of the compiled scenario was written, for diagnostics found after merging.
#[derive(Clone, Debug)]
pub(crate) struct Loc {
    pub(crate) source: Source,
    pub(crate) span: Span,
}

/// The places the merged scenario's parts come from.
#[derive(Clone, Debug, Default)]
pub(crate) struct Origins {
    /// The `team` statement of each side.
    pub(crate) team: [Option<Loc>; 2],
    /// Each player's line (or the formation), per side.
    pub(crate) players: [Vec<Loc>; 2],
    /// The `ball` statement.
    pub(crate) ball: Option<Loc>,
    /// Whether each side's `team` statement had errors (an unknown role or formation, a bad
    /// place): its players are then incomplete, and counting them would only repeat the error.
    pub(crate) team_errors: [bool; 2],
    /// Each `require` statement of the merged scenario, in order.
    pub(crate) requires: Vec<Loc>,
    /// The `start with` statement.
    pub(crate) start_with: Option<Loc>,
}
