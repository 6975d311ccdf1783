//! Typed reading of expressions: booleans, durations, fractions, coordinates with units,
//! distributions, points and regions. Each reader pushes a diagnostic and returns `None` when the
//! expression does not fit.

use touchline_engine::scenario::{Distribution, Region, Sample, Spot};

use super::pitch::{self, BALL_X_METRES, BALL_Y_METRES, PLAYER_X_METRES, PLAYER_Y_METRES};
use crate::diagnostic::{Code, Diagnostic, Diagnostics, Source};
use crate::suggest;
use crate::syntax::{Argument, Expr, ExprKind, Place, Span};

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

/// Reads expressions of one source, collecting diagnostics.
pub(crate) struct Reader<'a> {
    pub(crate) source: &'a Source,
    pub(crate) diags: &'a mut Diagnostics,
}

impl Reader<'_> {
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
        match &e.kind {
            ExprKind::Quantity { value, unit: None, .. } => Some(*value),
            ExprKind::Quantity { unit: Some(u), .. } => {
                self.error_help(
                    Code::WrongUnit,
                    format!("{what} takes a plain number, not `{}`", u.value),
                    u.span,
                    "unit not allowed here",
                    "remove the unit",
                );
                None
            }
            _ => {
                self.wrong_type(&format!("a number ({what})"), e, "write a plain number, e.g. `0.5`");
                None
            }
        }
    }

    /// A number in [0, 1] (a difficulty).
    pub(crate) fn fraction(&mut self, e: &Expr, what: &str) -> Option<f32> {
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
        let value = match &e.kind {
            ExprKind::Quantity { value, unit: None, .. } => *value,
            ExprKind::Quantity { value, unit: Some(u), .. } if u.value == "steps" => *value,
            ExprKind::Quantity { unit: Some(u), .. } => {
                self.error_help(
                    Code::WrongUnit,
                    format!("{what} is a duration in steps, not in `{}`", u.value),
                    u.span,
                    "not a duration unit",
                    "write a whole number of env steps (10 steps = 1 s of game time), e.g. `400` or `400 steps`",
                );
                return None;
            }
            _ => {
                self.wrong_type(
                    &format!("a number of steps ({what})"),
                    e,
                    "write a whole number, e.g. `400` or `400 steps`",
                );
                return None;
            }
        };
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
        match &e.kind {
            ExprKind::Quantity { value, unit: Some(u), .. } if u.value == "m" && *value >= 0.0 => Some(*value as f32),
            ExprKind::Quantity { value, unit: Some(u), .. } if u.value == "m" => {
                self.error_help(
                    Code::OutOfRange,
                    format!("a distance cannot be negative ({value} m)"),
                    e.span,
                    "negative",
                    "write a distance of 0 m or more",
                );
                None
            }
            ExprKind::Quantity { unit, .. } => {
                let span = unit.as_ref().map_or(e.span, |u| u.span);
                self.error_help(
                    Code::WrongUnit,
                    "a distance needs the unit `m`",
                    span,
                    "no distance unit",
                    "write metres, e.g. `5 m`",
                );
                None
            }
            _ => {
                self.wrong_type("a distance in metres", e, "write metres, e.g. `5 m`");
                None
            }
        }
    }

    /// One coordinate as a number: scenario units, or metres with `m`.
    fn coordinate(&mut self, e: &Expr, frame: Frame, axis: Axis) -> Option<f32> {
        match &e.kind {
            ExprKind::Quantity { value, unit: None, .. } => Some(*value as f32),
            ExprKind::Quantity { value, unit: Some(u), .. } if u.value == "m" => {
                Some((value / frame.metres(axis)) as f32)
            }
            ExprKind::Quantity { unit: Some(u), .. } => {
                self.error_help(
                    Code::WrongUnit,
                    format!("a position takes scenario units or metres, not `{}`", u.value),
                    u.span,
                    "not a length unit",
                    "write a plain number (x in [-1, 1], y in [-0.42, 0.42]) or metres, e.g. `10 m`",
                );
                None
            }
            _ => {
                self.wrong_type(
                    "a number",
                    e,
                    "write a plain number (x in [-1, 1], y in [-0.42, 0.42]) or metres, e.g. `10 m`",
                );
                None
            }
        }
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
            Place::At(e) => match &e.kind {
                ExprKind::Tuple(args) if args.len() == 2 => {
                    let x = self.sample(&args[0].value, frame, Axis::X);
                    let y = self.sample(&args[1].value, frame, Axis::Y);
                    let (x, y) = (x?, y?);
                    let nominal = [x.nominal(), y.nominal()];
                    let random = matches!((&x, &y), (Sample::Random(_), _) | (_, Sample::Random(_)));
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
            },
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
