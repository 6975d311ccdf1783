//! The compiler's diagnostics: a stable [`Code`] per kind of problem, a label on the exact span,
//! help text, and [`Diagnostics`], every problem of one compile at once.

use std::fmt;
use std::sync::Arc;

use miette::{LabeledSpan, NamedSource, Severity, SourceSpan};

use crate::excerpt::clip_message;
use crate::span::Span;

/// The stable code of a compiler diagnostic (`tl::E1xx` errors, `tl::W1xx` warnings). Codes are
/// never reused for another problem; grammar/README.md lists them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Code {
    /// The text does not follow the grammar.
    Syntax,
    /// A configuration key the language does not know.
    UnknownKey,
    /// A role name that is not one of GK CB LB RB DM CM LM RM AM CF.
    UnknownRole,
    /// A region name that is not known.
    UnknownRegion,
    /// A formation name that is not known.
    UnknownFormation,
    /// A value of the wrong type (a string where a number belongs, …).
    WrongType,
    /// A number with a unit that does not fit (`400 m` for a duration, …).
    WrongUnit,
    /// A value outside its range (off the pitch, a difficulty above 1, …).
    OutOfRange,
    /// More than 11 players in a team, or none.
    PlayerCount,
    /// A team without a goalkeeper, or with two.
    Goalkeepers,
    /// A statement given twice in one definition.
    Duplicate,
    /// `extends` goes round in a circle.
    ExtendsCycle,
    /// An imported file cannot be read.
    MissingImport,
    /// The scenario file itself cannot be read: missing, not a regular file, over 64 MiB, or not
    /// UTF-8 text.
    UnreadableSource,
    /// Relative places that depend on each other in a circle (`a at b`, `b at a`).
    PlacementCycle,
    /// A child's `team` puts another role (or no one) at an index its parent's relative places or
    /// `require`s name.
    TeamReordered,
    /// A `require` constraint that can never hold, or too rarely for the retry budget.
    Unsatisfiable,
    /// `extends` names no known preset or scenario.
    UnknownParent,
    /// A player reference that names no player.
    UnknownPlayer,
    /// A function (distribution, region, reward) that is not known.
    UnknownFunction,
    /// A call with the wrong number or names of arguments.
    Arguments,
    /// A file without a scenario, or with several.
    ScenarioCount,
    /// An end condition that is not known.
    UnknownCondition,
    /// Two definitions with the same name.
    DuplicateDefinition,
    /// `start from` names a file that is not a usable saved state.
    StartState,
    /// A behaviour name that is not known (`pres` for `press`).
    UnknownBehaviour,
    /// A behaviour with the wrong number or kind of arguments (a point, a player or a pass kind
    /// expected).
    BehaviourArguments,
    /// `me` or `done` in `end when`: they only mean something inside a player's behaviour.
    BehaviourOnly,
    /// `pass_to` a player of the other team, or to the passer himself.
    PassTarget,
    /// `game_mode is NAME` with a name that is not a game mode.
    UnknownGameMode,
    /// A comparison whose left side is not `distance(a, b)`, `steps` or `score(side)`.
    UnknownMeasure,
    /// `then shoot` after something other than `dribble_to(point)`.
    MisplacedShoot,
    /// `score`, `out_of_play`, `possession_change` or `script` where only the condition language
    /// fits (inside `and`/`not`/parentheses, or in `until`).
    EndOnlyCondition,
    /// `reward on` names an event that is not known.
    UnknownEvent,
    /// An event given a region it does not take, or lacking one it needs (`ball` without
    /// `enters REGION`).
    EventRegion,
    /// An event's scope that cannot apply: `by player` on an event no player of the
    /// controller's team does (`goal_against`, `ball enters`, `opponent_…`), or another word.
    EventScope,
    /// `once` and `each time` together, or one of them twice.
    EventRepeat,
    /// `any of ()` / `all of ()` with no event.
    EmptyEventGroup,
    /// A name read as a parameter that no `param` declares (or a lesson or assignment giving a
    /// value to one).
    UnknownParam,
    /// A parameter declared twice in one definition.
    ParamRedefined,
    /// A parameter's value that does not fit where it is used (unit, type, range), or one defined
    /// in terms of itself.
    ParamValue,
    /// A lesson extends a scenario that does not exist.
    UnknownLesson,
    /// A curriculum that is not well formed: no lessons, two criteria, a curriculum in a lesson
    /// or a preset.
    CurriculumShape,
    /// A curriculum that cannot advance: a criterion that can never be met, or a lesson before the
    /// last without any criterion.
    NeverAdvances,
    /// An `advance when` metric that is not known.
    UnknownMetric,
    /// Lessons that an env cannot switch between: different numbers of controllable players or
    /// different scripts.
    LessonMismatch,
    /// Text nested deeper than [`crate::syntax::MAX_NESTING`] levels (brackets, `not`, `-`,
    /// operators in one expression), or `extends`, imports or params chained deeper than that.
    TooDeep,
    /// A reward weight, event reward value or checkpoint value larger than
    /// [`RewardTerm::MAX_WEIGHT`](touchline_engine::scenario::RewardTerm::MAX_WEIGHT) in magnitude:
    /// summed in f32 with other terms it could make the reward inf or NaN.
    RewardTooLarge,
    /// `start with` names a restart that is not known (`penalty` for `penalty_kick`).
    UnknownRestart,
    /// A `start with` that cannot be set up: no team or an unknown one, a point missing where the
    /// restart needs one or given where it has a fixed spot, a corner or throw-in point on neither
    /// side, or together with `start from`.
    RestartShape,
    /// `facing` with something other than `ball`, `goal` or a non-zero direction `(dx, dy)`.
    Facing,
    /// Warning: a player or ball outside the lines (but inside the rim, so still playable).
    OutsideLines,
    /// Warning: the left team has no controllable player, so an agent has no one to drive.
    NoControllable,
    /// Warning: an import nothing uses.
    UnusedImport,
    /// Warning: a GRF key that changes nothing in touchline (`real_time`, …).
    NoEffect,
    /// Warning: a behaviour stage after one that never ends (a behaviour that never finishes,
    /// without an `until` that can hold), so it is never reached.
    UnreachableStage,
    /// Warning: a parameter holding a distribution used more than once (each use is drawn on its
    /// own).
    RepeatedDraw,
    /// Warning: `ball at` in a scenario that starts with a restart, which places the ball itself.
    BallReplaced,
}

