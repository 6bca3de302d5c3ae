//! A tour of the claims engine: one claim followed from its TOML to its verdict.
//!
//! # 1. The claim
//!
//! A claim is a `[[claim]]` table of a catalogue file (the format is in
//! `identities/README.md`).  This one says that `(a + b)² = a² + 2ab + b²` for `a, b` in
//! `[-2, 2]`, and asks for an exact check as well:
//!
//! ```
//! const TOML: &str = r#"
//! [[claim]]
//! id = "square"
//! location = "Tutorial"
//! printed = '(a+b)^2 = a^2 + 2ab + b^2'
//! environment = "Section 2"
//! role = "statement"
//! kind = "identity"
//! expect = "proved"
//! vars = [["a", "uniform(-2, 2)"], ["b", "uniform(-2, 2)"]]
//! lhs = "(a + b)^2"
//! rhs = "a^2 + 2*a*b + b^2"
//! exact = true
//! "#;
//! # let _ = TOML;
//! ```
//!
//! # 2. Loading
//!
//! [`load_sources`](super::catalogue::load_sources) (or
//! [`load_dir`](super::catalogue::load_dir) for a directory) reads the TOML into raw
//! structs, applies the [defaults](super::catalogue::defaults::DEFAULTS), parses every
//! expression into a syntax tree ([`super::ast::Expr`]) that remembers where it was
//! written, and checks every name: `rhs = "a^2 + 2*a*c"` would fail here, with the file,
//! line and column of `c`.  The functions available are the built-ins
//! ([`super::builtins::Builtin`]) and those of the [`Registry`](super::registry::Registry)
//! passed in; the command-line tool passes the Euler-top model's
//! ([`crate::bindings::euler_top::registry`]).
//!
//! ```
//! # const TOML: &str = "[[claim]]\nid = \"square\"\nlocation = \"Tutorial\"\nprinted = 'p'\nenvironment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\nexpect = \"proved\"\nvars = [[\"a\", \"uniform(-2, 2)\"], [\"b\", \"uniform(-2, 2)\"]]\nlhs = \"(a + b)^2\"\nrhs = \"a^2 + 2*a*b + b^2\"\nexact = true\n";
//! use eulertop::claims::catalogue::{load_sources, Body};
//! use eulertop::claims::kind::Kind;
//! use eulertop::claims::registry::Registry;
//!
//! let cat = load_sources(&[("t.toml".into(), TOML.into())], Registry::new()).unwrap();
//! let claim = &cat.claims[0];
//! assert_eq!(claim.kind, Kind::Identity);
//! assert_eq!(claim.samples, 8); // the default
//! let Body::Identity { lhs, .. } = &claim.body else { unreachable!() };
//! assert_eq!(lhs.text, "(a + b)^2");
//!
//! let bad = TOML.replace("2*a*b", "2*a*c");
//! let e = load_sources(&[("t.toml".into(), bad)], Registry::new()).unwrap_err();
//! assert!(e.to_string().contains(": unknown variable 'c'"));
//! assert_eq!((e.line, e.col), (11, 18)); // the `c` in `rhs = "a^2 + 2*a*c"`
//! ```
//!
//! # 3. Sampling
//!
//! A [`Sampler`](super::sampler::Sampler) draws the claim's variables in f64 from a
//! ChaCha20 stream seeded by the claim's id and seed; each purpose has its own
//! [`Stream`](super::sampler::Stream).  The values are dyadic rationals, used exactly at
//! every precision.
//!
//! ```
//! # const TOML: &str = "[[claim]]\nid = \"square\"\nlocation = \"Tutorial\"\nprinted = 'p'\nenvironment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\nexpect = \"proved\"\nvars = [[\"a\", \"uniform(-2, 2)\"], [\"b\", \"uniform(-2, 2)\"]]\nlhs = \"(a + b)^2\"\nrhs = \"a^2 + 2*a*b + b^2\"\nexact = true\n";
//! # use eulertop::claims::catalogue::load_sources;
//! # use eulertop::claims::registry::Registry;
//! # let cat = load_sources(&[("t.toml".into(), TOML.into())], Registry::new()).unwrap();
//! use eulertop::claims::sampler::{Sampler, Stream};
//! let mut sampler = Sampler::new(&cat, &cat.claims[0], Stream::Samples).unwrap();
//! let point = sampler.draw().unwrap();
//! assert_eq!(point.vars[0].0, "a");
//! let a = point.vars[0].1.as_real().unwrap();
//! assert!((-2.0..=2.0).contains(&a));
//! ```
//!
//! # 4. Evaluating
//!
//! An [`Evaluator`](super::eval::Evaluator) computes an expression in one number system,
//! the *backend*: `f64`, MPFR at any precision, dual numbers (derivatives) or exact
//! rationals.  The verdict engine evaluates both sides at every rung of the precision
//! ladder (53 bits = f64, then MPFR) and forms the scaled residual
//! |lhs − rhs| / max(|lhs|, |rhs|, size of the inputs), kept as log2.
//!
//! ```
//! use eulertop::claims::eval::Evaluator;
//! use eulertop::claims::parser::parse_expr;
//! use eulertop::claims::registry::Registry;
//! use eulertop::claims::value::Value;
//!
//! let reg = Registry::new();
//! let e = parse_expr("(a + b)^2 - (a^2 + 2*a*b + b^2)").unwrap();
//! // at 256 bits the difference is 0 or a few units of 2^-256
//! let mut ev = Evaluator::new(&reg, rug::Float::new(256));
//! ev.bind("a", Value::Real(rug::Float::with_val(256, 0.3)));
//! ev.bind("b", Value::Real(rug::Float::with_val(256, -1.7)));
//! assert!(ev.eval(&e).unwrap().log2_magnitude() < -240.0);
//! // over the rationals it is exactly zero
//! let q = |x: f64| Value::Real(eulertop::numbers::Rational::from_float(x).unwrap());
//! let mut ex = Evaluator::new(&reg, eulertop::numbers::Rational::from_integer(0.into()));
//! ex.bind("a", q(0.3));
//! ex.bind("b", q(-1.7));
//! assert_eq!(ex.eval(&e).unwrap().magnitude(), 0.0);
//! ```
//!
//! # 5. The verdict
//!
//! [`run_claim`](super::verdict::run_claim) runs the claim's kind (here
//! [`identity`](super::verdict::identity), then [`exact`](super::verdict::exact)).  The
//! [ladder rule](super::verdict::ladder) gives `holds`: with g = max over rungs of
//! (p + log2 r_p), the bits lost to conditioning, g stays within the claim's bound.  The
//! exact evaluation finds lhs − rhs = 0 at rational points, which with a Schwartz–Zippel
//! bound turns `holds` into `proved`.  A false claim is `refuted` with a counterexample.
//!
//! ```
//! # const TOML: &str = "[[claim]]\nid = \"square\"\nlocation = \"Tutorial\"\nprinted = 'p'\nenvironment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\nexpect = \"proved\"\nvars = [[\"a\", \"uniform(-2, 2)\"], [\"b\", \"uniform(-2, 2)\"]]\nlhs = \"(a + b)^2\"\nrhs = \"a^2 + 2*a*b + b^2\"\nexact = true\n";
//! # use eulertop::claims::catalogue::load_sources;
//! # use eulertop::claims::registry::Registry;
//! use eulertop::claims::verdict::{run_claim, Options, Verdict};
//! let opts = Options { bits: vec![53, 128, 256], exact: true };
//! let cat = load_sources(&[("t.toml".into(), TOML.into())], Registry::new()).unwrap();
//! let r = run_claim(&cat, &cat.claims[0], &opts);
//! assert_eq!(r.verdict, Verdict::Proved);
//! assert!(r.as_expected && r.loss_bits.unwrap() < 8.0);
//! let exact = r.exact.unwrap();
//! assert_eq!((exact.points, exact.all_zero), (4, true));
//!
//! // drop the factor 2: refuted, with the sample that shows it
//! let wrong = TOML.replace("2*a*b", "a*b").replace("proved", "refuted");
//! let cat = load_sources(&[("t.toml".into(), wrong)], Registry::new()).unwrap();
//! let r = run_claim(&cat, &cat.claims[0], &opts);
//! assert_eq!(r.verdict, Verdict::Refuted);
//! let c = r.counterexample.unwrap();
//! assert_eq!(c.point[0].name, "a");
//! ```
//!
//! The [`ClaimResult`](super::verdict::ClaimResult) carries everything the report writer
//! shows: the LaTeX of what was evaluated, the residual per rung, g, the samples that
//! could not be evaluated, the counterexample and the exact evidence.
