//! Text to syntax tree: the pest parser derived from `grammar/scenario.pest` and the conversion of
//! its parse tree into [`ast`] types with spans.

pub mod ast;
mod error;
mod nesting;

use pest::Parser;
use pest::iterators::Pair;

pub use ast::*;
pub use nesting::MAX_NESTING;

use crate::diagnostic::{Diagnostic, Source};

/// The parser pest derives from the grammar file (its `Rule` enum is generated, hence undocumented).
#[allow(missing_docs, unreachable_pub)]
mod generated {
    #[derive(pest_derive::Parser)]
    #[grammar = "../../grammar/scenario.pest"]
    pub struct ScenarioParser;
}

use error::syntax_error;
use generated::{Rule, ScenarioParser};

/// Parses a whole `.tl` text.
///
/// # Errors
/// A `tl::E100` diagnostic at the first place the text leaves the grammar; `tl::E148` at the
/// first place it nests deeper than [`MAX_NESTING`] levels (checked first, since parsing such
/// text would overflow the stack).
pub fn parse(source: &Source) -> Result<File, Box<Diagnostic>> {
    let text = source.inner().as_str();
    if let Some(deep) = nesting::scan(text) {
        return Err(Box::new(too_deep(deep, source)));
    }
    let mut pairs = ScenarioParser::parse(Rule::file, text).map_err(|e| Box::new(syntax_error(e, source)))?;
    let mut file = File::default();
    let root = pairs.next().expect("the file rule always yields one pair");
    if let Some(deep) = nesting::tree_depth(root.clone()) {
        return Err(Box::new(too_deep(deep, source)));
    }
    for pair in root.into_inner() {
        match pair.as_rule() {
            Rule::import => file.items.push(Item::Import(string(first(pair)))),
            Rule::definition => file.items.push(Item::Definition(definition(pair, &mut file.comments))),
            Rule::COMMENT => file.comments.push(spanned(&pair, pair.as_str().to_owned())),
            _ => {}
        }
    }
    // Comments inside definitions were gathered as they were met; keep them in source order.
    file.comments.sort_by_key(|c| c.span.start);
    Ok(file)
}

/// `tl::E148` at the token where the text nests deeper than [`MAX_NESTING`].
fn too_deep(deep: nesting::TooDeep, source: &Source) -> Diagnostic {
    Diagnostic::new(
        crate::diagnostic::Code::TooDeep,
        format!("nested too deeply: more than {MAX_NESTING} {}", deep.what),
        source,
        deep.span,
        format!("level {} starts here", MAX_NESTING + 1),
    )
    .with_help("write it flatter: name a part with `param`, or split a long sum or condition")
}

/// The pair's span without trailing whitespace and comments: pest gives a pair that ends in an
/// optional or repeated part (`flag*`) the spaces after it, but a label should end on its last
/// token.
fn span_of(pair: &Pair<'_, Rule>) -> Span {
    let s = pair.as_span();
    let (start, text) = (s.start(), s.as_str());
    let mut end = start + text.trim_end().len();
    if text[..end - start].rsplit('\n').next().is_some_and(|line| line.contains("//")) {
        let comments: Vec<(usize, usize)> = pair
            .clone()
            .into_inner()
            .flatten()
            .filter(|p| p.as_rule() == Rule::COMMENT)
            .map(|p| (p.as_span().start(), p.as_span().start() + p.as_str().trim_end().len()))
            .collect();
        while let Some(&(c, _)) = comments.iter().find(|&&(c, c_end)| c_end == end && c > start) {
            end = start + text[..c - start].trim_end().len();
        }
    }
    Span { start, end }
}

fn spanned<T>(pair: &Pair<'_, Rule>, value: T) -> Spanned<T> {
    Spanned { value, span: span_of(pair) }
}

/// The inner pairs without comments.
fn inner<'i>(pair: Pair<'i, Rule>) -> impl Iterator<Item = Pair<'i, Rule>> {
    pair.into_inner().filter(|p| p.as_rule() != Rule::COMMENT)
}

