//! [`format_source`]: the canonical layout of a `.tl` file (what `touchline fmt` writes).
//!
//! Two-space indentation, one statement or player a line, single spaces between tokens, `, `
//! after commas, one blank line between definitions. Statement order, number spellings, blank
//! lines between statements (at most one) and every comment are kept: a comment on its own line
//! stays on its own line before the same statement, a comment after a statement stays at the end
//! of that line. Formatting formatted text changes nothing.

use std::fmt::Write;
use std::sync::Arc;

use miette::NamedSource;

use crate::diagnostic::Diagnostic;
use crate::syntax::{
    self, Action, Argument, Behaviour, Condition, ConditionKind, Definition, Expr, ExprKind, Flag, Item, Kind, Place,
    RewardTerm, Span, Spanned, StatementKind,
};

/// Formats `.tl` text; `origin` names it in diagnostics.
///
/// # Errors
/// A `tl::E100` syntax error (nothing else is checked: formatting needs only the grammar).
pub fn format_source(text: &str, origin: &str) -> Result<String, Box<Diagnostic>> {
    let source = Arc::new(NamedSource::new(origin, text.to_owned()));
    let file = syntax::parse(&source)?;
    let mut f = Formatter { text, comments: &file.comments, next: 0, out: String::new() };
    let mut previous: Option<(Span, bool)> = None;
    for item in &file.items {
        let (span, is_import) = match item {
            Item::Import(p) => (p.span, true),
            Item::Definition(d) => (d.span, false),
        };
        // Imports stay together; definitions get a blank line before them.
        if let Some((_, was_import)) = previous
            && !(is_import && was_import)
        {
            f.out.push('\n');
        }
        match item {
            Item::Import(p) => {
                f.leading(p.span.start, 0);
                let _ = write!(f.out, "import \"{}\"", p.value);
                f.trailing(p.span.end);
            }
            Item::Definition(d) => f.definition(d),
        }
        previous = Some((span, is_import));
    }
    f.leading(text.len(), 0);
    Ok(f.out)
}

struct Formatter<'a> {
    text: &'a str,
    comments: &'a [Spanned<String>],
    /// Index of the first comment not yet written.
    next: usize,
    out: String,
}

