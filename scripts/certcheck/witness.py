"""Refutations certified at a point: the recheck of a certificate's `witness`.

A refutation's certificate is a derivation like a proof's, whose components are written
`side tA tB` (not claimed equal), followed by

    witness component J
    at X = m*2^e m'*2^e'       an indeterminate's or sn symbol's exact value (re, im)
    at r_1 ~ 0.7071 0          a root's value there, to 60 digits: which branch

The check evaluates, in interval arithmetic (mpmath.iv, outward rounding, real and
imaginary parts as intervals), every symbol at the point: the exact values as stated,
each root as the square root of its radicand's value, of the branch nearer the stated
value (the two branches must be told apart).  The branches are then verified, not
trusted: a root the checker proves positive (`posroot`) must be the positive one; the
sn, cn, dn of every elliptic base whose argument and modulus have values at the point
must agree with mpmath's own Jacobi functions there (to 40 digits), which fixes the
branches of the cn and dn roots; the stated value of every square-root node must be
the principal root (real part not negative) there; every sign the certificate proves,
and the condition of its part of the domain, must hold at the point.  A root that the
difference uses and that no such check reaches is refused.  Last, the numerator and the
denominator of component J's lhs - rhs must both exclude 0.

What this certifies: at a point where the certificate's relations hold with the
branches of the claim's formulas (the domain point it was sampled at, its sn values
within 2^-200 of the sn of its arguments), lhs - rhs is nonzero.  The normal form is
then a nonzero algebraic function of the domain's variables, and lhs - rhs, analytic on
the open domain, vanishes at most on a set without interior: the claim fails at the
point's neighbours in the domain.
"""

from fractions import Fraction

import mpmath
from mpmath import iv

PREC = 320


class WitnessError(Exception):
    """The witness does not certify the refutation."""


def _lo(x):
    return mpmath.mpf(x.a)


def _hi(x):
    return mpmath.mpf(x.b)


class Box:
    """A complex number enclosed in a rectangle: real and imaginary parts as intervals."""

    __slots__ = ("re", "im")

    def __init__(self, re, im=None):
        self.re = re
        self.im = iv.mpf(0) if im is None else im

    def __add__(self, o):
        return Box(self.re + o.re, self.im + o.im)

    def __sub__(self, o):
        return Box(self.re - o.re, self.im - o.im)

    def __neg__(self):
        return Box(-self.re, -self.im)

    def __mul__(self, o):
        return Box(self.re * o.re - self.im * o.im, self.re * o.im + self.im * o.re)

    def inv(self):
        n = self.re * self.re + self.im * self.im
        if _lo(n) <= 0:
            raise WitnessError("a division by a value that may be 0 at the point")
        return Box(self.re / n, -self.im / n)

    def power(self, e):
        out, b = Box(iv.mpf(1)), self
        while e:
            if e & 1:
                out = out * b
            b, e = b * b, e >> 1
        return out

    def excludes_zero(self):
        return not (0 in self.re and 0 in self.im)

    def mid(self):
        return mpmath.mpc((_lo(self.re) + _hi(self.re)) / 2, (_lo(self.im) + _hi(self.im)) / 2)

    def width(self):
        return max(_hi(self.re) - _lo(self.re), _hi(self.im) - _lo(self.im))

    def sqrt(self):
        """A square root (the principal one where the rectangle is off the negative real
        axis, else i times the principal root of the negative)."""
        if not self.excludes_zero():
            raise WitnessError("a square root of a value that may be 0 at the point")
        z = self if _lo(self.re) > 0 or 0 not in self.im else -self
        r = iv.sqrt(z.re * z.re + z.im * z.im)
        a = iv.sqrt((r + z.re) / 2)
        b = iv.sqrt(abs_iv((r - z.re) / 2))
        if 0 in z.im:
            # z.re > 0 here: b is near 0; its sign follows z.im's, both enclosed by +-b
            b = iv.mpf([-_hi(b), _hi(b)])
        elif _hi(z.im) < 0:
            b = -b
        w = Box(a, b)
        return w if z is self else Box(-w.im, w.re)


def abs_iv(x):
    """The interval of |x| for x an interval (a rounding error may make it dip below 0)."""
    return iv.mpf([max(_lo(x), 0), max(_hi(x), 0)])


