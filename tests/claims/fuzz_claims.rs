//! Fuzzing the expression language: random byte strings, random token soups and random
//! well-formed expressions (depth ≤ 12, every built-in with every argument type it takes,
//! every function the model registers, every value type) go through the lexer, the
//! parser, the catalogue loader and the evaluator at f64 and 256 bits.  Each step must
//! return a value or an error: no panic, no stack overflow, no hang.
//!
//! 2,000 cases per property in the default suite; `cargo test --release --test claims
//! fuzz_claims -- --ignored` runs 10⁵ (see the README).  A failure prints the input.

use eulertop::claims::builtins::Builtin;
use eulertop::claims::catalogue::load_sources;
use eulertop::claims::eval::Evaluator;
use eulertop::claims::lexer::lex;
use eulertop::claims::parser::{parse_bindings, parse_expr};
use eulertop::claims::registry::Registry;
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Built-ins with their argument types and result type: `r` real, `c` complex,
/// `v` vec3, `m` mat3, `q` cmat2 (2×2 complex), `b` bool, `i` a literal 1, 2 or 3.
const SIGS: &[(&str, &str, char)] = &[
    ("sqrt", "r", 'r'),
    ("sqrt", "c", 'c'),
    ("abs", "r", 'r'),
    ("abs", "c", 'r'),
    ("exp", "r", 'r'),
    ("exp", "c", 'c'),
    ("ln", "r", 'r'),
    ("ln", "c", 'c'),
    ("sin", "r", 'r'),
    ("cos", "r", 'r'),
    ("tan", "r", 'r'),
    ("atan", "r", 'r'),
    ("asin", "r", 'r'),
    ("sinh", "r", 'r'),
    ("cosh", "r", 'r'),
    ("tanh", "r", 'r'),
    ("asinh", "r", 'r'),
    ("atanh", "r", 'r'),
    ("floor", "r", 'r'),
    ("sign", "r", 'r'),
    ("atan2", "rr", 'r'),
    ("min", "rrr", 'r'),
    ("max", "rr", 'r'),
    ("re", "c", 'r'),
    ("im", "c", 'r'),
    ("conj", "c", 'c'),
    ("conj", "q", 'q'),
    ("arg", "c", 'r'),
    ("cplx", "rr", 'c'),
    ("sn", "rr", 'r'),
    ("cn", "cr", 'c'),
    ("dn", "rr", 'r'),
    ("cd", "rr", 'r'),
    ("dc", "cr", 'c'),
    ("ns", "rr", 'r'),
    ("nc", "cr", 'c'),
    ("nd", "rr", 'r'),
    ("sc", "cr", 'c'),
    ("sd", "rr", 'r'),
    ("cs", "cr", 'c'),
    ("ds", "rr", 'r'),
    ("am", "rr", 'r'),
    ("K", "r", 'r'),
    ("Kp", "r", 'r'),
    ("F", "rr", 'r'),
    ("jacobi_inverse", "rrrr", 'r'),
    ("ellipe", "r", 'r'),
    ("ellipeinc", "rr", 'r'),
    ("ellippi", "rrr", 'r'),
    ("jacobizeta", "rr", 'r'),
    ("heumanlambda", "rr", 'r'),
    ("nome", "r", 'r'),
    ("jtheta", "irr", 'r'),
    ("vec", "rrr", 'v'),
    ("dot", "vv", 'r'),
    ("cross", "vv", 'v'),
    ("norm2", "v", 'r'),
    ("norm", "v", 'r'),
    ("transpose", "m", 'm'),
    ("transpose", "q", 'q'),
    ("det", "m", 'r'),
    ("det", "q", 'c'),
    ("inv", "m", 'm'),
    ("inv", "q", 'q'),
    ("inv", "r", 'r'),
    ("tr", "m", 'r'),
    ("tr", "q", 'c'),
    ("comm", "mm", 'm'),
    ("comm", "qq", 'q'),
    ("I3", "", 'm'),
    ("I2", "", 'q'),
    ("diag", "v", 'm'),
    ("diag", "rrr", 'm'),
    ("pauli", "i", 'q'),
    ("skew", "v", 'm'),
    ("unskew", "m", 'v'),
    ("vnorm_inf", "v", 'r'),
];

/// The special forms (`sum`, `prod`, `d`, `grad`) have their own productions below.
const SPECIAL: [&str; 4] = ["sum", "prod", "d", "grad"];

