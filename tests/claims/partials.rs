//! Derivatives in a function's parameter are partial derivatives in the prover as in the
//! numerical backends: `d(x*y, x)` in `f(x, y)` called as `f(t, t^2)` is `t^2`, not the
//! total derivative `3 t^2` in the claim variable `t`.

use super::support::{attempt, controls_only, identity_claim};
use eulertop::claims::catalogue::Catalogue;

const DEFS: &str = r#"
[[claim]]
id = "t.def.partial"
environment = "Section 2"
role = "definition"
labels = []
location = "control: a derivative in a function parameter"
printed = 'x'
kind = "definition"
define = '''
pxy(x, y) = d(x * y, x)
px(x, c) = d(c * x^3, x)
'''
"#;

fn control(id: &str, lhs: &str, rhs: &str) -> String {
    identity_claim(
        id,
        "control: partial derivatives",
        r#"["t", "uniform(1, 2)"], ["c", "uniform(1, 2)"]"#,
        lhs,
        rhs,
    )
}

fn catalogue() -> Catalogue {
    let text = [
        DEFS.to_string(),
        control("t.partial.right", "pxy(t, t^2)", "t^2"),
        control("t.partial.total", "pxy(t, t^2)", "3*t^2"),
        control("t.partial.independent", "px(t, c)", "3*c*t^2"),
    ]
    .concat();
    controls_only(text)
}

#[test]
fn a_derivative_in_a_parameter_holds_the_other_parameters_fixed() {
    let cat = catalogue();
    let p = attempt(&cat, "t.partial.right");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(!attempt(&cat, "t.partial.total").is_proved());
    let q = attempt(&cat, "t.partial.independent");
    assert!(q.is_proved(), "{:?}", q.reason);
}