def exact(tok):
    """The interval of an exact value `m*2^e` (or an integer)."""
    if "*2^" in tok:
        m, e = tok.split("*2^")
        return iv.mpf(int(m)) * iv.mpf(2) ** int(e)
    return iv.mpf(Fraction(tok).numerator) / iv.mpf(Fraction(tok).denominator)


def approx(tok):
    return mpmath.mpf(tok)


class Point:
    """The certificate's symbols evaluated at the witness point."""

    def __init__(self, cert):
        self.c = cert
        self.vals = [None] * cert.ring.ngens
        self.approx = {}

    def poly(self, p):
        """The value of a polynomial of the ring, or None if a symbol has no value."""
        acc = Box(iv.mpf(0))
        powers = {}
        for monom, coeff in p.terms():
            t = Box(iv.mpf(int(coeff)))
            for i, k in enumerate(monom):
                if k == 0:
                    continue
                if self.vals[i] is None:
                    return None
                if (i, k) not in powers:
                    powers[(i, k)] = self.vals[i].power(k)
                t = t * powers[(i, k)]
            acc = acc + t
        return acc

    def frac(self, f):
        n, d = self.poly(f.num), self.poly(f.den)
        if n is None or d is None:
            return None
        return n * d.inv()

    def uses(self, f):
        """The indices of the generators that a value's numerator or denominator uses."""
        out = set()
        for p in (f.num, f.den):
            for monom in p.monoms():
                out.update(i for i, k in enumerate(monom) if k)
        return out


def set_values(pt, at):
    """The exact values of the indeterminates and sn symbols; each must have one."""
    c = pt.c
    for name, kind in c.kinds.items():
        if kind in ("indeterminate", "sn") and name not in at["exact"]:
            raise WitnessError(f"no value at the point for {name}")
    for name, (re, im) in at["exact"].items():
        if c.kinds.get(name) not in ("indeterminate", "sn"):
            raise WitnessError(f"an exact value for {name}, which is no indeterminate or sn symbol")
        pt.vals[c.index(name)] = Box(exact(re), exact(im))
    for name, (re, im) in at["approx"].items():
        kind = c.kinds.get(name)
        if kind in ("indeterminate", "sn", None):
            raise WitnessError(f"an approximate value for {name}, which needs none or an exact one")
        if kind == "root":
            pt.approx[name] = mpmath.mpc(approx(re), approx(im))
        elif kind in ("param", "K", "Kp"):
            # a chart parameter (free in the chart) or a quarter period (checked against
            # mpmath's K): the decimal is the point's value, which the checks of the
            # bases and periods tie to the rest
            pt.vals[c.index(name)] = Box(iv.mpf(re), iv.mpf(im))
        # any other symbol (opaque, named, ...) has no value: a difference using it fails


def adjoin_roots(pt):
    """Each root, in order, as the branch of the square root of its radicand nearer the
    stated value; a positive root (`posroot`) must be that one."""
    c = pt.c
    for name, i, rad in c.roots:
        a = pt.poly(rad)
        if a is None:
            continue
        w = a.sqrt()
        if name not in pt.approx:
            raise WitnessError(f"no value at the point for the root {name}")
        z, m = pt.approx[name], w.mid()
        if mpmath.fabs(z - m) > mpmath.fabs(z + m):
            w = -w
        near, far = sorted((mpmath.fabs(z - m), mpmath.fabs(z + m)))
        if not far > 1000 * (near + w.width()):
            raise WitnessError(f"the branch of {name} at the point is not told apart by its stated value")
        if name in c.posroots and not _lo(w.re) > 0:
            raise WitnessError(f"{name} is proved positive, but the stated value picks the negative root")
        pt.vals[i] = w


def check_bases(pt, verified):
    """sn, cn, dn of each base with values at the point agree with mpmath's; the roots
    in them are thereby verified.  Returns the number of bases compared."""
    n = 0
    with mpmath.workprec(PREC):
        for head, b in pt.c.bases.items():
            arg, k = pt.frac(b["arg"]), pt.frac(b["k"])
            vals = [pt.frac(b[x]) for x in "scd"]
            if arg is None or k is None or None in vals:
                continue
            m = k.mid() ** 2
            for f, v in zip(("sn", "cn", "dn"), vals):
                want = mpmath.ellipfun(f, arg.mid(), m=m)
                if mpmath.fabs(v.mid() - want) > mpmath.mpf(10) ** -40 * (1 + mpmath.fabs(want)):
                    raise WitnessError(f"{head}: {f} at the point is not mpmath's {f} of the base's argument "
                                       "(a wrong branch, or a point off the relations)")
            for x in "scd":
                verified.update(pt.uses(b[x]))
            n += 1
    return n


