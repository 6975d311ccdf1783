//! The `tl::E100` syntax error: where the text leaves the grammar, said in the language's words
//! (what was expected there, an unterminated string, a missing `}`) rather than pest's rule names.

use pest::Parser;

use super::Span;
use super::generated::{Rule, ScenarioParser};
use crate::diagnostic::{Code, Diagnostic, Source};

/// Words that begin a statement; one met where a player's role was read means that the team
/// block above lacks its `}`.
const STATEMENT_KEYWORDS: [&str; 12] = [
    "team",
    "ball",
    "extends",
    "require",
    "reward",
    "end",
    "on",
    "start",
    "import",
    "behaviour",
    "param",
    "curriculum",
];

pub(super) fn syntax_error(e: pest::error::Error<Rule>, source: &Source) -> Diagnostic {
    let (start, end) = match e.location {
        pest::error::InputLocation::Pos(p) => (p, p),
        pest::error::InputLocation::Span((a, b)) => (a, b),
    };
    let text = source.inner().as_str();
    if let Some(d) = unterminated_string(text, start, source)
        .or_else(|| missing_brace(&e, text, start, source))
        .or_else(|| non_ascii_name(text, start, source))
    {
        return d;
    }
    // Point at the offending token (up to the next space) rather than at a zero-width gap.
    let end = if end > start {
        end
    } else {
        start + text[start..].find(|c: char| c.is_whitespace()).unwrap_or(text.len() - start).max(1)
    };
    let end = ceil_char_boundary(text, end.min(text.len()));
    let found = text.get(start..end).filter(|s| !s.is_empty()).unwrap_or("end of file");
    let mut expected: Vec<String> = Vec::new();
    if let pest::error::ErrorVariant::ParsingError { positives, .. } = &e.variant {
        // Comments may come anywhere, so "a comment" is always possible and never worth saying.
        // Nor is an operator, possible after every value.
        for name in
            positives.iter().filter(|r| !matches!(r, Rule::COMMENT | Rule::WHITESPACE | Rule::binary_op)).map(rule_name)
        {
            if !expected.contains(&name) {
                expected.push(name);
            }
        }
    }
    if expected.is_empty() {
        expected = expected_literals(text);
    }
    let message = if expected.is_empty() {
        format!("syntax error: unexpected `{found}`")
    } else {
        format!("syntax error: expected {}", join_or(&expected))
    };
    Diagnostic::new(Code::Syntax, message, source, Span { start, end }, format!("found `{found}`"))
        .with_help("see grammar/README.md for the statements a scenario may contain")
}

/// The smallest char boundary at or after `i` (so that a one-byte span covers a whole char).
fn ceil_char_boundary(text: &str, mut i: usize) -> usize {
    while !text.is_char_boundary(i) {
        i += 1;
    }
    i
}

/// The punctuation the parser expected at the error (`)`, `,`, …): pest names only rules in its
/// error, so the text is parsed again with pest's detailed error tracking.
fn expected_literals(text: &str) -> Vec<String> {
    // Tracking stays on once switched on: switching it off could race with another thread's
    // re-parse and make its message depend on timing.
    pest::set_error_detail(true);
    let Err(e) = ScenarioParser::parse(Rule::file, text) else { return Vec::new() };
    let Some(attempts) = e.parse_attempts() else { return Vec::new() };
    attempts
        .expected_tokens()
        .into_iter()
        // Only literal text (not character ranges such as `a..z`), without whitespace and `//`.
        .filter(|t| format!("{t:?}").starts_with("Sensitive"))
        .map(|t| t.to_string())
        .filter(|t| !t.trim().is_empty() && !matches!(t.as_str(), "//" | "+" | "-" | "*" | "/"))
        .map(|t| format!("`{t}`"))
        .collect()
}

/// A string opened on the line of the error and never closed.
fn unterminated_string(text: &str, at: usize, source: &Source) -> Option<Diagnostic> {
    let line_start = text[..at].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[at..].find('\n').map_or(text.len(), |i| at + i);
    let line = &text[line_start..line_end];
    // Quotes before the error on this line, outside comments.
    let before = &text[line_start..at];
    let before = before.split("//").next().unwrap_or(before);
    let opening = if before.matches('"').count() % 2 == 1 {
        line_start + before.rfind('"')?
    } else if text[at..line_end].starts_with('"') && !text[at + 1..line_end].contains('"') {
        at
    } else {
        return None;
    };
    if text[opening + 1..line_end].contains('"') || line.trim_start().starts_with("//") {
        return None;
    }
    let end = opening + text[opening..line_end].trim_end().len();
    Some(
        Diagnostic::new(
            Code::Syntax,
            "syntax error: unterminated string",
            source,
            Span { start: opening, end },
            "this string has no closing `\"`",
        )
        .with_help("a string ends with `\"` on the line it starts on"),
    )
}

/// A statement keyword read as a player's role: the team block before it is not closed.
fn missing_brace(e: &pest::error::Error<Rule>, text: &str, at: usize, source: &Source) -> Option<Diagnostic> {
    let pest::error::ErrorVariant::ParsingError { positives, .. } = &e.variant else { return None };
    if !positives.contains(&Rule::place) {
        return None;
    }
    let before = text[..at].trim_end();
    let word_start = before
        .char_indices()
        .rev()
        .find(|&(_, c)| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |(i, c)| i + c.len_utf8());
    let word = &before[word_start..];
    if !STATEMENT_KEYWORDS.contains(&word) {
        return None;
    }
    Some(
        Diagnostic::new(
            Code::Syntax,
            format!("syntax error: `{word}` inside a team block"),
            source,
            Span { start: word_start, end: before.len() },
            "read as a player, but it starts a statement",
        )
        .with_help(format!("a `}}` closing the team block is missing before `{word}`")),
    )
}

