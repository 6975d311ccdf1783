//! Diagnostics on very long lines: excerpts clipped around the label.
//!
//! miette's graphical renderer pads a label to its column with `{:width$}`, and Rust's formatter
//! panics ("Formatting argument out of range") on a width above 65,535. A `.tl` with a very long
//! line, or a compiled JSON written on one line over 64 KiB, put labels there. So on a line longer
//! than [`LONG_LINE`] bytes, the excerpt shown is a window of at most [`WINDOW`] bytes around the
//! label (the header still gives the label's real line and column), and a label there is cut to
//! at most [`MAX_LABEL`] bytes on its first line. Lines up to [`LONG_LINE`] bytes render as
//! before.
//!
//! Messages, labels and help echo the user's text (`found the name `…``): [`clip_message`] cuts a
//! quoted piece longer than [`MAX_QUOTED`] bytes in the middle, and a whole message at
//! [`MAX_MESSAGE`] bytes, so that a 400 KB token does not become a 400 KB message.
//!
//! [`Clipped`] wraps any diagnostic for rendering; the compiler's
//! [`Diagnostic`](crate::Diagnostic) and [`JsonError`](crate::JsonError) clip by themselves (they
//! also reach renderers as related diagnostics, which a wrapper cannot reach).

use std::fmt;

use miette::{
    Diagnostic, LabeledSpan, MietteError, MietteSpanContents, NamedSource, SourceCode, SourceSpan, SpanContents,
};

/// Lines longer than this (in bytes) are shown clipped.
pub const LONG_LINE: usize = 512;
/// The most bytes of a label kept on a long line.
pub const MAX_LABEL: usize = 120;
/// Bytes shown either side of a label on a long line.
const MARGIN: usize = 60;
/// The most bytes of a long line an excerpt shows: a whole label and its margins (so an excerpt
/// is never itself a long line).
pub const WINDOW: usize = MAX_LABEL + 2 * MARGIN;

/// The most bytes of a `quoted` piece of the user's text kept in a message.
pub const MAX_QUOTED: usize = 80;
/// The most bytes of a message, label or help.
pub const MAX_MESSAGE: usize = 2_000;

/// `text` with each `` `quoted` `` piece over [`MAX_QUOTED`] bytes cut in the middle (its length
/// given), and the whole cut in the middle at [`MAX_MESSAGE`] bytes; shorter text is unchanged.
pub fn clip_message(text: String) -> String {
    if text.len() <= MAX_QUOTED {
        return text;
    }
    let mut out = String::with_capacity(text.len().min(MAX_MESSAGE));
    for (i, piece) in text.split('`').enumerate() {
        if i > 0 {
            out.push('`');
        }
        // Odd pieces are inside backquotes.
        if i % 2 == 1 && piece.len() > MAX_QUOTED {
            out.push_str(&middle_cut(piece, MAX_QUOTED, &format!("… {} bytes …", piece.len())));
        } else {
            out.push_str(piece);
        }
    }
    if out.len() > MAX_MESSAGE {
        out = middle_cut(&out, MAX_MESSAGE, &format!("… ({} bytes cut) …", out.len() - MAX_MESSAGE));
    }
    out
}

/// `text` cut to about `max` bytes: its start and end around `marker`, on char boundaries.
fn middle_cut(text: &str, max: usize, marker: &str) -> String {
    let data = text.as_bytes();
    let head = floor_boundary(data, max * 2 / 3);
    let tail = ceil_boundary(data, text.len() - max / 3);
    format!("{}{marker}{}", &text[..head], &text[tail..])
}

/// Whether `data` holds a line longer than [`LONG_LINE`].
fn has_long_line(data: &[u8]) -> bool {
    data.split(|&b| b == b'\n').any(|line| line.len() > LONG_LINE)
}

/// `i` moved back onto a UTF-8 boundary of `data`.
fn floor_boundary(data: &[u8], mut i: usize) -> usize {
    while i > 0 && i < data.len() && (data[i] & 0xC0) == 0x80 {
        i -= 1;
    }
    i
}

