//! `.tl` source → checked [`Scenario`]: parse every file involved (the source, its imports, the
//! prelude, stdlib scenarios it extends), resolve `extends` chains (with cycle detection), apply
//! each definition's statements on its parent, then check the result. Every problem found is
//! reported, not just the first.

mod behaviour;
mod check;
mod condition;
mod curriculum;
mod events;
mod origins;
mod params;
mod pitch;
mod reindex;
mod relative;
mod start;
mod statements;

pub(crate) use pitch::{BALL_X_METRES, BALL_Y_METRES, PLAYER_X_METRES, PLAYER_Y_METRES};
pub(crate) use start::restart_name;
mod value;

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use miette::NamedSource;
use touchline_engine::Scenario;

use crate::diagnostic::{Code, Diagnostic, Diagnostics, Source};
use crate::syntax::{self, Definition, Item, Kind, StatementKind};
use crate::{stdlib, suggest};
use origins::Origins;
use params::{Param, Params};
use value::{Reader, suggest_help};

/// A resolved definition: the scenario, where its parts were written, and its parameters.
type Resolved = (Scenario, Origins, Params);

/// The built-in presets every file may extend (`academy`).
pub const PRELUDE: &str = include_str!("../../../stdlib-scenarios/prelude.tl");

/// A compiled scenario with the warnings found and the files it was built from.
#[derive(Clone, Debug)]
pub struct Compiled {
    /// The checked scenario.
    pub scenario: Scenario,
    /// Warnings (`tl::W1xx`); errors make [`compile`] fail instead.
    pub warnings: Diagnostics,
    /// Every file read: the source itself (when it came from a path) and its imports, in the
    /// order read. A watcher recompiles when any of them changes.
    pub files: Vec<PathBuf>,
}

/// Compiles `.tl` text. `origin` names it in diagnostics; imports are resolved relative to
/// `origin`'s directory when it is a path.
///
/// # Errors
/// Every error found (`tl::E1xx`), with the warnings, as [`Diagnostics`].
pub fn compile(source: &str, origin: &str) -> Result<Compiled, Diagnostics> {
    let dir = Path::new(origin).parent().map(Path::to_path_buf);
    Compiler::default().run(source.to_owned(), origin, dir, None)
}

/// Reads and compiles the `.tl` file at `path`.
///
/// # Errors
/// `tl::E150` when the file cannot be read; otherwise as [`compile`].
pub fn compile_file(path: &Path) -> Result<Compiled, Diagnostics> {
    let origin = path.display().to_string();
    match crate::source_file::read_text(path) {
        Ok(text) => {
            let dir = path.parent().map(Path::to_path_buf);
            Compiler::default().run(text, &origin, dir, Some(path.to_path_buf()))
        }
        Err(e) => {
            let source: Source = Arc::new(NamedSource::new(origin.clone(), String::new()));
            let mut diags = Diagnostics::default();
            let help = match e.kind() {
                std::io::ErrorKind::NotFound => "check the path; a relative path starts from the current folder",
                std::io::ErrorKind::InvalidData => "a scenario is a `.tl` text file in UTF-8 (grammar/README.md)",
                _ => "a scenario is a regular `.tl` text file of at most 64 MiB",
            };
            diags.push(
                Diagnostic::bare(Code::UnreadableSource, format!("cannot read `{origin}`: {e}"), &source)
                    .with_help(help),
            );
            Err(diags)
        }
    }
}

/// Checks a `.tl` file as `touchline check` does: a file with a scenario is compiled as by
/// [`compile_file`]; a file of presets only (a library others import) has each preset resolved
/// and checked. Returns every diagnostic, errors and warnings.
pub fn check_file(path: &Path) -> Diagnostics {
    let text = match crate::source_file::read_text(path) {
        Ok(text) => text,
        Err(_) => return compile_file(path).err().unwrap_or_default(),
    };
    let library = syntax::parse(&Arc::new(NamedSource::new(path.display().to_string(), text.clone())))
        .map(|f| {
            let defs: Vec<Kind> =
                f.items.iter().filter_map(|i| if let Item::Definition(d) = i { Some(d.kind) } else { None }).collect();
            !defs.is_empty() && defs.iter().all(|k| *k == Kind::Preset)
        })
        .unwrap_or(false);
    if !library {
        return match compile_file(path) {
            Ok(c) => c.warnings,
            Err(d) => d,
        };
    }
    let mut c = Compiler::default();
    let origin = path.display().to_string();
    let key = path.canonicalize().ok();
    if let Some(main) = c.load(text, &origin, path.parent().map(Path::to_path_buf), false, key) {
        c.prelude = c.load(PRELUDE.to_owned(), "prelude.tl", None, true, None);
        let count = c.definitions(main).count();
        for def in 0..count {
            c.resolve(main, def);
        }
        c.report_unused_imports();
    }
    c.diags.dedup();
    c.diags
}

