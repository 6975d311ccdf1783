//! [`LoadError`], the diagnostics of loading a scenario, and [`render_plain`].

use miette::{Diagnostic, GraphicalReportHandler, GraphicalTheme, NamedSource, SourceSpan};
use serde_json::error::Category;
use thiserror::Error;

use crate::excerpt::{Clipped, ClippedSource};
use touchline_engine::EngineError;

/// Why a scenario could not be loaded. Every variant is a [`miette::Diagnostic`] with a stable
/// code: `tl::E001` … `tl::E004`, or the compiler's `tl::E1xx`. Codes are never reused for a different error.
#[derive(Debug, Error, Diagnostic)]
#[non_exhaustive]
pub enum LoadError {
    /// `tl::E001`: the spec is neither a stdlib scenario name nor a `.json` / `.tl` path.
    #[error("unknown scenario `{name}`")]
    #[diagnostic(code(tl::E001))]
    UnknownScenario {
        /// The name as given.
        name: String,
        /// The closest stdlib name(s), or the list of all of them when none is close.
        #[help]
        help: String,
    },

    /// `tl::E002`: the scenario file could not be read.
    #[error("cannot read scenario file `{path}`")]
    #[diagnostic(code(tl::E002))]
    Unreadable {
        /// The path as given.
        path: String,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },

    /// `tl::E003`: the text is not JSON, or not JSON of a compiled scenario's shape (unknown field,
    /// wrong type, unknown role, …). Boxed: the details with the source text are large.
    #[error(transparent)]
    #[diagnostic(transparent)]
    Json(Box<JsonError>),

    /// `tl::E004`: the scenario parsed but breaks a rule the engine relies on
    /// ([`touchline_engine::Scenario::validate`]).
    #[error("`{origin}` is not a playable scenario")]
    #[diagnostic(
        code(tl::E004),
        help("each team needs 1 to 11 players with exactly one GK, all positions inside the pitch")
    )]
    Invalid {
        /// Where the scenario came from: a path or a stdlib name.
        origin: String,
        /// The engine's reason.
        #[source]
        source: EngineError,
    },

    /// A `.tl` source did not compile: every diagnostic of the compile (`tl::E1xx`, with any
    /// warnings). (`tl::E005`, "language not available", is retired.)
    #[error(transparent)]
    #[diagnostic(transparent)]
    Compile(Box<crate::Diagnostics>),
}

/// The details of a `tl::E003` error ([`LoadError::Json`]): serde_json's message and position, and
/// the text it refers to.
#[derive(Debug, Error, Diagnostic)]
#[error("`{origin}` is not a valid compiled scenario: {message}")]
#[diagnostic(code(tl::E003))]
pub struct JsonError {
    /// Where the text came from: a path or a stdlib name.
    pub origin: String,
    /// serde_json's message, without its "at line … column …" suffix.
    pub message: String,
    /// 1-based line of the error (0 when serde_json gives no position).
    pub line: usize,
    /// 1-based column (in bytes) of the error (0 when serde_json gives no position).
    pub column: usize,
    /// The whole text, named after `origin` (excerpts clipped on very long lines).
    #[source_code]
    pub src: ClippedSource,
    /// Where the error is: serde_json's line and column as a byte span (the whole offending token
    /// for shape errors).
    #[label("{label}")]
    pub span: SourceSpan,
    /// The label's text: the message's first clause.
    pub label: String,
    /// What to do about it, when there is something to say.
    #[help]
    pub help: Option<String>,
}

impl LoadError {
    /// The diagnostic's stable code, e.g. `"tl::E001"` (the same as [`Diagnostic::code`]); for a
    /// failed compile, the code of its first error.
    pub fn code_str(&self) -> &'static str {
        match self {
            LoadError::UnknownScenario { .. } => "tl::E001",
            LoadError::Unreadable { .. } => "tl::E002",
            LoadError::Json(_) => "tl::E003",
            LoadError::Invalid { .. } => "tl::E004",
            LoadError::Compile(d) => d.errors().next().map_or("tl::E100", |e| e.code.as_str()),
        }
    }

    /// Builds `tl::E003` from a serde_json error on `text` (which came from `origin`).
    pub(crate) fn from_json(err: &serde_json::Error, text: &str, origin: &str) -> LoadError {
        let (line, column) = (err.line(), err.column());
        let full = err.to_string();
        let suffix = format!(" at line {line} column {column}");
        let message = shorten(full.strip_suffix(&suffix).unwrap_or(&full));
        let offset = byte_offset(text, line, column);
        let category = err.classify();
        let span = if category == Category::Data {
            token_span(text, offset)
        } else {
            let len = text[offset..].chars().next().map_or(0, char::len_utf8);
            SourceSpan::from((offset, len))
        };
        // The headline carries the whole message; the label only its first clause, since labels
        // are not wrapped ("unknown field `x`, expected one of …" -> "unknown field `x`").
        let short = message.split(", expected").next().unwrap_or(&message).to_owned();
        let (label, help) = match category {
            Category::Eof => ("the text ends here".to_owned(), Some("a closing `}` or `]` may be missing".to_owned())),
            Category::Data => (
                short,
                Some(
                    "a compiled scenario is a touchline `Scenario` serialised as JSON; \
                     the files in stdlib-scenarios/ show every field and its type"
                        .to_owned(),
                ),
            ),
            Category::Syntax | Category::Io => (short, None),
        };
        LoadError::Json(Box::new(JsonError {
            origin: origin.to_owned(),
            message,
            line,
            column,
            src: ClippedSource(NamedSource::new(origin, text.to_owned())),
            // A one-line JSON of 100 KB puts labels far along a long line: cut them to size.
            span: crate::excerpt::clamp_span(text, span),
            label,
            help,
        }))
    }
}

