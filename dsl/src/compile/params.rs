//! Compile-time parameters (`param gap = 10 m`): the values a definition chain declares, with
//! the overrides of definitions that extend it and of curriculum lessons.
//!
//! A parameter is kept as its expression, not as a number: `gap` reads as whatever the place it
//! is used in expects (a coordinate converts metres per axis, `difficulty` takes a plain number,
//! a region or a distribution works too). Parameters bind late: a parent's `CB at (gap, 0)` sees
//! the value a child or a lesson gives `gap`.

use crate::diagnostic::{Code, Source};
use crate::syntax::{Expr, Span, Statement, StatementKind};

/// One parameter's current value.
#[derive(Clone, Debug)]
pub(crate) struct Param {
    /// The name.
    pub(crate) name: String,
    /// The value's expression.
    pub(crate) value: Expr,
    /// The text `value` (and `span`) point into: the value may come from another file than the
    /// statement that reads it.
    pub(crate) source: Source,
    /// Where the value was given (the name of its `param` or assignment).
    pub(crate) span: Span,
}

/// Parameters by name (a handful per scenario: a list is faster than a map).
#[derive(Clone, Debug, Default)]
pub(crate) struct Params {
    items: Vec<Param>,
}

impl Params {
    /// The parameter `name`.
    pub(crate) fn get(&self, name: &str) -> Option<&Param> {
        self.items.iter().find(|p| p.name == name)
    }

    /// Sets `param`, replacing one of the same name.
    pub(crate) fn set(&mut self, param: Param) {
        match self.items.iter_mut().find(|p| p.name == param.name) {
            Some(slot) => *slot = param,
            None => self.items.push(param),
        }
    }

    /// Whether there are none.
    pub(crate) fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Every name, in declaration order (for suggestions).
    pub(crate) fn names(&self) -> Vec<&str> {
        self.items.iter().map(|p| p.name.as_str()).collect()
    }

    /// `self` with `other`'s values where `other` has the name too (`other` wins).
    pub(crate) fn overridden_by(&self, other: &Params) -> Params {
        let mut out = self.clone();
        for p in &other.items {
            out.set(p.clone());
        }
        out
    }
}

/// The `param` declarations and the assignments of a body, as two lists.
pub(crate) fn of_statements(statements: &[Statement], source: &Source) -> (Vec<Param>, Vec<Param>) {
    let mut declared = Vec::new();
    let mut assigned = Vec::new();
    for st in statements {
        let (list, name, value) = match &st.kind {
            StatementKind::Param { name, value } => (&mut declared, name, value),
            StatementKind::Assign { name, value } => (&mut assigned, name, value),
            _ => continue,
        };
        list.push(Param { name: name.value.clone(), value: value.clone(), source: source.clone(), span: name.span });
    }
    (declared, assigned)
}

impl super::value::Reader<'_> {
    /// `tl::W105` where a parameter holding a distribution gives a value for both axes: its uses
    /// share one draw per reset, so x and y move together, which is seldom meant.
    pub(crate) fn warn_repeated_draws(&mut self) {
        use super::value::Axis;
        let mut warned: Vec<&str> = Vec::new();
        let mut found = Vec::new();
        for (name, span, axis) in &self.random_uses {
            if warned.contains(&name.as_str()) {
                continue;
            }
            let other = self.random_uses.iter().find(|(n, _, a)| n == name && a != axis);
            if let (Some((_, first, _)), Axis::Y) = (other, axis) {
                warned.push(name);
                found.push((name.clone(), *span, *first));
            }
        }
        for (name, span, first) in found {
            self.diags.push(
                crate::diagnostic::Diagnostic::new(
                    Code::RepeatedDraw,
                    format!("param `{name}` is drawn once per reset and used for both x and y"),
                    self.source,
                    span,
                    "the same draw as a y",
                )
                .with_label(first, "and as an x")
                .with_help(
                    "every use of a distribution param shares one draw per reset, so these coordinates move \
                     together; give each axis its own param if they should not",
                ),
            );
        }
    }
}
