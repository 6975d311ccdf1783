//! Properties of the state read in a hook, checked when the script compiles.
//!
//! rhai resolves `s.ball_owner` only when the line runs, and then says "a getter is not registered
//! for type 'State'", which names neither the real properties nor the step it will fail at. The
//! hooks' first parameter is always the state, so a property read on it can be checked against
//! [`STATE_PROPERTIES`] before anything runs: `touchline check` and every loader report a misspelt
//! name with the closest real ones. Reads through other names (a helper's parameter, a variable
//! holding `s.prev`) cannot be typed statically; they fail at run time with the same help
//! ([`unknown_at_run_time`]).

use rhai::{AST, ASTNode, Expr, Stmt};

use super::api::STATE_PROPERTIES;

/// The hooks, each called with the state as its first parameter.
const HOOKS: [&str; 4] = ["reward", "end", "act", "reset"];

/// A property of the state that does not exist, and where it is read.
#[derive(Debug)]
pub(crate) struct UnknownProperty {
    pub(crate) name: String,
    pub(crate) position: rhai::Position,
}

/// The first property read on a hook's state parameter (or on its `prev`) that the state does not
/// have.
pub(crate) fn first_unknown(ast: &AST) -> Option<UnknownProperty> {
    for hook in ast.iter_functions().filter(|f| HOOKS.contains(&f.name) && !f.params.is_empty()) {
        let (name, arity, state) = (hook.name, hook.params.len(), hook.params[0]);
        let body = only_function(ast, name, Some(arity));
        let mut found = None;
        // A hook that declares a variable of its parameter's name reads something else through
        // it from there on; such a body is not checked rather than checked wrongly.
        let mut shadowed = false;
        body.walk(&mut |nodes: &[ASTNode]| {
            match nodes.last() {
                Some(ASTNode::Stmt(Stmt::Var(var, ..))) if var.0.name == state => shadowed = true,
                Some(ASTNode::Expr(Expr::Dot(dot, ..)))
                    if found.is_none() && matches!(&dot.lhs, Expr::Variable(v, ..) if v.1 == state) =>
                {
                    found = unknown_in_chain(&dot.rhs);
                }
                _ => {}
            }
            true
        });
        if let Some(found) = found.filter(|_| !shadowed) {
            return Some(found);
        }
    }
    None
}

/// `ast`'s functions named `name` (with `arity` parameters, when given), and nothing else, to
/// walk one function's body. (rhai's `clone_functions_only_filtered` keeps every function when it
/// copies into an empty module, so the filter is applied afterwards.)
pub(crate) fn only_function(ast: &AST, name: &str, arity: Option<usize>) -> AST {
    let mut only = ast.clone_functions_only();
    only.retain_functions(|_, _, n, a| n == name && arity.is_none_or(|arity| a == arity));
    only
}

/// Checks the property that starts a chain read on the state (`ball`, `left_team[0]`,
/// `prev.score`), following `prev` into the earlier view.
fn unknown_in_chain(rhs: &Expr) -> Option<UnknownProperty> {
    let (first, rest) = match rhs {
        Expr::Dot(inner, ..) => (&inner.lhs, Some(&inner.rhs)),
        Expr::Index(inner, ..) => (&inner.lhs, None),
        other => (other, None),
    };
    // A method call on the state (`s.type_of()`) is rhai's business, not a property.
    let Expr::Property(property, position) = first else { return None };
    let name = property.2.as_str();
    if !STATE_PROPERTIES.contains(&name) {
        return Some(UnknownProperty { name: name.to_owned(), position: *position });
    }
    match rest {
        Some(rest) if name == "prev" => unknown_in_chain(rest),
        _ => None,
    }
}