impl Code {
    /// Every code, in numbering order.
    pub const ALL: [Code; 58] = [
        Code::Syntax,
        Code::UnknownKey,
        Code::UnknownRole,
        Code::UnknownRegion,
        Code::UnknownFormation,
        Code::WrongType,
        Code::WrongUnit,
        Code::OutOfRange,
        Code::PlayerCount,
        Code::Goalkeepers,
        Code::Duplicate,
        Code::ExtendsCycle,
        Code::MissingImport,
        Code::Unsatisfiable,
        Code::UnknownParent,
        Code::UnknownPlayer,
        Code::UnknownFunction,
        Code::Arguments,
        Code::ScenarioCount,
        Code::UnknownCondition,
        Code::DuplicateDefinition,
        Code::StartState,
        Code::UnknownBehaviour,
        Code::BehaviourArguments,
        Code::BehaviourOnly,
        Code::PassTarget,
        Code::UnknownGameMode,
        Code::UnknownMeasure,
        Code::MisplacedShoot,
        Code::EndOnlyCondition,
        Code::UnknownEvent,
        Code::EventRegion,
        Code::EventScope,
        Code::EventRepeat,
        Code::EmptyEventGroup,
        Code::UnknownParam,
        Code::ParamRedefined,
        Code::ParamValue,
        Code::UnknownLesson,
        Code::CurriculumShape,
        Code::NeverAdvances,
        Code::UnknownMetric,
        Code::LessonMismatch,
        Code::TooDeep,
        Code::RewardTooLarge,
        Code::UnreadableSource,
        Code::PlacementCycle,
        Code::UnknownRestart,
        Code::RestartShape,
        Code::Facing,
        Code::TeamReordered,
        Code::OutsideLines,
        Code::NoControllable,
        Code::UnusedImport,
        Code::NoEffect,
        Code::UnreachableStage,
        Code::RepeatedDraw,
        Code::BallReplaced,
    ];

