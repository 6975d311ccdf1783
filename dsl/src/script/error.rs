//! [`ScriptError`]: the diagnostics of scenario scripts, codes `tl::S001` … `tl::S006` and
//! `tl::S008` … `tl::S010` (`tl::S007` is the watcher's; the scenario language's own codes are
//! `tl::E…`).

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
    #[error("script `{path}`: `{hook}` failed {}: {message}", when(hook, *step))]
    #[diagnostic(code(tl::S005))]
    Runtime {
        /// The script's path.
        path: String,
        /// The hook that failed.
        hook: &'static str,
        /// The step of the episode it failed in, 1 for the first (`reset` fails before any: 0).
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
    #[error("script `{path}`: the reward overflows in step {step}: {message}")]
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

    /// `tl::S010`: a hook reads a property the state does not have (`s.ball_owner`). Refused when
    /// the script compiles; the help names the closest real properties and lists them all.
    #[error("script `{path}`: the state has no property `{name}`")]
    #[diagnostic(code(tl::S010))]
    UnknownProperty {
        /// The script's path.
        path: String,
        /// The property as written.
        name: String,
        /// The script text.
        #[source_code]
        src: NamedSource<String>,
        /// The property.
        #[label("not a property of the state")]
        span: SourceSpan,
        /// The closest properties, and all of them.
        #[help]
        help: String,
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
        /// How to return the right value.
        #[help]
        help: String,
    },
}

/// When a hook failed, in the words the env's step counts use: `in step 1` is the episode's first
/// step (`info["steps"]` is 1 after it); `reset` runs before any.
fn when(hook: &str, step: u32) -> String {
    if hook == "reset" { "at the episode's reset".to_owned() } else { format!("in step {step}") }
}

/// Byte offset of rhai's 1-based `line` and `column` (a column counts characters) in `text`;
/// line 0 (no position) gives 0.
pub(crate) fn offset(text: &str, line: usize, column: usize) -> usize {
    if line == 0 {
        return 0;
    }
    let Some((start, line_text)) = crate::load_error::line_at(text, line) else { return text.len() };
    start + line_text.char_indices().nth(column.saturating_sub(1)).map_or(line_text.len(), |(i, _)| i)
}

/// The span at rhai's position: the whole word there (a name, a keyword), else one character (the
/// whole first line when there is no position).
pub(crate) fn span_at(text: &str, pos: rhai::Position) -> SourceSpan {
    match (pos.line(), pos.position()) {
        (Some(line), column) => {
            let at = offset(text, line, column.unwrap_or(1));
            let word = text[at..].bytes().take_while(|b| b.is_ascii_alphanumeric() || *b == b'_').count();
            let len = if word > 0 { word } else { text[at..].chars().next().map_or(0, char::len_utf8) };
            (at, len).into()
        }
        _ => (0, text.find('\n').unwrap_or(text.len())).into(),
    }
}

/// The span of `fn name` in `text` (the start when absent).
pub(crate) fn span_of_fn(text: &str, name: &str) -> SourceSpan {
    let needle = format!("fn {name}");
    // The definition, not a mention in a comment: first on its line (after `private`, if any) and
    // followed by its parameters.
    let definition = |at: usize| {
        let before = text[..at].rsplit('\n').next().unwrap_or_default().trim();
        let after = text[at + needle.len()..].trim_start();
        (before.is_empty() || before == "private") && after.starts_with('(')
    };
    match text.match_indices(&needle).map(|(at, _)| at).find(|&at| definition(at)) {
        Some(at) => (at, needle.len()).into(),
        None => (0, 0).into(),
    }
}

/// The span of the first loop (`loop`, `while`, `do`, `for`) in `fn name`'s body, if any: where an
/// exhausted operation budget was most likely spent, for a limit rhai reports without a position
/// (an empty `loop {}` has none).
pub(crate) fn span_of_first_loop(ast: &rhai::AST, text: &str, name: &str) -> Option<SourceSpan> {
    use rhai::{ASTNode, Stmt};
    let body = super::properties::only_function(ast, name, None);
    let mut found = None;
    body.walk(&mut |nodes: &[ASTNode]| {
        if let Some(ASTNode::Stmt(Stmt::While(_, pos) | Stmt::Do(_, _, pos) | Stmt::For(_, pos))) = nodes.last() {
            found = Some(*pos);
            return false;
        }
        true
    });
    let at = span_at(text, found?).offset();
    let word = text[at..].bytes().take_while(u8::is_ascii_alphabetic).count();
    Some((at, word).into())
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

    #[test]
    fn the_first_loop_of_a_hook() {
        let text = "fn helper() { while true {} }\nfn reset(s) {\n  let x = 1;\n  loop {}\n}";
        let ast = rhai::Engine::new_raw().compile(text).unwrap();
        let span = span_of_first_loop(&ast, text, "reset").unwrap();
        assert_eq!(&text[span.offset()..span.offset() + span.len()], "loop");
        assert!(span_of_first_loop(&ast, text, "reward").is_none());
    }
}