impl Formatter<'_> {
    /// Writes, each on its own line at `indent`, the comments that start before `before`.
    fn leading(&mut self, before: usize, indent: usize) {
        while let Some(c) = self.comments.get(self.next).filter(|c| c.span.start < before) {
            let _ = writeln!(self.out, "{:indent$}{}", "", c.value.trim_end());
            self.next += 1;
            // Keep one empty line where the source separates the comment from what follows.
            let following = self.comments.get(self.next).map_or(before, |n| n.span.start.min(before));
            if following <= self.text.len() && self.blank_between(c.span.end, following) {
                self.out.push('\n');
            }
        }
    }

    /// Ends the current line, first appending the next comment if it sits on the same source
    /// line right after `end`.
    fn trailing(&mut self, end: usize) {
        self.trailing_before(end, usize::MAX);
    }

    /// As [`Formatter::trailing`], for a comment that starts before `limit` (the next node).
    fn trailing_before(&mut self, end: usize, limit: usize) {
        if let Some(c) = self.comments.get(self.next)
            && c.span.start >= end
            && c.span.start < limit
            && !self.text[end..c.span.start].contains('\n')
        {
            let _ = write!(self.out, " {}", c.value.trim_end());
            self.next += 1;
        }
        self.out.push('\n');
    }

    /// Whether the source has an empty line between `from` and `to`.
    fn blank_between(&self, from: usize, to: usize) -> bool {
        let between = &self.text[from.min(to)..to];
        let lines: Vec<&str> = between.split('\n').collect();
        lines.len() > 2 && lines[1..lines.len() - 1].iter().any(|l| l.trim().is_empty())
    }

    fn definition(&mut self, d: &Definition) {
        self.leading(d.span.start, 0);
        for doc in &d.docs {
            if doc.is_empty() {
                self.out.push_str("///\n");
            } else {
                let _ = writeln!(self.out, "/// {doc}");
            }
        }
        let kind = if d.kind == Kind::Scenario { "scenario" } else { "preset" };
        let _ = write!(self.out, "{kind} {} {{", d.name.value);
        self.trailing_before(d.name.span.end, d.statements.first().map_or(d.span.end, |s| s.span.start));
        let mut previous_end = None;
        for st in &d.statements {
            if let Some(end) = previous_end
                && self.blank_between(end, st.span.start)
            {
                self.out.push('\n');
            }
            self.statement(&st.kind, st.span);
            previous_end = Some(st.span.end);
        }
        self.leading(d.span.end, 2);
        self.out.push('}');
        self.trailing(d.span.end);
    }

    /// Writes `curriculum { … }` at `indent`: one lesson or `advance when` a line, a lesson's
    /// statements one a line inside its braces.
    fn curriculum(&mut self, c: &syntax::Curriculum, span: Span, indent: usize) {
        self.leading(span.start, indent);
        let _ = write!(self.out, "{:indent$}curriculum {{", "");
        let mut items: Vec<(Span, Option<&syntax::Lesson>, Option<&syntax::Advance>)> = c
            .lessons
            .iter()
            .map(|l| (l.span, Some(l), None))
            .chain(c.advance.iter().map(|a| (a.span, None, Some(a))))
            .collect();
        items.sort_by_key(|(s, _, _)| s.start);
        self.trailing_before(span.start + "curriculum".len(), items.first().map_or(span.end, |i| i.0.start));
        let inner = indent + 2;
        for (item_span, lesson, advance) in items {
            if let Some(a) = advance {
                self.leading(item_span.end, inner);
                let _ = write!(self.out, "{:inner$}{}", "", advance_text(a));
                self.trailing(item_span.end);
                continue;
            }
            let Some(l) = lesson else { continue };
            self.leading(l.name.span.start, inner);
            let _ = write!(self.out, "{:inner$}lesson {}", "", l.name.value);
            if let Some(p) = &l.parent {
                let _ = write!(self.out, " extends {}", p.value);
            }
            if l.statements.is_empty() && !self.has_comment_before(item_span.end) {
                self.trailing(item_span.end);
                continue;
            }
            self.out.push_str(" {");
            let header_end = l.parent.as_ref().map_or(l.name.span.end, |p| p.span.end);
            self.trailing_before(header_end, l.statements.first().map_or(item_span.end, |s| s.span.start));
            for st in &l.statements {
                self.statement_at(&st.kind, st.span, inner + 2);
            }
            self.leading(item_span.end, inner + 2);
            let _ = write!(self.out, "{:inner$}}}", "");
            self.trailing(item_span.end);
        }
        self.leading(span.end, inner);
        let _ = write!(self.out, "{:indent$}}}", "");
        self.trailing(span.end);
    }

    fn statement(&mut self, kind: &StatementKind, span: Span) {
        self.statement_at(kind, span, 2);
    }

    fn statement_at(&mut self, kind: &StatementKind, span: Span, indent: usize) {
        if let StatementKind::Curriculum(c) = kind {
            self.curriculum(c, span, indent);
            return;
        }
        if indent != 2 {
            // Inside a lesson: one line per statement (a team block on one line too).
            self.leading(span.end, indent);
            let _ = write!(self.out, "{:indent$}{}", "", statement_line(kind));
            self.trailing(span.end);
            return;
        }
        if let StatementKind::Team(t) = kind
            && t.block
        {
            self.leading(span.start, 2);
            let _ = write!(self.out, "  team {}", side(t.side.value));
            if let Some(fm) = &t.formation {
                let _ = write!(self.out, " formation \"{}\"", fm.value);
            }
            if t.players.is_empty() && !self.has_comment_before(span.end) {
                self.out.push_str(" {}");
                self.trailing(span.end);
                return;
            }
            self.out.push_str(" {");
            let header_end = t.side.span.end.max(t.formation.as_ref().map_or(0, |f| f.span.end));
            self.trailing_before(header_end, t.players.first().map_or(span.end, |p| p.span.start));
            for p in &t.players {
                self.leading(p.span.end, 4);
                let _ = write!(self.out, "    {} {}", p.role.value, place(&p.place));
                for flag in &p.flags {
                    self.out.push_str(&flag_text(&flag.value));
                }
                if let Some(b) = &p.behaviour {
                    let _ = write!(self.out, " {}", behaviour(b));
                }
                self.trailing(p.span.end);
            }
            self.leading(span.end, 4);
            self.out.push_str("  }");
            self.trailing(span.end);
            return;
        }
        self.leading(span.end, 2);
        let line = statement_line(kind);
        let _ = write!(self.out, "  {line}");
        self.trailing(span.end);
    }

    fn has_comment_before(&self, end: usize) -> bool {
        self.comments.get(self.next).is_some_and(|c| c.span.start < end)
    }
}

