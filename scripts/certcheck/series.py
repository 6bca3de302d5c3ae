"""Power series in a certificate of an asymptotic claim, redone here from the leaves.

A proof of `f = O(h^p)` by exact power series (module src/algebra/series_trace.rs)
lists every operation that made its series; this module computes each one again with
its own truncated series arithmetic over the certificate's field (values reduced modulo
the root relations), taking nothing from the prover but the leaves:

  series h step S order P precision N   h = t**S; series are cut at O(t**N)
  sseries sI = var                      t
  sseries sI = const tK                 node tK's value (its derivation is rechecked as a node)
  sseries sI = add|sub|mul|div sA sB    p-adic precision as in the prover: (a*b).hi =
                                        min(a.lo + b.hi, b.lo + a.hi); a quotient keeps the
                                        smaller relative precision; div needs b's leading
                                        coefficient nonzero
  sseries sI = sqrt sA root tK          the square root, a.lo even; tK squared is a's
                                        leading coefficient and tK is a sqrt node (whose
                                        branch has its evidence) or a rational >= 0
  sseries sI = sn|cn|dn sU sK base tS tC tD
                                        sn, cn, dn of (u(t), k), k a constant: tS, tC, tD are
                                        the certificate's sn, cn, dn at (u(0), k) (0, 1, 1 at
                                        u(0) = 0), and the coefficients follow from integrating
                                        s' = c d u', c' = -s d u', d' = -k**2 s c u'
                                        (DLMF 22.13.1-3) from there
  sseries sI = deriv sA | cut sA H | bound sA
  sseries sI = moving sS sK             sS is sn, cn or dn at the constant term k0 of sK, and
                                        sK = k0 + O(t**v): the value at sK, known to O(t**v)
                                        (sn, cn, dn are analytic in (u, m) at real u and m:
                                        the prover takes it only where u(0) and k0 are real
                                        by construction, which is not rechecked here)
  schart NAME(sA, ...; sB; ...) value=sV,...
                                        the power series of the implicit map NAME at those
                                        arguments (components by ', ', arguments by '; '):
                                        substituted into the map's equations as the catalogue
                                        states them (module formula), and the map's value
                                        where a formula calls it there (module series_eval)
  ssolution x = sA; y = sB              an existence claim's solution for small h (module
                                        formula checks it against the claim)
  sclaim sI component J below E         every coefficient of t**e, e < E, of sI is 0 (and
                                        known: E <= its precision)
"""

from fractions import Fraction


class SeriesError(Exception):
    pass


class S:
    """sum c[i] t**(lo + i) + O(t**hi): lo the valuation (hi when every known
    coefficient is 0)."""

    __slots__ = ("lo", "hi", "c")

    def __init__(self, lo, hi, c):
        self.lo, self.hi, self.c = lo, hi, c

    def coef(self, e, zero):
        if e < self.lo or e >= self.hi or e - self.lo >= len(self.c):
            return zero
        return self.c[e - self.lo]