/// `i` moved forward onto a UTF-8 boundary of `data`.
fn ceil_boundary(data: &[u8], mut i: usize) -> usize {
    while i < data.len() && (data[i] & 0xC0) == 0x80 {
        i += 1;
    }
    i
}

/// Reads `span` from `inner` as [`SourceCode::read_span`] does, except that when the excerpt
/// holds a line longer than [`LONG_LINE`] it is narrowed to the span's own lines, at most
/// `MARGIN` bytes either side of the span.
///
/// # Errors
/// As `inner`; and [`MietteError::OutOfBounds`] for a span longer than [`MAX_LABEL`] that touches
/// a long line (miette then renders the labels it was merging apart, one excerpt each).
pub fn read_clipped<'a>(
    inner: &'a dyn SourceCode,
    span: &SourceSpan,
    before: usize,
    after: usize,
) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
    let contents = inner.read_span(span, before, after)?;
    let data: &'a [u8] = contents.data();
    if !has_long_line(data) {
        return Ok(contents);
    }
    if span.len() > MAX_LABEL {
        return Err(MietteError::OutOfBounds);
    }
    let base = contents.span().offset();
    let start = span.offset().saturating_sub(base).min(data.len());
    let end = (start + span.len()).min(data.len());
    let line_start = data[..start].iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let line_end = data[end..].iter().position(|&b| b == b'\n').map_or(data.len(), |i| end + i);
    let from = floor_boundary(data, line_start.max(start.saturating_sub(MARGIN)));
    let to = ceil_boundary(data, line_end.min(end + MARGIN));
    let line = contents.line() + data[..from].iter().filter(|&&b| b == b'\n').count();
    // With no context (the header's read) miette gives the label's own column; keep it.
    let column = if before == 0 && from == 0 { contents.column() } else { 0 };
    let window = &data[from..to];
    let window_span = SourceSpan::from((base + from, to - from));
    Ok(Box::new(match contents.name() {
        Some(name) => {
            MietteSpanContents::new_named(name.to_owned(), window, window_span, line, column, contents.line_count())
        }
        None => MietteSpanContents::new(window, window_span, line, column, contents.line_count()),
    }))
}

/// `span` cut, when it touches a line longer than [`LONG_LINE`], to its first line and at most
/// [`MAX_LABEL`] bytes. `text` is the whole source the span points into.
pub fn clamp_span(text: &str, span: SourceSpan) -> SourceSpan {
    let bytes = text.as_bytes();
    let start = span.offset().min(bytes.len());
    let end = (start + span.len()).min(bytes.len());
    let line_start = bytes[..start].iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
    let last_end = bytes[end..].iter().position(|&b| b == b'\n').map_or(bytes.len(), |i| end + i);
    if !has_long_line(&bytes[line_start..last_end]) {
        return span;
    }
    let first_end = bytes[start..].iter().position(|&b| b == b'\n').map_or(bytes.len(), |i| start + i);
    let cut = floor_boundary(bytes, end.min(first_end).min(start + MAX_LABEL)).max(start);
    SourceSpan::from((start, cut - start))
}

/// [`clamp_span`] through a [`SourceCode`] (whose whole text is not at hand): reads the span's
/// lines and cuts it the same way.
fn clamp_through(source: &dyn SourceCode, span: SourceSpan) -> SourceSpan {
    let Ok(contents) = source.read_span(&span, 0, 0) else { return span };
    let Ok(lines) = source.read_span(&span, 1, 1) else { return span };
    if !has_long_line(lines.data()) && !has_long_line(contents.data()) {
        return span;
    }
    let data = contents.data();
    let first_end = data.iter().position(|&b| b == b'\n').unwrap_or(data.len());
    let cut = floor_boundary(data, first_end.min(MAX_LABEL).min(span.len()));
    SourceSpan::from((span.offset(), cut))
}

/// A named source whose excerpts are clipped on long lines (see the module docs): what
/// [`JsonError`](crate::JsonError) points into.
#[derive(Debug)]
pub struct ClippedSource(pub NamedSource<String>);