/// One parsed file.
struct Unit {
    source: Source,
    file: syntax::File,
    /// Units this one imports, with the import's span.
    imports: Vec<(usize, syntax::Span)>,
    /// Whether the file is a stdlib scenario or the prelude (no imports allowed).
    embedded: bool,
}

#[derive(Default)]
struct Compiler {
    units: Vec<Unit>,
    by_path: HashMap<PathBuf, usize>,
    diags: Diagnostics,
    cache: HashMap<(usize, usize), Option<Resolved>>,
    stack: Vec<(usize, usize)>,
    used_imports: Vec<(usize, usize)>,
    files: Vec<PathBuf>,
    prelude: Option<usize>,
    /// Imports being loaded now, outermost first (each loads its own imports recursively).
    importing: usize,
}

impl Compiler {
    fn run(
        mut self,
        text: String,
        origin: &str,
        dir: Option<PathBuf>,
        path: Option<PathBuf>,
    ) -> Result<Compiled, Diagnostics> {
        if let Some(p) = &path {
            self.files.push(p.clone());
        }
        let key = path.as_ref().map(|p| p.canonicalize().unwrap_or_else(|_| p.clone()));
        let Some(main) = self.load(text, origin, dir, false, key) else { return Err(self.diags) };
        let prelude = self.load(PRELUDE.to_owned(), "prelude.tl", None, true, None);
        self.prelude = prelude;
        let scenarios: Vec<usize> =
            self.definitions(main).filter(|(_, d)| d.kind == Kind::Scenario).map(|(i, _)| i).collect();
        let source = self.units[main].source.clone();
        let def = match scenarios.as_slice() {
            [one] => *one,
            [] => {
                self.diags.push(
                    Diagnostic::bare(Code::ScenarioCount, "this file defines no scenario", &source)
                        .with_help("add `scenario NAME { … }`; presets alone cannot be played"),
                );
                return Err(self.diags);
            }
            [_, rest @ ..] => {
                for &i in rest {
                    let span = self.definition(main, i).name.span;
                    self.diags.push(
                        Diagnostic::new(
                            Code::ScenarioCount,
                            "a file defines one scenario",
                            &source,
                            span,
                            "another scenario",
                        )
                        .with_help("move it to its own file, or make it a `preset`"),
                    );
                }
                return Err(self.diags);
            }
        };
        let resolved = self.resolve(main, def);
        let Some((mut scenario, origins, _)) = resolved else {
            self.report_unused_imports();
            self.diags.dedup();
            return Err(self.diags);
        };
        let name_span = self.definition(main, def).name.span;
        check::check(&scenario, &origins, &source, name_span, &mut self.diags);
        scenario.curriculum = self.curriculum(main, def);
        self.report_unused_imports();
        // A parent resolved for several children (or lessons) reports its mistakes once.
        self.diags.dedup();
        if self.diags.has_errors() {
            return Err(self.diags);
        }
        Ok(Compiled { scenario, warnings: self.diags, files: self.files })
    }

