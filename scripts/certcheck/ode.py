"""Rechecks a proof by the uniqueness of the solution of an algebraic ODE.

The claim lhs = rhs is proved as an identity in one real variable x of its domain (the
others fixed): both sides solve one polynomial ODE P(x, y, y', ..., y^(n)) = 0, they
have the same values y, y', ..., y^(n) at a point x0, and dP/dy^(n) does not vanish
there.  Then, by the implicit function theorem, near that point the solutions of P = 0
are those of an explicit ODE y^(n) = F(x, y, ..., y^(n-1)) with F analytic; both sides
(analytic near x0, as their denominators do not vanish there) solve it with the same
initial values, so by the Picard-Lindelof theorem they agree near x0, and by the
identity theorem on every interval containing x0 on which both are analytic.  (This is
the simplest case of the zero test for D-algebraic functions: J. van der Hoeven, "A new
zero-test for formal power series", ISSAC 2002: a function given by an algebraic ODE is
0 when enough initial conditions vanish at a nonsingular point.)

What this module checks, with its own arithmetic and never the prover's results:

  * the sides are the claim's own lhs and rhs, evaluated here from the catalogue's
    formulas (module evaluate), with sn, cn, dn of an argument a at a modulus k as the
    symbols S, C, D of a `jet S C D arg=(..) k=(..)` line whose argument is a and whose
    modulus squared is k**2, and a square root as a product of root symbols whose square
    is the radicand (any branch: every check below holds modulo the relations, so for
    every choice of signs of the roots);
  * the derivatives of both sides in x, up to the order of P, computed here by the
    chain rule: S' = C D a', C' = -S D a', D' = -k**2 S C a' (DLMF 22.13.1-3), the
    other variables and the roots constant (a root whose radicand depends on x, or a
    modulus depending on x, is refused); they must be the values the `ode side` lines
    state;
  * P(x, side, side', ..., side^(n)) reduced modulo C**2 = 1 - S**2,
    D**2 = 1 - k**2 S**2 and the root relations is 0 for both sides (a reduction to 0
    proves the identity; the relations hold at the true values);
  * at x0 every jet's argument vanishes (so S = 0, C = D = 1 there), the denominators
    of every side's derivatives up to order n do not vanish, the values agree between
    the sides and are the `ode initial` values;
  * dP/dy^(n) at (x0, the initial values) is the `ode nonsingular` value and is not 0.

A value is nonzero here when the product of its conjugates over the roots (its norm) is
a nonzero polynomial: then it vanishes for no choice of signs of the roots, outside a
proper algebraic subset of the other variables (the scope the prover states: the claim
holds wherever its initial values are defined).
"""

import itertools
import re

from . import formula
from .evaluate import ELLIPTIC, Evaluator
from .exprlang import Parser, Unsupported


class OdeMismatch(Exception):
    pass


Y = re.compile(r"\by(\d)\b")
FRAC = r"(\([^()]*\)/\([^()]*\))"  # (N)/(D), N and D polynomials written without parentheses


def lines(text):
    """The certificate's statements (comments removed), as (word, rest)."""
    out = []
    for line in text.splitlines():
        if line.startswith("#") or line.startswith("source ") or line.startswith("premise "):
            continue
        line = line.split("  #", 1)[0].rstrip()
        if line:
            word, _, rest = line.partition(" ")
            out.append((word, rest))
    return out


def values(rest):
    """`y0=(..) y1=(..) ...` as {index: text}."""
    out = {}
    for m in re.finditer(r"y(\d+)=" + FRAC, rest):
        out[int(m.group(1))] = m.group(2)
    return out


