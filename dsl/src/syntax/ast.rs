//! The syntax tree of a `.tl` file: what the text says, with a byte span on every part, before
//! any name or value is checked.

pub use crate::span::{Span, Spanned};

/// A parsed file.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct File {
    /// Imports and definitions in source order.
    pub items: Vec<Item>,
    /// Every `//` comment, in source order (for the formatter).
    pub comments: Vec<Spanned<String>>,
}

/// A top-level item.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// `import "path"`.
    Import(Spanned<String>),
    /// `scenario NAME { … }` or `preset NAME { … }`.
    Definition(Definition),
}

/// Whether a definition is a scenario or a preset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A playable scenario; a file compiles to its one scenario.
    Scenario,
    /// A named set of statements others extend.
    Preset,
}

/// `/// docs` + `scenario|preset NAME { statements }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Definition {
    /// Doc comment lines, without the `///` and one leading space.
    pub docs: Vec<String>,
    /// Scenario or preset.
    pub kind: Kind,
    /// The name.
    pub name: Spanned<String>,
    /// Statements in source order.
    pub statements: Vec<Statement>,
    /// The whole definition, docs included.
    pub span: Span,
}

/// One statement of a definition body.
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    /// What it says.
    pub kind: StatementKind,
    /// The whole statement.
    pub span: Span,
}

/// The statements of the language.
#[derive(Clone, Debug, PartialEq)]
pub enum StatementKind {
    /// `extends NAME`.
    Extends(Spanned<String>),
    /// `ball at …` / `ball in …`.
    Ball(Place),
    /// `on odd episodes ball at …`.
    OddBall(Place),
    /// `on odd episodes swap teams`.
    SwapTeams,
    /// `team left|right [formation "…"] [{ players }]`.
    Team(Team),
    /// `require LHS >= RHS` / `<=`.
    Require {
        /// Left-hand side (`distance(a, b)`).
        lhs: Expr,
        /// `>=` (true) or `<=` (false).
        at_least: bool,
        /// Right-hand side (a distance).
        rhs: Expr,
    },
    /// `reward TERM + … [weight W]`.
    Reward {
        /// Terms.
        terms: Vec<RewardTerm>,
        /// `weight W`.
        weight: Option<Expr>,
    },
    /// `reward on EVENTS [once | each time] VALUE`.
    RewardOn(RewardOn),
    /// `end when COND or …`: the top-level disjuncts (`A or B and C` gives `[A, B and C]`).
    End(Vec<Condition>),
    /// `behaviour PLAYER does …`: a behaviour for a player of the teams given so far.
    Behaviour {
        /// The player (`right.CB`, `left[2]`).
        player: Expr,
        /// What the player does.
        behaviour: Behaviour,
    },
    /// `start from "file"`.
    StartFrom(Spanned<String>),
    /// `start with RESTART for TEAM [at PLACE]`.
    StartWith(StartWith),
    /// `param NAME = VALUE`: declares a parameter (or overrides a parent's).
    Param {
        /// The parameter's name.
        name: Spanned<String>,
        /// Its value.
        value: Expr,
    },
    /// `NAME = VALUE`: gives an existing parameter another value.
    Assign {
        /// The parameter's name.
        name: Spanned<String>,
        /// Its value.
        value: Expr,
    },
    /// `curriculum { … }`.
    Curriculum(Curriculum),
    /// `advance when …` (inside a lesson).
    Advance(Advance),
    /// `KEY VALUE`.
    Setting {
        /// The key.
        key: Spanned<String>,
        /// The value.
        value: Expr,
    },
}

/// `curriculum { lessons, advance when … }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Curriculum {
    /// The lessons, in the order they are played.
    pub lessons: Vec<Lesson>,
    /// `advance when` statements of the block itself (the criterion of every lesson without its
    /// own); more than one is an error.
    pub advance: Vec<Advance>,
}

/// `lesson NAME [extends SCENARIO] [{ statements }]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Lesson {
    /// The lesson's name.
    pub name: Spanned<String>,
    /// `extends SCENARIO`: the lesson plays that scenario instead of the curriculum's own.
    pub parent: Option<Spanned<String>>,
    /// Statements applied on top (parameter values, settings, `advance when`, …).
    pub statements: Vec<Statement>,
    /// The whole lesson.
    pub span: Span,
}

/// `advance when METRIC >= X and … over N episodes [min M episodes]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Advance {
    /// The thresholds, all of which must hold.
    pub thresholds: Vec<Threshold>,
    /// `over N episodes`: the window.
    pub window: Expr,
    /// `min M episodes`: episodes in the window before it is judged.
    pub min: Option<Expr>,
    /// The whole statement.
    pub span: Span,
}