    /// Parses a file and, recursively, its imports.
    /// `key` (a canonical path) registers the file before its imports load, so that an import
    /// cycle links back to it instead of loading it again.
    fn load(
        &mut self,
        text: String,
        origin: &str,
        dir: Option<PathBuf>,
        embedded: bool,
        key: Option<PathBuf>,
    ) -> Option<usize> {
        let source: Source = Arc::new(NamedSource::new(origin, text));
        let file = match syntax::parse(&source) {
            Ok(f) => f,
            Err(d) => {
                self.diags.push(*d);
                return None;
            }
        };
        let index = self.units.len();
        let imports: Vec<syntax::Spanned<String>> =
            file.items.iter().filter_map(|i| if let Item::Import(p) = i { Some(p.clone()) } else { None }).collect();
        self.units.push(Unit { source: source.clone(), file, imports: Vec::new(), embedded });
        if let Some(key) = key {
            self.by_path.insert(key, index);
        }
        self.check_duplicate_names(index);
        for import in imports {
            let Some(dir) = dir.as_ref().filter(|_| !embedded) else {
                self.diags.push(
                    Diagnostic::new(
                        Code::MissingImport,
                        "imports need a scenario file on disk",
                        &source,
                        import.span,
                        "here",
                    )
                    .with_help(
                        "compile the scenario from a file (touchline check FILE.tl) so imports have a directory",
                    ),
                );
                continue;
            };
            let path = dir.join(&import.value);
            let key = path.canonicalize().unwrap_or_else(|_| path.clone());
            if let Some(&u) = self.by_path.get(&key) {
                self.units[index].imports.push((u, import.span));
                continue;
            }
            if self.importing >= syntax::MAX_NESTING {
                self.diags.push(too_deep(&source, import.span, "imports", "an import of an import …"));
                continue;
            }
            match crate::source_file::read_text(&path) {
                Ok(text) => {
                    self.files.push(path.clone());
                    let origin = path.display().to_string();
                    self.importing += 1;
                    let loaded = self.load(text, &origin, path.parent().map(Path::to_path_buf), false, Some(key));
                    self.importing -= 1;
                    if let Some(u) = loaded {
                        self.units[index].imports.push((u, import.span));
                    }
                }
                Err(e) => self.diags.push(
                    Diagnostic::new(
                        Code::MissingImport,
                        format!("cannot import `{}`: {}", import.value, io_reason(&e)),
                        &source,
                        import.span,
                        "not found",
                    )
                    .with_help(format!("the path is relative to this file: {}", path.display())),
                ),
            }
        }
        Some(index)
    }

    fn definitions(&self, unit: usize) -> impl Iterator<Item = (usize, &Definition)> {
        self.units[unit]
            .file
            .items
            .iter()
            .filter_map(|i| if let Item::Definition(d) = i { Some(d) } else { None })
            .enumerate()
    }

    fn definition(&self, unit: usize, index: usize) -> &Definition {
        self.definitions(unit).nth(index).map(|(_, d)| d).expect("definition indices come from `definitions`")
    }

    fn check_duplicate_names(&mut self, unit: usize) {
        let mut seen: HashMap<&str, syntax::Span> = HashMap::new();
        let mut found = Vec::new();
        for (_, d) in self.definitions(unit) {
            if let Some(first) = seen.insert(&d.name.value, d.name.span) {
                found.push((d.name.value.clone(), d.name.span, first));
            }
        }
        let source = self.units[unit].source.clone();
        for (name, span, first) in found {
            self.diags.push(
                Diagnostic::new(
                    Code::DuplicateDefinition,
                    format!("`{name}` is defined twice"),
                    &source,
                    span,
                    "again here",
                )
                .with_label(first, "first defined here")
                .with_help("rename one of them: `extends` finds definitions by name"),
            );
        }
    }

    /// Finds the definition `name` as seen from `unit`: its own, its imports', the prelude's,
    /// then the stdlib's scenarios.
    fn lookup(&mut self, unit: usize, name: &str) -> Option<(usize, usize)> {
        let find = |c: &Compiler, u: usize| c.definitions(u).find(|(_, d)| d.name.value == name).map(|(i, _)| (u, i));
        if let Some(found) = find(self, unit) {
            return Some(found);
        }
        let imports: Vec<usize> = self.units[unit].imports.iter().map(|(u, _)| *u).collect();
        for (k, u) in imports.into_iter().enumerate() {
            if let Some(found) = find(self, u) {
                self.used_imports.push((unit, k));
                return Some(found);
            }
        }
        if let Some(found) = self.prelude.and_then(|p| find(self, p)) {
            return Some(found);
        }
        let text = stdlib::tl_source(name)?;
        let key = PathBuf::from(format!("stdlib/{name}.tl"));
        let u = match self.by_path.get(&key) {
            Some(&u) => u,
            None => {
                let origin = key.display().to_string();
                self.load(text.to_owned(), &origin, None, true, Some(key))?
            }
        };
        find(self, u)
    }