/// The help for an unknown property `name`: the closest real ones, then all of them.
pub(crate) fn help(name: &str) -> String {
    let mut close = crate::suggest::closest(name, STATE_PROPERTIES);
    if close.is_empty() {
        // Long names are often cut or run on (`ball_owner`): those sharing the longest start, when
        // that is most of what was written.
        let shared = |p: &str| p.bytes().zip(name.bytes()).take_while(|(a, b)| a == b).count();
        let best = STATE_PROPERTIES.iter().map(|p| shared(p)).max().unwrap_or(0);
        if best * 3 >= name.len() * 2 {
            close = STATE_PROPERTIES.iter().copied().filter(|p| shared(p) == best).collect();
        }
    }
    let all = STATE_PROPERTIES.join(", ");
    match close.as_slice() {
        [] => format!("the state's properties are {all} (grammar/scripts.md)"),
        [one] => format!("did you mean `{one}`? The state's properties are {all} (grammar/scripts.md)"),
        many => format!(
            "did you mean one of `{}`? The state's properties are {all} (grammar/scripts.md)",
            many.join("`, `")
        ),
    }
}

/// The message and help of rhai's run-time "Unknown property 'x' - a getter is not registered for
/// type 'State'" (or a setter: the state is read-only), when `message` is one.
pub(crate) fn unknown_at_run_time(message: &str) -> Option<(String, String)> {
    let rest = message.strip_prefix("Unknown property '").or_else(|| message.strip_prefix("No writable property '"))?;
    let (name, tail) = rest.split_once('\'')?;
    if !tail.contains("for type 'State'") {
        return None;
    }
    if tail.contains("setter") {
        return Some((
            format!("the state is read-only: `{name}` cannot be assigned"),
            "keep values of your own in `memory` (`memory.x = …`)".to_owned(),
        ));
    }
    Some((format!("the state has no property `{name}`"), help(name)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unknown(text: &str) -> Option<String> {
        let ast = rhai::Engine::new_raw().compile(text).unwrap();
        first_unknown(&ast).map(|u| u.name)
    }

    #[test]
    fn finds_unknown_properties_on_the_hooks_state() {
        assert_eq!(unknown("fn reward(s) { s.ball_owner }").as_deref(), Some("ball_owner"));
        assert_eq!(unknown("fn end(st) { st.stepz > 3 }").as_deref(), Some("stepz"));
        assert_eq!(unknown("fn act(s, me) { s.left_teem[me] }").as_deref(), Some("left_teem"));
        assert_eq!(unknown("fn reset(s) { memory.x = s.prev.scor; }").as_deref(), Some("scor"));
        assert_eq!(unknown("fn reward(s) { if s.steps > 1 { s.ball.len() + s.bal[0] } }").as_deref(), Some("bal"));
    }

    #[test]
    fn leaves_real_properties_methods_and_other_values_alone() {
        assert_eq!(unknown("fn reward(s) { s.ball[0] + s.left_team[0][1] + s.prev.score[0] }"), None);
        assert_eq!(unknown("fn reward(s) { s.ball.len() + s.type_of().len() }"), None);
        // Not a hook, or not its state: no static type to check against.
        assert_eq!(unknown("fn helper(s) { s.anything }"), None);
        assert_eq!(unknown("fn helper(s) { s.anything } fn reward(s) { 0 }"), None);
        assert_eq!(unknown("fn reward(s) { let m = #{a: 1}; m.a }"), None);
        assert_eq!(unknown("fn reward(s) { let s = #{a: 1}; s.a }"), None);
        assert_eq!(unknown("fn act(s, me) { me.x }"), None);
    }

    #[test]
    fn run_time_messages_are_rewritten() {
        let (message, help) =
            unknown_at_run_time("Unknown property 'ball_owner' - a getter is not registered for type 'State'").unwrap();
        assert_eq!(message, "the state has no property `ball_owner`");
        assert!(help.starts_with("did you mean one of `ball_owned_team`, `ball_owned_player`?"), "{help}");
        let (message, _) = unknown_at_run_time(
            "No writable property 'steps' - a setter is not registered for type 'State' to handle 'i64'",
        )
        .unwrap();
        assert!(message.contains("read-only"));
        assert!(unknown_at_run_time("Unknown property 'x' - a getter is not registered for type 'Map'").is_none());
    }
}