fn first(pair: Pair<'_, Rule>) -> Pair<'_, Rule> {
    inner(pair).next().expect("the grammar guarantees an inner pair")
}

fn string(pair: Pair<'_, Rule>) -> Spanned<String> {
    let span = span_of(&pair);
    let text = pair.into_inner().next().map_or("", |t| t.as_str()).to_owned();
    Spanned { value: text, span }
}

/// Collects every comment below `pair` into `comments`.
fn gather_comments(pair: &Pair<'_, Rule>, comments: &mut Vec<Spanned<String>>) {
    for p in pair.clone().into_inner().flatten() {
        if p.as_rule() == Rule::COMMENT {
            comments.push(spanned(&p, p.as_str().to_owned()));
        }
    }
}

fn definition(pair: Pair<'_, Rule>, comments: &mut Vec<Spanned<String>>) -> Definition {
    gather_comments(&pair, comments);
    let span = span_of(&pair);
    let mut docs = Vec::new();
    let mut kind = Kind::Scenario;
    let mut name = Spanned { value: String::new(), span };
    let mut statements = Vec::new();
    for p in inner(pair) {
        match p.as_rule() {
            Rule::doc => {
                let text = p.into_inner().next().map_or("", |t| t.as_str());
                docs.push(text.strip_prefix(' ').unwrap_or(text).trim_end().to_owned());
            }
            Rule::kind => kind = if p.as_str() == "preset" { Kind::Preset } else { Kind::Scenario },
            Rule::name => name = spanned(&p, p.as_str().to_owned()),
            _ => statements.push(statement(p)),
        }
    }
    Definition { docs, kind, name, statements, span }
}

fn statement(pair: Pair<'_, Rule>) -> Statement {
    let span = span_of(&pair);
    let kind = match pair.as_rule() {
        Rule::extends => {
            let n = first(pair);
            StatementKind::Extends(spanned(&n, n.as_str().to_owned()))
        }
        Rule::ball => StatementKind::Ball(place(first(pair))),
        Rule::on_odd => {
            let p = first(pair);
            match p.as_rule() {
                Rule::ball => StatementKind::OddBall(place(first(p))),
                _ => StatementKind::SwapTeams,
            }
        }
        Rule::team => StatementKind::Team(team(pair)),
        Rule::require => {
            let mut it = inner(pair);
            let lhs = expr(it.next().expect("lhs"));
            let at_least = it.next().is_some_and(|c| c.as_str() == ">=");
            let rhs = expr(it.next().expect("rhs"));
            StatementKind::Require { lhs, at_least, rhs }
        }
        Rule::reward => {
            let mut terms = Vec::new();
            let mut weight = None;
            for p in inner(pair) {
                match p.as_rule() {
                    Rule::reward_term => {
                        let t = first(p);
                        terms.push(match t.as_rule() {
                            Rule::script => RewardTerm::Script(string(first(t))),
                            _ => RewardTerm::Expr(expr(t)),
                        });
                    }
                    _ => weight = Some(expr(first(p))),
                }
            }
            StatementKind::Reward { terms, weight }
        }
        Rule::reward_on => StatementKind::RewardOn(reward_on(pair)),
        Rule::end => {
            let c = condition(first(pair));
            StatementKind::End(match c.kind {
                ConditionKind::Any(cs) => cs,
                _ => vec![c],
            })
        }
        Rule::behaviour_statement => {
            let mut it = inner(pair).filter(|p| p.as_rule() != Rule::behaviour_kw);
            let player = expr(it.next().expect("player"));
            let behaviour = does(it.next().expect("does"));
            StatementKind::Behaviour { player, behaviour }
        }
        Rule::start_from => StatementKind::StartFrom(string(first(pair))),
        Rule::start_with => {
            let mut it = inner(pair);
            let r = it.next().expect("restart");
            let restart = spanned(&r, r.as_str().to_owned());
            let (mut team, mut at) = (None, None);
            for p in it {
                match p.as_rule() {
                    Rule::start_team => {
                        let t = inner(p).find(|t| t.as_rule() == Rule::ident).expect("team");
                        team = Some(spanned(&t, t.as_str().to_owned()));
                    }
                    _ => at = Some(expr(first(p))),
                }
            }
            StatementKind::StartWith(StartWith { restart, team, at })
        }
        Rule::param | Rule::assignment => {
            let is_param = pair.as_rule() == Rule::param;
            let mut it = inner(pair);
            let n = it.next().expect("name");
            let name = spanned(&n, n.as_str().to_owned());
            let value = expr(it.next().expect("value"));
            if is_param { StatementKind::Param { name, value } } else { StatementKind::Assign { name, value } }
        }
        Rule::curriculum => {
            let mut c = Curriculum { lessons: Vec::new(), advance: Vec::new() };
            for p in inner(pair) {
                match p.as_rule() {
                    Rule::lesson => c.lessons.push(lesson(p)),
                    _ => c.advance.push(advance(p)),
                }
            }
            StatementKind::Curriculum(c)
        }
        Rule::advance => StatementKind::Advance(advance(pair)),
        _ => {
            let mut it = inner(pair);
            let k = it.next().expect("key");
            let key = spanned(&k, k.as_str().to_owned());
            let value = expr(it.next().expect("value"));
            StatementKind::Setting { key, value }
        }
    };
    Statement { kind, span }
}

fn lesson(pair: Pair<'_, Rule>) -> Lesson {
    let span = span_of(&pair);
    let mut it = inner(pair);
    let n = it.next().expect("name");
    let name = spanned(&n, n.as_str().to_owned());
    let mut parent = None;
    let mut statements = Vec::new();
    for p in it {
        match p.as_rule() {
            Rule::lesson_parent => {
                let n = first(p);
                parent = Some(spanned(&n, n.as_str().to_owned()));
            }
            _ => statements.push(statement(p)),
        }
    }
    Lesson { name, parent, statements, span }
}

fn advance(pair: Pair<'_, Rule>) -> Advance {
    let span = span_of(&pair);
    let mut thresholds = Vec::new();
    let mut window = None;
    let mut min = None;
    for p in inner(pair) {
        match p.as_rule() {
            Rule::threshold => {
                let mut it = inner(p);
                let m = it.next().expect("metric");
                let metric = spanned(&m, m.as_str().to_owned());
                let at_least = it.next().is_some_and(|c| c.as_str() == ">=");
                let value = expr(it.next().expect("bound"));
                thresholds.push(Threshold { metric, at_least, value });
            }
            Rule::advance_min => min = Some(expr(first(p))),
            _ => window = Some(expr(p)),
        }
    }
    Advance { thresholds, window: window.expect("the grammar requires `over`"), min, span }
}

fn team(pair: Pair<'_, Rule>) -> Team {
    let mut t = Team {
        side: Spanned { value: Side::Left, span: Span::default() },
        formation: None,
        players: Vec::new(),
        block: pair.as_str().contains('{'),
    };
    for p in inner(pair) {
        match p.as_rule() {
            Rule::side => t.side = spanned(&p, if p.as_str() == "left" { Side::Left } else { Side::Right }),
            Rule::formation => t.formation = Some(string(first(p))),
            _ => t.players.push(player(p)),
        }
    }
    t
}

fn player(pair: Pair<'_, Rule>) -> Player {
    let span = span_of(&pair);
    let mut it = inner(pair);
    let r = it.next().expect("role");
    let role = spanned(&r, r.as_str().to_owned());
    let place = place(it.next().expect("place"));
    let mut behaviour = None;
    let flags = it
        .filter(|f| {
            if f.as_rule() == Rule::does {
                behaviour = Some(does(f.clone()));
                return false;
            }
            true
        })
        .map(|f| {
            let kind = first(f.clone());
            let flag = match kind.as_rule() {
                Rule::lazy => Flag::Lazy,
                Rule::not_controllable => Flag::NotControllable,
                Rule::facing => {
                    let value = inner(kind).find(|v| v.as_rule() == Rule::operand_expr).expect("facing value");
                    Flag::Facing(expr(value))
                }
                _ => Flag::Controllable,
            };
            spanned(&f, flag)
        })
        .collect();
    Player { role, place, flags, behaviour, span }
}

fn place(pair: Pair<'_, Rule>) -> Place {
    let p = first(pair);
    let is_at = p.as_rule() == Rule::at_place;
    let e = expr(first(p));
    if is_at { Place::At(e) } else { Place::In(e) }
}

fn reward_on(pair: Pair<'_, Rule>) -> RewardOn {
    let mut sequence = Vec::new();
    let mut repeats = Vec::new();
    let mut value = None;
    for p in inner(pair) {
        match p.as_rule() {
            Rule::event_sequence => {
                for step in inner(p).filter(|s| s.as_rule() == Rule::event_step) {
                    sequence.push(event_step(first(step)));
                }
            }
            Rule::repeat => {
                let r = first(p);
                let kind = if r.as_rule() == Rule::once { Repeat::Once } else { Repeat::EachTime };
                repeats.push(spanned(&r, kind));
            }
            _ => value = Some(expr(p)),
        }
    }
    RewardOn { sequence, repeats, value: value.expect("the grammar requires a value") }
}

fn event_step(pair: Pair<'_, Rule>) -> EventStep {
    if pair.as_rule() == Rule::event {
        return EventStep::One(Box::new(event(pair)));
    }
    let span = span_of(&pair);
    let mut it = inner(pair);
    let all = first(it.next().expect("group kind")).as_rule() == Rule::all_of;
    EventStep::Group { all, events: it.map(event).collect(), span }
}

fn event(pair: Pair<'_, Rule>) -> Event {
    let span = span_of(&pair);
    let mut it = inner(pair);
    let n = it.next().expect("event name");
    let mut e = Event { name: spanned(&n, n.as_str().to_owned()), region: None, scope: None, span };
    for p in it {
        let rule = p.as_rule();
        let mut parts = inner(p);
        let word = parts.next().expect("word");
        let word = spanned(&word, word.as_str().to_owned());
        let rest = parts.next().expect("region or scope");
        if rule == Rule::event_region {
            e.region = Some((word, expr(rest)));
        } else {
            e.scope = Some((word, spanned(&rest, rest.as_str().to_owned())));
        }
    }
    e
}

/// `does STAGE then STAGE …`.
fn does(pair: Pair<'_, Rule>) -> Behaviour {
    let span = span_of(&pair);
    let stages = inner(pair).filter(|p| p.as_rule() == Rule::stage).map(stage).collect();
    Behaviour { stages, span }
}

fn stage(pair: Pair<'_, Rule>) -> Stage {
    let span = span_of(&pair);
    let mut stage = Stage { action: Action::Expr(placeholder(span)), shoot: None, until: None, span };
    for p in inner(pair) {
        match p.as_rule() {
            Rule::action => {
                let a = first(p);
                stage.action = match a.as_rule() {
                    Rule::script => Action::Script(string(first(a))),
                    _ => Action::Expr(expr(a)),
                };
            }
            Rule::shoot => stage.shoot = Some(span_of(&p)),
            Rule::until => stage.until = inner(p).find(|c| c.as_rule() == Rule::condition).map(condition),
            _ => {}
        }
    }
    stage
}

/// An expression that is never shown: the grammar guarantees every stage an action.
fn placeholder(span: Span) -> Expr {
    Expr { kind: ExprKind::Tuple(Vec::new()), span }
}

/// `condition`, `conjunction`, `negation`, `atom` or `group` pairs to a [`Condition`]; one-element
/// `or`/`and` lists collapse to their element.
fn condition(pair: Pair<'_, Rule>) -> Condition {
    let span = span_of(&pair);
    match pair.as_rule() {
        Rule::condition | Rule::conjunction => {
            let is_or = pair.as_rule() == Rule::condition;
            let mut parts: Vec<Condition> =
                inner(pair).filter(|p| !matches!(p.as_rule(), Rule::or_kw | Rule::and_kw)).map(condition).collect();
            if parts.len() == 1 {
                return parts.pop().expect("one part");
            }
            let kind = if is_or { ConditionKind::Any(parts) } else { ConditionKind::All(parts) };
            Condition { kind, span }
        }
        Rule::negation => {
            let mut it = inner(pair);
            let p = it.next().expect("negation part");
            if p.as_rule() == Rule::not_kw {
                let operand = condition(it.next().expect("operand"));
                Condition { kind: ConditionKind::Not(Box::new(operand)), span }
            } else {
                condition(p)
            }
        }
        Rule::atom => condition(first(pair)),
        Rule::group => Condition { kind: ConditionKind::Group(Box::new(condition(first(pair)))), span },
        Rule::script => Condition { kind: ConditionKind::Script(string(first(pair))), span },
        Rule::relation => {
            let mut it = inner(pair);
            let lhs = expr(it.next().expect("lhs"));
            let op = it.next().expect("operator");
            let rhs = expr(it.next().expect("rhs"));
            let kind = match op.as_rule() {
                Rule::in_kw => ConditionKind::In { what: lhs, region: rhs },
                Rule::is_kw => ConditionKind::Is { what: lhs, value: rhs },
                _ => ConditionKind::Compare { lhs, op: spanned(&op, op.as_str().to_owned()), rhs },
            };
            Condition { kind, span }
        }
        _ => Condition { kind: ConditionKind::Name(spanned(&pair, pair.as_str().to_owned())), span },
    }
}

fn expr(pair: Pair<'_, Rule>) -> Expr {
    match pair.as_rule() {
        // Operands and operators in a row, folded by precedence (left-associative).
        Rule::expr => {
            let mut operands = Vec::new();
            let mut ops = Vec::new();
            for p in inner(pair) {
                if p.as_rule() == Rule::binary_op {
                    ops.push(match p.as_str() {
                        "+" => BinaryOp::Add,
                        "-" => BinaryOp::Sub,
                        "*" => BinaryOp::Mul,
                        _ => BinaryOp::Div,
                    });
                } else {
                    operands.push(operand(p));
                }
            }
            fold(operands, &ops)
        }
        Rule::operand_expr => operand(first(pair)),
        _ => operand(pair),
    }
}

/// Folds `operands[0] ops[0] operands[1] …` into a tree: `*` `/` first, then `+` `-`, each
/// left to right.
fn fold(operands: Vec<Expr>, ops: &[BinaryOp]) -> Expr {
    let mut operands = operands.into_iter();
    let mut output: Vec<Expr> = vec![operands.next().expect("an expression has an operand")];
    let mut pending: Vec<BinaryOp> = Vec::new();
    let reduce = |output: &mut Vec<Expr>, op: BinaryOp| {
        let rhs = output.pop().expect("rhs");
        let lhs = output.pop().expect("lhs");
        let span = Span::join(lhs.span, rhs.span);
        output.push(Expr { kind: ExprKind::Binary { op, lhs: Box::new(lhs), rhs: Box::new(rhs) }, span });
    };
    for (&op, rhs) in ops.iter().zip(operands) {
        while let Some(&top) = pending.last().filter(|top| top.precedence() >= op.precedence()) {
            pending.pop();
            reduce(&mut output, top);
        }
        pending.push(op);
        output.push(rhs);
    }
    while let Some(op) = pending.pop() {
        reduce(&mut output, op);
    }
    output.pop().expect("one expression left")
}

fn operand(e: Pair<'_, Rule>) -> Expr {
    let span = span_of(&e);
    let kind = match e.as_rule() {
        Rule::call | Rule::index => {
            let is_call = e.as_rule() == Rule::call;
            let mut it = inner(e);
            let n = it.next().expect("name");
            let name = spanned(&n, n.as_str().to_owned());
            let args = it.next().map(arguments).unwrap_or_default();
            if is_call { ExprKind::Call { name, args } } else { ExprKind::Index { name, args } }
        }
        Rule::tuple => {
            // `(a)` without a trailing comma groups; `(a,)` and `(a, b)` are tuples.
            let trailing_comma = e.as_str().trim_end_matches(')').trim_end().ends_with(',');
            let mut args = arguments(first(e));
            if args.len() == 1 && args[0].name.is_none() && !trailing_comma {
                ExprKind::Paren(Box::new(args.pop().expect("one argument").value))
            } else {
                ExprKind::Tuple(args)
            }
        }
        Rule::quantity => {
            let mut it = e.into_inner();
            let n = it.next().expect("number");
            let text = n.as_str().to_owned();
            let value = text.parse::<f64>().unwrap_or(f64::NAN);
            let unit = it.next().map(|u| spanned(&u, u.as_str().to_owned()));
            ExprKind::Quantity { text, value, unit }
        }
        Rule::string => ExprKind::Str(string(e).value),
        Rule::minus => ExprKind::Negation(Box::new(operand(first(e)))),
        _ => {
            let mut it = inner(e);
            let h = it.next().expect("head");
            let head = spanned(&h, h.as_str().to_owned());
            let field = it.next().map(|f| spanned(&f, f.as_str().to_owned()));
            ExprKind::Path { head, field }
        }
    };
    Expr { kind, span }
}

fn arguments(pair: Pair<'_, Rule>) -> Vec<Argument> {
    inner(pair)
        .map(|a| {
            let mut it = inner(a).collect::<Vec<_>>();
            let value = expr(it.pop().expect("value"));
            let name = it.pop().map(|n| spanned(&n, n.as_str().to_owned()));
            Argument { name, value }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use miette::NamedSource;

    use super::*;
    use crate::diagnostic::Code;

    fn parse_text(text: &str) -> Result<File, Box<Diagnostic>> {
        parse(&Arc::new(NamedSource::new("t.tl", text.to_owned())))
    }

    #[test]
    fn a_scenario_parses_with_spans_and_comments() {
        let text = "/// A drill.\n/// Two lines.\nscenario drill { // here\n  extends academy\n  ball at (0.5, uniform(-0.1, 0.1))\n  team left { GK at (-1, 0) CB at (10 m, 0) lazy not controllable }\n  end when score or steps >= 200\n}\n";
        let file = parse_text(text).unwrap();
        let [Item::Definition(d)] = file.items.as_slice() else { panic!("{:?}", file.items) };
        assert_eq!(d.docs, ["A drill.", "Two lines."]);
        assert_eq!(d.name.value, "drill");
        assert_eq!(d.statements.len(), 4);
        assert_eq!(file.comments.len(), 1);
        assert_eq!(&text[file.comments[0].span.start..file.comments[0].span.end], "// here");
        let StatementKind::Team(t) = &d.statements[2].kind else { panic!() };
        assert_eq!(t.players.len(), 2);
        assert_eq!(
            t.players[1].flags.iter().map(|f| f.value.clone()).collect::<Vec<_>>(),
            [Flag::Lazy, Flag::NotControllable]
        );
        let Place::At(Expr { kind: ExprKind::Tuple(args), .. }) = &t.players[1].place else { panic!() };
        let ExprKind::Quantity { value, unit: Some(u), .. } = &args[0].value.kind else { panic!() };
        assert_eq!((*value, u.value.as_str()), (10.0, "m"));
        let StatementKind::End(conds) = &d.statements[3].kind else { panic!() };
        assert!(matches!(&conds[1].kind, ConditionKind::Compare { op, .. } if op.value == ">="));
    }

    #[test]
    fn a_number_before_or_has_no_unit() {
        let file = parse_text("scenario s { end when steps >= 400 or score }").unwrap();
        let [Item::Definition(d)] = file.items.as_slice() else { panic!() };
        let StatementKind::End(conds) = &d.statements[0].kind else { panic!() };
        assert_eq!(conds.len(), 2);
    }

    #[test]
    fn then_shoot_belongs_to_the_dribble_and_other_thens_start_stages() {
        let text = "scenario s { team right { CF at (0, 0) does do dribble_to((0.5, 0)) then shoot until steps > 5 m then shoot then press } }";
        let file = parse_text(text).unwrap();
        let [Item::Definition(d)] = file.items.as_slice() else { panic!() };
        let StatementKind::Team(t) = &d.statements[0].kind else { panic!() };
        let b = t.players[0].behaviour.as_ref().expect("a behaviour");
        assert_eq!(b.stages.len(), 3);
        let [first, second, third] = b.stages.as_slice() else { panic!() };
        assert!(first.shoot.is_some());
        assert!(matches!(&first.until, Some(Condition { kind: ConditionKind::Compare { .. }, .. })));
        // `shoot` after an `until` is a stage of its own (the compiler reports it).
        assert!(
            matches!(&second.action, Action::Expr(Expr { kind: ExprKind::Path { head, .. }, .. }) if head.value == "shoot")
        );
        assert!(second.shoot.is_none() && second.until.is_none());
        assert!(
            matches!(&third.action, Action::Expr(Expr { kind: ExprKind::Path { head, .. }, .. }) if head.value == "press")
        );
    }

    #[test]
    fn syntax_errors_point_at_the_token() {
        let e = parse_text("scenario s {\n  ball at (0.5, 0.0\n}").unwrap_err();
        assert_eq!(e.code, Code::Syntax);
        assert!(e.message.starts_with("syntax error: expected"), "{}", e.message);
    }
}