    /// Every name `unit` can extend, for suggestions.
    fn visible_names(&self, unit: usize) -> Vec<String> {
        let mut units = vec![unit];
        units.extend(self.units[unit].imports.iter().map(|(u, _)| *u));
        units.extend(self.prelude);
        let mut names: Vec<String> =
            units.iter().flat_map(|&u| self.definitions(u).map(|(_, d)| d.name.value.clone())).collect();
        names.extend(stdlib::names().iter().map(|n| (*n).to_owned()));
        names
    }

    /// The scenario definition `(unit, def)` describes, with its parents applied first.
    fn resolve(&mut self, unit: usize, def: usize) -> Option<Resolved> {
        self.resolve_with(unit, def, &Params::default())
    }

    /// As [`Compiler::resolve`], with `overrides` (from a definition extending this one, or a
    /// lesson) replacing the values of parameters of the same name along the whole chain.
    fn resolve_with(&mut self, unit: usize, def: usize, overrides: &Params) -> Option<Resolved> {
        let cached = overrides.is_empty();
        if cached && let Some(done) = self.cache.get(&(unit, def)) {
            return done.clone();
        }
        let d = self.definition(unit, def).clone();
        let source = self.units[unit].source.clone();
        let (declared, assigned) = params::of_statements(&d.statements, &source);
        self.check_param_duplicates(&declared, &source);
        if d.kind == Kind::Preset
            && let Some(st) = d.statements.iter().find(|s| matches!(s.kind, StatementKind::Curriculum(_)))
        {
            self.diags.push(
                Diagnostic::new(
                    Code::CurriculumShape,
                    "a curriculum belongs in a scenario",
                    &source,
                    st.span,
                    "in a preset",
                )
                .with_help("curricula are not inherited through `extends`: move it to the scenario that plays it"),
            );
        }
        // What the parent chain sees: this definition's values, then those given from below.
        let mut down = Params::default();
        for p in declared.iter().chain(&assigned) {
            down.set(p.clone());
        }
        let down = down.overridden_by(overrides);
        let parent = d.statements.iter().find_map(|s| match &s.kind {
            StatementKind::Extends(name) => Some(name.clone()),
            _ => None,
        });
        self.stack.push((unit, def));
        let base = match parent {
            None => Some((Scenario::default(), Origins::default(), Params::default())),
            Some(name) => match self.lookup(unit, &name.value) {
                Some(target) if self.stack.contains(&target) => {
                    let chain: Vec<String> = self
                        .stack
                        .iter()
                        .skip_while(|t| **t != target)
                        .map(|&(u, i)| self.definition(u, i).name.value.clone())
                        .chain(std::iter::once(name.value.clone()))
                        .collect();
                    self.diags.push(
                        Diagnostic::new(
                            Code::ExtendsCycle,
                            format!("`extends` goes round in a circle: {}", chain.join(" → ")),
                            &source,
                            name.span,
                            "closes the cycle",
                        )
                        .with_help("a definition cannot extend itself, directly or through others"),
                    );
                    None
                }
                Some(_) if self.stack.len() >= syntax::MAX_NESTING => {
                    self.diags.push(too_deep(
                        &source,
                        name.span,
                        "definitions in an `extends` chain",
                        "a preset extending a preset …",
                    ));
                    None
                }
                Some((u, i)) => self.resolve_with(u, i, &down),
                None => {
                    let names = self.visible_names(unit);
                    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
                    let close = suggest::closest(&name.value, &refs);
                    self.diags.push(
                        Diagnostic::new(
                            Code::UnknownParent,
                            format!("nothing called `{}` to extend", name.value),
                            &source,
                            name.span,
                            "unknown preset or scenario",
                        )
                        .with_help(suggest_help(
                            &close,
                            "extend a preset of this file or an import, `academy`, or a stdlib scenario",
                        )),
                    );
                    None
                }
            },
        };
        // Without a parent the body is still read, so that its own mistakes are reported too.
        let parent_ok = base.is_some();
        let (mut scenario, mut origins, mut env) = base.unwrap_or_default();
        for p in &declared {
            env.set(down.get(&p.name).cloned().unwrap_or_else(|| p.clone()));
        }
        self.assign_params(&mut env, &assigned, &down, &source, None);
        let mut reader = Reader::new(&source, &mut self.diags, &env);
        statements::apply(&d, &mut scenario, &mut origins, &mut reader);
        reader.warn_repeated_draws();
        scenario.name = d.name.value.clone();
        scenario.description = description(&d.docs);
        let result = parent_ok.then_some((scenario, origins, env));
        self.stack.pop();
        if cached {
            self.cache.insert((unit, def), result.clone());
        }
        result
    }

