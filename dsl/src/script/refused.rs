//! Calls the sandbox refuses when a script compiles: rhai's clock and blocking functions.
//!
//! The sandbox's engine does not have them ([`super::engine`] leaves out rhai's core package,
//! where `sleep` lives, and `no_time` leaves out the clock), so a call by a name computed at run
//! time only fails with "function not found". Refusing the calls that can be seen in the text
//! turns the mistake into a diagnostic at `touchline check`, before anything runs, and explains
//! why: a hook that blocks would hold the env (and Python's GIL), and a clock would make
//! trajectories depend on the machine.

use rhai::{AST, ASTNode, Expr, Stmt};

/// The names refused, with why each is not there.
const REFUSED: &[(&str, &str)] = &[
    ("sleep", "a hook must not block: it runs inside the env's step, holding the env (and Python's GIL)"),
    ("timestamp", "scripts have no clock: time would make trajectories depend on the machine"),
    ("elapsed", "scripts have no clock: time would make trajectories depend on the machine"),
];

/// A refused call or property: its name, why, and where.
#[derive(Debug)]
pub(crate) struct Refusal {
    pub(crate) name: &'static str,
    pub(crate) why: &'static str,
    pub(crate) position: rhai::Position,
}

/// The first refused call in `ast` (top level and function bodies), if any.
pub(crate) fn first_refused(ast: &AST) -> Option<Refusal> {
    let mut found = None;
    ast.walk(&mut |path: &[ASTNode]| {
        let (name, position) = match path.last() {
            // A call as a statement (`sleep(1);`) is a statement node, not an expression.
            Some(ASTNode::Stmt(Stmt::FnCall(call, pos))) => (call.name.as_str(), *pos),
            Some(ASTNode::Expr(Expr::FnCall(call, pos) | Expr::MethodCall(call, pos))) => (call.name.as_str(), *pos),
            Some(ASTNode::Expr(Expr::Property(property, pos))) => (property.2.as_str(), *pos),
            _ => return true,
        };
        match REFUSED.iter().find(|(refused, _)| *refused == name) {
            Some(&(name, why)) => {
                found = Some(Refusal { name, why, position });
                false
            }
            None => true,
        }
    });
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refused(text: &str) -> Option<&'static str> {
        let ast = rhai::Engine::new_raw().compile(text).unwrap();
        first_refused(&ast).map(|r| r.name)
    }

    #[test]
    fn finds_calls_methods_and_properties_anywhere() {
        assert_eq!(refused("fn reward(s) { sleep(1); 0 }"), Some("sleep"));
        assert_eq!(refused("const X = sleep(86400);"), Some("sleep"));
        assert_eq!(refused("fn f(x) { x.sleep() }"), Some("sleep"));
        assert_eq!(refused("fn f(x) { let t = timestamp(); t.elapsed }"), Some("timestamp"));
        assert_eq!(refused("fn f(x) { x.elapsed }"), Some("elapsed"));
        assert_eq!(refused("fn f(x) { if true { [1, elapsed(x)] } }"), Some("elapsed"));
        assert_eq!(refused("fn reward(s) { let sleeping = 1; sleeping }"), None);
        assert_eq!(refused("fn reward(s) { s.steps }"), None);
        assert_eq!(refused("fn reward(s) { sleep(1); 0 }"), Some("sleep"));
        assert_eq!(refused("sleep(1);"), Some("sleep"));
    }
}
