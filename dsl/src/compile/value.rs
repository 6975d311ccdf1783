//! Typed reading of expressions: booleans, durations, fractions, coordinates with units,
//! distributions, points and regions. Each reader pushes a diagnostic and returns `None` when the
//! expression does not fit.

use touchline_engine::scenario::{Distribution, Region, Sample, Shared, Spot};

use super::params::Params;
use super::pitch::{self, BALL_X_METRES, BALL_Y_METRES, PLAYER_X_METRES, PLAYER_Y_METRES};
use crate::diagnostic::{Code, Diagnostic, Diagnostics, Source};
use crate::suggest;
use crate::syntax::{Argument, BinaryOp, Expr, ExprKind, Place, Span};

/// Whose coordinates a place is in: a player's (team's own frame) or the ball's (global).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Frame {
    Player,
    Ball,
}

/// An axis of the pitch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Axis {
    X,
    Y,
}

impl Frame {
    /// Metres per scenario unit along `axis`.
    fn metres(self, axis: Axis) -> f64 {
        match (self, axis) {
            (Frame::Player, Axis::X) => PLAYER_X_METRES,
            (Frame::Player, Axis::Y) => PLAYER_Y_METRES,
            (Frame::Ball, Axis::X) => BALL_X_METRES,
            (Frame::Ball, Axis::Y) => BALL_Y_METRES,
        }
    }
}

/// A number after arithmetic, with its unit (`None`: a plain number).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Number {
    /// The value.
    pub(crate) value: f64,
    /// The unit, if any.
    pub(crate) unit: Option<String>,
    /// Where the unit is written (the whole expression when it has none).
    pub(crate) unit_span: Span,
}

/// How the numbers at the leaves of an arithmetic expression are read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Leaves {
    /// As written: `10 m` stays 10 metres.
    AsWritten,
    /// As a coordinate along an axis: metres convert to scenario units, so `0.5 + 10 m` adds.
    Coordinate(Frame, Axis),
    /// As a count of this unit, which plain numbers are too: `half * 2 + 1` with `half = 100
    /// steps` is 201 steps.
    Count(&'static str),
}

/// Reads expressions of one source, collecting diagnostics.
pub(crate) struct Reader<'a> {
    pub(crate) source: &'a Source,
    pub(crate) diags: &'a mut Diagnostics,
    /// The parameters in scope (`param gap = 10 m`): a one-name path reads as its value.
    pub(crate) params: &'a Params,
    /// The parameters being read now, innermost last (a parameter whose value names itself,
    /// directly or not, is an error rather than endless recursion).
    pub(crate) expanding: Vec<String>,
    /// Uses of parameters whose value is a distribution, in this source, with the axis each
    /// gives a value for ([`Reader::warn_repeated_draws`]).
    pub(crate) random_uses: Vec<(String, Span, Axis)>,
}