    /// `tl::E141` for a parameter declared twice in one body.
    fn check_param_duplicates(&mut self, declared: &[Param], source: &Source) {
        for (i, p) in declared.iter().enumerate() {
            if let Some(first) = declared[..i].iter().find(|q| q.name == p.name) {
                self.diags.push(
                    Diagnostic::new(
                        Code::ParamRedefined,
                        format!("param `{}` is declared twice", p.name),
                        source,
                        p.span,
                        "declared again here",
                    )
                    .with_label(first.span, "first declared here")
                    .with_help(format!(
                        "declare it once; to give an inherited param another value write `{} = VALUE`",
                        p.name
                    )),
                );
            }
        }
    }

    /// Gives `env`'s parameters the values of `assigned` (`NAME = VALUE`), unless `down` (from
    /// below) gives them already; `tl::E140` for a name `env` does not have. `lesson` names the
    /// lesson the assignments belong to, for the message.
    fn assign_params(
        &mut self,
        env: &mut Params,
        assigned: &[Param],
        down: &Params,
        source: &Source,
        lesson: Option<&str>,
    ) {
        for a in assigned {
            if env.get(&a.name).is_none() {
                let names = env.names();
                let close = suggest::closest(&a.name, &names);
                let message = match lesson {
                    Some(l) => format!("lesson `{l}` sets `{}`, which is not a param", a.name),
                    None => format!("`{}` is not a param", a.name),
                };
                let otherwise = if statements::is_key(&a.name) {
                    format!("`{}` is a configuration key: write `{} VALUE`, without `=`", a.name, a.name)
                } else if names.is_empty() {
                    "no param is declared; declare one with `param NAME = VALUE`".to_owned()
                } else {
                    format!("the params are {}", names.join(", "))
                };
                self.diags.push(
                    Diagnostic::new(Code::UnknownParam, message, source, a.span, "unknown param")
                        .with_help(suggest_help(&close, &otherwise)),
                );
                continue;
            }
            env.set(down.get(&a.name).cloned().unwrap_or_else(|| a.clone()));
        }
    }

    fn report_unused_imports(&mut self) {
        for (u, unit) in self.units.iter().enumerate() {
            if unit.embedded {
                continue;
            }
            for (k, (_, span)) in unit.imports.iter().enumerate() {
                if !self.used_imports.contains(&(u, k)) {
                    self.diags.push(
                        Diagnostic::new(
                            Code::UnusedImport,
                            "nothing from this import is used",
                            &unit.source,
                            *span,
                            "unused",
                        )
                        .with_help("remove the import, or `extends` one of its definitions"),
                    );
                }
            }
        }
    }
}

/// Why a file cannot be read, in words that do not depend on the platform for the common cases.
/// `tl::E148` for a chain (`extends`, imports, params) longer than [`syntax::MAX_NESTING`]: each
/// link is resolved recursively, so an endless-looking chain would overflow the stack.
pub(crate) fn too_deep(source: &Source, span: syntax::Span, what: &str, shape: &str) -> Diagnostic {
    let max = syntax::MAX_NESTING;
    Diagnostic::new(
        Code::TooDeep,
        format!("nested too deeply: more than {max} {what}"),
        source,
        span,
        format!("link {} of the chain", max + 1),
    )
    .with_help(format!("{shape} may go {max} deep; shorten the chain"))
}

pub(crate) fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".to_owned(),
        std::io::ErrorKind::PermissionDenied => "permission denied".to_owned(),
        std::io::ErrorKind::InvalidData => "the file is not UTF-8 text".to_owned(),
        std::io::ErrorKind::IsADirectory => "it is a directory".to_owned(),
        _ => e.to_string(),
    }
}

/// Doc lines joined: consecutive lines with a space, an empty line starts a new paragraph.
fn description(docs: &[String]) -> String {
    let mut out = String::new();
    for line in docs {
        if line.is_empty() {
            out.push_str("\n\n");
        } else {
            if !out.is_empty() && !out.ends_with('\n') {
                out.push(' ');
            }
            out.push_str(line);
        }
    }
    out.trim().to_owned()
}