/// `METRIC >= X` or `METRIC <= X`.
#[derive(Clone, Debug, PartialEq)]
pub struct Threshold {
    /// `mean_reward`, `mean_score` or `success_rate`.
    pub metric: Spanned<String>,
    /// `>=` (true) or `<=` (false).
    pub at_least: bool,
    /// The bound.
    pub value: Expr,
}

/// Left or right.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The left team.
    Left,
    /// The right team.
    Right,
}

/// A `team` statement.
#[derive(Clone, Debug, PartialEq)]
pub struct Team {
    /// Which team.
    pub side: Spanned<Side>,
    /// `formation "4-4-2"`.
    pub formation: Option<Spanned<String>>,
    /// Players of the block.
    pub players: Vec<Player>,
    /// Whether a `{ }` block was written.
    pub block: bool,
}

/// `ROLE at|in … flags`.
#[derive(Clone, Debug, PartialEq)]
pub struct Player {
    /// The role name as written.
    pub role: Spanned<String>,
    /// Where the player starts.
    pub place: Place,
    /// Flags as written.
    pub flags: Vec<Spanned<Flag>>,
    /// `does …`.
    pub behaviour: Option<Behaviour>,
    /// The whole player line.
    pub span: Span,
}

/// A player flag.
#[derive(Clone, Debug, PartialEq)]
pub enum Flag {
    /// `lazy`.
    Lazy,
    /// `controllable` (the default, written out).
    Controllable,
    /// `not controllable`.
    NotControllable,
    /// `facing ball`, `facing goal`, `facing (dx, dy)`: the value after `facing`.
    Facing(Expr),
}

/// `start with RESTART for TEAM [at PLACE]`.
#[derive(Clone, Debug, PartialEq)]
pub struct StartWith {
    /// The restart's name as written (`penalty_kick`, `corner_kick`, …).
    pub restart: Spanned<String>,
    /// The team after `for`, as written.
    pub team: Option<Spanned<String>>,
    /// The value after `at`.
    pub at: Option<Expr>,
}

/// `at EXPR` or `in EXPR`.
#[derive(Clone, Debug, PartialEq)]
pub enum Place {
    /// A point, a point of distributions, or `choice[points]`.
    At(Expr),
    /// A region.
    In(Expr),
}

/// One reward term.
#[derive(Clone, Debug, PartialEq)]
pub enum RewardTerm {
    /// `script "file.rhai"`.
    Script(Spanned<String>),
    /// `scoring`, `checkpoint(…)`.
    Expr(Expr),
}

/// `reward on EVENTS [once | each time] VALUE`.
#[derive(Clone, Debug, PartialEq)]
pub struct RewardOn {
    /// The steps joined by `then`, in order.
    pub sequence: Vec<EventStep>,
    /// `once` / `each time` as written (several are checked by the compiler).
    pub repeats: Vec<Spanned<Repeat>>,
    /// The value paid.
    pub value: Expr,
}

/// `once` or `each time`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Repeat {
    /// `once`.
    Once,
    /// `each time`.
    EachTime,
}

/// One step of an event sequence.
#[derive(Clone, Debug, PartialEq)]
pub enum EventStep {
    /// One event (boxed: an event is much larger than a group's list).
    One(Box<Event>),
    /// `any of (…)` (`all` false) or `all of (…)` (`all` true).
    Group {
        /// `all of` rather than `any of`.
        all: bool,
        /// The events listed (possibly none: the compiler reports it).
        events: Vec<Event>,
        /// The whole group.
        span: Span,
    },
}

/// `NAME [enters|in REGION] [by player|for team]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    /// The event's name.
    pub name: Spanned<String>,
    /// `enters REGION` / `in REGION`: the word and the region.
    pub region: Option<(Spanned<String>, Expr)>,
    /// `by player` / `for team`: the two words.
    pub scope: Option<(Spanned<String>, Spanned<String>)>,
    /// The whole event.
    pub span: Span,
}

/// `does STAGE then STAGE …`: a player's behaviour.
#[derive(Clone, Debug, PartialEq)]
pub struct Behaviour {
    /// The stages in order.
    pub stages: Vec<Stage>,
    /// From `does` to the end.
    pub span: Span,
}

/// `[do] ACTION [then shoot] [until COND]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Stage {
    /// What the player does.
    pub action: Action,
    /// The span of `then shoot`, when written.
    pub shoot: Option<Span>,
    /// `until COND`.
    pub until: Option<Condition>,
    /// The whole stage.
    pub span: Span,
}

/// A behaviour as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// `script "file.rhai"`.
    Script(Spanned<String>),
    /// `press`, `move_to((x, y))`, `builtin(0.8)`, ….
    Expr(Expr),
}

