#!/usr/bin/env python3
"""Rechecks eulertop's algebraic certificates with SymPy, independently of FLINT.

Usage: scripts/recheck-certificates.py [--catalogue DIR | --unbound] [--jobs N] PATH...
       scripts/recheck-certificates.py [--catalogue DIR | --unbound] --self-test CERT
(PATHs: files, or directories of *.cert / *.txt; DIR defaults to identities)

Bound to the claim (package certcheck): the `source` lines carry the claim's fields, its
domain, its stated hypotheses and the definitions its formulas call, verbatim; they must
be what the catalogue holds (the first difference is the reason).  The formulas are then
evaluated here, by this checker's own parser of the expression language, from the
certificate's symbols: each `claim` line's sides must be the claim's lhs and rhs (or
d(expr, wrt) and 0) component by component.  Where the evaluator does not reach
(implicit maps, complex values, a comparison whose sign the certificate does not prove)
the claim is bound by its text only; the summary line counts both.  `premise` lines are
the theorem's premises (printed under the certificate's line): a branch or sign premise must be a
hypothesis the claim states, with the catalogue's statement; every `assume` line of the
derivation needs a premise; a lemma premise needs the lemma's certificate in the same
run.  `claims N` states the number of claim lines.  With --unbound, the derivation alone
is rechecked (for hand-written tests of the derivation rules).

A certificate (written by the algebra layer, src/algebra/certificate.rs) declares the
symbols, the root relations r**2 = a, the elliptic base arguments and the derivation DAG.
A root with radicand 1 is a sign symbol: arithmetic modulo r**2 - 1 is arithmetic for
r = 1 and r = -1 at once, so a claim checked modulo it holds for both signs.
This script:
  * checks every base (c**2 = 1 - s**2, d**2 = 1 - k**2 s**2) and the quarter-period
    data (kp**2 = 1 - k**2 and the half-period values of DLMF 22.5.1 squared);
  * recomputes every node from its arguments with its own rational-function arithmetic
    modulo the relations, and compares with the stated normal form where one is given
    (a `dot + tA tB - tC tD ...` node is a sum of products, formed at once);
  * square roots: the stated root squared equals the radicand, and its branch has
    evidence: a proved `sign tN > 0` line, a nonnegative constant, a sign proved here from
    the parametrization, or c*r for a root symbol r whose branch is otherwise free (no
    posroot, no sign symbol; the same r never needed with both signs; c free of r, a
    constant or of a sign proved here), or c*r with c > 0 and r a posroot;
  * a sign decided by a hypothesis the claim states (`sign tN > 0 [square (A)/(B)]
    hypothesis hypothesis.NAME factor (F)/(G)`): the value (or A/B, whose square it is)
    is the hypothesis' value a - b, read from the catalogue's `when = "a > b"` and
    evaluated here in the claim's scope, times F/G, whose sign is proved here; the
    hypothesis must be the catalogue's table, stated by the claim and a premise, and the
    sign it gives the one stated (module certcheck.hypothesis); its condition and the
    paper's words are printed with the premise; with `hypothesis part:K`, the value is
    the condition of the K-th `part` line (this part of the domain) times F/G;
  * a sign symbol (a root of radicand 1) with a definition `signsym S = sign (X)/(Y)`,
    x = X/Y a constant multiple c v of an indeterminate v: S v has the sign of c, and a
    sign test of b S with v dividing b takes the sign of c times that of b/v (a symbol
    defined twice, or also named a posroot, is rejected);
  * facts of the Jacobi functions: `fact Fi dn base B value (D)` (D the d of base B) or
    `fact Fi dn tN` (a dn node, no iK' shift): the argument must be real by
    construction (equivalents replaced) and the modulus real with 0 < k**2 < 1 proved
    here, so the value is positive (DLMF 22.2.4, 22.4.1); `sign tN > 0 fact Fi factor
    (F)/(G)` then needs tN = fact * F/G with F/G of the stated sign, proved here;
  * `sign value (N)/(D) > 0`: the sign of a value written out (one the derivation made
    only for a decision), proved here like any other sign line;
  * `sign tN > 0 parts` (or `sign value (N)/(D) > 0 parts`): a sign of a value in a square
    root decided from the signs of its parts: for a numerator or denominator
    p = a + b*r in a posroot r whose radicand has a sign so decided, the sign of b where
    a = 0, of a and b where they agree, else of a times that of a**2 - b**2 * radicand;
    each part's sign proved by the parametrization, by a sign line checked before, by a
    sign symbol's definition, by the condition of this part of the domain (a `part`
    line: the part is the condition times a rational number or a factor of proved
    sign), or by its own parts in turn.  A comparison of the claim's formulas is
    decided the same way;
  * `dominance (Q) > 0 constant C factor (G) ^ k ...`: the sign of q = a**2 - b**2 * rad
    for p = a + b*r (r a posroot, rad its radicand) where only one of a, b has a proved
    sign (the side that wins, rule 2b of src/algebra/decide.rs): Q = C * prod G**k
    exactly, each G (G**2 for an even k) of a sign proved here, their product the stated
    sign; a sign test of p then takes the sign of a where q > 0 (|a| > |b r|), of b
    where q < 0 (|b r| > |a|), that side's sign proved in turn;
  * a proof by parts: the `part` lines of its certificates must cover the domain, as
    the leaves of a tree of splits (each split value with a part for each sign);
  * sn, cn, dn: recomputed from the base symbols with the addition theorems
    (DLMF 22.8.1-3), the quarter-period shifts (DLMF 22.4.3) and the half-period values,
    and the argument is checked to be the stated combination of the bases;
  * the inverse of sn, cn, dn (the phase of the elliptic coordinates) is an opaque symbol
    whose `equiv` line gives its derived sn, cn, dn values and an argument as a combination
    of the bases: sn, cn, dn of that argument are recomputed and must equal the values, so
    the symbol equals the argument modulo 4K, and it is replaced by it inside sn, cn, dn
    (period 4K) before an argument is compared with its combination;
  * an `inverse` line gives an opaque symbol v the values s, c, d of its sn, cn, dn at
    modulus k (s^2 + c^2 = 1 and d^2 + k^2 s^2 = 1 are checked) and, where k varies, the
    symbol Z = E(am v, k) - k'^2 v; its derivative must satisfy c d v' + (dsn/dk) k' = s';
  * derivatives: recomputed by the chain rule from the `dvar` table, whose entries are
    checked (roots: 2 r r' = a'; sn: s' = c d u' (+ the modulus terms); indeterminates;
    a `param`, a parameter of the proof's chart such as a phase step, moves with the
    claim's variables as the chart says: its stated derivative in x is taken as stated
    and, once the certificate is read, every `coord NAME = tN` line (a claim's variable
    the chart replaces, with its value in the chart's parameters) must have the
    derivative 1 in x when NAME is x and 0 otherwise, computed with the stated
    derivatives: the parameter moves exactly so that the claim's other variables stay
    fixed (implicit differentiation of the chart); without a coord line a derivative of
    a `param` is rejected);
  * a proof by parts of the domain writes one certificate per part, each from its own
    `# eulertop certificate` header; each part is rechecked with its own symbols, as the
    same name may stand for another root in another part;
  * a lemma's stated value (a proved step value) enters as the derivation of its value;
    the certificate names the lemma in an assumption line, and the lemma has its own
    certificate;
  * signs proved on the domain: `param t positive|nonzero` and `image x = (N)/(D)` give
    each indeterminate as a rational function of parameters t > 0 (or t != 0), and
    `posroot r` names a root taken as the positive square root of its radicand, which
    must itself be proved positive; `sign tN > 0` is checked by substituting the images
    into the numerator and the denominator of tN (p(x) * prod d_i**deg_i expanded term by
    term, roots as further positive parameters): every coefficient must have the stated
    sign, and a parameter t != 0 may occur to even powers only.  The parametrization
    must be the catalogue's (certcheck.domain rebuilds it from the definitions of the
    sampled variables: a set that contains the domain).  Where it proves no sign, the
    `alt param` / `alt image` lines (the box of the domain's intervals, also rebuilt
    from the catalogue) are tried.  sn of a base whose argument is real by construction
    (indeterminates, opaque symbols declared `real`, roots of radicands proved positive,
    ...) at a real modulus proved in 0 < k**2 < 1 enters through its square, as the
    parameter sn**2 = u/(1 + u), u > 0 (DLMF 22.2.4, 22.4.1), where it occurs to even
    powers only;
  * `call NAME = ln (X)` / `call NAME = am (U) (K)`: an opaque symbol for that call; the
    claim's ln and am evaluate to it, and its `dvar` lines must be X'/X, and dn(U, K) U'
    for K independent of the variable (DLMF 22.16.3); am(u, 0) = u (DLMF 22.16.4);
  * a proof by the uniqueness of the solution of an ODE (`jet` and `ode` lines, module
    certcheck.ode): both sides evaluated from the claim's formulas, differentiated here,
    solve the stated polynomial ODE, agree at the initial point with their derivatives,
    and dP/dy^(n) is not 0 there;
  * finally every claim lhs = rhs.
The arithmetic is SymPy's sparse polynomial arithmetic (sympy.polys.rings over ZZ, on
SymPy's own integers or gmpy2, never python-flint): a value is a quotient of two
polynomials in one ring holding every symbol of the certificate, built once after a scan
of the declarations; expressions are read by a small parser (sums of products of
integers, symbols, integer powers and parenthesised sub-expressions).  A polynomial is
reduced modulo r**2 = a by replacing r**k with a**(k//2) r**(k%2), the innermost (last
declared) root first; two values are equal when the reduced cross product vanishes.
Quotients are kept in lowest terms (sums by Henrici's method, products by cross
cancellation).  A gcd removes monomial and integer content, tries exact division,
then takes images modulo a prime (sympy.polys.galoistools) that show in which variables a
common factor can have positive degree (usually none: the operands are coprime) and
takes the gcd of the coefficients with respect to the other variables; only what
remains goes to SymPy's heuristic gcd.  The gcds only keep the quotients small: every
verdict rests on exact divisions and on the vanishing of reduced cross products.
Exit status 0 when every certificate checks, 1 otherwise, 2 for bad usage; with
--self-test, 0 when the certificate checks and each corrupted copy (a coefficient of a
stated normal form, a radicand, a claim's right-hand side) fails.  CI runs it on every
proved claim (scripts/recheck-all-certificates.sh); its own tests are
scripts/test-recheck-certificates.py.
"""

import heapq
import json
import multiprocessing
import os
import random
import re
import sys
import time
from fractions import Fraction

# SymPy picks python-flint's integers when they are installed ("auto"); that would put
# FLINT back under the arithmetic, so the ground types are chosen here: gmpy2 or Python.
try:
    import gmpy2  # noqa: F401
    os.environ["SYMPY_GROUND_TYPES"] = "gmpy"
except ImportError:
    os.environ["SYMPY_GROUND_TYPES"] = "python"

from sympy.external.gmpy import GROUND_TYPES  # noqa: E402
from sympy.polys.domains import ZZ  # noqa: E402
from sympy.polys.galoistools import gf_gcd, gf_strip  # noqa: E402
from sympy.polys.polyerrors import HeuristicGCDFailed  # noqa: E402
from sympy.polys.rings import ring  # noqa: E402

assert GROUND_TYPES != "flint", "the recheck must not run on FLINT"

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from certcheck import binding, domain, formula, hypothesis, ode, series, witness  # noqa: E402


class CheckError(Exception):
    pass


class Frac:
    """num/den, both polynomials of the certificate's ring."""

    __slots__ = ("num", "den")

    def __init__(self, num, den):
        self.num, self.den = num, den


TOKEN = re.compile(r"\s*(?:(\d+)|([A-Za-z_][A-Za-z0-9_]*)|(\*\*|[-+*/()]))")