def declare(cert, text):
    """The ring: the certificate's symbols and y0..y9 (the ODE's unknowns); returns the
    parsed `jet` and `ode` lines."""
    stmts = lines(text)
    if any(Y.fullmatch(r.split()[0]) for w, r in stmts if w in ("field", "root") and r.split()):
        raise OdeMismatch("a symbol of the certificate is named like the ODE's unknowns")
    extra = "\n".join(f"field y{j} ode" for j in range(10))
    cert.declare(text + "\n" + extra)
    jets, ode = [], {"side": {}}
    for word, rest in stmts + [("field", f"y{j} ode") for j in range(10)]:
        if word in ("field", "root"):
            cert.statement(word, rest)
        elif word == "jet":
            m = re.fullmatch(r"(\w+) (\w+) (\w+) arg=" + FRAC + " k=" + FRAC, rest)
            if m is None:
                raise OdeMismatch(f"bad jet line {rest[:60]}")
            names = m.group(1, 2, 3)
            if any(cert.kinds.get(n) != "jet" for n in names):
                raise OdeMismatch(f"jet {' '.join(names)}: not three symbols declared as jets")
            jets.append((names, cert.frac(m.group(4)), cert.frac(m.group(5))))
        elif word == "ode":
            key, _, val = rest.partition(" ")
            if key == "side":
                which, _, vals = val.partition(" ")
                ode["side"][which] = values(vals)
            else:
                ode[key] = val
        elif word != "claims":
            raise OdeMismatch(f"a `{word}` line in a certificate of the ODE method")
    used = [n for names, _, _ in jets for n in names]
    if len(set(used)) != len(used) or set(used) != {n for n, k in cert.kinds.items() if k == "jet"}:
        raise OdeMismatch("each jet symbol must belong to exactly one jet line")
    return jets, ode


class JetEvaluator(Evaluator):
    """The claim's formulas with sn, cn, dn as jet symbols and square roots as products
    of root symbols."""

    def __init__(self, cert, defines, jets):
        super().__init__(cert, defines)
        self.jets = jets

    def elliptic(self, name, u, k):
        c = self.c
        k2 = c.mul(k, k)
        for (s, cn, dn), arg, kk in self.jets:
            if c.eq(arg, u) and c.eq(c.mul(kk, kk), k2):
                val = {"s": c.frac(s), "c": c.frac(cn), "d": c.frac(dn), "n": c.one}
                num, den = ELLIPTIC[name]
                return c.div(val[num], val[den])
        raise Unsupported(f"{name} at an argument and modulus of no jet line")

    def sqrt(self, x):
        c = self.c
        roots = [c.frac(name) for name, _, _ in c.roots]
        for size in range(1, min(len(roots), 4) + 1):
            for combo in itertools.combinations(roots, size):
                p = c.one
                for r in combo:
                    p = c.mul(p, r)
                if c.eq(c.mul(p, p), x):
                    return p
        return super().sqrt(x)


class Ode:
    """The ODE's variable, the relations and the derivative of every symbol."""

    def __init__(self, cert, jets, var):
        self.c, self.jets, self.var = cert, jets, var
        self.x = cert.index(var)
        jet_idx = {cert.index(n) for names, _, _ in jets for n in names}
        for name, _, rad in cert.roots:
            if rad.degree(cert.syms[var]) > 0 or any(rad.degree(cert.ring.gens[i]) > 0 for i in jet_idx):
                raise OdeMismatch(f"the radicand of {name} depends on {var}")
        for (s, _, _), arg, k in jets:
            for v in (arg.num, arg.den, k.num, k.den):
                if any(v.degree(cert.ring.gens[i]) > 0 for i in jet_idx):
                    raise OdeMismatch(f"the jet of {s}: an argument or modulus with a Jacobi function")
            if k.num.degree(cert.syms[var]) > 0 or k.den.degree(cert.syms[var]) > 0:
                raise OdeMismatch(f"the modulus of {s} depends on {var}")
        self.dsym = {var: cert.one}
        for (s, cn, dn), arg, k in jets:
            da = self.d(arg)
            S, C, D = (cert.frac(n) for n in (s, cn, dn))
            self.dsym[s] = cert.mul(cert.mul(C, D), da)
            self.dsym[cn] = cert.neg(cert.mul(cert.mul(S, D), da))
            self.dsym[dn] = cert.neg(cert.mul(cert.mul(cert.mul(k, k), cert.mul(S, C)), da))

    def dpoly(self, p):
        """dp/dx of a polynomial, as a quotient."""
        c = self.c
        out = c.zero
        for name, i in c.idx.items():
            g = c.ring.gens[i]
            if p.degree(g) <= 0:
                continue
            kind = c.kinds.get(name)
            if name in self.dsym:
                out = c.add(out, c.mul(c.norm(type(c.one)(p.diff(g), c.ring.one)), self.dsym[name]))
            elif kind not in ("indeterminate", "root"):
                raise OdeMismatch(f"a value with the symbol {name} ({kind}), whose derivative is not known here")
        return out

    def d(self, f):
        """df/dx of a quotient."""
        c = self.c
        frac = type(c.one)
        dn, dd = self.dpoly(f.num), self.dpoly(f.den)
        top = c.add(c.mul(dn, frac(f.den, c.ring.one)), c.mul(frac(f.num, c.ring.one), dd), -1)
        return c.div(top, frac(f.den * f.den, c.ring.one))

    def reduce(self, p):
        """p modulo C**2 = 1 - S**2, D**2 = 1 - k**2 S**2 (times a power of k**2's
        denominator, which is not 0) and the root relations."""
        c = self.c
        for (s, cn, dn), _, k in self.jets:
            S = c.syms[s]
            p = square_out(c, p, c.syms[cn], c.ring.one - S * S, c.ring.one)
            k2 = c.mul(k, k)
            p = square_out(c, p, c.syms[dn], k2.den - k2.num * S * S, k2.den)
        return c.reduce(p)

    def same(self, a, b):
        """a = b modulo the relations (the denominators are not 0 where a and b are)."""
        return not self.reduce(a.num * b.den - b.num * a.den)

    def at(self, f, x0, what):
        """f at x = x0, where every jet's argument vanishes (S = 0, C = D = 1)."""
        c = self.c
        subs = [(c.syms[self.var], x0)]
        for (s, cn, dn), _, _ in self.jets:
            subs += [(c.syms[s], 0), (c.syms[cn], 1), (c.syms[dn], 1)]
        num, den = c.ring(f.num.subs(subs)), c.ring(f.den.subs(subs))
        if not nonzero(c, den):
            raise OdeMismatch(f"singular starting point: the denominator of {what} vanishes at {self.var} = {x0}")
        return c.norm(type(c.one)(num, den))