/// A condition of the condition language (`until`, `end when`).
#[derive(Clone, Debug, PartialEq)]
pub struct Condition {
    /// What it says.
    pub kind: ConditionKind,
    /// Where it is written.
    pub span: Span,
}

/// The forms of a condition.
#[derive(Clone, Debug, PartialEq)]
pub enum ConditionKind {
    /// `A or B or …` (two or more).
    Any(Vec<Condition>),
    /// `A and B and …` (two or more).
    All(Vec<Condition>),
    /// `not A`.
    Not(Box<Condition>),
    /// `(A)`.
    Group(Box<Condition>),
    /// `LHS OP RHS`: `distance(a, b) < 5 m`, `steps >= 50`, `score(left) >= 1`.
    Compare {
        /// What is measured.
        lhs: Expr,
        /// `<`, `<=`, `>`, `>=`, `==` or `!=`.
        op: Spanned<String>,
        /// The value compared with.
        rhs: Expr,
    },
    /// `WHAT in REGION`.
    In {
        /// The ball or a player.
        what: Expr,
        /// The region.
        region: Expr,
    },
    /// `WHAT is VALUE`: `owner is left`, `game_mode is corner`.
    Is {
        /// `owner` or `game_mode`.
        what: Expr,
        /// The value.
        value: Expr,
    },
    /// `script "file.rhai"` (only in `end when`).
    Script(Spanned<String>),
    /// A name: `done`, `score`, `out_of_play`, `possession_change`.
    Name(Spanned<String>),
}

/// An expression with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where it is written.
    pub span: Span,
}

/// The expressions of the language.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// `name(args)`.
    Call {
        /// Function name.
        name: Spanned<String>,
        /// Arguments.
        args: Vec<Argument>,
    },
    /// `name[args]`.
    Index {
        /// Name before the brackets.
        name: Spanned<String>,
        /// Arguments.
        args: Vec<Argument>,
    },
    /// `(a, b)`.
    Tuple(Vec<Argument>),
    /// A number with an optional unit.
    Quantity {
        /// The number as written (kept for the formatter).
        text: String,
        /// Its value.
        value: f64,
        /// The unit, if any.
        unit: Option<Spanned<String>>,
    },
    /// `"text"`.
    Str(String),
    /// `name` or `name.field`.
    Path {
        /// First name.
        head: Spanned<String>,
        /// `.field`.
        field: Option<Spanned<String>>,
    },
    /// `a + b`, `a - b`, `a * b`, `a / b`.
    Binary {
        /// The operator.
        op: BinaryOp,
        /// Left operand.
        lhs: Box<Expr>,
        /// Right operand.
        rhs: Box<Expr>,
    },
    /// `-a`.
    Negation(Box<Expr>),
    /// `(a)`: a parenthesised expression.
    Paren(Box<Expr>),
}

/// An arithmetic operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    /// `+`.
    Add,
    /// `-`.
    Sub,
    /// `*`.
    Mul,
    /// `/`.
    Div,
}

impl BinaryOp {
    /// The operator as written.
    pub fn symbol(self) -> &'static str {
        match self {
            BinaryOp::Add => "+",
            BinaryOp::Sub => "-",
            BinaryOp::Mul => "*",
            BinaryOp::Div => "/",
        }
    }

    /// Binding strength: `*` `/` bind tighter than `+` `-`.
    pub fn precedence(self) -> u8 {
        match self {
            BinaryOp::Add | BinaryOp::Sub => 1,
            BinaryOp::Mul | BinaryOp::Div => 2,
        }
    }
}

/// A positional or named argument.
#[derive(Clone, Debug, PartialEq)]
pub struct Argument {
    /// `name:` of a named argument.
    pub name: Option<Spanned<String>>,
    /// The value.
    pub value: Expr,
}

impl Expr {
    /// A short description of what the expression is, for "expected X, found Y" messages.
    pub fn describe(&self) -> String {
        match &self.kind {
            ExprKind::Call { name, .. } => format!("a call to `{}`", name.value),
            ExprKind::Index { name, .. } => format!("`{}[…]`", name.value),
            ExprKind::Tuple(args) => format!("a tuple of {}", args.len()),
            ExprKind::Quantity { unit: Some(u), .. } => format!("a number in `{}`", u.value),
            ExprKind::Quantity { .. } => "a number".into(),
            ExprKind::Str(_) => "a string".into(),
            ExprKind::Path { head, field: None } => format!("the name `{}`", head.value),
            ExprKind::Path { head, field: Some(f) } => format!("the name `{}.{}`", head.value, f.value),
            ExprKind::Binary { op, .. } => format!("an arithmetic expression (`{}`)", op.symbol()),
            ExprKind::Negation(_) => "a negation".into(),
            ExprKind::Paren(inner) => inner.describe(),
        }
    }
}