class Parser:
    """Reads an expression into a Frac: integers, declared symbols, + - * / ** and ()."""

    def __init__(self, cert, text):
        self.cert, self.ring = cert, cert.ring
        toks, pos, text = [], 0, text.strip()
        while pos < len(text):
            m = TOKEN.match(text, pos)
            if m is None or m.end() == pos:
                raise CheckError(f"cannot parse '{text[:80]}': unexpected '{text[pos:pos + 10]}'")
            pos = m.end()
            if m.group(1) is not None:
                toks.append(("n", int(m.group(1))))
            elif m.group(2) is not None:
                toks.append(("s", m.group(2)))
            else:
                toks.append(("o", m.group(3)))
        self.toks, self.i, self.text = toks, 0, text

    def fail(self, what):
        raise CheckError(f"cannot parse '{self.text[:80]}': {what}")

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else ("e", None)

    def take(self, op):
        if self.peek() == ("o", op):
            self.i += 1
            return True
        return False

    def whole(self):
        if not self.toks:
            self.fail("empty expression")
        v = self.expr()
        if self.i != len(self.toks):
            self.fail(f"unexpected '{self.peek()[1]}'")
        return v

    def expr(self):
        """Sum of terms; terms that are monomials with integer coefficients go straight
        into one coefficient dictionary."""
        c = self.cert
        poly, rest = {}, []
        sign = 1
        if self.take("-"):
            sign = -1
        else:
            self.take("+")
        while True:
            t = self.term()
            if isinstance(t, tuple):
                mono, num, den = t
                if den == 1:
                    poly[mono] = poly.get(mono, 0) + sign * num
                else:
                    rest.append(Frac(self.ring({mono: sign * num}), self.ring(den)))
            else:
                rest.append(c.neg(t) if sign < 0 else t)
            if self.take("+"):
                sign = 1
            elif self.take("-"):
                sign = -1
            else:
                break
        out = Frac(self.ring.from_dict({m: k for m, k in poly.items() if k}), self.ring.one)
        for t in rest:
            out = c.raw_add(out, t)
        return out

    def exponent(self):
        neg = self.take("-")
        kind, e = self.peek()
        if kind != "n":
            self.fail("exponent is not an integer")
        self.i += 1
        return -e if neg else e

    def term(self):
        """A product; returns (monomial, num, den) while it stays a monomial, else a Frac."""
        c = self.cert
        exps = [0] * self.ring.ngens
        num, den, general = 1, 1, None
        divide = False
        while True:
            kind, t = self.peek()
            f = None
            if kind == "n":
                self.i += 1
                e = self.exponent() if self.take("**") else 1
                if t == 0 and (divide or e < 0):
                    raise CheckError("division by zero")
                q = Fraction(t) ** e
                num, den = (num * q.denominator, den * q.numerator) if divide else (num * q.numerator, den * q.denominator)
            elif kind == "s":
                self.i += 1
                idx = c.index(t)
                e = self.exponent() if self.take("**") else 1
                e = -e if divide else e
                if e >= 0:
                    exps[idx] += e
                else:
                    f = Frac(self.ring.one, self.ring.gens[idx] ** -e)
            elif self.take("("):
                f = self.expr()
                if not self.take(")"):
                    self.fail("missing ')'")
                if self.take("**"):
                    f = c.raw_pow(f, self.exponent())
                if divide:
                    f = c.raw_inv(f)
            elif kind == "o" and t == "-" and not divide:
                self.i += 1
                num = -num
                continue
            else:
                self.fail(f"unexpected '{t}'")
            if f is not None:
                general = f if general is None else c.raw_mul(general, f)
            if self.take("*"):
                divide = False
            elif self.take("/"):
                divide = True
            else:
                break
        if den < 0:
            num, den = -num, -den
        if general is None:
            return tuple(exps), num, den
        mono = Frac(self.ring({tuple(exps): num}), self.ring(den))
        return c.raw_mul(general, mono)