/// A name with a letter outside ASCII (`gäp`): pest stops at the letter and would list what may
/// follow a name; the grammar's names are ASCII letters, digits and `_`.
fn non_ascii_name(text: &str, at: usize, source: &Source) -> Option<Diagnostic> {
    let letter = text[at..].chars().next().filter(|c| !c.is_ascii() && c.is_alphabetic())?;
    let name_char = |c: char| c.is_alphanumeric() || c == '_';
    let start = text[..at].char_indices().rev().take_while(|&(_, c)| name_char(c)).last().map_or(at, |(i, _)| i);
    let end = text[at..].char_indices().find(|&(_, c)| !name_char(c)).map_or(text.len(), |(i, _)| at + i);
    let word = &text[start..end];
    let ascii: String = word.chars().map(ascii_letter).collect();
    Some(
        Diagnostic::new(
            Code::Syntax,
            format!("syntax error: `{word}` is not a name: names are ASCII"),
            source,
            Span { start, end },
            format!("`{letter}` is not an ASCII letter"),
        )
        .with_help(format!(
            "a name is ASCII letters, digits and `_` (non-ASCII text may go in strings and comments): `{ascii}`?"
        )),
    )
}

/// The ASCII letter a Latin letter with a diacritic is written with, else `_`.
fn ascii_letter(c: char) -> char {
    if c.is_ascii() {
        return c;
    }
    match c.to_lowercase().next().unwrap_or(c) {
        'à' | 'á' | 'â' | 'ã' | 'ä' | 'å' | 'ā' => 'a',
        'ç' | 'č' | 'ć' => 'c',
        'è' | 'é' | 'ê' | 'ë' | 'ē' | 'ę' => 'e',
        'ì' | 'í' | 'î' | 'ï' => 'i',
        'ñ' | 'ń' => 'n',
        'ò' | 'ó' | 'ô' | 'õ' | 'ö' | 'ø' | 'ō' => 'o',
        'ù' | 'ú' | 'û' | 'ü' | 'ū' => 'u',
        'ý' | 'ÿ' => 'y',
        'š' | 'ś' => 's',
        'ž' | 'ź' | 'ż' => 'z',
        'ł' => 'l',
        _ => '_',
    }
}

fn join_or(names: &[String]) -> String {
    match names {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} or {last}", rest.join(", ")),
    }
}

/// Readable names of grammar rules for "expected …" messages.
fn rule_name(rule: &Rule) -> String {
    match rule {
        Rule::EOI => "end of file",
        Rule::import | Rule::definition | Rule::doc | Rule::kind => "`scenario`, `preset` or `import`",
        Rule::name => "a name",
        Rule::extends => "`extends`",
        Rule::ball => "`ball`",
        Rule::on_odd => "`on odd episodes`",
        Rule::team => "`team`",
        Rule::require => "`require`",
        Rule::reward => "`reward`",
        Rule::reward_on | Rule::event_sequence | Rule::event_step | Rule::event => "an event",
        Rule::event_group | Rule::group_kind | Rule::any_of | Rule::all_of => "`any of` or `all of`",
        Rule::event_region | Rule::region_word => "`enters` or `in`",
        Rule::scope | Rule::scope_word => "`by player` or `for team`",
        Rule::repeat | Rule::once | Rule::each_time => "`once` or `each time`",
        Rule::then_word => "`then`",
        Rule::end => "`end when`",
        Rule::start_from => "`start from`",
        Rule::start_with | Rule::start_team | Rule::for_kw => "`start with`",
        Rule::facing | Rule::facing_kw => "`facing`",
        Rule::setting | Rule::assignment => "a statement",
        Rule::param => "`param`",
        Rule::curriculum => "`curriculum`",
        Rule::lesson | Rule::lesson_parent => "`lesson`",
        Rule::advance | Rule::advance_min => "`advance when`",
        Rule::threshold => "a threshold (`success_rate >= 0.8`)",
        Rule::binary_op => "an operator",
        Rule::minus | Rule::operand_expr => "a value",
        Rule::side => "`left` or `right`",
        Rule::formation => "`formation`",
        Rule::player => "a player (`ROLE at (x, y)`)",
        Rule::flag | Rule::lazy | Rule::controllable | Rule::not_controllable => "a flag",
        Rule::place | Rule::at_place | Rule::in_place => "`at` or `in`",
        Rule::comparison => "`>=` or `<=`",
        Rule::reward_term | Rule::script => "a reward term",
        Rule::weight => "`weight`",
        Rule::condition | Rule::conjunction | Rule::negation | Rule::atom | Rule::group | Rule::relation => {
            "a condition"
        }
        Rule::compare => "a comparison (`<`, `<=`, `>`, `>=`, `==`, `!=`)",
        Rule::or_kw => "`or`",
        Rule::and_kw => "`and`",
        Rule::not_kw => "`not`",
        Rule::in_kw => "`in`",
        Rule::is_kw => "`is`",
        Rule::then_kw | Rule::shoot => "`then`",
        Rule::shoot_kw => "`shoot`",
        Rule::until | Rule::until_kw => "`until`",
        Rule::does | Rule::does_kw => "`does`",
        Rule::do_kw | Rule::stage | Rule::action => "a behaviour",
        Rule::behaviour_statement | Rule::behaviour_kw => "`behaviour`",
        Rule::swap_teams => "`swap teams` or `ball`",
        Rule::expr | Rule::call | Rule::index | Rule::tuple | Rule::path => "a value",
        Rule::arguments | Rule::argument => "an argument",
        Rule::quantity | Rule::number => "a number",
        Rule::unit => "a unit",
        Rule::string | Rule::string_text => "a string",
        Rule::ident => "a name",
        _ => "something else",
    }
    .to_owned()
}