class Trace:
    """The series of one part of a certificate (see the module doc)."""

    def __init__(self, cert):
        self.cert, self.series, self.header, self.claims = cert, {}, None, []
        self.refuted = None  # (component, exponent, series name, coefficient) of `srefute`
        self.moduli = {}  # the constant modulus of each sn, cn, dn series
        self.charts = {}  # NAME -> [(arguments' components, value's components)] as series
        self.solution = None  # an existence claim's unknowns and their series

    # ---- the certificate's lines -----------------------------------------------------
    def header_line(self, rest):
        t = rest.split()
        ok = len(t) == 7 and t[1] == "step" and t[3] == "order" and t[5] == "precision"
        if not ok or self.header is not None:
            raise SeriesError(f"bad series line {rest[:60]}")
        self.header = {"var": t[0], "step": int(t[2]), "order": Fraction(t[4]), "precision": int(t[6])}
        if self.header["step"] not in (1, 2) or not 0 < self.header["precision"] <= 64:
            raise SeriesError(f"bad series line {rest[:60]}")

    def record(self, rest):
        if self.header is None:
            raise SeriesError("an sseries line before the series line")
        name, _, body = rest.partition(" = ")
        name, t = name.strip(), body.split()
        if name in self.series or not name.startswith("s") or not t:
            raise SeriesError(f"bad sseries line {rest[:60]}")
        self.pending_modulus = None
        self.series[name] = self.operation(t)
        if self.pending_modulus is not None:
            self.moduli[name] = self.pending_modulus

    def chart(self, rest):
        head, _, value = rest.rpartition(" value=")
        name, _, args = head.partition("(")
        if not (args.endswith(")") and value and name):
            raise SeriesError(f"malformed schart line {rest[:40]}")
        argv = [[self.get(x.strip()) for x in a.split(", ")] for a in args[:-1].split("; ")]
        self.charts.setdefault(name, []).append((argv, [self.get(x) for x in value.split(",")]))

    def solution_line(self, rest):
        if self.solution is not None:
            raise SeriesError("a second ssolution line")
        pairs = [p.split(" = ") for p in rest.split("; ")]
        if not all(len(p) == 2 for p in pairs):
            raise SeriesError(f"malformed ssolution line {rest[:40]}")
        self.solution = [(u.strip(), self.get(v.strip())) for u, v in pairs]
        return 1

    def claim(self, rest):
        t = rest.split()
        if len(t) != 5 or t[1] != "component" or t[3] != "below" or t[0] not in self.series:
            raise SeriesError(f"bad sclaim line {rest[:60]}")
        s, j, below = self.series[t[0]], int(t[2]), int(t[4])
        if below > s.hi:
            raise SeriesError(f"sclaim {t[0]}: the coefficient of t^{below - 1} is not known (O(t^{s.hi}))")
        for e in range(min(s.lo, 0), below):
            if not self.is_zero(s.coef(e, self.cert.zero)):
                raise SeriesError(f"sclaim {t[0]}: the coefficient of t^{e} is not 0")
        self.claims.append((j, below, t[0]))
        return 1

    def refute(self, rest):
        """`srefute SN component J coefficient E`: a refuted order; the coefficient of
        t^E of SN, computed here, must lie below the claimed order, and is the value
        the witness point must show nonzero (certcheck.witness)."""
        t = rest.split()
        if len(t) != 5 or t[1] != "component" or t[3] != "coefficient" or t[0] not in self.series:
            raise SeriesError(f"bad srefute line {rest[:60]}")
        if self.refuted is not None:
            raise SeriesError("a second srefute line")
        s, j, e = self.series[t[0]], int(t[2]), int(t[4])
        if e >= s.hi:
            raise SeriesError(f"srefute {t[0]}: the coefficient of t^{e} is not known (O(t^{s.hi}))")
        self.refuted = (j, e, t[0], s.coef(e, self.cert.zero))
        return 1

    # ---- arithmetic ------------------------------------------------------------------
    def is_zero(self, x):
        return self.cert.eq(x, self.cert.zero)

    def make(self, lo, c, hi):
        """Normalised: cut at the working precision, leading and trailing zeros dropped."""
        hi = min(hi, self.header["precision"])
        c = list(c[:max(hi - lo, 0)])
        while c and self.is_zero(c[0]):
            c.pop(0)
            lo += 1
        while c and self.is_zero(c[-1]):
            c.pop()  # trailing zeros are implicit
        return S(lo if c else hi, hi, c)

    def get(self, name):
        if name not in self.series:
            raise SeriesError(f"unknown series {name[:20]}")
        return self.series[name]

    def node(self, t):
        v = self.cert.vals.get(t)
        if v is None:
            raise SeriesError(f"unknown node {t[:20]}")
        return v

    def operation(self, t):
        c, z = self.cert, self.cert.zero
        n = self.header["precision"]
        op, args = t[0], t[1:]
        if op == "var" and not args:
            return self.make(1, [c.one], n)
        if op == "const" and len(args) == 1:
            return self.make(0, [self.node(args[0])], n)
        if op in ("add", "sub", "mul", "div") and len(args) == 2:
            a, b = self.get(args[0]), self.get(args[1])
            return getattr(self, op)(a, b)
        if op == "sqrt" and len(args) == 3 and args[1] == "root":
            return self.sqrt(self.get(args[0]), args[2])
        if op in ("sn", "cn", "dn") and len(args) == 6 and args[2] == "base":
            out = self.jacobi(op, self.get(args[0]), self.get(args[1]), args[3:])
            self.pending_modulus = self.get(args[1]).coef(0, z)
            return out
        if op == "moving" and len(args) == 2:
            return self.moving(args[0], self.get(args[1]))
        if op == "deriv" and len(args) == 1:
            a = self.get(args[0])
            cs = [c.mul(c.const(e), a.coef(e, z)) for e in range(a.lo, a.hi)]
            return self.make(a.lo - 1, cs, a.hi - 1)
        if op == "cut" and len(args) == 2:
            a = self.get(args[0])
            return self.make(a.lo, list(a.c), min(int(args[1]), a.hi))
        if op == "bound" and len(args) == 1:
            v = self.get(args[0]).lo
            return S(v, v, [])
        raise SeriesError(f"unknown series operation {' '.join(t)[:60]}")

    def moving(self, name, k):
        z = self.cert.zero
        if name not in self.moduli:
            raise SeriesError(f"moving {name}: not sn, cn or dn at a constant modulus")
        if k.lo < 0 or k.hi <= 0 or not self.cert.eq(k.coef(0, z), self.moduli[name]):
            raise SeriesError(f"moving {name}: the modulus's constant term is not {name}'s modulus")
        v = next((e for e in range(1, k.hi) if not self.is_zero(k.coef(e, z))), k.hi)
        a = self.get(name)
        return self.make(a.lo, list(a.c), min(v, a.hi))

    def add(self, a, b, sign=1):
        z = self.cert.zero
        lo, hi = min(a.lo, b.lo), min(a.hi, b.hi)
        return self.make(lo, [self.cert.add(a.coef(e, z), b.coef(e, z), sign) for e in range(lo, hi)], hi)

    def sub(self, a, b):
        return self.add(a, b, -1)

    def mul(self, a, b):
        c, z = self.cert, self.cert.zero
        lo, hi = a.lo + b.lo, min(a.lo + b.hi, b.lo + a.hi, self.header["precision"])
        out = []
        for e in range(lo, hi):
            acc = z
            for i in range(a.lo, a.lo + len(a.c)):
                if b.lo <= e - i < b.lo + len(b.c):
                    acc = c.add(acc, c.mul(a.coef(i, z), b.coef(e - i, z)))
            out.append(acc)
        return self.make(lo, out, hi)

    def div(self, a, b):
        c, z = self.cert, self.cert.zero
        if not b.c:
            raise SeriesError("division by a series whose known coefficients vanish")
        lo = a.lo - b.lo
        rel = min(a.hi - a.lo, b.hi - b.lo)
        n = min(lo + rel, self.header["precision"]) - lo
        inv = c.inv(b.c[0])
        q = []
        for i in range(max(n, 0)):
            rest = z
            for j in range(i):
                rest = c.add(rest, c.mul(q[j], b.coef(b.lo + i - j, z)))
            q.append(c.mul(c.add(a.coef(a.lo + i, z), rest, -1), inv))
        return self.make(lo, q, lo + n)

    def sqrt(self, a, root):
        c = self.cert
        if not a.c:
            h = a.hi // 2
            return S(h, h, [])
        s0 = self.node(root)
        ops = c.ops.get(root, [])
        r = c.rational(s0)
        if not ((ops and ops[0] == "sqrt") or (r is not None and r >= 0)):
            raise SeriesError(f"sqrt: the root {root} is no square-root node (no branch evidence)")
        return self.sqrt_from(a, s0, root)

    def sqrt_from(self, a, s0, root="the root"):
        """sqrt(a) whose leading coefficient's root is s0 (a branch with its evidence)."""
        c, z = self.cert, self.cert.zero
        if a.lo % 2:
            raise SeriesError("the square root of a series of odd valuation")
        if not c.eq(c.mul(s0, s0), a.c[0]):
            raise SeriesError(f"sqrt: {root} squared is not the leading coefficient")
        inv = c.inv(c.mul(c.const(2), s0))
        n = a.hi - a.lo
        s = [s0]
        for i in range(1, n):
            rest = z
            for j in range(1, i):
                rest = c.add(rest, c.mul(s[j], s[i - j]))
            s.append(c.mul(c.add(a.coef(a.lo + i, z), rest, -1), inv))
        lo = a.lo // 2
        return self.make(lo, s, lo + n)

    def jacobi(self, f, u, k, base):
        c, z = self.cert, self.cert.zero
        self.constant_modulus(f, u, k)
        u0, k0 = u.coef(0, z), k.coef(0, z)
        s0, c0, d0 = (self.node(t) for t in base)
        if self.is_zero(u0):
            ok = self.is_zero(s0) and c.eq(c0, c.one) and c.eq(d0, c.one)
        else:
            ok = all(c.eq(v, self.at(g, u0, k0)) for g, v in (("sn", s0), ("cn", c0), ("dn", d0)))
        if not ok:
            raise SeriesError(f"{f}: the base values are not sn, cn, dn at the constant term")
        return self.jacobi_from(u, k0, (s0, c0, d0))["sn cn dn".split().index(f)]

    def constant_modulus(self, f, u, k):
        if not (k.lo >= 0 and k.hi >= self.header["precision"] and len(k.c) <= 1 and (k.lo == 0 or not k.c)):
            raise SeriesError(f"{f} at a modulus that depends on t")
        if u.lo < 0 or u.hi <= 0:
            raise SeriesError(f"{f} of a series with a pole or no constant term")

    def jacobi_from(self, u, k0, base):
        """(sn, cn, dn)(u(t), k0) from their values at u(0), by integrating DLMF 22.13.1-3."""
        c, z = self.cert, self.cert.zero
        k2 = c.mul(k0, k0)
        du = [c.mul(c.const(j + 1), u.coef(j + 1, z)) for j in range(u.hi)]
        s, cc, d = [base[0]], [base[1]], [base[2]]
        conv = lambda x, y, m: _sum(c, [c.mul(x[i], y[m - i]) for i in range(m + 1)])  # noqa: E731
        cd, sd, sc = [], [], []
        for m in range(u.hi - 1):
            cd.append(conv(cc, d, m))
            sd.append(conv(s, d, m))
            sc.append(conv(s, cc, m))
            inv = c.inv(c.const(m + 1))
            s.append(c.mul(conv(cd, du, m), inv))
            cc.append(c.neg(c.mul(conv(sd, du, m), inv)))
            d.append(c.neg(c.mul(c.mul(conv(sc, du, m), k2), inv)))
        return tuple(self.make(0, v, u.hi) for v in (s, cc, d))

    def at(self, g, u0, k0):
        """The certificate's g(u0, k0) (an elliptic node or its bases), as the evaluator
        finds it."""
        from .evaluate import Evaluator
        return Evaluator(self.cert, []).elliptic(g, u0, k0)


def _sum(c, xs):
    acc = c.zero
    for x in xs:
        acc = c.add(acc, x)
    return acc