/// A statement on one line (a team's players, if any, inline in braces).
fn statement_line(kind: &StatementKind) -> String {
    match kind {
        StatementKind::Extends(n) => format!("extends {}", n.value),
        StatementKind::Ball(p) => format!("ball {}", place(p)),
        StatementKind::OddBall(p) => format!("on odd episodes ball {}", place(p)),
        StatementKind::SwapTeams => "on odd episodes swap teams".to_owned(),
        StatementKind::Team(t) => {
            let mut s = format!("team {}", side(t.side.value));
            if let Some(fm) = &t.formation {
                let _ = write!(s, " formation \"{}\"", fm.value);
            }
            if t.block {
                s.push_str(" {");
                for p in &t.players {
                    let _ = write!(s, " {} {}", p.role.value, place(&p.place));
                    for flag in &p.flags {
                        s.push_str(&flag_text(&flag.value));
                    }
                    if let Some(b) = &p.behaviour {
                        let _ = write!(s, " {}", behaviour(b));
                    }
                }
                s.push_str(" }");
            }
            s
        }
        StatementKind::Require { lhs, at_least, rhs } => {
            format!("require {} {} {}", expr(lhs), if *at_least { ">=" } else { "<=" }, expr(rhs))
        }
        StatementKind::Reward { terms, weight } => {
            let terms: Vec<String> = terms
                .iter()
                .map(|t| match t {
                    RewardTerm::Script(p) => format!("script \"{}\"", p.value),
                    RewardTerm::Expr(e) => expr(e),
                })
                .collect();
            let mut s = format!("reward {}", terms.join(" + "));
            if let Some(w) = weight {
                let _ = write!(s, " weight {}", expr(w));
            }
            s
        }
        StatementKind::RewardOn(ro) => reward_on(ro),
        StatementKind::End(conditions) => {
            let c: Vec<String> = conditions.iter().map(condition).collect();
            format!("end when {}", c.join(" or "))
        }
        StatementKind::Behaviour { player, behaviour: b } => {
            format!("behaviour {} {}", expr(player), behaviour(b))
        }
        StatementKind::StartFrom(p) => format!("start from \"{}\"", p.value),
        StatementKind::StartWith(w) => {
            let mut s = format!("start with {}", w.restart.value);
            if let Some(t) = &w.team {
                let _ = write!(s, " for {}", t.value);
            }
            if let Some(at) = &w.at {
                let _ = write!(s, " at {}", expr(at));
            }
            s
        }
        StatementKind::Setting { key, value } => format!("{} {}", key.value, expr(value)),
        StatementKind::Param { name, value } => format!("param {} = {}", name.value, expr(value)),
        StatementKind::Assign { name, value } => format!("{} = {}", name.value, expr(value)),
        StatementKind::Advance(a) => advance_text(a),
        // Written by `Formatter::curriculum`; a curriculum inside a lesson (an error) on one line.
        StatementKind::Curriculum(_) => "curriculum {}".to_owned(),
    }
}