/// Literals, variables (bound in every evaluation) and operators.
const LITERALS: [&str; 12] = [
    "0", "1", "2", "0.5", ".25", "3.75", "1e-3", "1e3", "7", "0.1", "1e300", "1e-300",
];
const VARS: [(char, &str); 7] = [
    ('r', "x"),
    ('r', "y"),
    ('c', "z"),
    ('v', "w"),
    ('m', "a"),
    ('q', "s"),
    ('b', "p"),
];
const BINDINGS: &str = "x = 0.3\ny = -1.7\nz = cplx(0.5, -2)\nw = vec(0.3, -0.7, 1.1)\n\
    a = [[2, 1, 0], [0, 3, 1], [1, 0, 4]]\ns = cplx(1, 2) * I2 + 0.5 * pauli(1) - pauli(2)\np = x < y";

/// A random expression generator: typed, depth-bounded and size-bounded.
struct Gen<'a> {
    rng: ChaCha8Rng,
    budget: usize,
    model: &'a [(String, usize, String)],
}

impl Gen<'_> {
    fn leaf(&mut self, t: char) -> String {
        let vars: Vec<&str> = VARS.iter().filter(|v| v.0 == t).map(|v| v.1).collect();
        match t {
            'r' if self.rng.gen_bool(0.5) => LITERALS[self.rng.gen_range(0..LITERALS.len())].into(),
            'r' if self.rng.gen_bool(0.1) => "pi".into(),
            'c' if self.rng.gen_bool(0.3) => "i".into(),
            'i' => self.rng.gen_range(1..=3).to_string(),
            _ => vars[self.rng.gen_range(0..vars.len())].into(),
        }
    }

    fn call(&mut self, name: &str, args: &str, depth: usize) -> String {
        let a: Vec<String> = args.chars().map(|t| self.expr(t, depth - 1)).collect();
        format!("{name}({})", a.join(", "))
    }

    /// Operators and special forms producing type `t`, if any was chosen.
    fn operator(&mut self, t: char, d: usize) -> Option<String> {
        let k = self.rng.gen_range(0..8);
        let mut e = |t: char| self.expr(t, d - 1);
        Some(match (t, k) {
            ('r' | 'c', 0) => format!("({} + {})", e(t), e(t)),
            ('r' | 'c', 1) => format!("({} * {} - {})", e(t), e(t), e(t)),
            ('r' | 'c', 2) => format!("{} / {}", e(t), e(t)),
            ('r' | 'c', 3) => format!("-{}^{}", e(t), e('r')),
            ('r', 4) => format!("sum(x, 0, {}, {})", e('i'), e('r')),
            ('r', 5) => format!("prod(x, 1, {}, {})", e('i'), e('r')),
            ('r', 6) => format!("d({}, x)", e('r')),
            ('r', 7) => format!(
                "{}[{}] + {}[{}, {}]",
                e('v'),
                e('i'),
                e('m'),
                e('i'),
                e('i')
            ),
            ('v', 0) => format!("grad({}, w)", e('r')),
            ('v', 1) => format!("[{}, {}, {}]", e('r'), e('r'), e('r')),
            ('v', 2) => format!("{} * {} + {}", e('m'), e('v'), e('v')),
            ('m' | 'q', 0) => format!("{} * {} - {}", e(t), e(t), e(t)),
            ('m', 1) => format!(
                "[[{}, 0, 1], [0, {}, 0], [1, 0, {}]]",
                e('r'),
                e('r'),
                e('r')
            ),
            ('q', 1) => format!("[[{}, 1], [{}, 0]]", e('c'), e('c')),
            ('b', 0) => format!("{} < {} and not {}", e('r'), e('r'), e('b')),
            ('b', 1) => format!("({} == {} or {})", e('r'), e('r'), e('b')),
            (_, 7) => format!("(if {} then {} else {})", e('b'), e(t), e(t)),
            _ => return None,
        })
    }

    fn expr(&mut self, t: char, depth: usize) -> String {
        if depth == 0 || self.budget == 0 || t == 'i' || self.rng.gen_bool(0.15) {
            return self.leaf(t);
        }
        self.budget -= 1;
        if self.rng.gen_bool(0.3)
            && let Some(s) = self.operator(t, depth)
        {
            return s;
        }
        if t == 'r' && self.rng.gen_bool(0.15) && !self.model.is_empty() {
            // a model function: mostly real and vec3 arguments, any result type
            let (name, arity, _) = self.model[self.rng.gen_range(0..self.model.len())].clone();
            let args: String = (0..arity)
                .map(|_| ['r', 'r', 'v', 'c'][self.rng.gen_range(0..4)])
                .collect();
            return self.call(&name, &args, depth);
        }
        let sigs: Vec<&(&str, &str, char)> = SIGS.iter().filter(|s| s.2 == t).collect();
        if sigs.is_empty() {
            return self.leaf(t);
        }
        let (name, args, _) = *sigs[self.rng.gen_range(0..sigs.len())];
        self.call(name, args, depth)
    }
}