def check_periods(pt):
    """A quarter period's value at the point is mpmath's K (or K') of the modulus."""
    with mpmath.workprec(PREC):
        for p in pt.c.periods.values():
            k = pt.frac(p["k"])
            for key, comp in (("K", False), ("Kp", True)):
                sym = p[key]
                v = pt.frac(sym) if sym is not None else None
                if v is None or k is None:
                    continue
                m = k.mid() ** 2
                want = mpmath.ellipk(1 - m if comp else m)
                if mpmath.fabs(v.mid() - want) > mpmath.mpf(10) ** -40 * (1 + mpmath.fabs(want)):
                    raise WitnessError(f"the quarter period {key} at the point is not mpmath's")


def check_signs(pt, verified):
    """The principal branch of every square-root node, and every proved sign and part
    condition, at the point."""
    c = pt.c
    for tid, _, nf in c.sqrts:
        v = pt.frac(nf)
        if v is None:
            continue
        if _hi(v.re) < 0:
            raise WitnessError(f"{tid}: the square root is not the principal root at the point")
        if _lo(v.re) > 0:
            verified.update(pt.uses(nf))
    signs = [(val, s, "a proved sign") for val, s in c.proved_signs]
    signs += [(val, s, "the part's condition") for val, s in c.part_conditions]
    for val, s, what in signs:
        v = pt.frac(val)
        if v is None:
            continue
        if not (_lo(s * v.re) > 0 and 0 in v.im):
            raise WitnessError(f"{what} does not hold at the point: the point is not in the domain")
    for name, (i, sgn) in c.signsyms.items():
        x, sigma = pt.vals[i], pt.vals[c.index(name)]
        if x is not None and sigma is not None:
            if not _lo((sigma * x).re * sgn) > 0:
                raise WitnessError(f"the sign symbol {name} has the wrong sign at the point")
            verified.add(c.index(name))


def check(cert, component, at):
    """Raises WitnessError unless component `component` (from 1) of the certificate's
    sides differs at the point; returns a description of the enclosure."""
    pairs = cert.claim_pairs
    series = cert.trace.refuted if cert.trace is not None else None
    if series is None and not 1 <= component <= len(pairs):
        raise WitnessError(f"witness of component {component}, of {len(pairs)}")
    iv.prec = PREC
    with mpmath.workprec(PREC):  # endpoints converted exactly
        return _check(cert, component, at)


def _check(cert, component, at):
    pairs = cert.claim_pairs
    pt = Point(cert)
    set_values(pt, at)
    adjoin_roots(pt)
    verified = {cert.index(n) for n in cert.posroots}
    bases = check_bases(pt, verified)
    check_periods(pt)
    check_signs(pt, verified)
    cert.witness_point = pt
    series = cert.trace.refuted if cert.trace is not None else None
    if series is not None:
        # a refuted order: the coefficient the srefute line names, computed by the checker
        d = series[3]
    else:
        a, b = pairs[component - 1]
        d = cert.add(cert.vals[a], cert.vals[b], -1)
    used, todo = set(), list(pt.uses(d))
    radicands = {i: rad for _, i, rad in cert.roots}
    while todo:
        i = todo.pop()
        if i in used:
            continue
        used.add(i)
        if i in radicands:
            todo.extend(j for m in radicands[i].monoms() for j, k in enumerate(m) if k)
    for name, i, rad in cert.roots:
        if i in used and i not in verified and rad != cert.ring.one:
            raise WitnessError(f"the branch of {name} at the point has no evidence")
    n, q = pt.poly(d.num), pt.poly(d.den)
    if n is None or q is None:
        raise WitnessError("a symbol of lhs - rhs has no value at the point")
    if not (n.excludes_zero() and q.excludes_zero()):
        raise WitnessError("lhs - rhs is not certified nonzero at the point")
    v = n * q.inv()
    what = f"component {component}: lhs - rhs" if series is None else \
        f"component {series[0]}: the coefficient of t^{series[1]}"
    return f"{what} = {mpmath.nstr(v.mid(), 12)} != 0 at the point ({bases} elliptic base(s) checked against mpmath)"