fn advance_text(a: &syntax::Advance) -> String {
    let thresholds: Vec<String> = a
        .thresholds
        .iter()
        .map(|t| format!("{} {} {}", t.metric.value, if t.at_least { ">=" } else { "<=" }, expr(&t.value)))
        .collect();
    let mut s = format!("advance when {} over {}", thresholds.join(" and "), expr(&a.window));
    if let Some(m) = &a.min {
        let _ = write!(s, " min {}", expr(m));
    }
    s
}

fn flag_text(f: &Flag) -> String {
    match f {
        Flag::Lazy => " lazy".to_owned(),
        Flag::Controllable => " controllable".to_owned(),
        Flag::NotControllable => " not controllable".to_owned(),
        Flag::Facing(e) => format!(" facing {}", expr(e)),
    }
}

fn side(s: syntax::Side) -> &'static str {
    match s {
        syntax::Side::Left => "left",
        syntax::Side::Right => "right",
    }
}

fn place(p: &Place) -> String {
    match p {
        Place::At(e) => format!("at {}", expr(e)),
        Place::In(e) => format!("in {}", expr(e)),
    }
}

/// `does A then B until C …`, without the optional `do` words.
fn behaviour(b: &Behaviour) -> String {
    let stages: Vec<String> = b
        .stages
        .iter()
        .map(|st| {
            let mut text = match &st.action {
                Action::Script(p) => format!("script \"{}\"", p.value),
                Action::Expr(e) => expr(e),
            };
            if st.shoot.is_some() {
                text.push_str(" then shoot");
            }
            if let Some(c) = &st.until {
                let _ = write!(text, " until {}", condition(c));
            }
            text
        })
        .collect();
    format!("does {}", stages.join(" then "))
}

/// A condition as written: the parse tree keeps parentheses, so precedence comes out unchanged.
fn condition(c: &Condition) -> String {
    match &c.kind {
        ConditionKind::Any(parts) => parts.iter().map(condition).collect::<Vec<_>>().join(" or "),
        ConditionKind::All(parts) => parts.iter().map(condition).collect::<Vec<_>>().join(" and "),
        ConditionKind::Not(inner) => format!("not {}", condition(inner)),
        ConditionKind::Group(inner) => format!("({})", condition(inner)),
        ConditionKind::Compare { lhs, op, rhs } => format!("{} {} {}", expr(lhs), op.value, expr(rhs)),
        ConditionKind::In { what, region } => format!("{} in {}", expr(what), expr(region)),
        ConditionKind::Is { what, value } => format!("{} is {}", expr(what), expr(value)),
        ConditionKind::Script(p) => format!("script \"{}\"", p.value),
        ConditionKind::Name(n) => n.value.clone(),
    }
}

/// `reward on A then any of (B, C) once 0.5`.
fn reward_on(ro: &syntax::RewardOn) -> String {
    let steps: Vec<String> = ro
        .sequence
        .iter()
        .map(|step| match step {
            syntax::EventStep::One(e) => event(e),
            syntax::EventStep::Group { all, events, .. } => {
                let events: Vec<String> = events.iter().map(event).collect();
                format!("{} of ({})", if *all { "all" } else { "any" }, events.join(", "))
            }
        })
        .collect();
    let mut s = format!("reward on {}", steps.join(" then "));
    for r in &ro.repeats {
        s.push_str(match r.value {
            syntax::Repeat::Once => " once",
            syntax::Repeat::EachTime => " each time",
        });
    }
    let _ = write!(s, " {}", expr(&ro.value));
    s
}