def square_out(c, p, g, num, den):
    """p with g**2 = num/den: sum of p_j (num/den)**(j//2) g**(j%2), times den**m."""
    top = p.degree(g)
    if top < 2:
        return p
    i = c.ring.gens.index(g)
    parts = {}
    for m, coef in p.iterterms():
        parts.setdefault(m[i], {})[m[:i] + (0,) + m[i + 1:]] = coef
    m = top // 2
    out = c.ring.zero
    for j, terms in parts.items():
        out += c.ring.from_dict(terms) * num ** (j // 2) * den ** (m - j // 2) * g ** (j % 2)
    return out


def nonzero(c, p):
    """Is p nonzero for every choice of signs of the roots: its norm, the product of its
    conjugates p(r) p(-r) over each root (innermost first), a nonzero polynomial?"""
    p = c.reduce(p)
    for _, i, _ in reversed(c.roots):
        g = c.ring.gens[i]
        if p.degree(g) > 0:
            p = c.reduce(p * conjugate(c, p, i))
    return bool(p)


def conjugate(c, p, i):
    """p with the root of generator i negated."""
    out = {}
    for m, coef in p.iterterms():
        out[m] = -coef if m[i] % 2 else coef
    return c.ring.from_dict(out)


def sides_here(cert, src, jets):
    """The claim's lhs and rhs, evaluated here with the jets."""
    ev = JetEvaluator(cert, [v for k, v in sorted(src.items()) if k.startswith("define.")], jets)
    env = formula.environment(cert, src, charts=False)
    ev.let(src.get("claim.let"), env)
    if src.get("claim.kind") != "identity":
        raise OdeMismatch("an ODE proof of a claim that is not an identity")
    try:
        out = [ev.components(ev.eval(Parser(src[f"claim.{s}"]).whole(), env)) for s in ("lhs", "rhs")]
    except Unsupported as e:
        raise OdeMismatch(f"the claim's formulas are not evaluated here: {e}")
    if any(len(v) != 1 for v in out):
        raise OdeMismatch("a side is not a scalar")
    return out[0][0], out[1][0]


def equation(cert, ode, order_max=9):
    """(P's numerator, its denominator, the order n) of the `ode equation` line."""
    text = ode.get("equation")
    if text is None:
        raise OdeMismatch("no `ode equation` line")
    P = cert.frac(text)
    ys = [cert.syms[f"y{j}"] for j in range(order_max + 1)]
    n = max((j for j, y in enumerate(ys) if P.num.degree(y) > 0), default=-1)
    if n < 1 or any(P.den.degree(y) > 0 for y in ys):
        raise OdeMismatch("the equation is no polynomial ODE of order at least 1 in y0, y1, ...")
    if any(P.num.degree(cert.syms[s]) > 0 or P.den.degree(cert.syms[s]) > 0
           for s, k in cert.kinds.items() if k == "jet"):
        raise OdeMismatch("the equation has a Jacobi function of the variable")
    return P.num, P.den, n


def substitute(cert, p, vals):
    """The polynomial p in y0.. with y_j = vals[j] (quotients)."""
    c = cert
    frac = type(c.one)
    ys = {c.index(f"y{j}"): v for j, v in enumerate(vals)}
    out = c.zero
    for m, coef in p.iterterms():
        rest = list(m)
        term = c.one
        for i, v in ys.items():
            if m[i]:
                term = c.mul(term, c.power(v, m[i]))
                rest[i] = 0
        term = c.mul(term, frac(c.ring.from_dict({tuple(rest): coef}), c.ring.one))
        out = c.add(out, term)
    return out


def jets_of_side(od, side, n, stated, which):
    """y, y', ..., y^(n) of a side, each the value its `ode side` line states."""
    vals = [side]
    for _ in range(n):
        vals.append(od.d(vals[-1]))
    for j, v in enumerate(vals):
        if j not in stated:
            raise OdeMismatch(f"the {which}'s line states no y{j}")
        if not od.same(v, od.c.frac(stated[j])):
            what = "the claim's formula evaluated here" if j == 0 else "its derivative computed here"
            raise OdeMismatch(f"the {which}'s y{j} is not {what}")
    return vals


def check(cert, text, src):
    """Rechecks the ODE proof of the certificate `text` bound to the claim `src` (its
    source lines); OdeMismatch with the first failure."""
    jets, ode = declare(cert, text)
    m = re.fullmatch(r"(\w+) at (-?\d+)", ode.get("var", ""))
    if m is None:
        raise OdeMismatch("no `ode var X at X0` line")
    var, x0 = m.group(1), int(m.group(2))
    real = [n for n, smp in formula.var_pairs(src) if "cplx(" not in smp and "vec(" not in smp]
    if var not in real or cert.kinds.get(var) != "indeterminate":
        raise OdeMismatch(f"{var} is not a real variable of the claim")
    od = Ode(cert, jets, var)
    for (s, _, _), arg, _ in jets:
        if od.reduce(od.at(arg, x0, f"the argument of {s}").num):
            raise OdeMismatch(f"the argument of {s} is not 0 at {var} = {x0}")
    pn, pd, n = equation(cert, ode)
    lhs, rhs = sides_here(cert, src, jets)
    init = None
    for which, side in (("lhs", lhs), ("rhs", rhs)):
        vals = jets_of_side(od, side, n, ode["side"].get(which, {}), which)
        if od.reduce(substitute(cert, pn, vals).num):
            raise OdeMismatch(f"the {which} does not satisfy the ODE: P(y, y', ...) does not reduce to 0")
        here = [od.at(v, x0, f"the {which}'s y{j}") for j, v in enumerate(vals)]
        if init is not None and not all(cert.eq(a, b) for a, b in zip(init, here)):
            raise OdeMismatch(f"the initial values differ at {var} = {x0}")
        init = here
    stated = values(ode.get("initial", ""))
    if sorted(stated) != list(range(n + 1)) or not all(cert.eq(cert.frac(stated[j]), init[j]) for j in stated):
        raise OdeMismatch(f"the `ode initial` values are not y, ..., y^({n}) of the sides at {var} = {x0}")
    nonsingular(cert, od, (pn, pd, n), init, (ode.get("nonsingular"), x0))
    return "evaluated"


def nonsingular(cert, od, eq, init, stated_at):
    """dP/dy_n at (x0, the initial values) is the stated value and is not 0."""
    pn, pd, n = eq
    stated, x0 = stated_at
    yn = cert.syms[f"y{n}"]
    frac = type(cert.one)
    dp = substitute(cert, pn.diff(yn), init)
    val = od.at(cert.div(dp, frac(pd, cert.ring.one)), x0, "dP/dy_n")
    if stated is None or not cert.eq(cert.frac(stated), val):
        raise OdeMismatch(f"the `ode nonsingular` value is not dP/dy{n} at the initial point")
    if not nonzero(cert, val.num):
        raise OdeMismatch(f"singular starting point: dP/dy{n} vanishes at the initial point")