    /// The code as shown: `tl::E100` … `tl::W102`.
    pub fn as_str(self) -> &'static str {
        match self {
            Code::Syntax => "tl::E100",
            Code::UnknownKey => "tl::E101",
            Code::UnknownRole => "tl::E102",
            Code::UnknownRegion => "tl::E103",
            Code::UnknownFormation => "tl::E104",
            Code::WrongType => "tl::E105",
            Code::WrongUnit => "tl::E106",
            Code::OutOfRange => "tl::E107",
            Code::PlayerCount => "tl::E108",
            Code::Goalkeepers => "tl::E109",
            Code::Duplicate => "tl::E110",
            Code::ExtendsCycle => "tl::E111",
            Code::MissingImport => "tl::E112",
            Code::Unsatisfiable => "tl::E113",
            Code::UnknownParent => "tl::E114",
            Code::UnknownPlayer => "tl::E115",
            Code::UnknownFunction => "tl::E116",
            Code::Arguments => "tl::E117",
            Code::ScenarioCount => "tl::E118",
            Code::UnknownCondition => "tl::E119",
            Code::DuplicateDefinition => "tl::E120",
            Code::StartState => "tl::E121",
            Code::UnknownBehaviour => "tl::E122",
            Code::BehaviourArguments => "tl::E123",
            Code::BehaviourOnly => "tl::E124",
            Code::PassTarget => "tl::E125",
            Code::UnknownGameMode => "tl::E126",
            Code::UnknownMeasure => "tl::E127",
            Code::MisplacedShoot => "tl::E128",
            Code::EndOnlyCondition => "tl::E129",
            Code::UnknownEvent => "tl::E130",
            Code::EventRegion => "tl::E131",
            Code::EventScope => "tl::E132",
            Code::EventRepeat => "tl::E133",
            Code::EmptyEventGroup => "tl::E134",
            Code::UnknownParam => "tl::E140",
            Code::ParamRedefined => "tl::E141",
            Code::ParamValue => "tl::E142",
            Code::UnknownLesson => "tl::E143",
            Code::CurriculumShape => "tl::E144",
            Code::NeverAdvances => "tl::E145",
            Code::UnknownMetric => "tl::E146",
            Code::LessonMismatch => "tl::E147",
            Code::TooDeep => "tl::E148",
            Code::RewardTooLarge => "tl::E149",
            Code::UnreadableSource => "tl::E150",
            Code::PlacementCycle => "tl::E151",
            Code::UnknownRestart => "tl::E152",
            Code::RestartShape => "tl::E153",
            Code::Facing => "tl::E154",
            Code::TeamReordered => "tl::E155",
            Code::OutsideLines => "tl::W100",
            Code::NoControllable => "tl::W101",
            Code::UnusedImport => "tl::W102",
            Code::NoEffect => "tl::W103",
            Code::UnreachableStage => "tl::W104",
            Code::RepeatedDraw => "tl::W105",
            Code::BallReplaced => "tl::W106",
        }
    }

    /// Whether diagnostics with this code are warnings.
    pub fn is_warning(self) -> bool {
        self.as_str().starts_with("tl::W")
    }
}

impl fmt::Display for Code {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A source text with its name, shared by every diagnostic about it.
pub type Source = Arc<NamedSource<String>>;

/// One problem found in a source: code, message, labelled spans and help.
#[derive(Clone, Debug)]
pub struct Diagnostic {
    /// The stable code.
    pub code: Code,
    /// One-line message.
    pub message: String,
    /// The text the spans point into.
    pub source: Source,
    /// Labelled spans; the first is the primary one.
    pub labels: Vec<(Span, String)>,
    /// What to do about it ("did you mean `CB`?").
    pub help: Option<String>,
}

impl Diagnostic {
    /// A diagnostic with one labelled span.
    pub fn new(code: Code, message: impl Into<String>, source: &Source, span: Span, label: impl Into<String>) -> Self {
        Diagnostic {
            code,
            message: clip_message(message.into()),
            source: source.clone(),
            labels: vec![(span, clip_message(label.into()))],
            help: None,
        }
    }

    /// A diagnostic about a whole source, without a span (an unreadable file, an empty one).
    pub fn bare(code: Code, message: impl Into<String>, source: &Source) -> Self {
        Diagnostic {
            code,
            message: clip_message(message.into()),
            source: source.clone(),
            labels: Vec::new(),
            help: None,
        }
    }

    /// Adds help text.
    pub fn with_help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(clip_message(help.into()));
        self
    }

    /// Adds a secondary label.
    pub fn with_label(mut self, span: Span, label: impl Into<String>) -> Self {
        self.labels.push((span, clip_message(label.into())));
        self
    }

    /// The primary span.
    pub fn span(&self) -> Span {
        self.labels.first().map_or(Span::default(), |(s, _)| *s)
    }