/// `message` cut in the middle when it is long: serde_json quotes the offending value whole, and a
/// string value can be 100 KB.
fn shorten(message: &str) -> String {
    const HEAD: usize = 600;
    const TAIL: usize = 100;
    if message.len() <= 1000 {
        return message.to_owned();
    }
    let mut head = HEAD;
    while !message.is_char_boundary(head) {
        head -= 1;
    }
    let mut tail = message.len() - TAIL;
    while !message.is_char_boundary(tail) {
        tail += 1;
    }
    format!("{}…{}", &message[..head], &message[tail..])
}

/// Converts serde_json's 1-based `line` and `column` (a column counts bytes: column `c` is the line's
/// byte `c - 1`; serde_json reports 0 for "before the line's first byte") to a byte offset into
/// `text`, clamped to the line and moved back onto a `char` boundary. Line 0 (no position) gives 0.
fn byte_offset(text: &str, line: usize, column: usize) -> usize {
    if line == 0 {
        return 0;
    }
    let Some((start, line_text)) = line_at(text, line) else { return text.len() };
    let mut offset = start + column.saturating_sub(1).min(line_text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

/// Where 1-based `line` of `text` starts (a byte offset) and its text without the newline; `None`
/// past the last line. Shared by the JSON and the script diagnostics, whose positions are lines and
/// columns.
pub(crate) fn line_at(text: &str, line: usize) -> Option<(usize, &str)> {
    let mut start = 0;
    for _ in 1..line {
        start += text[start..].find('\n')? + 1;
    }
    let rest = &text[start..];
    Some((start, &rest[..rest.find('\n').unwrap_or(rest.len())]))
}

/// The span of the JSON token that ends at byte `end` (serde_json reports shape errors at a token's
/// last byte): a whole string with its quotes, or a whole number or literal; one byte otherwise.
fn token_span(text: &str, end: usize) -> SourceSpan {
    let bytes = text.as_bytes();
    let Some(&last) = bytes.get(end) else {
        return SourceSpan::from((text.len(), 0));
    };
    if !last.is_ascii() {
        // `end` is a char boundary (see `byte_offset`): label the whole char.
        let len = text[end..].chars().next().map_or(0, char::len_utf8);
        return SourceSpan::from((end, len));
    }
    let mut start = end;
    if last == b'"' {
        // Back to the opening quote on the same line, skipping escaped quotes.
        let mut i = end;
        while i > 0 {
            i -= 1;
            match bytes[i] {
                b'\n' => break,
                b'"' if i == 0 || bytes[i - 1] != b'\\' => {
                    start = i;
                    break;
                }
                _ => {}
            }
        }
    } else if last.is_ascii_alphanumeric() {
        let literal = |b: u8| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'+' | b'-');
        while start > 0 && literal(bytes[start - 1]) {
            start -= 1;
        }
    }
    SourceSpan::from((start, end + 1 - start))
}

/// Renders a diagnostic as plain text: unicode box drawing, no colour, no hyperlinks, 80 columns.
///
/// The output depends only on the diagnostic, so it is stable for snapshot tests and for the
/// messages of Python exceptions.
pub fn render_plain(err: &dyn Diagnostic) -> String {
    // A compile's diagnostics are a list without a message of their own: render each of them.
    if err.labels().is_none()
        && err.help().is_none()
        && let Some(related) = err.related()
    {
        let parts: Vec<String> = related.map(render_one).collect();
        if !parts.is_empty() {
            return parts.join("\n");
        }
    }
    render_one(err)
}

fn render_one(err: &dyn Diagnostic) -> String {
    let mut out = String::new();
    let handler =
        GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor()).with_width(80).with_links(false);
    if handler.render_report(&mut out, &Clipped::new(err)).is_err() {
        // Rendering only fails if a source span cannot be read; fall back to the message.
        out = err.to_string();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets() {
        let text = "ab\ncdé\nf";
        assert_eq!(byte_offset(text, 0, 0), 0);
        assert_eq!(byte_offset(text, 1, 1), 0);
        assert_eq!(byte_offset(text, 1, 2), 1);
        assert_eq!(byte_offset(text, 1, 9), 2, "clamped to the end of the line");
        assert_eq!(byte_offset(text, 2, 1), 3);
        assert_eq!(byte_offset(text, 2, 0), 3);
        assert_eq!(byte_offset(text, 2, 3), 5, "start of é");
        assert_eq!(byte_offset(text, 2, 4), 5, "inside é: moved back to its start");
        assert_eq!(byte_offset(text, 2, 5), 7, "the line's newline");
        assert_eq!(byte_offset(text, 2, 9), 7, "clamped to the end of the line");
        assert_eq!(byte_offset(text, 3, 1), 8);
        assert_eq!(byte_offset(text, 7, 1), text.len());
    }

    fn spanned(text: &str, end: usize) -> &str {
        let span = token_span(text, end);
        &text[span.offset()..span.offset() + span.len()]
    }

    #[test]
    fn token_spans() {
        let text = r#"{"a": "x\"y", "b": -1.5e3, "c": true, "d": é}"#;
        assert_eq!(spanned(text, 11), r#""x\"y""#);
        assert_eq!(spanned(text, 24), "-1.5e3");
        assert_eq!(spanned(text, 35), "true");
        assert_eq!(spanned(text, 36), ",");
        assert_eq!(spanned(text, 43), "é");
        assert_eq!(spanned(text, 99), "");
    }

    #[test]
    fn codes() {
        let err = LoadError::UnknownScenario { name: "x".into(), help: String::new() };
        assert_eq!(err.code_str(), "tl::E001");
        assert_eq!(err.code().map(|c| c.to_string()).as_deref(), Some("tl::E001"));
    }
}
