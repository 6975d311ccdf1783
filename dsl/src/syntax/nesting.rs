//! The depth limit: how deeply a `.tl` text may nest, checked before anything recurses over it.
//!
//! pest's parser, the syntax-tree conversion and the compiler recurse once per level of nesting,
//! so text nested thousands deep (1,000 parentheses in `end when`, `not` 10,000 times) would
//! overflow the stack and abort the process. Two checks keep every level count under
//! [`MAX_NESTING`], each reporting `tl::E148` where the limit is crossed:
//!
//! - [`scan`], on the raw text before pest sees it: brackets open at once, and `not` or `-`
//!   prefixes in a row (strings and comments skipped);
//! - [`tree_depth`], on pest's parse tree, iteratively: the levels the syntax tree will have,
//!   counting each bracket, `not`, `-` prefix and each binary operator of one expression (`a + b
//!   + c` folds into a tree one level deeper per operator).

use pest::iterators::Pair;

use super::Rule;
use crate::syntax::Span;

/// The most levels an expression or condition may nest. Real scenarios nest a handful.
pub const MAX_NESTING: usize = 64;

/// Where the text first nests deeper than [`MAX_NESTING`], and what nests there.
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct TooDeep {
    /// The token that crosses the limit.
    pub(crate) span: Span,
    /// What is nested, as the message ends: "brackets open at once", "`not` or `-` in a row", ….
    pub(crate) what: &'static str,
}

/// The first bracket opened, or `not`/`-` prefix given, beyond [`MAX_NESTING`] at once.
pub(crate) fn scan(text: &str) -> Option<TooDeep> {
    let bytes = text.as_bytes();
    let (mut open, mut prefixes, mut i) = (0usize, 0usize, 0usize);
    while i < bytes.len() {
        let b = bytes[i];
        match b {
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                i += bytes[i..].iter().position(|&c| c == b'\n').unwrap_or(bytes.len() - i);
                continue;
            }
            b'"' => {
                let rest = &bytes[i + 1..];
                i += 1 + rest.iter().position(|&c| c == b'"' || c == b'\n').map_or(rest.len(), |p| p + 1);
                prefixes = 0;
                continue;
            }
            b'(' | b'[' | b'{' => {
                open += 1;
                prefixes = 0;
                if open > MAX_NESTING {
                    return Some(TooDeep { span: Span { start: i, end: i + 1 }, what: "brackets open at once" });
                }
            }
            b')' | b']' | b'}' => {
                open = open.saturating_sub(1);
                prefixes = 0;
            }
            b'-' => {
                prefixes += 1;
                if prefixes > MAX_NESTING {
                    return Some(TooDeep { span: Span { start: i, end: i + 1 }, what: "`not` or `-` in a row" });
                }
            }
            b if b.is_ascii_alphanumeric() || b == b'_' => {
                let len = bytes[i..]
                    .iter()
                    .position(|c| !(c.is_ascii_alphanumeric() || *c == b'_'))
                    .unwrap_or(bytes.len() - i);
                if &bytes[i..i + len] == b"not" {
                    prefixes += 1;
                    if prefixes > MAX_NESTING {
                        return Some(TooDeep { span: Span { start: i, end: i + len }, what: "`not` or `-` in a row" });
                    }
                } else {
                    prefixes = 0;
                }
                i += len;
                continue;
            }
            b if b.is_ascii_whitespace() => {}
            _ => prefixes = 0,
        }
        i += 1;
    }
    None
}

/// The first place the syntax tree built from `root` would nest deeper than [`MAX_NESTING`]
/// levels, walked without recursion.
pub(crate) fn tree_depth(root: Pair<'_, Rule>) -> Option<TooDeep> {
    let mut stack = vec![(root, 0usize)];
    while let Some((pair, depth)) = stack.pop() {
        let levels = match pair.as_rule() {
            Rule::expr => pair.clone().into_inner().filter(|p| p.as_rule() == Rule::binary_op).count(),
            Rule::tuple | Rule::call | Rule::index | Rule::minus | Rule::group => 1,
            Rule::negation if pair.clone().into_inner().next().is_some_and(|p| p.as_rule() == Rule::not_kw) => 1,
            _ => 0,
        };
        if depth + levels > MAX_NESTING {
            // The token at which the count passes the limit: the operator itself in a long
            // chain, the opening bracket or prefix otherwise.
            let span = if pair.as_rule() == Rule::expr {
                let k = MAX_NESTING.saturating_sub(depth);
                let op = pair.clone().into_inner().filter(|p| p.as_rule() == Rule::binary_op).nth(k);
                op.map_or_else(|| first_byte(&pair), |p| Span { start: p.as_span().start(), end: p.as_span().end() })
            } else {
                first_keyword(&pair)
            };
            return Some(TooDeep { span, what: "levels (each bracket, `not`, `-` and operator is one)" });
        }
        for child in pair.into_inner() {
            stack.push((child, depth + levels));
        }
    }
    None
}

fn first_byte(pair: &Pair<'_, Rule>) -> Span {
    let start = pair.as_span().start();
    let len = pair.as_str().chars().next().map_or(0, char::len_utf8);
    Span { start, end: start + len }
}

/// The `not` of a negation, or the first byte (a bracket, a `-`, a name's first letter).
fn first_keyword(pair: &Pair<'_, Rule>) -> Span {
    match pair.clone().into_inner().next() {
        Some(p) if p.as_rule() == Rule::not_kw => Span { start: p.as_span().start(), end: p.as_span().end() },
        _ => first_byte(pair),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brackets_and_prefixes_are_counted_outside_strings_and_comments() {
        let deep = format!("{}1{}", "(".repeat(MAX_NESTING), ")".repeat(MAX_NESTING));
        assert_eq!(scan(&deep), None);
        let deeper = format!("x {}1", "(".repeat(MAX_NESTING + 1));
        assert_eq!(
            scan(&deeper),
            Some(TooDeep {
                span: Span { start: 2 + MAX_NESTING, end: 3 + MAX_NESTING },
                what: "brackets open at once"
            })
        );
        let quoted = format!("\"{}\" // {}\n", "(".repeat(200), "[".repeat(200));
        assert_eq!(scan(&quoted), None);
        let nots = "not ".repeat(MAX_NESTING + 1);
        assert_eq!(scan(&nots).map(|d| d.span.start), Some(4 * MAX_NESTING));
        assert_eq!(scan(&"not x ".repeat(500)), None, "separate `not`s do not add up");
        assert_eq!(scan(&"- ".repeat(MAX_NESTING + 1)).map(|d| d.what), Some("`not` or `-` in a row"));
        assert_eq!(scan("nothing not_a_keyword notnot"), None);
    }
}