impl<'a> Reader<'a> {
    /// A reader of `source` with the parameters `params`.
    pub(crate) fn new(source: &'a Source, diags: &'a mut Diagnostics, params: &'a Params) -> Reader<'a> {
        Reader { source, diags, params, expanding: Vec::new(), random_uses: Vec::new() }
    }

    /// When `e` names a parameter, reads its value with `read` and returns `Some(result)`;
    /// `None` when it does not. Problems found in the value are reported at `e` (the use),
    /// as `tl::E142`, since the same value may fit one use and not another.
    pub(crate) fn through_param<T>(
        &mut self,
        e: &Expr,
        read: impl FnOnce(&mut Self, &Expr) -> Option<T>,
    ) -> Option<Option<T>> {
        let ExprKind::Path { head, field: None } = &e.kind else { return None };
        let params: &'a Params = self.params;
        let param = params.get(&head.value)?;
        if self.expanding.contains(&param.name) {
            let chain = self.expanding.join(" → ");
            self.error_help(
                Code::ParamValue,
                format!("param `{}` is defined in terms of itself ({chain} → {})", param.name, param.name),
                e.span,
                "refers back to itself",
                "give one of these params a value that does not name the others",
            );
            return Some(None);
        }
        if self.expanding.len() >= crate::syntax::MAX_NESTING {
            // Each param named in another's value is read recursively.
            self.diags.push(super::too_deep(
                self.source,
                e.span,
                "params each named in the next one's value",
                "a param defined through another param …",
            ));
            return Some(None);
        }
        let before = self.diags.items.len();
        let use_source: &'a Source = self.source;
        self.source = &param.source;
        self.expanding.push(param.name.clone());
        let result = read(self, &param.value);
        self.expanding.pop();
        self.source = use_source;
        let same_file = std::sync::Arc::ptr_eq(&param.source, use_source);
        let shown = crate::format::expr_text(&param.value);
        for d in &mut self.diags.items[before..] {
            // A chain too deep is reported as such where it crosses the limit.
            if d.code.is_warning() || d.code == Code::TooDeep {
                continue;
            }
            if d.code != Code::ParamValue {
                d.message = format!("param `{}` (= {shown}) does not fit here: {}", param.name, d.message);
                d.code = Code::ParamValue;
            }
            d.source = use_source.clone();
            d.labels = vec![(e.span, format!("`{}` is {shown}", param.name))];
            if same_file {
                d.labels.push((param.span, "given here".to_owned()));
            }
        }
        Some(result)
    }

    /// Evaluates the arithmetic of `e` to a number with a unit. `expected` says what a
    /// non-number should have been (for the wrong-type message) and `help` what to write.
    fn number(&mut self, e: &Expr, leaves: Leaves, expected: &str, help: &str) -> Option<Number> {
        if let Some(result) = self.through_param(e, |r, v| r.number(v, leaves, expected, help)) {
            return result;
        }
        match &e.kind {
            ExprKind::Quantity { value, unit, .. } => {
                let unit_span = unit.as_ref().map_or(e.span, |u| u.span);
                match (leaves, unit) {
                    (Leaves::Count(counted), Some(u)) if u.value == counted => {
                        Some(Number { value: *value, unit: None, unit_span })
                    }
                    (Leaves::AsWritten | Leaves::Count(_), _) | (Leaves::Coordinate(..), None) => {
                        Some(Number { value: *value, unit: unit.as_ref().map(|u| u.value.clone()), unit_span })
                    }
                    (Leaves::Coordinate(frame, axis), Some(u)) if u.value == "m" => {
                        Some(Number { value: value / frame.metres(axis), unit: None, unit_span })
                    }
                    (Leaves::Coordinate(..), Some(u)) => {
                        self.error_help(
                            Code::WrongUnit,
                            format!("a position takes scenario units or metres, not `{}`", u.value),
                            u.span,
                            "not a length unit",
                            "write a plain number (x in [-1, 1], y in [-0.42, 0.42]) or metres, e.g. `10 m`",
                        );
                        None
                    }
                }
            }
            ExprKind::Paren(inner) => self.number(inner, leaves, expected, help),
            ExprKind::Negation(inner) => {
                let n = self.number(inner, leaves, expected, help)?;
                Some(Number { value: -n.value, ..n })
            }
            ExprKind::Binary { op, lhs, rhs } => {
                let a = self.number(lhs, leaves, expected, help);
                let b = self.number(rhs, leaves, expected, help);
                self.arithmetic(*op, a?, b?, e.span)
            }
            ExprKind::Path { head, field: None } if !self.params.is_empty() && !is_keyword(&head.value) => {
                let names = self.params.names();
                let close = suggest::closest(&head.value, &names);
                self.error_help(
                    Code::UnknownParam,
                    format!("unknown param `{}`", head.value),
                    head.span,
                    "not a param",
                    suggest_help(
                        &close,
                        &format!("the params are {}; declare others with `param NAME = VALUE`", names.join(", ")),
                    ),
                );
                None
            }
            _ => {
                self.wrong_type(expected, e, help);
                None
            }
        }
    }

    /// `a op b` with units: `+` `-` need the same unit, `*` at most one unit, `/` a plain
    /// divisor or the same unit on both sides (giving a plain number).
    fn arithmetic(&mut self, op: BinaryOp, a: Number, b: Number, span: Span) -> Option<Number> {
        let unit_name = |u: &Option<String>| u.as_ref().map_or("a plain number".to_owned(), |u| format!("`{u}`"));
        let mismatch = |r: &mut Self, what: &str| {
            r.error_help(
                Code::WrongUnit,
                format!("cannot {what} {} and {}", unit_name(&a.unit), unit_name(&b.unit)),
                span,
                "units do not match",
                "give both sides the same unit (in a position, plain numbers and metres mix: metres convert)",
            );
            None
        };
        let (value, unit, unit_span) = match op {
            BinaryOp::Add | BinaryOp::Sub => {
                if a.unit != b.unit {
                    return mismatch(self, if op == BinaryOp::Add { "add" } else { "subtract" });
                }
                let v = if op == BinaryOp::Add { a.value + b.value } else { a.value - b.value };
                (v, a.unit, a.unit_span)
            }
            BinaryOp::Mul => match (&a.unit, &b.unit) {
                (Some(_), Some(_)) => return mismatch(self, "multiply"),
                (Some(_), None) => (a.value * b.value, a.unit, a.unit_span),
                _ => (a.value * b.value, b.unit, b.unit_span),
            },
            BinaryOp::Div => {
                if b.value == 0.0 {
                    self.error_help(
                        Code::OutOfRange,
                        "division by zero",
                        span,
                        "divides by 0",
                        "divide by a number other than 0",
                    );
                    return None;
                }
                match (&a.unit, &b.unit) {
                    (_, None) => (a.value / b.value, a.unit, a.unit_span),
                    (Some(x), Some(y)) if x == y => (a.value / b.value, None, span),
                    _ => return mismatch(self, "divide"),
                }
            }
        };
        if !value.is_finite() {
            self.error_help(
                Code::OutOfRange,
                "the result is not a finite number",
                span,
                "overflows",
                "use smaller numbers",
            );
            return None;
        }
        Some(Number { value, unit, unit_span })
    }

    pub(crate) fn error_help(
        &mut self,
        code: Code,
        message: impl Into<String>,
        span: Span,
        label: impl Into<String>,
        help: impl Into<String>,
    ) {
        self.diags.push(Diagnostic::new(code, message, self.source, span, label).with_help(help));
    }

    /// `tl::E105` "expected …, found …" with `help` saying what to write.
    fn wrong_type(&mut self, expected: &str, e: &Expr, help: &str) {
        self.error_help(
            Code::WrongType,
            format!("expected {expected}, found {}", e.describe()),
            e.span,
            format!("not {expected}"),
            help,
        );
    }

    /// `true` or `false`.
    pub(crate) fn boolean(&mut self, e: &Expr) -> Option<bool> {
        if let Some(result) = self.through_param(e, Self::boolean) {
            return result;
        }
        match &e.kind {
            ExprKind::Path { head, field: None } if head.value == "true" => Some(true),
            ExprKind::Path { head, field: None } if head.value == "false" => Some(false),
            _ => {
                self.wrong_type("`true` or `false`", e, "write `true` or `false`");
                None
            }
        }
    }

    /// A plain number (no unit).
    pub(crate) fn plain_number(&mut self, e: &Expr, what: &str) -> Option<f64> {
        if let Some(result) = self.through_param(e, |r, v| r.plain_number(v, what)) {
            return result;
        }
        let n = self.number(e, Leaves::AsWritten, &format!("a number ({what})"), "write a plain number, e.g. `0.5`")?;
        if let Some(u) = &n.unit {
            self.error_help(
                Code::WrongUnit,
                format!("{what} takes a plain number, not `{u}`"),
                n.unit_span,
                "unit not allowed here",
                "remove the unit",
            );
            return None;
        }
        Some(n.value)
    }

    /// A number in [0, 1] (a difficulty).
    pub(crate) fn fraction(&mut self, e: &Expr, what: &str) -> Option<f32> {
        if let Some(result) = self.through_param(e, |r, v| r.fraction(v, what)) {
            return result;
        }
        let v = self.plain_number(e, what)?;
        if !(0.0..=1.0).contains(&v) {
            self.error_help(
                Code::OutOfRange,
                format!("{what} must be in [0, 1], found {v}"),
                e.span,
                "out of range",
                "a difficulty θ runs from 0 (weakest built-in AI) to 1 (strongest)",
            );
            return None;
        }
        Some(v as f32)
    }

    /// A whole number of steps, plain or with the unit `steps`, at least `min`.
    pub(crate) fn steps(&mut self, e: &Expr, what: &str, min: u32) -> Option<u32> {
        self.whole(
            e,
            what,
            min,
            "steps",
            "write a whole number of env steps (10 steps = 1 s of game time), e.g. `400` or `400 steps`",
        )
    }

    /// A whole number, plain or with the unit `unit`, at least `min`; `help` for a wrong unit.
    pub(crate) fn whole(&mut self, e: &Expr, what: &str, min: u32, unit: &'static str, help: &str) -> Option<u32> {
        if let Some(result) = self.through_param(e, |r, v| r.whole(v, what, min, unit, help)) {
            return result;
        }
        let n = self.number(
            e,
            Leaves::Count(unit),
            &format!("a number of {unit} ({what})"),
            &format!("write a whole number, e.g. `400` or `400 {unit}`"),
        )?;
        let value = n.value;
        if let Some(u) = n.unit.as_ref().filter(|u| *u != unit) {
            let kind = if unit == "steps" { "a duration in steps".to_owned() } else { format!("a number of {unit}") };
            self.error_help(
                Code::WrongUnit,
                format!("{what} is {kind}, not in `{u}`"),
                n.unit_span,
                if unit == "steps" { "not a duration unit" } else { "wrong unit" },
                help,
            );
            return None;
        }
        if value.fract() != 0.0 || value < f64::from(min) || value > f64::from(u32::MAX) {
            self.error_help(
                Code::OutOfRange,
                format!("{what} must be a whole number >= {min}, found {value}"),
                e.span,
                "out of range",
                format!("write a whole number from {min} to {}", u32::MAX),
            );
            return None;
        }
        Some(value as u32)
    }

    /// A distance in metres (the unit `m` is required).
    pub(crate) fn metres(&mut self, e: &Expr) -> Option<f32> {
        if let Some(result) = self.through_param(e, Self::metres) {
            return result;
        }
        let n = self.number(e, Leaves::AsWritten, "a distance in metres", "write metres, e.g. `5 m`")?;
        match n.unit.as_deref() {
            Some("m") if n.value >= 0.0 => Some(n.value as f32),
            Some("m") => {
                self.error_help(
                    Code::OutOfRange,
                    format!("a distance cannot be negative ({} m)", n.value),
                    e.span,
                    "negative",
                    "write a distance of 0 m or more",
                );
                None
            }
            _ => {
                self.error_help(
                    Code::WrongUnit,
                    "a distance needs the unit `m`",
                    n.unit_span,
                    "no distance unit",
                    "write metres, e.g. `5 m`",
                );
                None
            }
        }
    }

    /// One coordinate as a number: scenario units, or metres with `m`, with arithmetic.
    fn coordinate(&mut self, e: &Expr, frame: Frame, axis: Axis) -> Option<f32> {
        self.number(
            e,
            Leaves::Coordinate(frame, axis),
            "a number",
            "write a plain number (x in [-1, 1], y in [-0.42, 0.42]) or metres, e.g. `10 m`",
        )
        .map(|n| n.value as f32)
    }

    fn arity(&mut self, name: &str, args: &[Argument], n: usize, span: Span, usage: &str) -> bool {
        if args.len() == n {
            return true;
        }
        self.error_help(
            Code::Arguments,
            format!("`{name}` takes {n} arguments, found {}", args.len()),
            span,
            "wrong number of arguments",
            format!("write `{usage}`"),
        );
        false
    }

    /// A coordinate: a number, `uniform(a, b)`, `normal(mean, std)` or `choice[a, b, …]`.
    pub(crate) fn sample(&mut self, e: &Expr, frame: Frame, axis: Axis) -> Option<Sample> {
        // A param holding a distribution is drawn once per reset: its uses share the draw.
        let shared = match &e.kind {
            ExprKind::Path { head, field: None } => {
                self.params.get(&head.value).filter(|p| is_distribution(&p.value)).map(|p| p.name.clone())
            }
            _ => None,
        };
        if let Some(name) = &shared
            && self.expanding.is_empty()
        {
            self.random_uses.push((name.clone(), e.span, axis));
        }
        if let Some(result) = self.through_param(e, |r, v| r.sample(v, frame, axis)) {
            return match (result, shared) {
                (Some(Sample::Random(of)), Some(name)) => {
                    Some(Sample::Shared(Shared { shared: shared_key(&name), of }))
                }
                (result, _) => result,
            };
        }
        match &e.kind {
            ExprKind::Call { name, args } => {
                let usage = match name.value.as_str() {
                    "uniform" => "uniform(low, high)",
                    "normal" => "normal(mean, std)",
                    other => {
                        let close = suggest::closest(other, &["uniform", "normal", "choice"]);
                        self.error_help(
                            Code::UnknownFunction,
                            format!("unknown distribution `{other}`"),
                            name.span,
                            "not a distribution",
                            suggest_help(&close, "the distributions are uniform(a, b), normal(mean, std), choice[…]"),
                        );
                        return None;
                    }
                };
                if !self.arity(&name.value, args, 2, e.span, usage) {
                    return None;
                }
                let a = self.coordinate(&args[0].value, frame, axis);
                let b = self.coordinate(&args[1].value, frame, axis);
                let (a, b) = (a?, b?);
                let d = if name.value == "uniform" {
                    if a > b {
                        self.error_help(
                            Code::OutOfRange,
                            format!("uniform({}, {}) has low > high", short(a), short(b)),
                            e.span,
                            "empty range",
                            format!("write the smaller bound first: `uniform({}, {})`", short(b), short(a)),
                        );
                        return None;
                    }
                    Distribution::Uniform(a, b)
                } else {
                    if b < 0.0 {
                        self.error_help(
                            Code::OutOfRange,
                            "a standard deviation cannot be negative",
                            args[1].value.span,
                            "negative",
                            "write `normal(mean, std)` with std >= 0",
                        );
                        return None;
                    }
                    Distribution::Normal(a, b)
                };
                Some(Sample::Random(d))
            }
            ExprKind::Index { name, args } if name.value == "choice" => {
                if args.is_empty() {
                    self.error_help(
                        Code::Arguments,
                        "`choice` needs at least one value",
                        e.span,
                        "empty choice",
                        "write `choice[v1, v2, …]`",
                    );
                    return None;
                }
                let values: Vec<Option<f32>> = args.iter().map(|a| self.coordinate(&a.value, frame, axis)).collect();
                Some(Sample::Random(Distribution::Choice(values.into_iter().collect::<Option<Vec<_>>>()?)))
            }
            _ => self.coordinate(e, frame, axis).map(Sample::Fixed),
        }
    }

    /// A fixed point `(x, y)`.
    pub(crate) fn fixed_point(&mut self, e: &Expr, frame: Frame) -> Option<[f32; 2]> {
        if let Some(result) = self.through_param(e, |r, v| r.fixed_point(v, frame)) {
            return result;
        }
        let ExprKind::Tuple(args) = &e.kind else {
            self.wrong_type("a point `(x, y)`", e, "write a point as `(x, y)`");
            return None;
        };
        if args.len() != 2 {
            self.point_arity(e, args.len());
            return None;
        }
        let x = self.coordinate(&args[0].value, frame, Axis::X);
        let y = self.coordinate(&args[1].value, frame, Axis::Y);
        Some([x?, y?])
    }

    /// A region: a named one (`penalty_area`), `circle(x, y, r)` or `rect((x0, y0), (x1, y1))`.
    pub(crate) fn region(&mut self, e: &Expr, frame: Frame) -> Option<Region> {
        if let Some(result) = self.through_param(e, |r, v| r.region(v, frame)) {
            return result;
        }
        match &e.kind {
            ExprKind::Path { head, field: None } => pitch::region(&head.value).or_else(|| {
                let close = suggest::closest(&head.value, &pitch::REGION_NAMES);
                self.error_help(
                    Code::UnknownRegion,
                    format!("unknown region `{}`", head.value),
                    head.span,
                    "not a region",
                    suggest_help(
                        &close,
                        &format!(
                            "the regions are {}, circle(x, y, r), rect((x0, y0), (x1, y1))",
                            pitch::REGION_NAMES.join(", ")
                        ),
                    ),
                );
                None
            }),
            ExprKind::Call { name, args } if name.value == "circle" => {
                if !self.arity("circle", args, 3, e.span, "circle(x, y, r)") {
                    return None;
                }
                let x = self.coordinate(&args[0].value, frame, Axis::X);
                let y = self.coordinate(&args[1].value, frame, Axis::Y);
                let r = self.coordinate(&args[2].value, frame, Axis::X);
                let (x, y, r) = (x?, y?, r?);
                if r <= 0.0 {
                    self.error_help(
                        Code::OutOfRange,
                        "a circle's radius must be positive",
                        args[2].value.span,
                        "not positive",
                        "write `circle(x, y, r)` with r > 0",
                    );
                    return None;
                }
                Some(Region::Circle { x, y, r })
            }
            ExprKind::Call { name, args } if name.value == "rect" => {
                if !self.arity("rect", args, 2, e.span, "rect((x0, y0), (x1, y1))") {
                    return None;
                }
                let a = self.fixed_point(&args[0].value, frame);
                let b = self.fixed_point(&args[1].value, frame);
                let ([x0, y0], [x1, y1]) = (a?, b?);
                Some(Region::Rect { x: [x0.min(x1), x0.max(x1)], y: [y0.min(y1), y0.max(y1)] })
            }
            ExprKind::Call { name, .. } => {
                let close = suggest::closest(&name.value, &["circle", "rect"]);
                self.error_help(
                    Code::UnknownRegion,
                    format!("unknown region `{}`", name.value),
                    name.span,
                    "not a region",
                    suggest_help(
                        &close,
                        "regions are named (penalty_area, …) or circle(x, y, r), rect((x0, y0), (x1, y1))",
                    ),
                );
                None
            }
            _ => {
                self.wrong_type(
                    "a region",
                    e,
                    "write a named region (penalty_area, …), circle(x, y, r) or rect((x0, y0), (x1, y1))",
                );
                None
            }
        }
    }

    /// A starting place: `(x, y)` with coordinates possibly random, `choice[(x, y), …]`, or
    /// `in REGION`. Returns the nominal point and the random spot, if any.
    pub(crate) fn place(&mut self, place: &Place, frame: Frame) -> Option<([f32; 2], Option<Spot>)> {
        match place {
            Place::In(e) => {
                let region = self.region(e, frame)?;
                Some((region.centre(), Some(Spot::In(region))))
            }
            Place::At(e) => self.place_at(e, frame),
        }
    }

    /// `at EXPR` of [`Reader::place`].
    fn place_at(&mut self, e: &Expr, frame: Frame) -> Option<([f32; 2], Option<Spot>)> {
        if let Some(result) = self.through_param(e, |r, v| r.place_at(v, frame)) {
            return result;
        }
        {
            match &e.kind {
                ExprKind::Tuple(args) if args.len() == 2 => {
                    let x = self.sample(&args[0].value, frame, Axis::X);
                    let y = self.sample(&args[1].value, frame, Axis::Y);
                    let (x, y) = (x?, y?);
                    let nominal = [x.nominal(), y.nominal()];
                    let random = !matches!((&x, &y), (Sample::Fixed(_), Sample::Fixed(_)));
                    Some((nominal, random.then_some(Spot::Point { x, y })))
                }
                ExprKind::Index { name, args } if name.value == "choice" => {
                    let points: Vec<Option<[f32; 2]>> =
                        args.iter().map(|a| self.fixed_point(&a.value, frame)).collect();
                    let points = points.into_iter().collect::<Option<Vec<_>>>()?;
                    let Some(&first) = points.first() else {
                        self.error_help(
                            Code::Arguments,
                            "`choice` needs at least one point",
                            e.span,
                            "empty choice",
                            "write `choice[(x1, y1), (x2, y2), …]`",
                        );
                        return None;
                    };
                    Some((first, Some(Spot::OneOf(points))))
                }
                ExprKind::Tuple(args) => {
                    self.point_arity(e, args.len());
                    None
                }
                _ => {
                    self.wrong_type(
                        "a point `(x, y)` or `choice[(x, y), …]`",
                        e,
                        "write `at (x, y)`, `at choice[(x1, y1), (x2, y2)]` or `in REGION`",
                    );
                    None
                }
            }
        }
    }
}

impl Reader<'_> {
    /// `tl::E117` for a point with `n` ≠ 2 coordinates.
    fn point_arity(&mut self, e: &Expr, n: usize) {
        self.error_help(
            Code::Arguments,
            format!("a point has 2 coordinates, found {n}"),
            e.span,
            "not (x, y)",
            "write a point as `(x, y)`: positions are on the ground, so there is no height",
        );
    }
}