impl ClippedSource {
    /// The whole text.
    pub fn inner(&self) -> &String {
        self.0.inner()
    }
}

impl SourceCode for ClippedSource {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        read_clipped(&self.0, span, before, after)
    }
}

/// Any diagnostic, rendered with clipped excerpts and labels (see the module docs): what
/// [`render_plain`](crate::render_plain) and the CLI's report handler render.
pub struct Clipped<'a> {
    diagnostic: &'a dyn Diagnostic,
    source: Option<Window<'a>>,
}

impl<'a> Clipped<'a> {
    /// `diagnostic`, to be rendered with clipped excerpts.
    pub fn new(diagnostic: &'a dyn Diagnostic) -> Clipped<'a> {
        Clipped { diagnostic, source: diagnostic.source_code().map(Window) }
    }
}

/// A diagnostic's source, read through [`read_clipped`].
struct Window<'a>(&'a dyn SourceCode);

impl SourceCode for Window<'_> {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        read_clipped(self.0, span, before, after)
    }
}

impl fmt::Debug for Clipped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self.diagnostic, f)
    }
}

impl fmt::Display for Clipped<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self.diagnostic, f)
    }
}

impl std::error::Error for Clipped<'_> {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        self.diagnostic.source()
    }
}

impl Diagnostic for Clipped<'_> {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.diagnostic.code()
    }

    fn severity(&self) -> Option<miette::Severity> {
        self.diagnostic.severity()
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.diagnostic.help()
    }

    fn url<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.diagnostic.url()
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        self.source.as_ref().map(|s| s as &dyn SourceCode)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        let labels = self.diagnostic.labels()?;
        let Some(source) = self.diagnostic.source_code() else { return Some(labels) };
        Some(Box::new(labels.map(move |l| {
            let span = clamp_through(source, *l.inner());
            let label = l.label().map(str::to_owned);
            if l.primary() {
                LabeledSpan::new_primary_with_span(label, span)
            } else {
                LabeledSpan::new_with_span(label, span)
            }
        })))
    }

    fn related<'a>(&'a self) -> Option<Box<dyn Iterator<Item = &'a dyn Diagnostic> + 'a>> {
        self.diagnostic.related()
    }

    fn diagnostic_source(&self) -> Option<&dyn Diagnostic> {
        self.diagnostic.diagnostic_source()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_lines_read_as_miette_reads_them() {
        let text = NamedSource::new("t", "ab\ncd\nef".to_owned());
        let span = SourceSpan::from((3, 2));
        let plain = text.read_span(&span, 1, 1).unwrap();
        let clipped = read_clipped(&text, &span, 1, 1).unwrap();
        assert_eq!(plain.data(), clipped.data());
        assert_eq!((plain.line(), plain.column()), (clipped.line(), clipped.column()));
    }

    #[test]
    fn a_label_far_along_a_long_line_gets_a_window() {
        let line = "x".repeat(100_000);
        let text = NamedSource::new("t", format!("first\n{line}\nlast"));
        let span = SourceSpan::from((6 + 70_000, 3));
        let c = read_clipped(&text, &span, 1, 1).unwrap();
        assert_eq!(c.line(), 1);
        assert_eq!(c.span().offset(), 6 + 70_000 - MARGIN);
        assert!(c.data().len() <= WINDOW);
        let header = read_clipped(&text, &span, 0, 0).unwrap();
        assert_eq!((header.line(), header.column()), (1, 70_000));
    }

    #[test]
    fn long_labels_are_cut_on_long_lines_only() {
        let text = format!("short\n{}\n", "y".repeat(1000));
        assert_eq!(clamp_span(&text, SourceSpan::from((0, 5))), SourceSpan::from((0, 5)));
        assert_eq!(clamp_span(&text, SourceSpan::from((6, 900))), SourceSpan::from((6, MAX_LABEL)));
        assert_eq!(clamp_span(&text, SourceSpan::from((0, 500))), SourceSpan::from((0, 5)));
    }
}