class Cert:
    def __init__(self, name):
        self.name = name
        self.ring = None
        self.syms = {}  # name -> generator
        self.idx = {}  # name -> generator index
        self.kinds = {}
        self.roots = []  # (name, generator index, radicand), creation order
        self.named = {}
        self.bases = {}
        self.periods = {}
        self.dvar = {}
        self.equiv = {}  # symbol -> the argument with its sn, cn, dn (equal modulo 4K)
        self.inverse = {}  # symbol -> its prescribed k, s, c, d and Z symbol (or None)
        self.calls = {}  # opaque symbol -> (ln | am, its arguments): `call` lines
        self.vals = {}
        self.params = []  # (name, kind) of the domain's parametrization
        self.pring = None
        self.images = {}  # indeterminate -> (num, den) in the parameters
        self.image_texts = {}  # indeterminate -> its image as written
        self.posroots = {}  # root name -> None (declared), True/False (radicand checked)
        self.real_declared = set()  # opaque symbols declared real (`field x param real`)
        self.alt_lines = []  # the `alt param` / `alt image` lines: a second parametrization
        self.alt = None  # its state once built (see `swap_parametrization`)
        self.pnames = None
        self.realmemo = {}  # symbol -> None (being checked), True/False
        self.real_assumed = set()  # indeterminates whose being real a check has used
        self.checked = 0
        self.points = []
        self.sqrts = []  # (node id, radicand, stated value) of every square root
        self.proved_signs = []  # (value, +1 or -1) of every checked sign line
        self.sqrt_nodes = []  # (radicand, value): the evaluator's square roots
        self.claim_pairs = []  # (tA, tB) of every claim line, in order
        self.trace = None  # the power series of a proof by series (certcheck.series)
        self.expected_claims = None  # the `claims N` line
        self.assumes = []  # (kind, name, statement) of the `assume` lines
        self.conditions = []  # the `part` lines: the conditions of this part of the domain
        self.sign_lines = set()  # node ids with a proved sign > 0
        self.hyp_signs = []  # (node, hypothesis, value, factor, its sign, stated sign or None): by a hypothesis
        self.ops = {}  # node id -> its operation, as tokens
        self.elliptic_nodes = []  # (sn|cn|dn, argument, modulus, value): the evaluator's
        self.charts = {}  # implicit map -> [(arguments' components, value's components)]
        self.signsyms = {}  # sign symbol -> (index of the indeterminate x, sign c): sigma = sign(c x)
        self.facts = {}  # fact name -> a value proved positive (dn of a real argument)
        self.chart_counts = (0, 0)
        self.part_conditions = []  # (value, sign) of each `part` line: this part of the domain
        self.coords = {}  # claim variable -> its value in the chart's parameters (`coord`)
        self.param_dvars = []  # (x, param) of every stated derivative of a chart parameter
        self.sides = 0  # `side` lines: the components of a refutation
        self.witness = None  # the component a refutation shows nonzero (`witness` line)
        self.at = {"exact": {}, "approx": {}}  # the `at` lines: the witness point
        self.refuted = None  # what the witness certified
        self.dominance = []  # (q, sign) of every checked `dominance` line: q = a**2 - b**2 * rad

    # ---- the ring ----------------------------------------------------------------
    def declare(self, text):
        """Builds the ring of every symbol declared by a `field` or `root` line."""
        names = []
        for line in text.splitlines():
            word, _, rest = line.partition(" ")
            if word == "field":
                name = rest.split()[0] if rest.split() else ""
            elif word == "root":
                name = rest.split("=", 1)[0].strip()
            else:
                continue
            if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
                raise CheckError(f"bad symbol name '{name[:40]}'")
            if name not in self.idx:
                self.idx[name] = len(names)
                names.append(name)
        if names:
            self.ring, *gens = ring(",".join(names), ZZ)
        else:
            self.ring, gens = ring("_unused", ZZ)[0], []
        self.syms = dict(zip(names, gens))
        # fixed evaluation points for the coprimality test (deterministic runs)
        rng = random.Random(20240601)
        self.points = [[rng.randrange(2, PRIME - 1) for _ in range(self.ring.ngens)] for _ in range(3)]
        self.zero, self.one = Frac(self.ring.zero, self.ring.one), Frac(self.ring.one, self.ring.one)

    def index(self, name):
        if name not in self.idx:
            raise CheckError(f"undeclared symbol {name}")
        return self.idx[name]

    def symbol(self, name):
        self.index(name)
        return self.syms[name]

    # ---- parsing -----------------------------------------------------------------
    def frac(self, text):
        return self.norm(Parser(self, text).whole())

    def triple(self, text):
        inner = text.strip()
        if inner == "none":
            return None
        if not (inner.startswith("[") and inner.endswith("]")):
            raise CheckError(f"bad triple {text[:60]}")
        parts = split_top(inner[1:-1])
        return [self.frac(p) for p in parts]

    # ---- arithmetic without normalisation (the parser's) ------------------------
    def raw_add(self, a, b):
        if a.den == b.den:
            return Frac(a.num + b.num, a.den)
        return Frac(a.num * b.den + b.num * a.den, a.den * b.den)

    def raw_mul(self, a, b):
        return Frac(a.num * b.num, a.den * b.den)

    def raw_inv(self, a):
        if not a.num:
            raise CheckError("division by zero")
        return Frac(a.den, a.num)

    def raw_pow(self, a, e):
        num, den = (a.num, a.den) if e >= 0 else (a.den, a.num)
        if not num and e < 0:
            raise CheckError("division by zero")
        return Frac(num ** abs(e), den ** abs(e))

    # ---- arithmetic modulo the relations ----------------------------------------
    def reduce(self, p):
        """p with every root's exponent below 2 (r**k -> a**(k//2) r**(k%2))."""
        for _, i, a in reversed(self.roots):
            if all(m[i] < 2 for m in p.itermonoms()):
                continue
            parts = {}
            for m, c in p.iterterms():
                j, k = divmod(m[i], 2)
                mm = m[:i] + (k,) + m[i + 1:]
                part = parts.setdefault(j, {})
                part[mm] = c
            top = max(parts)
            out = self.ring.from_dict(parts[top])
            for j in range(top - 1, -1, -1):
                out = out * a
                if j in parts:
                    out = out + self.ring.from_dict(parts[j])
            p = out
        return p

    def gcd(self, n, d):
        """(g, n / g, d / g) for a common factor g of n and d that is their gcd up to an
        integer factor (`lowest` removes common integer content)."""
        one = self.ring.one
        if n.is_ground or d.is_ground:
            return one, n, d
        g = self.common(n, d)
        if g.is_ground:
            return one, n, d
        qn, qd = exact_quotient(n, g), exact_quotient(d, g)
        if qn is None or qd is None:
            raise CheckError("internal error: a gcd does not divide its operands")
        return g, qn, qd

    def common(self, a, b):
        """The gcd of two non-zero polynomials, primitive, up to its sign.

        Monomial factors come out first.  Modular images (`support`) show in which
        variables the gcd can have positive degree; it divides every coefficient of a
        and b with respect to the other variables, so the gcd of those (smaller)
        coefficients is taken instead.  Only what remains goes to SymPy's heuristic gcd."""
        one = self.ring.one
        if a.is_ground or b.is_ground:
            return one
        (ma, a), (mb, b) = monomial_part(a), monomial_part(b)
        mono = self.ring({tuple(map(min, ma, mb)): 1})
        if a.is_ground or b.is_ground:
            return mono
        a, b = a.primitive()[1], b.primitive()[1]
        if a == b or a == -b:
            return mono * a
        da, db = a.degrees(), b.degrees()
        for x, y, dx, dy in ((a, b, da, db), (b, a, db, da)):
            if len(y) <= len(x) and all(p >= q for p, q in zip(dx, dy)) and exact_quotient(x, y) is not None:
                return mono * y
        support = self.support(a, b, da, db)
        if support is not None and not support:
            return mono
        if support is not None:
            pieces = coefficients(a, support, da) + coefficients(b, support, db)
            if len(pieces) > 2:
                return mono * self.common_list(pieces)
        try:
            g = a.cofactors(b)[0]
        except HeuristicGCDFailed:
            g = self.ring.dmp_inner_gcd(a, b)[0]
        return mono * g.primitive()[1]

    def common_list(self, polys):
        """The gcd of several non-zero polynomials (smallest first)."""
        polys = sorted(polys, key=len)
        g = polys[0].primitive()[1]
        for p in polys[1:]:
            if g.is_ground:
                break
            if exact_quotient(p, g) is None:
                g = self.common(g, p)
        return g

    def support(self, f, g, df, dg):
        """The variables in which a common factor of f and g can have positive degree,
        from images modulo a prime: a common factor h of degree e in x keeps degree e in
        the image in x (the other variables at fixed values) when the leading
        coefficient of f or g in x does not vanish there, and then divides both images;
        so an image gcd of degree 0 shows that h is free of x.  None when the fixed
        points all make some leading coefficient vanish."""
        both = [i for i in range(self.ring.ngens) if df[i] and dg[i]]
        if not both:
            return []
        for pt in self.points:
            fi, gi = images(f, both, pt, df), images(g, both, pt, dg)
            out = []
            for i in both:
                a, b = fi[i], gi[i]
                if not a[df[i]] and not b[dg[i]]:
                    out = None
                    break
                if len(gf_gcd(gf_strip(a[::-1]), gf_strip(b[::-1]), PRIME, ZZ)) > 1:
                    out.append(i)
            if out is not None:
                return out
        return None

    def lowest(self, n, d):
        """n/d without common integer content, with a positive leading denominator."""
        if not d:
            raise CheckError("division by zero")
        if not n:
            return self.zero
        g = ZZ.gcd(n.content(), d.content())
        if d.LC < 0:
            g = -g
        if g != 1:
            n, d = n.quo_ground(g), d.quo_ground(g)
        return Frac(n, d)

    def finish(self, n, d):
        """Reduces n/d modulo the relations; cancels the full gcd only when the reduction
        changed something (the callers have cancelled every other common factor)."""
        rn, rd = self.reduce(n), self.reduce(d)
        if (rn is not n or rd is not d) and rn and rd:
            _, rn, rd = self.gcd(rn, rd)
        return self.lowest(rn, rd)

    def norm(self, f):
        n, d = self.reduce(f.num), self.reduce(f.den)
        if n and d:
            _, n, d = self.gcd(n, d)
        return self.lowest(n, d)

    def add(self, a, b, sign=1):
        """Henrici's sum: only the gcd of the denominators and one gcd with it."""
        bn = b.num if sign > 0 else -b.num
        g, da, db = self.gcd(a.den, b.den)
        raw = a.num * db + bn * da
        n = self.reduce(raw)
        if not n:
            return self.zero
        if n is not raw:  # the relations may have made new common factors
            return self.norm(Frac(n, da * db * g))
        _, n, g = self.gcd(n, g)
        return self.finish(n, da * db * g)

    def mul(self, a, b):
        """The product with the cross gcds cancelled first."""
        if not a.num or not b.num:
            return self.zero
        _, n1, d2 = self.gcd(a.num, b.den)
        _, n2, d1 = self.gcd(b.num, a.den)
        return self.finish(n1 * n2, d1 * d2)

    def inv(self, a):
        n = self.reduce(a.num)
        if not n:
            raise CheckError("division by zero")
        return Frac(a.den, n)

    def div(self, a, b):
        return self.mul(a, self.inv(b))

    def power(self, a, e):
        base, e = (a if e >= 0 else self.inv(a)), abs(e)
        out = self.one
        while e:
            if e & 1:
                out = self.mul(out, base)
            e >>= 1
            if e:
                base = self.mul(base, base)
        return out

    def neg(self, a):
        return Frac(-a.num, a.den)

    def const(self, c):
        return Frac(self.ring(c), self.ring.one)

    def eq(self, a, b):
        self.checked += 1
        if a.den == b.den and not self.reduce(a.num - b.num):
            return True  # then the cross product below vanishes as well
        return not self.reduce(a.num * b.den - b.num * a.den)

    def need(self, ok, what):
        if not ok:
            raise CheckError(what)

    # ---- declarations -------------------------------------------------------------
    def field(self, rest):
        parts = rest.split()
        self.index(parts[0])
        self.kinds[parts[0]] = parts[1] if len(parts) > 1 else "indeterminate"
        if "real" in parts[2:]:
            self.real_declared.add(parts[0])

    def root(self, rest):
        name, rad = rest.split("=", 1)
        name = name.strip()
        a = Parser(self, rad).whole()
        self.need(a.den == self.ring.one, f"the radicand of {name} is not a polynomial with integer coefficients")
        self.roots.append((name, self.index(name), a.num))
        self.kinds[name] = "root"

    # ---- signs proved with a parametrization of the domain --------------------------
    def param_frac(self, text):
        """An image (N)/(D): polynomials over ZZ in the parameters (and, unused, the roots)."""
        import sympy
        if self.pring is None:
            names = [n for n, _ in self.params] + ["root__" + r for r, _, _ in self.roots]
            names += ["sq__" + n for n, k in self.kinds.items() if k == "sn"]
            self.pring, *_ = ring(",".join(names) or "_unused", ZZ)
            self.pnames = {str(g): g for g in self.pring.gens}
        parts = split_top(text.strip().replace(")/(", "),("))
        self.need(len(parts) == 2, f"bad image {text[:60]}")
        loc = {n: sympy.Symbol(n) for n in self.pnames}
        num, den = [self.pring.from_expr(sympy.sympify(p, locals=loc)) for p in parts]
        self.need(den != 0, "an image with denominator 0")
        return num, den

    def definite(self, p):
        """The sign of a polynomial in the parameters whose terms all have one sign."""
        if not p:
            return None
        nonzero = [i for i, (_, k) in enumerate(self.params) if k == "nonzero"]
        signs = set()
        for monom, c in p.terms():
            if any(monom[i] % 2 for i in nonzero):
                return None
            signs.add(c > 0)
        return (1 if True in signs else -1) if len(signs) == 1 else None

    def root_positive(self, name):
        if name not in self.posroots:
            return False
        if self.posroots[name] is None:
            self.posroots[name] = False  # no cycles
            rad = next(a for r, _, a in self.roots if r == name)
            self.posroots[name] = self.tower_sign(rad) == 1
        return self.posroots[name]

    def poly_sign(self, p):
        """The sign of p (a polynomial in the certificate's symbols) on the parametrized
        domain, or None: p * prod d_i**deg_i with x_i = n_i/d_i, term by term."""
        if not p or self.pring is None:
            return None
        rows, factor = [], 1
        for i, deg in enumerate(p.degrees()):
            if deg <= 0:
                continue
            name = str(self.ring.symbols[i])
            half = 1
            if name in self.images:
                n, d = self.images[name]
            elif self.kinds.get(name) == "root" and self.root_positive(name):
                n, d = self.pnames["root__" + name], self.pring.one
            elif self.sn_square(name) and all(m[i] % 2 == 0 for m in p.itermonoms()):
                # sn of a real argument at a real modulus 0 < k² < 1 enters through its
                # square: sn² = u/(1 + u), u > 0 (DLMF 22.2.4, 22.4.1: sn is real and
                # |sn| <= 1; the strict signs hold where 0 < sn² < 1)
                n = self.pnames["sq__" + name]
                d, half, deg = self.pring.one + n, 2, deg // 2
            else:
                return None
            sd = self.definite(d)
            if sd is None:
                return None
            factor *= sd ** (deg % 2)
            rows.append((i, [n**k for k in range(deg + 1)], [d**k for k in range(deg + 1)], deg, half))
        acc = self.pring.zero
        for monom, c in p.terms():
            t = self.pring(c)
            for i, npw, dpw, deg, half in rows:
                e = monom[i] // half
                t = t * npw[e] * dpw[deg - e]
            acc += t
        s = self.definite(acc)
        return None if s is None else s * factor

    # ---- the second parametrization (`alt` lines) --------------------------------------
    PARAM_STATE = ("params", "pring", "pnames", "images", "image_texts", "posroots", "realmemo")

    def swap_parametrization(self):
        """Exchanges the parametrization in use (with what its sign tests remember) and
        the second one, which is built from the `alt` lines on first use: both contain
        the domain, so a sign either proves holds on it."""
        if self.alt is None:
            first = {k: getattr(self, k) for k in self.PARAM_STATE}
            self.params, self.pring, self.pnames, self.images, self.image_texts = [], None, None, {}, {}
            self.posroots = {r: None for r in first["posroots"]}
            self.realmemo = {}
            for sub, more in self.alt_lines:
                self.statement(sub, more)
            self.alt = first
            return
        mine = {k: getattr(self, k) for k in self.PARAM_STATE}
        for k, v in self.alt.items():
            setattr(self, k, v)
        self.alt = mine

    def alt_sign(self, f):
        self.swap_parametrization()
        try:
            return self.frac_sign(f)
        finally:
            self.swap_parametrization()

    # ---- real values: sn² of a real argument as a parameter in (0, 1) -----------------
    def frac_sign(self, f):
        a, b = self.tower_sign(f.num), self.tower_sign(f.den)
        return None if a is None or b is None else a * b

    def frac_real(self, f):
        gens = [i for i, (a, b) in enumerate(zip(f.num.degrees(), f.den.degrees())) if a > 0 or b > 0]
        return all(self.sym_real(str(self.ring.symbols[i])) for i in gens)

    def sym_real(self, name):
        """Is the symbol real by construction: an indeterminate, an opaque symbol declared
        real, a named value whose definition is real, sn of a real base argument at a
        real modulus with 0 < k² < 1, or a square root of a real radicand proved
        positive?  Cycles count as not real."""
        if name in self.realmemo:
            return bool(self.realmemo[name])
        self.realmemo[name] = None
        kind = self.kinds.get(name)
        if kind == "indeterminate" or name in self.real_declared:
            ok = True
            self.real_assumed.add(name)
        elif name in self.named:
            ok = self.frac_real(self.named[name])
        elif kind == "sn":
            ok = self.sn_square(name)
        elif kind == "K":
            # K(k) is real for a real modulus with 0 < k**2 < 1 (DLMF 19.2.8)
            p = next((p for p in self.periods.values() if p["K"] is not None and p["K"].num == self.syms[name]), None)
            ok = p is not None and self.frac_real(p["k"])
            if ok:
                k2 = self.mul(p["k"], p["k"])
                ok = self.frac_sign(k2) == 1 and self.frac_sign(self.add(self.one, k2, -1)) == 1
        elif kind == "root":
            rad = next(a for r, _, a in self.roots if r == name)
            ok = self.frac_real(Frac(rad, self.ring.one)) and self.tower_sign(rad) == 1
        else:
            ok = False
        self.realmemo[name] = ok
        return ok

    def sn_square(self, name):
        """Is `name` the sn of a base whose argument is real and whose modulus is real
        with 0 < k² < 1 (so that sn² lies in [0, 1])?"""
        if self.kinds.get(name) != "sn":
            return False
        key = ("sn", name)
        if key in self.realmemo:
            return bool(self.realmemo[key])
        self.realmemo[key] = None
        b = next((b for b in self.bases.values() if b["s_name"] == name), None)
        ok = False
        if b is not None and b["z"] is None and self.frac_real(b["arg"]) and self.frac_real(b["k"]):
            k2 = self.mul(b["k"], b["k"])
            ok = self.frac_sign(k2) == 1 and self.frac_sign(self.add(self.one, k2, -1)) == 1
        self.realmemo[key] = ok
        return ok

    def tower_sign(self, p, depth=0):
        """poly_sign, and where it fails and p = a + b*r in its last declared positive root
        r (radicand proved positive): the signs of a and b, and where they differ the
        sign of a**2 - b**2 * radicand, which says which term wins."""
        s = self.poly_sign(p)
        if s is not None or not p or depth >= 8:
            return s
        s = self.sign_symbol_sign(p, depth)
        if s is not None:
            return s
        used = [k for k, deg in enumerate(p.degrees()) if deg > 0]
        cands = [(name, i, rad) for name, i, rad in self.roots if i in used and name not in self.signsyms]
        if not cands:
            return None
        name, i, rad = cands[-1]
        if not self.root_positive(name) or self.tower_sign(rad, depth + 1) != 1:
            return None
        a = self.ring.from_dict({m: c for m, c in p.iterterms() if m[i] == 0})
        b = self.ring.from_dict({m[:i] + (0,) + m[i + 1:]: c for m, c in p.iterterms() if m[i] == 1})
        if any(m[i] > 1 for m in p.itermonoms()):
            return None
        if not a:
            return self.tower_sign(b, depth + 1)
        sa, sb = self.tower_sign(a, depth + 1), self.tower_sign(b, depth + 1)
        if sa is None and sb is None:
            return None
        if sa is None or sb is None:
            # the side that wins: a `dominance` line checked before gives the sign of q
            w = self.dominance_sign(self.reduce(a * a - b * b * rad))
            return sa if w == 1 else sb if w == -1 else None
        if sa == sb:
            return sa
        sq = self.tower_sign(self.reduce(a * a - b * b * rad), depth + 1)
        return None if sq is None else sa * sq

    # ---- the side that wins (`dominance` lines) ---------------------------------------
    def dominance_line(self, rest):
        """`dominance (Q) > 0 constant C factor (G1) ^ k1 factor (G2) ^ k2 ...`: Q equals
        C * prod Gi**ki, each Gi of odd ki has a sign proved here (by the parametrization
        or the second one), Gi**2 > 0 is proved for even ki, and the signs multiply to
        the stated one.  tower_sign then decides p = a + b*r (r a posroot of positive
        radicand) where q = a**2 - b**2 * radicand is Q: (a + b r)(a - b r) = q, so q > 0
        gives |a| > |b r| and p the sign of a, q < 0 gives |b r| > |a| and p the sign of
        b (r > 0); that side's sign must be proved there, the other is not needed."""
        m = re.fullmatch(r"\((.+?)\) ([<>]) 0 constant (-?\d+)((?: factor \(.+?\) \^ \d+)+)", rest.strip())
        self.need(m is not None, f"bad dominance line {rest[:40]}")
        qtext, rel, c, ftext = m.groups()
        want = 1 if rel == ">" else -1
        q = self.frac(qtext)
        self.need(q.den == self.ring.one, f"dominance {qtext[:40]}: not a polynomial")
        prod, sign = self.const(int(c)), (int(c) > 0) - (int(c) < 0)
        for g, k in re.findall(r" factor \((.+?)\) \^ (\d+)", ftext):
            g, k = self.frac(g), int(k)
            self.need(k > 0, f"dominance {qtext[:40]}: a factor to the power 0")
            prod = self.mul(prod, self.power(g, k))
            sg = self.proved_sign(g) if k % 2 else self.proved_sign(self.mul(g, g))
            self.need(sg in (1, -1), f"dominance {qtext[:40]}: the sign of the factor {g.num.as_expr()} is not proved")
            sign *= sg ** k
        self.need(self.eq(q, prod), f"dominance {qtext[:40]}: Q is not the product of its factors")
        self.need(sign == want, f"dominance {qtext[:40]} {rel} 0: its factors' signs give the other sign")
        self.dominance.append((self.reduce(q.num), want))
        self.checked += 1

    def dominance_sign(self, q):
        """The sign of the polynomial q that a checked `dominance` line states, or None."""
        return next((s for p, s in self.dominance if p == q), None)

    def keyed(self, rest, keys):
        pat = r"\s(" + "|".join(keys) + r")="
        pieces = re.split(pat, " " + rest)
        head = pieces[0].strip()
        vals = {pieces[i]: pieces[i + 1].strip() for i in range(1, len(pieces) - 1, 2)}
        return head, vals

    def base(self, rest):
        head, v = self.keyed(rest, ["k", "s", "c", "d", "arg", "z"])
        # s is the base's own symbol, or the prescribed value (such as sn = x for F(asin x, k))
        named = re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", v["s"]) is not None
        b = {"k": self.frac(v["k"]), "s": self.frac(v["s"]), "c": self.frac(v["c"]),
             "s_name": v["s"] if named else None,
             "d": self.frac(v["d"]), "arg": self.frac(v["arg"]),
             "z": v["z"] if "z" in v else None}
        if b["z"] is not None:
            self.index(b["z"])
        one, s = self.one, b["s"]
        k2 = self.mul(b["k"], b["k"])
        self.need(self.eq(self.mul(b["c"], b["c"]), self.add(one, self.mul(s, s), -1)), f"{head}: c**2 != 1 - s**2")
        self.need(self.eq(self.mul(b["d"], b["d"]), self.add(one, self.mul(k2, self.mul(s, s)), -1)),
                  f"{head}: d**2 != 1 - k**2 s**2")
        self.bases[head] = b

    def period(self, rest):
        head, v = self.keyed(rest, ["k", "kp", "K", "Kp", "i", "halfK", "halfiKp"])
        table = head.split()[1]
        sym = lambda name: None if name == "none" else Frac(self.symbol(name), self.ring.one)  # noqa: E731
        p = {"k": self.frac(v["k"]), "kp": None if v["kp"] == "none" else self.frac(v["kp"]),
             "K": sym(v["K"]), "Kp": sym(v["Kp"]), "i": sym(v["i"]),
             "halfK": self.triple(v["halfK"]), "halfiKp": self.triple(v["halfiKp"])}
        one, k = self.one, p["k"]
        sq = lambda x: self.mul(x, x)  # noqa: E731
        if p["kp"] is not None:
            self.need(self.eq(sq(p["kp"]), self.add(one, sq(k), -1)), "kp**2 != 1 - k**2")
        if p["halfK"] is not None:
            s, c, d = p["halfK"]
            kp = p["kp"]
            self.need(kp is not None, "half K without kp")
            self.need(self.eq(self.mul(sq(s), self.add(one, kp)), one), "sn(K/2)**2 != 1/(1+k')")
            self.need(self.eq(self.mul(sq(c), self.add(one, kp)), kp), "cn(K/2)**2 != k'/(1+k')")
            self.need(self.eq(sq(d), kp), "dn(K/2)**2 != k'")
        if p["halfiKp"] is not None:
            s, c, d = p["halfiKp"]
            self.need(self.eq(self.mul(sq(s), k), self.const(-1)), "sn(iK'/2)**2 != -1/k")
            self.need(self.eq(self.mul(sq(c), k), self.add(one, k)), "cn(iK'/2)**2 != (1+k)/k")
            self.need(self.eq(sq(d), self.add(one, k)), "dn(iK'/2)**2 != 1+k")
        self.linked_periods(table, p)
        self.periods[table] = p

    def linked_periods(self, table, p):
        """A quarter-period symbol shared by two tables stands for one value: K(k) and
        K'(k) depend on k**2 only, and K'(k) = K(k') (DLMF 19.2.9, 22.2.2), so a symbol
        that is K (or K') of both tables needs equal k**2, and one that is K of one and
        K' of the other needs complementary moduli, k_a**2 + k_b**2 = 1."""
        sq = lambda x: self.mul(x, x)  # noqa: E731
        for other, q in self.periods.items():
            for mine, theirs in (("K", "K"), ("Kp", "Kp"), ("K", "Kp"), ("Kp", "K")):
                a, b = p[mine], q[theirs]
                if a is None or b is None or not self.eq(a, b):
                    continue
                ka, kb = sq(p["k"]), sq(q["k"])
                if mine == theirs:
                    self.need(self.eq(ka, kb), f"{mine} of tables {table} and {other}: the moduli differ")
                else:
                    self.need(self.eq(self.add(ka, kb), self.one),
                              f"{mine} of table {table} is {theirs} of table {other}: the moduli are not complementary")

    # ---- elliptic functions -------------------------------------------------------
    def tadd(self, a, b, k2):
        s1, c1, d1 = a
        s2, c2, d2 = b
        one = self.one
        s1s2 = self.mul(s1, s2)
        den = self.add(one, self.mul(k2, self.mul(s1s2, s1s2)), -1)
        sn = self.add(self.mul(s1, self.mul(c2, d2)), self.mul(s2, self.mul(c1, d1)))
        cn = self.add(self.mul(c1, c2), self.mul(s1s2, self.mul(d1, d2)), -1)
        dn = self.add(self.mul(d1, d2), self.mul(k2, self.mul(s1s2, self.mul(c1, c2))), -1)
        return [self.div(sn, den), self.div(cn, den), self.div(dn, den)]

    def elliptic(self, f, argv, table, combo, hk, hkp):
        one, zero = self.one, self.zero
        trip = [zero, one, one]
        arg = zero
        k = None
        for item in combo:
            bname, n = item.rsplit(":", 1)
            n = int(n)
            b = self.bases[bname]
            k = b["k"]
            k2 = self.mul(k, k)
            unit = [b["s"], b["c"], b["d"]]
            if n < 0:
                unit = [self.neg(unit[0]), unit[1], unit[2]]
            for _ in range(abs(n)):
                trip = self.tadd(trip, unit, k2)
            arg = self.add(arg, self.mul(self.const(n), b["arg"]))
        p = self.periods.get(table)
        if hk or hkp:
            self.need(p is not None, "period shift without period data")
            k = p["k"]
        if hk or hkp:
            k2 = self.mul(k, k)
            if hk % 2:
                trip = self.tadd(trip, p["halfK"], k2)
            quarters = (hk // 2) % 4
            if quarters >= 2:
                # sn(u + 2K) = -sn u, cn(u + 2K) = -cn u, dn(u + 2K) = dn u (DLMF 22.4.3): no k'
                s, c, d = trip
                trip = [self.neg(s), self.neg(c), d]
                quarters -= 2
            for _ in range(quarters):
                s, c, d = trip
                trip = [self.div(c, d), self.neg(self.div(self.mul(p["kp"], s), d)), self.div(p["kp"], d)]
            if hkp % 2:
                trip = self.tadd(trip, p["halfiKp"], k2)
            for _ in range((hkp // 2) % 4):
                s, c, d = trip
                i = p["i"]
                ks = self.mul(k, s)
                trip = [self.div(one, ks), self.neg(self.div(self.mul(i, d), ks)), self.neg(self.div(self.mul(i, c), s))]
            half = Frac(self.ring.one, self.ring(2))
            if hk:
                arg = self.add(arg, self.mul(half, self.mul(self.const(hk), p["K"])))
            if hkp:
                arg = self.add(arg, self.mul(half, self.mul(self.const(hkp), self.mul(p["i"], p["Kp"]))))
        argv, factor = self.substitute_equivalents(argv)
        self.need(self.eq(arg, argv), "argument is not the stated combination of the bases")
        if factor is not None:
            trip = [self.mul(factor, trip[0]), self.mul(factor, trip[1]), trip[2]]
        return trip[["sn", "cn", "dn"].index(f)]

    def substitute_equivalents(self, v):
        """v with every symbol of an `equiv` line replaced by its argument (inside sn, cn,
        dn only: they have the period 4K, and the symbol equals the argument modulo 4K),
        and the factor (or None) that sn and cn take on: a symbol equal to its argument
        plus (1 - sigma)K for a sign sigma (sigma**2 = 1) enters with an integer
        coefficient q only, and contributes sigma**q (sn, cn change sign under 2K)."""
        factor = None
        for name, (u, sign) in self.equiv.items():
            g = self.syms[name]
            if v.num.degree(g) <= 0 and v.den.degree(g) <= 0:
                continue
            self.need(v.den.degree(g) <= 0 and v.num.degree(g) == 1, f"{name} enters an argument non-linearly")
            coeff = Frac(v.num.coeff_wrt(g, 1), v.den)
            rest = Frac(v.num.coeff_wrt(g, 0), v.den)
            v = self.add(rest, self.mul(coeff, u))
            if sign is not None:
                q = self.integer_of(coeff)
                self.need(q is not None, f"{name} (equal to its argument up to a sign) enters with a coefficient that is not an integer")
                if q % 2:
                    factor = sign if factor is None else self.mul(factor, sign)
        return v, factor

    def integer_of(self, x):
        """The integer that the value x is, or None."""
        if not (x.num.is_ground and x.den.is_ground):
            return None
        n, d = int(x.num.LC if x.num else 0), int(x.den.LC)
        return n // d if d != 0 and n % d == 0 else None

    def equivalence(self, rest):
        """equiv NAME s=tA c=tB d=tC table T combo C halfK h halfiKp q arg=NF: sn, cn, dn of
        the argument, recomputed from the bases, are the derived values s, c, d, which the
        prover prescribed for the symbol NAME (the inverse of sn, cn, dn): so NAME equals the
        argument modulo 4K."""
        head, argtext = rest.split(" arg=", 1)
        sign = None
        if " sign=" in head:
            head, signtext = head.split(" sign=", 1)
            sign = self.frac(signtext)
        toks = head.split()
        name = toks[0]
        if sign is not None:
            self.need(self.eq(self.mul(sign, sign), self.one), f"the sign of the equivalent of {name} is not a sign")
        kv = dict(t.split("=", 1) for t in toks[1:4])
        table, combo = toks[5], [c for c in toks[7].split(",") if c]
        hk, hkp = int(toks[9]), int(toks[11])
        self.need(self.kinds.get(name) == "opaque", f"equiv of {name}, which is not an opaque symbol")
        u = self.frac(argtext)
        for f, key in (("sn", "s"), ("cn", "c"), ("dn", "d")):
            got = self.elliptic(f, u, table, combo, hk, hkp)
            if sign is not None and f != "dn":
                got = self.mul(sign, got)
            self.need(self.eq(got, self.vals[kv[key]]), f"{f} of the argument of {name} is not its prescribed value")
        self.equiv[name] = (u, sign)

    def inverse_of_sn(self, rest):
        """inverse NAME k=NF s=NF c=NF d=NF z=Z|none: the symbol NAME stands for an argument
        with sn = s, cn = c, dn = d at modulus k (the prover's inverse of sn, cn, dn); the
        values must satisfy s^2 + c^2 = 1 and d^2 + k^2 s^2 = 1; Z names E(am NAME, k) - k'^2 NAME
        for the derivative in a varying modulus."""
        name, vals = self.keyed(rest, ["k", "s", "c", "d", "z"])
        self.need(self.kinds.get(name) == "opaque", f"inverse of {name}, which is not an opaque symbol")
        k, s, c, d = (self.frac(vals[key]) for key in ("k", "s", "c", "d"))
        one = self.one
        self.need(self.eq(self.add(self.mul(s, s), self.mul(c, c)), one), f"{name}: sn^2 + cn^2 != 1")
        self.need(self.eq(self.add(self.mul(d, d), self.mul(self.mul(k, k), self.mul(s, s))), one),
                  f"{name}: dn^2 + k^2 sn^2 != 1")
        z = vals.get("z", "none")
        if z != "none":
            self.need(self.kinds.get(z) == "opaque", f"{name}: Z symbol {z} is not declared")
        self.inverse[name] = (k, s, c, d, None if z == "none" else z)
        self.checked += 2

    # ---- derivatives --------------------------------------------------------------
    def dpoly(self, e, x):
        out = self.zero
        present = [i for i in range(self.ring.ngens) if e.degree(i) > 0]
        for i in sorted(present, key=lambda i: self.ring.symbols[i].name):
            dv = self.dsym(self.ring.symbols[i].name, x)
            if dv.num:
                out = self.add(out, self.mul(Frac(e.diff(self.ring.gens[i]), self.ring.one), dv))
        return out

    def dfrac(self, f, x):
        dn, dd = self.dpoly(f.num, x), self.dpoly(f.den, x)
        top = self.add(self.mul(dn, Frac(f.den, self.ring.one)), self.mul(Frac(f.num, self.ring.one), dd), -1)
        return self.div(top, Frac(f.den * f.den, self.ring.one))

    def dsym(self, v, x):
        if (x, v) in self.dvar:
            return self.dvar[(x, v)]
        kind = self.kinds.get(v)
        if kind == "indeterminate":
            return self.const(1 if v == x else 0)
        if kind == "param" and v != x:
            raise CheckError(f"the derivative of the chart parameter {v} with respect to {x} is what the chart "
                             "implies, and no `dvar` line states it (a param is not held fixed by fiat)")
        raise CheckError(f"no derivative of {v} with respect to {x}")

    def check_dvar(self, x, v, val):
        kind = self.kinds.get(v)
        one = self.one
        if kind == "indeterminate":
            self.need(self.eq(val, self.const(1 if v == x else 0)), f"d{v}/d{x}")
        elif kind == "constant":
            self.need(self.eq(val, self.const(0)), f"d{v}/d{x} of a constant")
        elif kind == "root":
            _, i, a = next(r for r in self.roots if r[0] == v)
            r = Frac(self.ring.gens[i], self.ring.one)
            self.need(self.eq(self.mul(self.const(2), self.mul(r, val)), self.dpoly(a, x)), f"2 {v} {v}' != a'")
        elif kind == "named":
            self.need(self.eq(val, self.dfrac(self.named[v], x)), f"d{v}/d{x} != derivative of its definition")
        elif kind in ("sn", "zeta"):
            b = next(b for b in self.bases.values() if (b["s_name"] == v if kind == "sn" else b["z"] == v))
            k, s, c, d, u = b["k"], b["s"], b["c"], b["d"], b["arg"]
            du, dk = self.dfrac(u, x), self.dfrac(k, x)
            cd = self.mul(c, d)
            k2 = self.mul(k, k)
            along = self.mul(cd, du) if kind == "sn" else self.mul(self.mul(k2, self.mul(c, c)), du)
            if dk.num:
                self.need(b["z"] is not None, f"{v}: modulus varies but no Z symbol")
                z, kp2 = Frac(self.symbol(b["z"]), self.ring.one), self.add(one, k2, -1)
                c2 = self.mul(c, c)
                if kind == "sn":
                    part = self.add(self.div(self.mul(self.mul(k, s), c2), kp2), self.div(self.mul(cd, z), self.mul(k, kp2)), -1)
                else:
                    t = self.add(self.mul(self.mul(k, s), cd), self.mul(self.mul(k, c2), z), -1)
                    part = self.add(self.div(t, kp2), self.mul(k, u))
                along = self.add(along, self.mul(part, dk))
            self.need(self.eq(val, along), f"d{v}/d{x} is not the derivative of sn/Z")
        elif kind == "opaque" and v in self.inverse:
            # sn(v, k) = s: c d v' + (dsn/dk)(v) k' = s', dsn/dk = k s c^2/k'^2 - c d Z/(k k'^2)
            k, s, c, d, z = self.inverse[v]
            cd, dk = self.mul(c, d), self.dfrac(k, x)
            rhs = self.dfrac(s, x)
            if dk.num:
                self.need(z is not None, f"{v}: modulus varies but no Z symbol")
                k2 = self.mul(k, k)
                kp2 = self.add(one, k2, -1)
                zf = Frac(self.symbol(z), self.ring.one)
                part = self.add(self.div(self.mul(self.mul(k, s), self.mul(c, c)), kp2),
                                self.div(self.mul(cd, zf), self.mul(k, kp2)), -1)
                rhs = self.add(rhs, self.mul(part, dk), -1)
            self.need(self.eq(self.mul(cd, val), rhs), f"d{v}/d{x} is not the derivative of the inverse of sn")
        elif kind == "opaque" and v in self.calls:
            self.check_call_dvar(x, v, val)
        elif kind in ("K", "Kp"):
            self.need(self.eq(val, self.const(0)), f"d{v}/d{x} must be 0")
        elif kind == "param" and v != x:
            # a parameter of the proof's chart (a phase step δ, with h a function of it)
            # moves with the claim's variables as the chart says: taken as stated, and
            # checked against the `coord` lines once they are read (check_coordinates)
            self.need(self.kinds.get(x) == "indeterminate", f"d{v}/d{x}: {x} is no indeterminate")
            self.param_dvars.append((x, v))
        else:
            raise CheckError(f"cannot check the derivative of {v} ({kind})")

    def call_line(self, rest):
        """`call NAME = ln (X)` or `call NAME = am (U) (K)`: an opaque symbol standing for
        that call (the evaluator's value of the claim's call; its derivative is checked)."""
        m = re.fullmatch(r"(\w+) = (ln|am)((?: \([^()]*\)/\([^()]*\))+)", rest.strip())
        self.need(m is not None, f"bad call line {rest[:60]}")
        name, fn = m.group(1), m.group(2)
        args = [self.frac(a) for a in re.findall(r"\([^()]*\)/\([^()]*\)", m.group(3))]
        self.need(self.kinds.get(name) == "opaque" and name not in self.calls and name not in self.inverse,
                  f"call {name}: not an opaque symbol of its own")
        self.need(len(args) == (1 if fn == "ln" else 2), f"call {name}: {fn} with {len(args)} argument(s)")
        self.calls[name] = (fn, args)

    def check_call_dvar(self, x, v, val):
        """d/dx of a call: ln X has X'/X; am(U, K) has dn(U, K) U' for K independent of x
        (DLMF 22.16.3), dn recomputed from the bases (the evaluator's rule)."""
        from certcheck.evaluate import Evaluator
        fn, args = self.calls[v]
        if fn == "ln":
            self.need(self.eq(self.mul(val, args[0]), self.dfrac(args[0], x)), f"d{v}/d{x} is not X'/X of ln X")
            return
        u, k = args
        self.need(not self.dfrac(k, x).num, f"d{v}/d{x}: the modulus of am depends on {x}")
        try:
            dn = Evaluator(self, []).elliptic("dn", u, k)
        except Exception as e:  # noqa: BLE001 - dn not recomputed here: the derivative is not checked
            raise CheckError(f"d{v}/d{x}: dn of am's argument is not recomputed here ({e})")
        self.need(self.eq(val, self.mul(dn, self.dfrac(u, x))), f"d{v}/d{x} is not dn(u, k) u' (DLMF 22.16.3)")

    # ---- nodes --------------------------------------------------------------------
    def node(self, rest):
        lhs, body = rest.split("=", 1)
        tid = lhs.strip()
        nf = None
        if "->" in body:
            body, nft = body.split("->", 1)
            nf = self.frac(nft)
        toks = body.split()
        val = self.evaluate(toks, nf)
        self.ops[tid] = toks
        if toks[0] in ("sn", "cn", "dn"):
            k = next((b["k"] for name, b in self.bases.items() if name.startswith(f"b_{toks[3]}_")), None)
            self.elliptic_nodes.append((toks[0], self.vals[toks[1]], k, val if nf is None else nf))
        if toks[0] == "sqrt":
            self.sqrts.append((tid, self.vals[toks[1]], nf))
            self.sqrt_nodes.append((self.vals[toks[1]], nf))
        if nf is not None:
            if toks[0] not in ("sqrt",):
                self.need(self.eq(val, nf), f"{tid}: the stated normal form differs from the recomputed value")
            val = nf
        self.vals[tid] = val

    def evaluate(self, toks, nf):
        v = self.vals
        if len(toks) == 1:
            t = toks[0]
            if t in self.syms:
                return Frac(self.syms[t], self.ring.one)
            try:
                q = Fraction(t)
            except (ValueError, ZeroDivisionError):
                raise CheckError(f"bad constant '{t[:40]}'")
            return Frac(self.ring(q.numerator), self.ring(q.denominator))
        if len(toks) == 3 and toks[1] in "+-*/^":
            a = v[toks[0]]
            if toks[1] == "^":
                return self.power(a, int(toks[2]))
            b = v[toks[2]]
            return {"+": lambda: self.add(a, b), "-": lambda: self.add(a, b, -1),
                    "*": lambda: self.mul(a, b), "/": lambda: self.div(a, b)}[toks[1]]()
        if toks[0] == "-" and len(toks) == 2:
            return self.neg(v[toks[1]])
        if toks[0] == "dot":
            # dot + tA tB - tC tD ...: a sum of products (signs before each product)
            rest = toks[1:]
            self.need(len(rest) % 3 == 0 and len(rest) > 0, "malformed dot step")
            acc = self.zero
            for i in range(0, len(rest), 3):
                sign, a, b = rest[i], v[rest[i + 1]], v[rest[i + 2]]
                self.need(sign in "+-", "malformed dot step")
                acc = self.add(acc, self.mul(a, b), -1 if sign == "-" else 1)
            return acc
        if toks[0] == "sqrt":
            self.need(nf is not None, "sqrt without a value")
            self.need(self.eq(self.mul(nf, nf), v[toks[1]]), "the square of a root is not its radicand")
            return nf
        if toks[0] in ("sn", "cn", "dn"):
            # sn tA table T combo b..:n,... halfK p halfiKp q
            combo = [] if toks[5].startswith("halfK") else [c for c in toks[5].split(",") if c]
            hk = int(toks[toks.index("halfK") + 1])
            hkp = int(toks[toks.index("halfiKp") + 1])
            return self.elliptic(toks[0], v[toks[1]], toks[3], combo, hk, hkp)
        if toks[0] == "d":
            return self.dfrac(v[toks[1]], toks[2])
        raise CheckError(f"unknown node {' '.join(toks)[:60]}")

    def statement(self, word, rest):
        if word == "field":
            self.field(rest)
        elif word == "root":
            self.root(rest)
        elif word == "named":
            name, d = rest.split("=", 1)
            self.named[name.strip()] = self.frac(d)
        elif word == "base":
            self.base(rest)
        elif word == "period":
            self.period(rest)
        elif word == "dvar":
            head, val = rest.split("=", 1)
            x, v = head.split()
            f = self.frac(val)
            self.check_dvar(x, v, f)
            self.dvar[(x, v)] = f
        elif word == "node":
            self.node(rest)
        elif word == "equiv":
            self.equivalence(rest)
        elif word in ("inverse", "call"):
            (self.inverse_of_sn if word == "inverse" else self.call_line)(rest)
        elif word == "param":
            name, kind = rest.split()
            if (name, kind) not in self.params:  # a later case of the proof repeats them
                self.need(kind in ("positive", "nonzero") and self.pring is None, f"bad parameter {name}")
                self.params.append((name, kind))
        elif word == "image":
            name, val = rest.split("=", 1)
            self.images[name.strip()] = self.param_frac(val)
            self.image_texts[name.strip()] = val.strip()
        elif word == "alt":
            sub, _, more = rest.partition(" ")
            self.need(sub in ("param", "image"), f"bad alt line {rest[:40]}")
            self.alt_lines.append((sub, more))
        elif word == "posroot":
            self.need(self.kinds.get(rest.strip()) == "root", f"posroot of a non-root {rest[:40]}")
            self.need(rest.strip() not in self.signsyms, f"posroot of the sign symbol {rest[:40]}")
            self.posroots[rest.strip()] = None
        elif word == "sign":
            self.sign_line(rest)
        elif word == "signsym":
            self.sign_symbol(rest)
        elif word == "dominance":
            self.dominance_line(rest)
        elif word == "fact":
            self.fact_line(rest)
        elif word == "claim":
            a, b = [s.strip() for s in rest.split("=")]
            self.need(self.eq(self.vals[a], self.vals[b]), f"claim {a} = {b} fails")
            self.claim_pairs.append((a, b))
            return 1
        elif word == "side":
            a, b = rest.split()
            self.need(a in self.vals and b in self.vals, f"side {rest[:40]}: undefined node")
            self.claim_pairs.append((a, b))
            self.sides += 1
            return 1
        elif word == "witness":
            m = re.fullmatch(r"component (\d+)", rest.strip())
            self.need(m is not None and self.witness is None, f"bad witness line {rest[:40]}")
            self.witness = int(m.group(1))
        elif word == "at":
            m = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*) ([=~]) (\S+) (\S+)", rest.strip())
            self.need(m is not None, f"bad at line {rest[:40]}")
            table = self.at["exact" if m.group(2) == "=" else "approx"]
            self.need(m.group(1) not in table, f"two values for {m.group(1)}")
            table[m.group(1)] = (m.group(3), m.group(4))
        elif word == "claims":
            self.need(rest.strip().isdigit() and self.expected_claims is None, f"bad claims line {rest[:40]}")
            self.expected_claims = int(rest)
        elif word == "assume":
            kind, name, stmt = rest.split(" ", 2)
            self.need(kind in ("branch", "lemma", "hypothesis"), f"unknown assumption kind {kind[:20]}")
            self.assumes.append((kind, name, json.loads(stmt)))
        elif word == "part":
            self.conditions.append(rest)
        elif word == "chart":
            self.chart(rest)
        elif word == "coord":
            name, _, t = rest.partition(" = ")
            self.need(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*(\[\d+\])?", name.strip()) is not None
                      and name.strip() not in self.coords, f"bad coord line {rest[:40]}")
            self.coords[name.strip()] = self.vals[t.strip()]
        elif word in ("series", "sseries", "sclaim", "srefute", "schart", "ssolution"):
            if self.trace is None:
                self.trace = series.Trace(self)
            try:
                if word == "series":
                    self.trace.header_line(rest)
                elif word == "sseries":
                    self.trace.record(rest)
                elif word == "schart":
                    self.trace.chart(rest)
                elif word == "ssolution":
                    return self.trace.solution_line(rest)
                elif word == "srefute":
                    return self.trace.refute(rest)
                else:
                    return self.trace.claim(rest)
            except series.SeriesError as e:
                raise CheckError(str(e))
        elif word in ("source", "premise"):
            pass  # the claim and the theorem's premises: checked for the whole file
        else:
            raise CheckError(f"unknown statement '{word}'")
        return 0

    def sign_line(self, rest):
        """`sign tN > 0`, proved here by the parametrization; or, with evidence,
        `sign tN > 0 [square (A)/(B)] [hypothesis LABEL factor (F)/(G)]`: tN is (A/B)**2
        with A/B of a proved nonzero sign, and the value (or A/B) is the stated
        hypothesis' value times F/G, whose sign is proved here.  The hypothesis'
        value is checked once the claim is read (certcheck.hypothesis).  Or
        `sign tN > 0 fact Fi factor (F)/(G)`: the value is the fact's (dn of a real
        argument, checked by its `fact` line) times F/G, whose sign is proved here.
        `sign value (N)/(D) > 0 ...` states the sign of a value written out (one the
        derivation made only for a decision) with the same evidence.  A LABEL `part:K`
        is the condition of the K-th `part` line, this part of the domain's."""
        m = re.fullmatch(r"(t\d+|value .+?) ([<>]) 0(?: square (.+?))?(?: hypothesis (\S+) factor (.+))?"
                         r"(?: fact (F\d+) factor (.+))?( parts)?", rest.strip())
        self.need(m is not None, f"bad sign line {rest[:40]}")
        t, rel, square, label, factor, fact, ffactor, by_parts = m.groups()
        self.need(fact is None or (label is None and square is None), f"bad sign line {rest[:40]}")
        self.need(by_parts is None or (fact is None and label is None and square is None), f"bad sign line {rest[:40]}")
        want = 1 if rel == ">" else -1
        value = self.vals[t] if t.startswith("t") else self.frac(t[len("value "):])
        base = value if square is None else self.frac(square)
        if by_parts is not None:
            self.need(self.parts_sign(value) == want,
                      f"sign {t[:40]} {rel} 0 is not decided by the signs of its parts")
        if square is not None:
            self.need(want == 1 and self.eq(value, self.mul(base, base)),
                      f"sign {t} {rel} 0: {t} is not the square of {square[:60]}")
        if by_parts is not None:
            pass
        elif fact is not None:
            self.need(fact in self.facts, f"sign {t[:40]} {rel} 0: no fact {fact}")
            f = self.frac(ffactor)
            self.need(self.eq(value, self.mul(self.facts[fact], f)),
                      f"sign {t[:40]} {rel} 0: the value is not the fact {fact} times the stated factor")
            self.need(self.proved_sign(f) == want,
                      f"sign {t[:40]} {rel} 0: the factor {ffactor[:60]} does not have that sign")
        elif label is None:
            got = self.proved_sign(base)
            self.need(got == want or (square is not None and got in (1, -1)),
                      f"sign {t[:40]} {rel} 0 is not proved by the parametrization")
        else:
            f = self.frac(factor)
            r = self.rational(f)
            fsign = (r > 0) - (r < 0) if r is not None else (self.frac_sign(f) or (self.alt_lines and self.alt_sign(f)))
            self.need(fsign in (1, -1), f"sign {t} {rel} 0: the sign of the factor {factor[:60]} is not proved")
            if label.startswith("part:"):
                self.part_sign(t, label, base, f, fsign, None if square is not None else want)
            else:
                self.hyp_signs.append((t, label, base, f, fsign, None if square is not None else want))
        self.checked += 1
        self.proved_signs.append((value, want))
        if want == 1 and t.startswith("t"):
            self.sign_lines.add(t)

    def part_sign(self, t, label, base, f, fsign, want):
        """`sign tN > 0 hypothesis part:K factor (F)/(G)`: the value (or the base of its
        square) is the condition of the K-th `part` line times F/G, so on this part of
        the domain its sign is that condition's times F/G's (a square's is positive
        wherever the base is nonzero, which the condition's strict sign gives)."""
        k = label[len("part:"):]
        self.need(k.isdigit() and 1 <= int(k) <= len(self.part_conditions),
                  f"sign {t[:40]}: no part condition {label}")
        cond, s = self.part_conditions[int(k) - 1]
        self.need(self.eq(base, self.mul(cond, f)),
                  f"sign {t[:40]}: the value is not the condition of {label} times the stated factor")
        self.need(want is None or want == s * fsign,
                  f"sign {t[:40]}: the condition of {label} times the factor does not have that sign")

    # ---- signs from the signs of the parts in a square root (`sign ... parts`) --------
    def parts_sign(self, f):
        """The sign of f = N/D from the signs of the parts of N and D in their positive
        roots (part_poly_sign), or None."""
        n, d = self.part_poly_sign(f.num, 0), self.part_poly_sign(f.den, 0)
        return None if n is None or d is None else n * d

    def part_poly_sign(self, p, depth):
        """The sign of the polynomial p: proved by the parametrization (tower_sign), a
        sign line checked before, or the condition of this part of the domain
        (known_sign); else, for p = a + b*r in a positive root r (a posroot, not a sign
        symbol) whose radicand has a sign decided so: the sign of b where a = 0, of a and
        b where they agree, else of a times that of a**2 - b**2 * radicand, which is
        (a + b r)(a - b r), a - b r having the sign of a."""
        if not p:
            return None
        if p.is_ground:
            return 1 if p.LC > 0 else -1
        s = self.tower_sign(p) or self.known_sign(Frac(p, self.ring.one))
        if s is not None or depth >= 6:
            return s
        used = [k for k, deg in enumerate(p.degrees()) if deg > 0]
        for name, i, rad in reversed(self.roots):
            if i not in used or name in self.signsyms or name not in self.posroots or rad == self.ring.one:
                continue
            if any(m[i] > 1 for m in p.itermonoms()) or self.part_poly_sign(rad, depth + 1) != 1:
                continue
            a = self.ring.from_dict({m: c for m, c in p.iterterms() if m[i] == 0})
            b = self.ring.from_dict({m[:i] + (0,) + m[i + 1:]: c for m, c in p.iterterms() if m[i] == 1})
            sb = self.part_poly_sign(b, depth + 1)
            sa = self.part_poly_sign(a, depth + 1) if a else 0
            if sb is None or sa is None:
                continue
            if sa in (0, sb):
                return sb
            sq = self.part_poly_sign(self.reduce(a * a - b * b * rad), depth + 1)
            if sq is not None:
                return sa * sq
        return None

    def known_sign(self, f):
        """The sign of f where a sign line checked before states the sign of f (or of
        -f), or where f is the condition c of this part of the domain (a `part` line)
        times a rational number, or times a factor whose sign the parametrization proves
        (f/c, or f*c, of proved sign); None otherwise."""
        for val, s in self.proved_signs:
            if self.eq(val, f):
                return s
            if self.eq(val, self.neg(f)):
                return -s
        for c, s in self.part_conditions:
            q = self.div(f, c)
            r = self.rational(q)
            if r is not None:
                if r != 0:
                    return s * (1 if r > 0 else -1)
                continue
            qs = self.frac_sign(q) or self.frac_sign(self.mul(f, c))
            if qs in (1, -1):
                return s * qs
        return None

    def proved_sign(self, f):
        """The sign of f: a rational constant's, or proved by a parametrization."""
        r = self.rational(f)
        if r is not None:
            return (r > 0) - (r < 0) or None
        return self.frac_sign(f) or (self.alt_lines and self.alt_sign(f)) or None

    def sign_symbol(self, rest):
        """`signsym S = sign (X)/(Y)`: the root S of radicand 1 (both signs in the
        arithmetic) is sign(x) for x = c*v, c a nonzero rational and v an indeterminate,
        so that S*v has the sign of c (where v != 0).  Arithmetic modulo S**2 = 1 holds for
        both signs, so for this one; a sign test then uses S*v."""
        name, _, val = rest.partition(" = ")
        name = name.strip()
        self.need(val.startswith("sign "), f"bad signsym line {rest[:40]}")
        rad = next((a for r, _, a in self.roots if r == name), None)
        self.need(rad is not None and rad == self.ring.one, f"signsym {name[:40]}: not a root of radicand 1")
        self.need(name not in self.signsyms and name not in self.posroots, f"signsym {name}: defined twice")
        x = self.frac(val[len("sign "):])
        terms = list(x.num.terms())
        self.need(x.den.is_ground and len(terms) == 1 and sum(terms[0][0]) == 1,
                  f"signsym {name}: sign of a value that is no constant multiple of a symbol")
        (monom, c), = terms
        i = monom.index(1)
        self.need(self.kinds.get(str(self.ring.symbols[i])) == "indeterminate",
                  f"signsym {name}: sign of a value that is no multiple of an indeterminate")
        d = int(x.den.LC)
        self.signsyms[name] = (i, 1 if (c > 0) == (d > 0) else -1)

    def sign_symbol_sign(self, p, depth):
        """The sign of p = b*S for a sign symbol S = sign(c v) with v dividing b: the sign
        of c times that of b/v (as S*v has the sign of c); None where p is not of that
        form."""
        for name, (vi, sc) in self.signsyms.items():
            i = self.idx[name]
            if p.degree(i) <= 0:
                continue
            if any(m[i] != 1 or m[vi] < 1 for m in p.itermonoms()):
                return None
            q = self.ring.from_dict({m[:i] + (0,) + m[i + 1:]: c for m, c in p.iterterms()})
            q = self.ring.from_dict({m[:vi] + (m[vi] - 1,) + m[vi + 1:]: c for m, c in q.iterterms()})
            s = self.tower_sign(q, depth + 1)
            return None if s is None else sc * s
        return None

    def fact_line(self, rest):
        """`fact Fi dn base B value (D)`: D is the d of base B; or `fact Fi dn tN`: tN is
        a dn node.  Either way dn of an argument real by construction (after the
        equivalents are replaced) at a real modulus with 0 < k**2 < 1 proved here, which
        is positive (DLMF 22.2.4, 22.4.1: dn is real, never 0, 1 at 0 on the real line);
        no shift by iK'."""
        m = re.fullmatch(r"(F\d+) dn (?:base (\S+) value (.+)|(t\d+))", rest.strip())
        self.need(m is not None, f"bad fact line {rest[:40]}")
        name, bname, dtext, node = m.groups()
        self.need(name not in self.facts, f"fact {name} stated twice")
        if bname is not None:
            self.need(bname in self.bases, f"fact {name}: no base {bname[:40]}")
            b = self.bases[bname]
            d, arg, k = self.frac(dtext), b["arg"], b["k"]
            self.need(self.eq(d, b["d"]), f"fact {name}: the value is not dn of base {bname}")
        else:
            toks = self.ops.get(node)
            self.need(toks is not None and toks[0] == "dn", f"fact {name}: {node} is no dn node")
            self.need(int(toks[toks.index("halfiKp") + 1]) == 0, f"fact {name}: an argument shifted by iK'")
            arg, _ = self.substitute_equivalents(self.vals[toks[1]])
            k = next((b["k"] for bn, b in self.bases.items() if bn.startswith(f"b_{toks[3]}_")), None)
            self.need(k is not None, f"fact {name}: no modulus")
            d = self.vals[node]
        self.need(self.frac_real(arg), f"fact {name}: dn of an argument that is not real by construction")
        k2 = self.mul(k, k)
        self.need(self.frac_real(k) and self.proved_sign(k2) == 1 and self.proved_sign(self.add(self.one, k2, -1)) == 1,
                  f"fact {name}: dn at a modulus not proved real with 0 < k**2 < 1")
        self.facts[name] = d
        self.checked += 1

    def run(self, text, first_line=1):
        self.declare(text)
        # the conditions of this part of the domain (`part "X" > 0`, written last), which
        # decide the signs of the parts in a square root (`sign ... parts`)
        for line in text.splitlines():
            if line.startswith("part "):
                m = re.fullmatch(r'part (".*") ([<>]) 0', line.split("  #", 1)[0].rstrip())
                self.need(m is not None, f"bad part line {line[:40]}")
                self.part_conditions.append((self.frac(json.loads(m.group(1))), 1 if m.group(2) == ">" else -1))
        claims = 0
        for ln, line in enumerate(text.splitlines(), first_line):
            line = line.split("  #", 1)[0].rstrip() if not line.startswith("#") else ""
            if not line:
                continue
            word, _, rest = line.partition(" ")
            try:
                claims += self.statement(word, rest)
            except CheckError as e:
                raise CheckError(f"line {ln}: {e}")
        if claims == 0:
            raise CheckError("no claim")
        if self.expected_claims is not None:
            self.need(self.expected_claims == claims,
                      f"{claims} claim line(s) where the certificate announces {self.expected_claims}")
        self.check_branches()
        self.check_coordinates()
        refuted_series = self.trace is not None and self.trace.refuted is not None
        if self.sides or self.witness is not None or refuted_series:
            if refuted_series:
                self.need(claims == 1 and not self.sides and not self.trace.claims and self.witness == 1,
                          "a refuted order needs one `srefute` line, no `sclaim` line, and `witness component 1`")
            else:
                self.need(self.sides == claims and self.witness is not None,
                          "a refutation needs `side` lines only, and a `witness` line")
            try:
                self.refuted = witness.check(self, self.witness, self.at)
            except witness.WitnessError as e:
                raise CheckError(f"witness: {e}")
        else:
            self.need(not self.at["exact"] and not self.at["approx"], "a witness point without a witness line")
        return claims

    def check_coordinates(self):
        """Every stated derivative of a chart parameter in x holds the claim's other
        variables fixed: each `coord NAME = tN` (a claim's variable the chart replaces)
        has the derivative 1 in x where NAME is x, else 0, computed with the stated
        derivatives (the chart differentiated implicitly: for h = H(q, delta),
        H_x + H_delta * delta' = 0).  Which claim variables need a coord line is checked
        with the claim's formulas (certcheck.formula)."""
        if not self.param_dvars:
            return
        self.need(self.coords, f"d{self.param_dvars[0][1]}/d{self.param_dvars[0][0]}: a derivative of a chart "
                  "parameter, and no coord line gives a claim's variable the chart replaces")
        for x in sorted({x for x, _ in self.param_dvars}):
            for name, val in self.coords.items():
                want = self.const(1 if name == x else 0)
                self.need(self.eq(self.dfrac(val, x), want),
                          f"coord {name}: with the stated derivatives of the chart's parameters, d{name}/d{x} "
                          f"is not {1 if name == x else 0}: the chart does not hold the claim's other variables fixed")

    def chart(self, rest):
        """chart NAME(ARGS) value=tA,...: the value of an implicit map at the chart's
        arguments (components separated by ', ', arguments by '; ')."""
        head, _, value = rest.rpartition(" value=")
        name, _, args = head.partition("(")
        self.need(args.endswith(")") and value, f"malformed chart line {rest[:40]}")
        argv = [[self.frac(c) for c in a.split(", ")] for a in args[:-1].split("; ")]
        self.charts.setdefault(name, []).append((argv, [self.vals[t] for t in value.split(",")]))

    def rational(self, v):
        """v as a Fraction when it is a constant, else None."""
        if not (v.num.is_ground and v.den.is_ground):
            return None
        n, d = int(v.num.LC) if v.num else 0, int(v.den.LC)
        return Fraction(n, d)

    def check_branches(self):
        """Every square root's stated value is the nonnegative root, with evidence: a
        proved sign line, a nonnegative constant, a sign proved here from the
        parametrization, or the value c*r of a root symbol r whose branch is otherwise free
        (no posroot, no sign symbol), taken as the root of sign(c) consistently."""
        free = {}
        for tid, rad, val in self.sqrts:
            if tid in self.sign_lines:
                continue
            r = self.rational(val)
            if r is not None:
                self.need(r >= 0, f"{tid}: the square root is stated as {r} < 0")
                continue
            # c * r first: its factor c is smaller than the value
            one = self.single_root(val)
            if one is None and self.pring is not None:
                if self.frac_sign(val) == 1 or (self.alt_lines and self.alt_sign(val) == 1):
                    continue
            self.need(one is not None, f"{tid}: the square-root branch has no evidence: its stated value "
                      f"{val.num.as_expr()}/{val.den.as_expr()} has no proved sign")
            name, s = one
            if name in self.posroots and s == 1:
                continue  # c * r with c > 0 and r the positive root
            self.need(name not in self.posroots and free.get(name, s) == s,
                      f"{tid}: the square-root branch needs {name} of sign {s}, which the certificate contradicts")
            free[name] = s

    def single_root(self, val):
        """(root name, sign of c) when val = c * r with r a root symbol that is no sign
        symbol and c free of r, a nonzero constant or of a sign proved here, else None.
        The candidates are tried first with the signs of sign lines checked before (of
        c's numerator and denominator), then with the parametrizations, whose test of a
        factor with a large root can take minutes."""
        cands = []
        for name, i, a in self.roots:
            if a == self.ring.one or val.den.degree(i) > 0 or val.num.degree(i) != 1:
                continue
            x = self.ring.gens[i]
            rest = val.num - val.num.coeff_wrt(x, 1) * x
            if rest:
                continue
            cands.append((name, Frac(val.num.coeff_wrt(x, 1), val.den)))
        for name, c in cands:
            s = self.stated_sign(c)
            if s in (1, -1):
                return name, s
        for name, c in cands:
            r = self.rational(c)
            s = ((r > 0) - (r < 0)) if r is not None else (
                self.frac_sign(c) if self.pring is not None else None) or (
                self.alt_lines and self.alt_sign(c)) or None
            if s in (1, -1):
                return name, s
        return None

    def stated_sign(self, f):
        """The sign of f = N/D from rational constants and the sign lines checked before
        (of N and of D, each up to its negative), or None: no sign test."""
        signs = []
        for p in (f.num, f.den):
            if p.is_ground:
                signs.append((p.LC > 0) - (p.LC < 0))
                continue
            x = Frac(p, self.ring.one)
            signs.append(next((s * t for val, s in self.proved_signs
                               for t, y in ((1, x), (-1, self.neg(x))) if self.eq(val, y)), None))
        return None if None in signs else signs[0] * signs[1]


PRIME = 2147483647  # 2**31 - 1


def images(f, both, pt, deg):
    """For each variable index i in `both`: f modulo PRIME as a polynomial in x_i (the
    coefficient list, constant first) with every other variable x_j set to pt[j]."""
    pw = [[pow(v, e, PRIME) for e in range(d + 1)] for v, d in zip(pt, deg)]
    ipw = {i: [pow(pt[i], -e, PRIME) for e in range(deg[i] + 1)] for i in both}
    img = {i: [0] * (deg[i] + 1) for i in both}
    active = [j for j, d in enumerate(deg) if d]
    for m, c in f.iterterms():
        b = c % PRIME
        for j in active:
            e = m[j]
            if e:
                b = b * pw[j][e] % PRIME
        for i in both:
            e = m[i]
            img[i][e] += b * ipw[i][e]
    for i in both:
        img[i] = [x % PRIME for x in img[i]]
    return img


def monomial_part(f):
    """(the exponents of the largest monomial dividing f, f divided by that monomial)."""
    terms = list(f.iterterms())
    low = tuple(map(min, *[m for m, _ in terms])) if len(terms) > 1 else terms[0][0]
    if not any(low):
        return low, f
    return low, f.ring.from_dict({tuple(x - y for x, y in zip(m, low)): c for m, c in terms})


def coefficients(f, support, deg):
    """The coefficients of f as a polynomial in the variables outside `support`."""
    outside = [j for j, d in enumerate(deg) if d and j not in support]
    if not outside:
        return [f]
    parts = {}
    for m, c in f.iterterms():
        key = tuple(m[j] for j in outside)
        mm = list(m)
        for j in outside:
            mm[j] = 0
        parts.setdefault(key, {})[tuple(mm)] = c
    return [f.ring.from_dict(p) for p in parts.values()]


def exact_quotient(p, d):
    """p / d when d divides p exactly (over the integers), else None.  The division
    stops at the first leading term that d's leading term does not divide."""
    lm = d.leading_expv()
    lc = d[lm]
    rest = [(m, c) for m, c in d.iterterms() if m != lm]
    rem = dict(p)
    heap = [tuple(-x for x in m) for m in rem]
    heapq.heapify(heap)
    q = {}
    while heap:
        m = tuple(-x for x in heapq.heappop(heap))
        c = rem.pop(m, 0)
        if not c:
            continue
        e = tuple(x - y for x, y in zip(m, lm))
        if min(e) < 0 or c % lc:
            return None
        k = c // lc
        q[e] = k
        for dm, dc in rest:
            mm = tuple(x + y for x, y in zip(e, dm))
            v = rem.get(mm, 0) - k * dc
            if v:
                if mm not in rem:
                    heapq.heappush(heap, tuple(-x for x in mm))
                rem[mm] = v
            else:
                rem.pop(mm, None)
    return p.ring.from_dict(q)


def split_top(s):
    """Splits on commas outside parentheses."""
    out, depth, cur = [], 0, ""
    for ch in s:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    out.append(cur)
    return out


def files(paths):
    for p in paths:
        if os.path.isdir(p):
            for f in sorted(os.listdir(p)):
                if f.endswith((".cert", ".txt")):
                    yield os.path.join(p, f)
        else:
            yield p


def parts(text):
    """The certificates a file holds, as (first line number, text): a proof by parts of
    the domain writes one certificate per part, each from its own header on, and each
    declares its own symbols (the same name may stand for another root in another part)."""
    lines = text.splitlines()
    starts = [i for i, ln in enumerate(lines) if ln.startswith(HEADER)] or [0]
    starts[0] = 0  # lines before the first header belong to the first certificate
    ends = starts[1:] + [len(lines)]
    return [(a + 1, "\n".join(lines[a:b])) for a, b in zip(starts, ends)]


HEADER = "# eulertop certificate "


class Result:
    """What the recheck of one certificate file found."""

    def __init__(self, path):
        self.path, self.ok, self.why, self.secs = path, False, "", 0.0
        self.claim, self.premises, self.lemmas, self.binding = None, [], [], "unbound"
        self.charts = [0, 0]  # equations of implicit maps verified at the chart, not reached
        self.cases = []  # the condition of each part of a proof by parts ('' for a whole proof)
        self.refuted = None  # what a refutation's witness certified


def check_premises(text, claim, catalogue, assumes):
    """The theorem's premises: each `premise` a hypothesis the claim states in the
    catalogue (same statement) or a lemma; each `assume` of the derivation covered by a
    premise.  Returns the premises."""
    prem = binding.premises(text)
    stated = claim.get("hypotheses", []) if claim else []
    for kind, source, statement in prem:
        if kind == "lemma":
            continue
        name = source[len("hypothesis."):] if source.startswith("hypothesis.") else None
        if kind not in ("branch", "sign") or name is None:
            raise CheckError(f"premise {kind} {source}: not a hypothesis of the catalogue or a lemma")
        if claim is not None:
            if name not in stated:
                raise CheckError(f"premise {source}: the claim does not state hypothesis {name}")
            table = catalogue.tables.get(f"hypothesis.{name}", {})
            if table.get("statement") != statement:
                raise CheckError(f"premise {source}: its statement is not the catalogue's")
    for kind, name, statement in assumes:
        if kind == "branch":
            ok = any(k == "branch" and catalogue is not None and
                     catalogue.tables.get(src, {}).get("branch") == name for k, src, _ in prem)
        elif kind == "hypothesis":
            ok = any(k == "sign" and src == name for k, src, _ in prem)
        else:
            ok = any(k == "lemma" and src == name for k, src, _ in prem)
        if not ok:
            raise CheckError(f"the derivation rests on the {kind} {name} ({statement[:80]}), "
                             "which is no premise of the theorem")
    return prem


def covers(cases):
    """Do the parts of a proof by parts cover the domain: the conditions of the parts (a
    list of (value, '>' or '<') per part) are the leaves of a tree of splits, where every
    part under a split states its value's sign and both signs have their parts?  (Where
    a split value vanishes, on a set of measure zero, no part holds.)  A certificate
    without conditions covers what is left (as do the cases of a discrete variable,
    which state none)."""
    if [] in cases:
        return True
    first = cases[0][0][0]
    if not all(any(v == first for v, _ in c) for c in cases):
        return False
    for rel in (">", "<"):
        sub = [[(v, r) for v, r in c if v != first] for c in cases if (first, rel) in c]
        if not sub or not covers(sub):
            return False
    return True


def check_text(name, text, catalogue=None):
    """A Result: ok when the certificate is bound to its claim in the catalogue (none:
    the derivation alone), every part rechecks with symbols of its own, its formulas
    evaluate to the derivation's sides where the evaluator covers them, and every fact
    the derivation rests on is a premise."""
    res = Result(name)
    claims = checked = 0
    try:
        src, claim = {}, None
        if catalogue is not None:
            res.claim, claim, src = binding.bind(text, catalogue)
        assumes, modes, charts, used, conditions = [], set(), [0, 0], {}, []
        if any(line.startswith("ode ") for line in text.splitlines()):
            # a proof by the uniqueness of the solution of an ODE (module certcheck.ode)
            if catalogue is None:
                raise CheckError("a proof by the ODE method is rechecked bound to its claim only")
            cert = Cert(name)
            modes.add(ode.check(cert, text, src))
            claims, checked, conditions, res.cases = 1, cert.checked, [[]], [""]
        for first, part in ([] if claims else parts(text)):
            cert = Cert(name)
            claims += cert.run(part, first)
            checked += cert.checked
            assumes += cert.assumes
            res.cases.append(" and ".join(cert.conditions))
            res.refuted = res.refuted or cert.refuted
            conditions.append(cert.conditions)
            if catalogue is not None:
                domain.check(cert, src)
                modes.add(formula.check(cert, src, catalogue))
                if cert.refuted is not None:
                    try:
                        res.refuted = f"{res.refuted}; {witness.check_domain(cert, src)}"
                    except witness.WitnessError as e:
                        raise CheckError(f"witness: {e}")
                charts = [a + b for a, b in zip(charts, cert.chart_counts)]
            used.update(hypothesis.check(cert, src, catalogue, claim, binding.premises(text)))
        cases = [[tuple(c.rsplit(" ", 2)[:2]) for c in cert_conditions] for cert_conditions in conditions]
        if res.refuted is None and not covers(cases):
            raise CheckError("the parts of the domain do not cover it: each split value needs a part for "
                             "each of its signs (" + "; ".join(c or "the rest" for c in res.cases) + ")")
        res.premises = [(k, s, f"{used[s]['when']}: {st} (paper: {used[s]['paper']})" if s in used else st)
                        for k, s, st in check_premises(text, claim, catalogue, assumes)]
        res.lemmas = [s for k, s, _ in res.premises if k == "lemma"]
        res.binding = "unbound" if catalogue is None else (
            "evaluated" if modes == {"evaluated"} else sorted(m for m in modes if m != "evaluated")[0])
    except (CheckError, binding.BindError, formula.FormulaMismatch, domain.DomainMismatch,
            hypothesis.HypothesisMismatch, ode.OdeMismatch, KeyError, ValueError, IndexError) as e:
        known = (CheckError, binding.BindError, formula.FormulaMismatch, domain.DomainMismatch,
                 hypothesis.HypothesisMismatch, ode.OdeMismatch)
        res.why = f"{type(e).__name__ + ' ' if not isinstance(e, known) else ''}{e}"
        return res
    res.charts = charts if catalogue is not None else [0, 0]
    chart_note = ""
    if sum(res.charts):
        chart_note = f"; charts: {res.charts[0]} equation(s) of the catalogue verified" + (
            f", {res.charts[1]} not reached" if res.charts[1] else "")
    negation = claim is not None and claim.get("kind") == "negation"
    if negation and res.refuted is None:
        res.why = "a negation is proved by a witness point only, and the certificate has none"
        return res
    if res.refuted is None:
        what = f"{claims} claim(s)"
    else:
        counted = "1 coefficient" if "the coefficient of t^" in res.refuted else f"{claims} side(s)"
        what = (f"{'PROVED (negation): the inner claim fails' if negation else 'REFUTED'}, {res.refuted}; "
                f"{counted}")
    res.ok, res.why = True, f"{what}, {checked} equalities checked; formulas: {res.binding}{chart_note}"
    return res


def corruptions(text):
    """Corrupted copies of a certificate, as (what, text) pairs: one coefficient of the
    last product node's stated normal form, the first root's radicand (+ 1), in a
    certificate of several parts the last part's last radicand (+ 1), the first
    equivalent argument of an inverse of sn, cn, dn (+ 1, where there is one), the first
    proved sign (flipped, where there is one), the first claim's right-hand side (+ 1)."""
    lines = text.splitlines()
    out = []

    def swap(i, new, what):
        out.append((f"line {i + 1}: {what}", "\n".join(lines[:i] + new + lines[i + 1:])))

    products = [i for i, ln in enumerate(lines) if re.match(r"node t\d+ = t\d+ \* t\d+ -> \((?!0\))", ln)]
    if products:
        i = products[-1]
        head, nf = lines[i].split("-> (", 1)
        m = re.match(r"(-?)(\d+)\*", nf)
        first = f"{m.group(1)}{int(m.group(2)) + 1}*{nf[m.end():]}" if m else re.sub(r"^(-?)", r"\g<1>2*", nf)
        swap(i, [f"{head}-> ({first}"], "one coefficient of the stated normal form changed")
    roots = [i for i, ln in enumerate(lines) if ln.startswith("root ")]
    last_part = max((i for i, ln in enumerate(lines) if ln.startswith(HEADER)), default=0)
    later = [i for i in roots if i > last_part]
    for i, what in ([(roots[0], "radicand + 1")] if roots else []) + (
        [(later[-1], "the last part's last radicand + 1 (a part has roots of its own)")] if last_part and later else []
    ):
        head, rad = lines[i].split("  #", 1)[0].split("=", 1)
        swap(i, [f"{head}= {rad.strip()} + 1"], what)
    equivs = [i for i, ln in enumerate(lines) if ln.startswith("equiv ") and " arg=(" in ln]
    if equivs:
        i = equivs[0]
        head, arg = lines[i].split(" arg=(", 1)
        swap(i, [f"{head} arg=(1 + {arg}"], "an equivalent argument + 1")
    signs = [i for i, ln in enumerate(lines) if re.match(r"sign t\d+ [<>] 0$", ln)]
    if signs:
        i = signs[0]
        flipped = lines[i].replace(" > 0", " < 0") if " > 0" in lines[i] else lines[i].replace(" < 0", " > 0")
        swap(i, [flipped], "a proved sign flipped")
    claims = [i for i, ln in enumerate(lines) if re.match(r"claim t\d+ = t\d+$", ln)]
    if claims:
        i = claims[0]
        lhs, rhs = lines[i][len("claim "):].split(" = ")
        swap(i, ["node t_one = 1", f"node t_bad = {rhs} + t_one", f"claim {lhs} = t_bad"], "claim rhs + 1")
    return out


def self_test(path, catalogue):
    """The certificate must recheck as written and fail after each corruption."""
    with open(path, encoding="utf-8") as fh:
        text = fh.read()
    res = check_text(path, text, catalogue)
    print(f"{'OK  ' if res.ok else 'FAIL'}  {path} as written: {res.why}")
    good = res.ok
    cases = corruptions(text)
    for what, bad in cases:
        bad_res = check_text(path, bad, catalogue)
        caught = not bad_res.ok
        print(f"{'rejected' if caught else 'ACCEPTED'}  {what}: {bad_res.why}")
        good = good and caught
    if len(cases) < 3:
        print(f"({3 - len(cases)} of the three corruptions do not apply: no root or no product node)")
    print("self-test passes" if good else "self-test FAILS")
    return 0 if good else 1


def check_path(job):
    """The Result of one certificate file."""
    path, catalogue = job
    start = time.perf_counter()
    try:
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
    except (OSError, UnicodeDecodeError) as e:
        res = Result(path)
        res.why = f"cannot read it: {e}"
        return res
    res = check_text(path, text, catalogue)
    res.secs = time.perf_counter() - start
    return res


USAGE = "usage: recheck-certificates.py [--catalogue DIR | --unbound] [--jobs N] (PATH... | --self-test CERT)"


def options(args):
    """(catalogue dir or None, jobs, self-test path or None, paths)."""
    cat, jobs, test, paths = "identities", os.cpu_count() or 1, None, []
    i = 0
    while i < len(args):
        a = args[i]
        if a in ("--catalogue", "--jobs", "--self-test"):
            if i + 1 >= len(args):
                raise CheckError(f"{a} takes a value")
            v = args[i + 1]
            i += 2
            if a == "--catalogue":
                cat = v
            elif a == "--self-test":
                test = v
            elif not v.isdigit() or int(v) < 1:
                raise CheckError("--jobs takes a positive integer")
            else:
                jobs = int(v)
            continue
        if a == "--unbound":
            cat = None
        elif a.startswith("--"):
            raise CheckError(f"unknown option {a}")
        else:
            paths.append(a)
        i += 1
    if test is None and not paths:
        raise CheckError("no certificate given")
    return cat, jobs, test, paths


def lemma_failures(results):
    """The certificates that use a lemma whose certificate is not in the run (or fails)."""
    passed = {r.claim for r in results if r.ok and r.claim}
    out = {}
    for r in results:
        missing = [lem for lem in r.lemmas if lem not in passed]
        if r.ok and missing:
            out[r.path] = f"lemma {missing[0]} is used without its certificate in this run"
    return out


def main(argv):
    try:
        cat_dir, jobs, test, paths = options(argv[1:])
        catalogue = binding.Catalogue(cat_dir) if cat_dir is not None else None
    except (CheckError, binding.BindError) as e:
        print(f"recheck-certificates: {e} ({USAGE})", file=sys.stderr)
        return 2
    if test is not None:
        return self_test(test, catalogue)
    paths = list(files(paths))
    start = time.perf_counter()
    # certificates are independent: several processes, results printed in path order
    with multiprocessing.Pool(min(jobs, max(len(paths), 1))) as pool:
        results = list(pool.imap(check_path, [(p, catalogue) for p in paths]))
    late = lemma_failures(results)
    bound = {}
    for r in results:
        if r.path in late:
            r.ok, r.why = False, late[r.path]
        bound[r.binding.split(" ")[0]] = bound.get(r.binding.split(" ")[0], 0) + r.ok
        print(f"{'OK  ' if r.ok else 'FAIL'}  {r.path}: {r.why} ({r.secs:.2f} s)", flush=True)
        for kind, source, statement in (r.premises if r.ok else []):
            print(f"      premise [{kind}: {source}] {statement}")
        for j, case in enumerate(r.cases if r.ok and len(r.cases) > 1 else [], 1):
            print(f"      part {j} of the domain: {case or 'the rest'}")
    bad = sum(not r.ok for r in results)
    n = len(results)
    how = ", ".join(f"{v} {k}" for k, v in sorted(bound.items()) if v)
    with_chart = [r for r in results if r.ok and sum(r.charts)]
    if with_chart:
        how += f"; {sum(r.charts[0] > 0 for r in with_chart)} of {len(with_chart)} charts verified"
    refuted = sum(r.ok and r.refuted is not None for r in results)
    if refuted:
        how += f"; {refuted} of them witness certificates (refutations, and negations proved)"
    print(f"{n - bad} of {n} certificates recheck ({how}; {time.perf_counter() - start:.1f} s)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