    /// Name of the source (a path or `stdlib/NAME.tl`).
    pub fn origin(&self) -> &str {
        self.source.name()
    }
}

/// The source text, excerpted as [`crate::excerpt`] says: a window around the label on a very
/// long line (which miette's renderer cannot pad to).
impl miette::SourceCode for Diagnostic {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn miette::SpanContents<'a> + 'a>, miette::MietteError> {
        crate::excerpt::read_clipped(&*self.source, span, before, after)
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Diagnostic {}

impl miette::Diagnostic for Diagnostic {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        Some(Box::new(self.code))
    }

    fn severity(&self) -> Option<Severity> {
        Some(if self.code.is_warning() { Severity::Warning } else { Severity::Error })
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.help.as_ref().map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn miette::SourceCode> {
        // Itself: its excerpts are clipped on long lines (crate::excerpt).
        (!self.labels.is_empty()).then_some(self as &dyn miette::SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let text = self.source.inner();
        Some(Box::new(self.labels.iter().enumerate().map(move |(i, (span, label))| {
            let len = span.end.saturating_sub(span.start);
            let span = crate::excerpt::clamp_span(text, SourceSpan::from((span.start, len)));
            let label = (!label.is_empty()).then(|| label.clone());
            if i == 0 {
                LabeledSpan::new_primary_with_span(label, span)
            } else {
                LabeledSpan::new_with_span(label, span)
            }
        })))
    }
}

/// Every diagnostic of one compile: errors and warnings, in source order.
#[derive(Clone, Debug, Default)]
pub struct Diagnostics {
    /// All diagnostics, errors and warnings mixed, in the order found.
    pub items: Vec<Diagnostic>,
}

impl Diagnostics {
    /// Adds one.
    pub fn push(&mut self, d: Diagnostic) {
        self.items.push(d);
    }

    /// Drops repeats (same code, message, file and labels), keeping the first: a parent
    /// resolved for several children reports each of its mistakes once.
    pub fn dedup(&mut self) {
        // Code, message, file and label spans identify a diagnostic.
        type Key = (Code, String, String, Vec<(usize, usize)>);
        let mut seen: Vec<Key> = Vec::new();
        self.items.retain(|d| {
            let key = (
                d.code,
                d.message.clone(),
                d.source.name().to_owned(),
                d.labels.iter().map(|(s, _)| (s.start, s.end)).collect(),
            );
            if seen.contains(&key) {
                return false;
            }
            seen.push(key);
            true
        });
    }

    /// Whether any is an error.
    pub fn has_errors(&self) -> bool {
        self.items.iter().any(|d| !d.code.is_warning())
    }

    /// The errors.
    pub fn errors(&self) -> impl Iterator<Item = &Diagnostic> {
        self.items.iter().filter(|d| !d.code.is_warning())
    }

    /// The warnings.
    pub fn warnings(&self) -> impl Iterator<Item = &Diagnostic> {
        self.items.iter().filter(|d| d.code.is_warning())
    }

    /// All diagnostics rendered as plain text (no colour, 80 columns), one after another: what
    /// Python exceptions and snapshot tests show.
    pub fn render_plain(&self) -> String {
        self.items.iter().map(|d| crate::render_plain(d)).collect::<Vec<_>>().join("\n")
    }
}

impl fmt::Display for Diagnostics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let errors = self.errors().count();
        match self.errors().next() {
            Some(first) if errors == 1 => write!(f, "{}: {}", first.code, first.message),
            Some(first) => write!(f, "{}: {} (and {} more errors)", first.code, first.message, errors - 1),
            None => write!(f, "{} warnings", self.items.len()),
        }
    }
}

impl std::error::Error for Diagnostics {}

impl miette::Diagnostic for Diagnostics {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.errors().next().map(|d| Box::new(d.code) as Box<dyn fmt::Display>)
    }

    fn related<'a>(&'a self) -> Option<Box<dyn Iterator<Item = &'a dyn miette::Diagnostic> + 'a>> {
        Some(Box::new(self.items.iter().map(|d| d as &dyn miette::Diagnostic)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_unique_and_ordered() {
        let codes: Vec<&str> = Code::ALL.iter().map(|c| c.as_str()).collect();
        let mut sorted = codes.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), codes.len());
        assert!(Code::OutsideLines.is_warning() && !Code::Syntax.is_warning());
    }
}