/// Whether a param's value is a distribution (`uniform(…)`, `normal(…)`, `choice[…]`).
fn is_distribution(value: &Expr) -> bool {
    matches!(&value.kind, ExprKind::Call { name, .. } if matches!(name.value.as_str(), "uniform" | "normal"))
        || matches!(&value.kind, ExprKind::Index { name, .. } if name.value == "choice")
}

/// The key of a param's shared draw: a hash of its name (FNV-1a), the same in every body and
/// lesson, so that a parent's uses and a child's share it.
fn shared_key(name: &str) -> u32 {
    name.bytes().fold(0x811c_9dc5_u32, |h, b| (h ^ u32::from(b)).wrapping_mul(0x0100_0193))
}

/// Names that are values of their own (`true`, regions, rewards, conditions), never reported as
/// unknown params.
fn is_keyword(name: &str) -> bool {
    matches!(name, "true" | "false") || pitch::region(name).is_some()
}

/// A number for messages: at most 4 decimals, without trailing zeros (`0.1`, not `0.099999994`).
pub(crate) fn short(v: f32) -> String {
    let text = format!("{v:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" { "0".to_owned() } else { text.to_owned() }
}

/// "did you mean …?" for the close names, or `otherwise`.
pub(crate) fn suggest_help(close: &[&str], otherwise: &str) -> String {
    match close {
        [] => otherwise.to_owned(),
        [one] => format!("did you mean `{one}`?"),
        many => {
            format!("did you mean one of {}?", many.iter().map(|c| format!("`{c}`")).collect::<Vec<_>>().join(", "))
        }
    }
}