/// A well-formed expression of a random type from `seed`, depth at most `depth`.
fn generate(seed: u64, depth: usize, model: &[(String, usize, String)]) -> String {
    let mut g = Gen {
        rng: ChaCha8Rng::seed_from_u64(seed),
        budget: 100,
        model,
    };
    let t = ['r', 'r', 'r', 'c', 'v', 'm', 'q', 'b'][g.rng.gen_range(0..8)];
    g.expr(t, depth)
}

/// Evaluates `src` with the variables of [`BINDINGS`] bound, at the precision of `like`.
fn evaluate<T: eulertop::claims::eval::Backend>(reg: &Registry, like: T, src: &str) {
    let Ok(e) = parse_expr(src) else { return };
    let mut ev = Evaluator::new(reg, like);
    for b in parse_bindings(BINDINGS).expect("bindings parse") {
        ev.bind_let(&b).expect("bindings evaluate");
    }
    let _ = ev.eval(&e);
}

/// Every stage on one input: lexer, parser (expression and bindings), the loader (the
/// text as a catalogue file, and as a claim's `lhs`), the evaluator at f64 and 256 bits.
fn check(src: &str) {
    let reg = catalogue_registry();
    let _ = lex(src);
    let _ = parse_bindings(src);
    let _ = load_sources(&[("fuzz.toml".into(), src.into())], catalogue_registry());
    let claim = format!(
        "[[claim]]\nid = \"f\"\nlocation = \"f\"\nprinted = 'f'\nkind = \"identity\"\n\
         vars = [[\"x\", \"uniform(0, 1)\"], [\"y\", \"uniform(-2, -1)\"]]\n\
         let = '''\n{BINDINGS}\n'''\nlhs = '''{src}'''\nrhs = \"0\"\n"
    );
    let _ = load_sources(&[("fuzz.toml".into(), claim)], catalogue_registry());
    evaluate(&reg, 0.0f64, src);
    evaluate(&reg, rug::Float::new(256), src);
}

/// Token soup: names of built-ins and model functions, literals, variables and symbols.
fn tokens() -> Vec<String> {
    let syms = "+ - * / ^ ( ) [ ] , < > <= >= == != = ; ' \n # if then else and or not";
    let mut t: Vec<String> = syms.split(' ').map(String::from).collect();
    t.extend(Builtin::ALL.iter().map(|b| b.name().to_string()));
    t.extend(LITERALS.iter().map(|s| s.to_string()));
    t.extend(VARS.iter().map(|v| v.1.to_string()));
    t.extend(catalogue_registry().registered().into_iter().map(|r| r.0));
    t
}

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// The generator covers every built-in, so a new one cannot escape the fuzzing.
#[test]
fn signatures_cover_every_builtin() {
    for b in Builtin::ALL.iter().map(|b| b.name()) {
        let covered = SIGS.iter().any(|s| s.0 == b) || SPECIAL.contains(&b);
        assert!(covered, "built-in '{b}' missing from the fuzz signatures");
    }
}

fn byte_strings(cases: u32) {
    proptest!(config(cases), |(bytes in prop::collection::vec(any::<u8>(), 0..256))| {
        check(&String::from_utf8_lossy(&bytes));
    });
}

fn token_soups(cases: u32) {
    let toks = tokens();
    proptest!(config(cases), |(ix in prop::collection::vec(any::<prop::sample::Index>(), 0..64))| {
        let src: Vec<&str> = ix.iter().map(|i| i.get(&toks).as_str()).collect();
        check(&src.join(" "));
    });
}

fn expressions(cases: u32) {
    let model = catalogue_registry().registered();
    proptest!(config(cases), |(seed in any::<u64>(), depth in 1usize..=12)| {
        let src = generate(seed, depth, &model);
        prop_assert!(parse_expr(&src).is_ok(), "generated text does not parse: {src}");
        check(&src);
    });
}

#[test]
fn random_bytes_never_panic() {
    byte_strings(2_000);
}

#[test]
fn random_token_soups_never_panic() {
    token_soups(2_000);
}

#[test]
fn random_expressions_never_panic() {
    expressions(2_000);
}

#[test]
#[ignore = "10^5 cases per property; run with --ignored (see the README)"]
fn long_run_100k_cases() {
    byte_strings(100_000);
    token_soups(100_000);
    expressions(100_000);
}

/// The catalogue's registry (the model's functions).
fn catalogue_registry() -> Registry {
    eulertop::bindings::euler_top::registry().expect("the model's registry builds")
}