fn event(e: &syntax::Event) -> String {
    let mut s = e.name.value.clone();
    if let Some((word, region)) = &e.region {
        let _ = write!(s, " {} {}", word.value, expr(region));
    }
    if let Some((word, target)) = &e.scope {
        let _ = write!(s, " {} {}", word.value, target.value);
    }
    s
}

fn arguments(args: &[Argument]) -> String {
    args.iter()
        .map(|a| match &a.name {
            Some(n) => format!("{}: {}", n.value, expr(&a.value)),
            None => expr(&a.value),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// An expression as the formatter writes it (for messages that quote a value).
pub(crate) fn expr_text(e: &Expr) -> String {
    expr(e)
}

fn expr(e: &Expr) -> String {
    match &e.kind {
        ExprKind::Call { name, args } => format!("{}({})", name.value, arguments(args)),
        ExprKind::Index { name, args } => format!("{}[{}]", name.value, arguments(args)),
        ExprKind::Tuple(args) => format!("({})", arguments(args)),
        ExprKind::Quantity { text, unit: Some(u), .. } => format!("{text} {}", u.value),
        ExprKind::Quantity { text, unit: None, .. } => text.clone(),
        ExprKind::Str(s) => format!("\"{s}\""),
        ExprKind::Path { head, field: Some(f) } => format!("{}.{}", head.value, f.value),
        ExprKind::Path { head, field: None } => head.value.clone(),
        ExprKind::Binary { op, lhs, rhs } => format!("{} {} {}", expr(lhs), op.symbol(), expr(rhs)),
        ExprKind::Negation(inner) => format!("-{}", expr(inner)),
        ExprKind::Paren(inner) => format!("({})", expr(inner)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MESSY: &str = "// header comment\nimport   \"a.tl\"\n/// Docs.\nscenario   s{extends academy // parent\n\n\n  ball at(0.5,uniform( -0.1 ,0.1 ))\n team left{GK at (-1,0) lazy\n // a keeper above\n CB in circle(0.5 ,0, 5 m)}\n  end when score or\n   // why steps\n   steps>=200\n  reward scoring+checkpoint(count:5) weight 0.5 }\n// trailing\n";

    #[test]
    fn canonical_layout_keeps_comments() {
        let out = format_source(MESSY, "m.tl").unwrap();
        assert!(!out.contains(" \n"), "no trailing spaces:\n{out}");
        assert!(out.starts_with("// header comment\nimport \"a.tl\"\n\n/// Docs.\nscenario s {\n"), "{out}");
        assert!(
            out.contains("scenario s {\n  extends academy // parent\n\n  ball at (0.5, uniform(-0.1, 0.1))\n"),
            "{out}"
        );
        assert!(
            out.contains(
                "  team left {\n    GK at (-1, 0) lazy\n    // a keeper above\n    CB in circle(0.5, 0, 5 m)\n  }\n"
            ),
            "{out}"
        );
        assert!(out.contains("  // why steps\n  end when score or steps >= 200\n"), "{out}");
        assert!(out.contains("  reward scoring + checkpoint(count: 5) weight 0.5\n}\n"), "{out}");
        assert!(out.ends_with("}\n// trailing\n"), "{out}");
        for c in ["// header comment", "// parent", "// a keeper above", "// why steps", "// trailing"] {
            assert_eq!(out.matches(c).count(), 1, "{c} in\n{out}");
        }
    }

    #[test]
    fn formatting_is_a_fixed_point() {
        let once = format_source(MESSY, "m.tl").unwrap();
        assert_eq!(format_source(&once, "m.tl").unwrap(), once);
        for name in crate::stdlib::names().iter().copied().chain(crate::stdlib::test_names()) {
            let text = crate::stdlib::tl_source(name).unwrap();
            let once = format_source(text, name).unwrap();
            assert_eq!(once, text, "stdlib sources are formatted: {name}");
        }
        let prelude = format_source(crate::PRELUDE, "prelude.tl").unwrap();
        assert_eq!(prelude, crate::PRELUDE);
    }
}
