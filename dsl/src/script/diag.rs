//! [`ScriptError`]: the diagnostics of scenario scripts, codes `tl::S001` … `tl::S006`, `tl::S008`
//! and `tl::S009` (`tl::S007` is the watcher's; the scenario language's own codes are `tl::E…`).

use miette::{Diagnostic, NamedSource, SourceSpan};
use thiserror::Error;

/// A script that cannot be loaded, or a hook that failed while the env ran. Each variant is a
/// [`miette::Diagnostic`] with a stable code; those with a source carry the script text and point
/// at the line and column.
#[derive(Debug, Error, Diagnostic)]
#[non_exhaustive]
pub enum ScriptError {
    /// `tl::S001`: the script file cannot be read.
    #[error("cannot read script `{path}`")]
    #[diagnostic(
        code(tl::S001),
        help("script paths are relative to the scenario file; a script is a `.rhai` text file of at most 256 KiB")
    )]
    Unreadable {
        /// The path as the scenario wrote it, resolved against the scenario's folder.
        path: String,
        /// The operating system's error.
        #[source]
        source: std::io::Error,
    },

    /// `tl::S002`: the script does not compile (syntax, an undefined variable, a reserved word).
    #[error("script `{path}` does not compile: {message}")]
    #[diagnostic(code(tl::S002))]
    Syntax {
        /// The script's path.
        path: String,
        /// rhai's message.
        message: String,
        /// The script text.
        #[source_code]
        src: NamedSource<String>,
        /// Where.
        #[label("here")]
        span: SourceSpan,
    },

    /// `tl::S003`: the hook the scenario needs is missing or takes the wrong parameters.
    #[error("script `{path}` has no `fn {hook}(s)`")]
    #[diagnostic(code(tl::S003))]
    MissingHook {
        /// The script's path.
        path: String,
        /// The hook: `reward` or `end`.
        hook: &'static str,
        /// What to write instead.
        #[help]
        help: String,
    },

    /// `tl::S004`: the script's top level does something other than define functions and
    /// constants (a `let` variable, a failing statement).
    #[error("script `{path}`: {message}")]
    #[diagnostic(
        code(tl::S004),
        help("the top level of a script may only define `fn`s and `const`s; keep per-episode state in `memory`")
    )]
    TopLevel {
        /// The script's path.
        path: String,
        /// What is wrong.
        message: String,
        /// The script text.
        #[source_code]
        src: NamedSource<String>,
        /// Where.
        #[label("here")]
        span: SourceSpan,
    },

    /// `tl::S005`: a hook failed while running: a runtime error, or an exhausted limit
    /// (operations, call depth, string/array/map size).
    #[error("script `{path}`: `{hook}` failed at step {step}: {message}")]
    #[diagnostic(code(tl::S005))]
    Runtime {
        /// The script's path.
        path: String,
        /// The hook that failed.
        hook: &'static str,
        /// Steps taken in the episode when it failed (0: at reset).
        step: u32,
        /// rhai's message.
        message: String,
        /// The script text.
        #[source_code]
        src: NamedSource<String>,
        /// Where (the hook's definition when rhai gives no position, as for limits).
        #[label("here")]
        span: SourceSpan,
        /// How to fix it.
        #[help]
        help: Option<String>,
    },

    /// `tl::S008`: the script calls a function the sandbox does not have: `sleep`, or a clock
    /// (`timestamp`, `elapsed`). Refused when the script compiles, before anything runs.
    #[error("script `{path}`: `{name}` is not available to scripts")]
    #[diagnostic(code(tl::S008))]
    Refused {
        /// The script's path.
        path: String,
        /// The function.
        name: &'static str,
        /// The script text.
        #[source_code]
        src: NamedSource<String>,
        /// The call.
        #[label("not available")]
        span: SourceSpan,
        /// Why it is not there.
        #[help]
        help: String,
    },

    /// `tl::S009`: a reward term paid a value that is not finite (its weight times what the
    /// script returned overflows), or the step's reward overflowed when it was added in.
    #[error("script `{path}`: the reward overflows at step {step}: {message}")]
    #[diagnostic(
        code(tl::S009),
        help("scale the script's value or the term's `weight` down; a reward must stay a finite f32")
    )]
    NotFinite {
        /// The script's path (the term).
        path: String,
        /// Steps taken in the episode.
        step: u32,
        /// What overflowed.
        message: String,
    },

    /// `tl::S006`: a hook returned a value of the wrong type.
    #[error("script `{path}`: `{hook}` returned {got}; it must return {expected}")]
    #[diagnostic(code(tl::S006))]
    ReturnType {
        /// The script's path.
        path: String,
        /// The hook.
        hook: &'static str,
        /// What it returned (type and value).
        got: String,
        /// What it must return.
        expected: String,
        /// The script text.
        #[source_code]
        src: NamedSource<String>,
        /// The hook's definition.
        #[label("this hook")]
        span: SourceSpan,
    },
}

/// Byte offset of rhai's 1-based `line` and `column` (a column counts characters) in `text`;
/// line 0 (no position) gives 0.
pub(crate) fn offset(text: &str, line: usize, column: usize) -> usize {
    if line == 0 {
        return 0;
    }
    let Some((start, line_text)) = crate::diag::line_at(text, line) else { return text.len() };
    start + line_text.char_indices().nth(column.saturating_sub(1)).map_or(line_text.len(), |(i, _)| i)
}

/// A one-character span at rhai's position (the whole first line when there is none).
pub(crate) fn span_at(text: &str, pos: rhai::Position) -> SourceSpan {
    match (pos.line(), pos.position()) {
        (Some(line), column) => {
            let at = offset(text, line, column.unwrap_or(1));
            let len = text[at..].chars().next().map_or(0, char::len_utf8);
            (at, len).into()
        }
        _ => (0, text.find('\n').unwrap_or(text.len())).into(),
    }
}

/// The span of `fn name` in `text` (the start when absent).
pub(crate) fn span_of_fn(text: &str, name: &str) -> SourceSpan {
    let needle = format!("fn {name}");
    match text.find(&needle) {
        Some(at) => (at, needle.len()).into(),
        None => (0, 0).into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_count_characters() {
        let text = "ab\ncdé!\nf";
        assert_eq!(offset(text, 1, 1), 0);
        assert_eq!(offset(text, 2, 1), 3);
        assert_eq!(offset(text, 2, 4), 7, "after é (2 bytes)");
        assert_eq!(offset(text, 3, 1), 9);
        assert_eq!(offset(text, 9, 1), text.len());
    }
}
