"""A claim's formulas evaluated here on power series: the evaluator of module evaluate,
run on truncated series in t (h = t**step) with coefficients in the certificate's field.

The claim's small variable is t**step, its other variables the certificate's symbols as
constant series; the arithmetic is module series' (the same precision rules).  sn, cn,
dn of a series argument at a constant modulus start from the certificate's values at
the argument's constant term (as module evaluate finds them) and integrate DLMF
22.13.1-3; a square root starts from the certificate's root of the leading coefficient
(a sqrt node, whose branch has its evidence); a comparison is decided, for every small
enough t > 0, by the sign of the leading coefficient of the difference as the
certificate proves it.  Anything else (implicit maps, derivatives) is Unsupported.
"""

from fractions import Fraction

from .evaluate import Evaluator
from .exprlang import Unsupported
from .series import S, SeriesError


class Field:
    """The certificate's interface that module evaluate uses, on series."""

    def __init__(self, trace):
        self.t, self.cert = trace, trace.cert
        n = trace.header["precision"]
        self.zero, self.one = S(n, n, []), self.const_of(self.cert.one)
        self.ring = self.cert.ring
        self.proved_signs, self.part_conditions, self.sqrt_nodes, self.elliptic_nodes = [], [], [], []
        self.charts, self.kinds, self.bases = {}, self.cert.kinds, self.cert.bases

    def const_of(self, x):
        return self.t.make(0, [x], self.t.header["precision"])

    def finish(self, n, d):
        return self.const_of(self.cert.finish(n, d))

    def frac(self, name):
        return self.const_of(self.cert.frac(name))

    def add(self, a, b, sign=1):
        return self.t.add(a, b, sign)

    def mul(self, a, b):
        return self.t.mul(a, b)

    def div(self, a, b):
        return self.t.div(a, b)

    def inv(self, a):
        return self.t.div(self.one, a)

    def neg(self, a):
        return self.t.sub(self.zero, a)

    def power(self, a, e):
        out = self.one
        for _ in range(abs(e)):
            out = self.mul(out, a)
        return out if e >= 0 else self.inv(out)

    def constant(self, v):
        """The value of a series that does not depend on t, else None."""
        n = self.t.header["precision"]
        if v.hi < n:
            return None
        if not v.c:
            return self.cert.zero
        return v.c[0] if v.lo == 0 and len(v.c) == 1 else None

    def rational(self, v):
        x = self.constant(v)
        return None if x is None else self.cert.rational(x)

    def eq(self, a, b):
        z = self.cert.zero
        if a.hi != b.hi:
            return False
        return all(self.cert.eq(a.coef(e, z), b.coef(e, z)) for e in range(min(a.lo, b.lo), a.hi))