COMPARE = {">": lambda lo, hi: lo > 0, ">=": lambda lo, hi: lo >= 0,
           "<": lambda lo, hi: hi < 0, "<=": lambda lo, hi: hi <= 0}


def check_domain(cert, src):
    """The witness point satisfies the `where` conditions of the claim and of its
    domain, each evaluated at the point in interval arithmetic: `abs`, `min`, `max`,
    `re`, `+ - * / ^`, comparisons, `and`, `or` and `not` here, the rest from the
    claim's formulas in the certificate's symbols.  Returns a description; a condition
    that fails, or is not decided at the point, raises WitnessError; one the evaluator
    does not cover is named as not checked."""
    from .exprlang import Parser, Unsupported
    from .formula import claim_scope

    conds = list(src.get("claim.where") or [])
    dom = src.get("claim.domain")
    if dom:
        conds += list((src.get(f"domain.{dom}") or {}).get("where") or [])
    pt = getattr(cert, "witness_point", None)
    if not conds or pt is None:
        return "no domain condition" if not conds else "the domain conditions are not checked"
    ev, env = claim_scope(cert, src)
    unchecked = []
    iv.prec = PREC
    with mpmath.workprec(PREC):
        for text in conds:
            try:
                ok = _holds(ev, env, pt, Parser(text).whole())
            except Unsupported as e:
                unchecked.append(f"{text} ({e})")
                continue
            if not ok:
                raise WitnessError(f"the point is not shown to satisfy the domain's condition {text}")
    done = len(conds) - len(unchecked)
    note = f"{done} of {len(conds)} domain condition(s) hold at the point"
    return note + (f"; not checked: {'; '.join(unchecked)}" if unchecked else "")


def _holds(ev, env, pt, e):
    from .exprlang import Unsupported

    if e[0] == "un" and e[1] == "not":
        return not _holds(ev, env, pt, e[2])
    if e[0] == "bin" and e[1] in ("and", "or"):
        a, b = _holds(ev, env, pt, e[2]), _holds(ev, env, pt, e[3])
        return (a and b) if e[1] == "and" else (a or b)
    if e[0] == "bin" and e[1] in COMPARE:
        d = _num(ev, env, pt, e[2]) - _num(ev, env, pt, e[3])
        if 0 not in d.im:
            raise Unsupported("a comparison of values that are not real at the point")
        lo, hi = _lo(d.re), _hi(d.re)
        if COMPARE[e[1]](lo, hi):
            return True
        if COMPARE[{">": "<=", ">=": "<", "<": ">=", "<=": ">"}[e[1]]](lo, hi):
            return False
        raise Unsupported("a comparison not decided at the point (too close)")
    raise Unsupported("a condition that is no comparison")


def _num(ev, env, pt, e):
    from .exprlang import Unsupported

    if e[0] == "call" and e[1] in ("abs", "re") and len(e[2]) == 1:
        x = _num(ev, env, pt, e[2][0])
        if e[1] == "re":
            return Box(x.re)
        if 0 not in x.im:
            raise Unsupported("abs of a value that is not real at the point")
        lo, hi = _lo(x.re), _hi(x.re)
        if hi < 0:
            return Box(-x.re)
        return Box(x.re if lo >= 0 else iv.mpf([0, max(-lo, hi)]))
    if e[0] == "call" and e[1] in ("min", "max") and e[2]:
        xs = [_num(ev, env, pt, a) for a in e[2]]
        if any(0 not in x.im for x in xs):
            raise Unsupported(f"{e[1]} of values that are not real at the point")
        pick = min if e[1] == "min" else max
        return Box(iv.mpf([pick(_lo(x.re) for x in xs), pick(_hi(x.re) for x in xs)]))
    if e[0] == "un" and e[1] == "-":
        return -_num(ev, env, pt, e[2])
    if e[0] == "bin" and e[1] in ("+", "-", "*", "/"):
        a, b = _num(ev, env, pt, e[2]), _num(ev, env, pt, e[3])
        if e[1] == "/":
            if not b.excludes_zero():
                raise Unsupported("a division by a value not shown nonzero at the point")
            return a * b.inv()
        return a + b if e[1] == "+" else a - b if e[1] == "-" else a * b
    v = ev.eval(e, env)
    if isinstance(v, (tuple, bool)):
        raise Unsupported("a value that is no scalar")
    x = pt.frac(v)
    if x is None:
        raise Unsupported("a symbol without a value at the point")
    return x