class SeriesEvaluator(Evaluator):
    """Module evaluate's evaluator on power series (see the module doc)."""

    def __init__(self, trace, defines):
        super().__init__(Field(trace), defines)
        self.base = Evaluator(trace.cert, [])

    def elliptic(self, name, u, k):
        from .evaluate import ELLIPTIC
        t, c = self.c.t, self.c.cert
        try:
            t.constant_modulus(name, u, k)
        except SeriesError as e:
            raise Unsupported(str(e))
        u0, k0 = u.coef(0, c.zero), k.coef(0, c.zero)
        if t.is_zero(u0):
            start = (c.zero, c.one, c.one)
        else:
            start = tuple(self.base.elliptic(g, u0, k0) for g in ("sn", "cn", "dn"))
        vals = dict(zip("scd", t.jacobi_from(u, k0, start)))
        vals["n"] = self.c.one
        num, den = ELLIPTIC[name]
        return self.c.div(vals[num], vals[den])

    def sqrt(self, x):
        t = self.c.t
        if not x.c:
            h = x.hi // 2
            return S(h, h, [])
        root = self.base.sqrt(x.c[0])
        try:
            return t.sqrt_from(x, root)
        except SeriesError as e:
            raise Unsupported(str(e))

    def compare(self, op, a, b):
        d = self.c.add(self.scalar(a), self.scalar(b), -1)
        if not d.c:
            r = self.c.rational(d)
            if r is None:
                raise Unsupported("a comparison of values whose known coefficients vanish")
            s = 0
        else:
            s = self.sign(d.c[0])
        return {"<": s < 0, ">": s > 0, "<=": s <= 0, ">=": s >= 0, "==": s == 0, "!=": s != 0}[op]

    def derivative(self, name, args, env):
        raise Unsupported("a derivative of a power series")

    def implicit(self, name, args):
        """An implicit map's power series where the certificate's `schart` gives it: at
        arguments equal to the chart's, component by component."""
        comps = [self.components(a) for a in args]
        for argv, value in self.c.t.charts.get(name, []):
            if [len(a) for a in argv] == [len(a) for a in comps] and all(
                    self.c.eq(x, y) for a, b in zip(argv, comps) for x, y in zip(a, b)):
                if len(value) == 1:
                    return value[0]
                if len(value) == 3:
                    return ("vec", tuple(value))
                if len(value) == 9:
                    return ("mat", tuple(tuple(value[3 * i:3 * i + 3]) for i in range(3)))
        raise Unsupported(f"the implicit map {name} at arguments that are not its chart's")

    def call(self, name, args, env):
        if name in self.c.t.charts and name not in self.funcs:
            return self.implicit(name, [self.eval(a, env) for a in args])
        if name in ("abs", "norm", "min", "max") and name not in self.funcs and name not in env:
            vals = [self.eval(a, env) for a in args]
            if name == "abs" and len(vals) == 1:
                return self.absolute(self.scalar(vals[0]))
            if name == "norm" and len(vals) == 1:
                comps = self.components(vals[0])
                return self.sqrt(self.dot(comps, comps))
            if name in ("min", "max") and vals:
                best = self.scalar(vals[0])
                for v in vals[1:]:
                    if self.compare("<" if name == "min" else ">", self.scalar(v), best):
                        best = self.scalar(v)
                return best
        return super().call(name, args, env)

    def binop(self, op, ea, eb, env):
        """`min(xs) op b` and `max(xs) op b` compared argument by argument (min(xs) > b
        when every x > b, min(xs) < b when some x < b; max the other way), so that the
        arguments need not be ordered among themselves."""
        if op in ("<", ">", "<=", ">=") and ea[0] == "call" and ea[1] in ("min", "max") and \
                ea[1] not in self.funcs and ea[2]:
            b = self.eval(eb, env)
            tests = [self.compare(op, self.eval(x, env), b) for x in ea[2]]
            every = (ea[1] == "min") == (op in (">", ">="))
            return all(tests) if every else any(tests)
        return super().binop(op, ea, eb, env)

    def absolute(self, x):
        """|x| for every small enough t > 0: x or -x by the sign of its leading
        coefficient, as the certificate proves it; where that sign is not proved, only
        |x| = O(t^v) for the valuation v (no coefficient of it known)."""
        if not x.c:
            return S(x.hi, x.hi, [])  # |O(t^hi)| = O(t^hi)
        try:
            s = self.sign(x.c[0])
        except Unsupported:
            return S(x.lo, x.lo, [])  # only |x| = O(t^v) is known, v the valuation
        return x if s > 0 else self.c.neg(x)

    def sign(self, v):
        """The sign of a field value: by a sign line, a part's condition or a constant
        (module evaluate), else proved here from the domain's parametrization (the
        certificate's, checked against the catalogue by module domain)."""
        try:
            return self.base.sign_of(v)
        except Unsupported:
            s = self.domain_sign(v)
            if s is None:
                s = self.factor_sign(v)
            if s is None:
                raise
            return s

    def domain_sign(self, v):
        cert = self.c.cert
        if getattr(cert, "pring", None) is None:
            return None
        s = cert.frac_sign(v)
        if s is None and cert.alt_lines:
            s = cert.alt_sign(v)
        return s if s in (1, -1) else None

    def factor_sign(self, v):
        """The sign of a value whose numerator and denominator factor over Q into
        factors of proved sign: c * prod f_i^m_i has the sign of c times f_i's sign for
        odd m_i (an even power of a factor of proved sign is positive)."""
        out = 1
        for p in (v.num, v.den):
            if p.is_ground:
                out *= 1 if p.LC > 0 else -1
                continue
            c, factors = p.factor_list()
            out *= 1 if c > 0 else -1
            for f, m in factors:
                frac = type(v)(f, self.c.cert.ring.one)
                try:
                    fs = self.base.sign_of(frac)
                except Unsupported:
                    fs = self.domain_sign(frac)
                if fs not in (1, -1):
                    return None
                out *= fs ** m
        return out


def chart_residuals(trace, catalogue, environment_of):
    """(verified, not reached) counts of the certificate's series charts substituted
    into the catalogue's equations of each map (the claims whose `construction` names
    it, calling it at bare variables): every known coefficient of lhs - rhs must be 0;
    an equation that fails raises ValueError with its id."""
    from .exprlang import Parser
    from .formula import construction_claims, map_parameters
    done = skipped = 0
    for name, entries in trace.charts.items():
        claims = construction_claims(catalogue, name)
        for argv, _ in entries:
            for c in claims:
                try:
                    params = map_parameters(name, c, len(argv))
                    ev = SeriesEvaluator(trace, [t for _, t in catalogue.defines.values()])
                    env = environment(trace, environment_of(c))
                    env.update({p: (a[0] if len(a) == 1 else ("vec", tuple(a))) for p, a in zip(params, argv)})
                    ev.let(c.get("let"), env)
                    lhs = ev.components(ev.eval(Parser(c["lhs"]).whole(), env))
                    rhs = ev.components(ev.eval(Parser(c["rhs"]).whole(), env))
                except Exception:  # noqa: BLE001 - an equation this evaluator does not reach
                    skipped += 1
                    continue
                diffs = [trace.sub(x, y) for x, y in zip(lhs, rhs)]
                bad = [d for d in diffs if d.c]
                if bad or len(lhs) != len(rhs):
                    raise ValueError(f"the series chart of {name} does not satisfy {c['id']}, its equation "
                                     f"in the catalogue")
                if min(d.hi for d in diffs) < 1:
                    skipped += 1  # nothing of the residual is known
                    continue
                done += 1
    return done, skipped


def environment(trace, env):
    """The claim's environment of field values (module formula) as constant series."""
    field = Field(trace)
    out = {}
    for name, v in env.items():
        if isinstance(v, tuple):
            out[name] = (v[0], tuple(field.const_of(x) for x in v[1]))
        elif not callable(v):
            out[name] = field.const_of(v)
    return out


def small_variable(trace):
    """The claim's small variable, t**step."""
    t = trace
    var = t.make(1, [t.cert.one], t.header["precision"])
    return var if t.header["step"] == 1 else t.mul(var, var)


def order_bound(order, factor, step):
    """The first exponent of t whose coefficient O(h^order) leaves free."""
    import math
    return math.ceil(Fraction(order) * factor * step)
