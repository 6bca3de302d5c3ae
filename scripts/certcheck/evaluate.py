"""Evaluates a claim's formulas from a certificate's symbols (module exprlang for the
language), with the certificate's own exact arithmetic.

A comparison in an `if` is decided only by a sign the certificate proves (a `sign tN`
line whose node has the compared value, up to its negative), by a rational constant, or
by the condition of the part of the domain the certificate is on (a `part` line: the
compared value is the condition times a factor of proved sign, or a value in a square
root whose parts' signs these decide, as for a `sign ... parts` line);
a square root only as a `sqrt` node of the certificate with that radicand (whose branch
has its own evidence).  Anything else raises Unsupported.
"""

from fractions import Fraction

from .exprlang import Unsupported, ExprError, bindings

VEC, MAT = "vec", "mat"
# the Jacobi functions pq = p/q in Glaisher's notation, n standing for 1
ELLIPTIC = {f"{p}{q}": (p, q) for p in "scdn" for q in "scdn" if p != q}
ELLIPTIC.update({"sn": ("s", "n"), "cn": ("c", "n"), "dn": ("d", "n")})


class Evaluator:
    def __init__(self, cert, defines):
        self.c = cert
        self.funcs = {}
        for text in defines:
            for name, params, tree in bindings(text):
                self.funcs[name] = (params or [], tree)

    # ---- values ----------------------------------------------------------------------
    def const(self, q):
        q = Fraction(q)
        r = self.c.ring
        return self.c.finish(r(q.numerator), r(q.denominator)) if q else self.c.zero

    def scalar(self, v):
        if isinstance(v, tuple) or isinstance(v, bool):
            raise ExprError("a scalar was expected")
        return v

    def kind(self, v):
        if isinstance(v, bool):
            return "bool"
        if isinstance(v, tuple):
            return v[0]
        return "real"

    def lift(self, f, *vs):
        """f applied componentwise to values of one shape."""
        kinds = {self.kind(v) for v in vs}
        if len(kinds) != 1 or "bool" in kinds:
            raise ExprError("operands of different types")
        k = kinds.pop()
        if k == "real":
            return f(*vs)
        if k == VEC:
            return (VEC, tuple(f(*xs) for xs in zip(*(v[1] for v in vs))))
        return (MAT, tuple(tuple(f(*xs) for xs in zip(*rows)) for rows in zip(*(v[1] for v in vs))))

    def components(self, v):
        k = self.kind(v)
        if k == "real":
            return [v]
        if k == VEC:
            return list(v[1])
        if k == MAT:
            return [x for row in v[1] for x in row]
        raise ExprError("a boolean has no components")

    def scale(self, s, v):
        return self.lift(lambda x: self.c.mul(s, x), v)

    # ---- products --------------------------------------------------------------------
    def times(self, a, b):
        ka, kb = self.kind(a), self.kind(b)
        if ka == "real":
            return self.scale(a, b)
        if kb == "real":
            return self.scale(b, a)
        if ka == MAT and kb == VEC:
            return (VEC, tuple(self.dot(row, b[1]) for row in a[1]))
        if ka == MAT and kb == MAT:
            cols = list(zip(*b[1]))
            return (MAT, tuple(tuple(self.dot(row, col) for col in cols) for row in a[1]))
        raise ExprError("vector * vector (use dot or cross)")

    def dot(self, u, w):
        acc = self.c.zero
        for x, y in zip(u, w):
            acc = self.c.add(acc, self.c.mul(x, y))
        return acc

    def cross(self, u, w):
        m, s = self.c.mul, self.c.add
        return (VEC, (s(m(u[1], w[2]), m(u[2], w[1]), -1), s(m(u[2], w[0]), m(u[0], w[2]), -1),
                      s(m(u[0], w[1]), m(u[1], w[0]), -1)))

    def skew(self, v):
        z, n = self.c.zero, self.c.neg
        a, b, c = v
        return (MAT, ((z, n(c), b), (c, z, n(a)), (n(b), a, z)))

    # ---- decisions -------------------------------------------------------------------
    def sign_of(self, v):
        """+1 or -1 when the certificate proves the sign of v, else Unsupported."""
        r = self.c.rational(v)
        if r is not None and r != 0:
            return 1 if r > 0 else -1
        for val, s in self.c.proved_signs:
            if self.c.eq(val, v):
                return s
            if self.c.eq(val, self.c.neg(v)):
                return -s
        if self.c.part_conditions:
            s = self.c.parts_sign(v)
            if s in (1, -1):
                return s
        raise Unsupported("a comparison whose sign the certificate does not prove")

    def compare(self, op, a, b):
        """a op b decided by a - b: a rational constant (zero included), else a proved
        (nonzero) sign."""
        d = self.c.add(self.scalar(a), self.scalar(b), -1)
        r = self.c.rational(d)
        s = (r > 0) - (r < 0) if r is not None else self.sign_of(d)
        return {"<": s < 0, ">": s > 0, "<=": s <= 0, ">=": s >= 0, "==": s == 0, "!=": s != 0}[op]

    def sqrt(self, x):
        for rad, val in self.c.sqrt_nodes:
            if self.c.eq(rad, x):
                return val
        r = self.c.rational(x)
        if r is not None and r >= 0:
            n, d = r.numerator, r.denominator
            rn, rd = _isqrt(n), _isqrt(d)
            if rn * rn == n and rd * rd == d:
                return self.const(Fraction(rn, rd))
        raise Unsupported("a square root that is no sqrt node of the certificate")

    # ---- evaluation ------------------------------------------------------------------
    def eval(self, e, env):
        tag = e[0]
        if tag == "num":
            return self.const(e[1])
        if tag == "var":
            if e[1] in env:
                v = env[e[1]]
                return v.force() if isinstance(v, Lazy) else v
            if e[1] == "I3":
                return self.builtin("I3", [])
            raise Unsupported(f"the name {e[1]}")
        if tag == "list":
            items = [self.eval(x, env) for x in e[1]]
            if all(self.kind(x) == "real" for x in items) and len(items) == 3:
                return (VEC, tuple(items))
            if all(self.kind(x) == VEC for x in items) and len(items) == 3:
                return (MAT, tuple(x[1] for x in items))
            raise Unsupported("a literal that is no vec3 or mat3")
        if tag == "index":
            return self.index(self.eval(e[1], env), [self.eval(i, env) for i in e[2]])
        if tag == "un":
            v = self.eval(e[2], env)
            if e[1] == "not":
                return not self.boolean(v)
            return self.lift(self.c.neg, v)
        if tag == "if":
            return self.eval(e[2] if self.boolean(self.eval(e[1], env)) else e[3], env)
        if tag == "bin":
            return self.binop(e[1], e[2], e[3], env)
        if tag == "call":
            return self.call(e[1], e[2], env)
        raise ExprError(f"unknown expression {tag}")

    def derivative(self, name, args, env):
        """d(expr, x), d(expr, v, j), grad(expr, v): the exact derivative with respect to
        a variable that is an indeterminate of the certificate (the `let` bindings are
        already functions of it)."""
        if len(args) not in (2, 3) or args[1][0] != "var" or (name == "grad" and len(args) != 2):
            raise ExprError(f"malformed {name}")
        x = args[1][1]
        if name == "grad":
            names = [f"{x}{j}" for j in (1, 2, 3)]
        elif len(args) == 3:
            j = self.c.rational(self.scalar(self.eval(args[2], env)))
            names = [f"{x}{int(j)}"] if j in (1, 2, 3) else []
        else:
            names = [x]
        sym = {n for n in names if self.c.kinds.get(n) == "indeterminate"}
        bx = env.get(x)
        bx = bx.force() if isinstance(bx, Lazy) else bx
        bound = self.components(bx) if bx is not None and not callable(bx) else []
        own = [self.c.frac(n) for n in names] if len(sym) == len(names) else []
        if names and len(bound) == 1 and len(names) == 1 and len(own) == 1:
            bound = [bound[0]]
        elif len(bound) == 3 and len(names) == 1 and own:
            bound = [bound[int(names[0][-1]) - 1]]
        if not names or not own or len(bound) != len(own) or \
                not all(self.c.eq(b, o) for b, o in zip(bound, own)):
            raise Unsupported(f"a derivative with respect to {x}, which is no indeterminate here")
        v = self.eval(args[0], env)
        if name == "grad":
            return (VEC, tuple(self.c.dfrac(self.scalar(v), n) for n in names))
        return self.lift(lambda f: self.c.dfrac(f, names[0]), v)

    def boolean(self, v):
        if not isinstance(v, bool):
            raise ExprError("a condition that is not a boolean")
        return v

    def index(self, v, idx):
        ints = []
        for i in idx:
            r = self.c.rational(self.scalar(i))
            if r is None or r.denominator != 1 or not 1 <= r <= 3:
                raise Unsupported("an index that is not 1, 2 or 3")
            ints.append(int(r) - 1)
        if self.kind(v) == VEC and len(ints) == 1:
            return v[1][ints[0]]
        if self.kind(v) == MAT and len(ints) == 2:
            return v[1][ints[0]][ints[1]]
        if self.kind(v) == MAT and len(ints) == 1:
            return (VEC, v[1][ints[0]])
        raise ExprError("indexing a value that has no such components")

    def binop(self, op, ea, eb, env):
        if op in ("and", "or"):
            a = self.boolean(self.eval(ea, env))
            if (op == "and" and not a) or (op == "or" and a):
                return a
            return self.boolean(self.eval(eb, env))
        a, b = self.eval(ea, env), self.eval(eb, env)
        if op in ("<", ">", "<=", ">=", "==", "!="):
            return self.compare(op, a, b)
        if op == "+":
            return self.lift(self.c.add, a, b)
        if op == "-":
            return self.lift(lambda x, y: self.c.add(x, y, -1), a, b)
        if op == "*":
            return self.times(a, b)
        if op == "/":
            return self.scale(self.c.inv(self.scalar(b)), a)
        if op == "^":
            r = self.c.rational(self.scalar(b))
            if r is None or r.denominator != 1:
                raise Unsupported("a power that is not an integer")
            return self.c.power(self.scalar(a), int(r))
        raise ExprError(f"unknown operator {op}")

    def call(self, name, args, env):
        if name in ("d", "grad"):
            return self.derivative(name, args, env)
        if name in self.funcs:
            params, body = self.funcs[name]
            if len(params) != len(args):
                raise ExprError(f"{name} takes {len(params)} arguments")
            vals = [self.eval(a, env) for a in args]
            return self.eval(body, dict(zip(params, vals)))
        if name in self.c.charts:
            return self.implicit(name, [self.eval(a, env) for a in args])
        if name in env and callable(env[name]):
            return env[name]([self.eval(a, env) for a in args])
        return self.builtin(name, [self.eval(a, env) for a in args])

    def builtin(self, name, v):
        c = self.c
        if name == "vec" and len(v) == 3:
            return (VEC, tuple(self.scalar(x) for x in v))
        if name == "dot":
            return self.dot(v[0][1], v[1][1])
        if name == "cross":
            return self.cross(v[0][1], v[1][1])
        if name in ("norm2", "msq"):
            return self.dot(v[0][1], v[0][1])
        if name in ("Omega", "OmegaM", "energy") and len(v) == 4:
            om = (VEC, tuple(c.div(m, d) for m, d in zip(v[0][1], v[1:])))
            if name == "Omega":
                return om
            return self.dot(v[0][1], om[1]) if name == "energy" else self.hat(om[1])
        if name in ELLIPTIC and len(v) == 2:
            return self.elliptic(name, self.scalar(v[0]), self.scalar(v[1]))
        if name == "inv" and self.kind(v[0]) == MAT:
            return self.inverse(v[0][1])
        if name == "det" and self.kind(v[0]) == MAT:
            return self.det(v[0][1])
        if name == "diag" and len(v) == 1 and self.kind(v[0]) == VEC:
            return self.builtin("diag", list(v[0][1]))
        if name == "unskew" and self.kind(v[0]) == MAT:
            m = v[0][1]
            return (VEC, (m[2][1], m[0][2], m[1][0]))
        if name == "hatM":
            return self.hat(v[0][1])
        if name == "skew":
            return self.skew(v[0][1])
        if name == "sqrt":
            return self.sqrt(self.scalar(v[0]))
        if name in ("ln", "am"):
            return self.call_symbol(name, [self.scalar(x) for x in v])
        if name == "inv" and self.kind(v[0]) == "real":
            return c.inv(v[0])
        if name == "I3":
            one, z = c.one, c.zero
            return (MAT, ((one, z, z), (z, one, z), (z, z, one)))
        if name == "transpose" and self.kind(v[0]) == MAT:
            return (MAT, tuple(zip(*v[0][1])))
        if name == "tr" and self.kind(v[0]) == MAT:
            return c.add(c.add(v[0][1][0][0], v[0][1][1][1]), v[0][1][2][2])
        if name == "diag" and len(v) == 3:
            z = c.zero
            return (MAT, ((v[0], z, z), (z, v[1], z), (z, z, v[2])))
        if name == "comm" and self.kind(v[0]) == MAT:
            return self.lift(lambda x, y: c.add(x, y, -1), self.times(v[0], v[1]), self.times(v[1], v[0]))
        if name == "Jdiag" and len(v) == 3:
            a, b, cc = v
            half = self.const(Fraction(1, 2))
            j = lambda x, y, w: c.mul(half, c.add(c.add(x, y), w, -1))  # noqa: E731
            return (VEC, (j(b, cc, a), j(cc, a, b), j(a, b, cc)))
        raise Unsupported(f"the function {name}")

    def elliptic(self, name, u, k):
        """sn, cn, dn of (u, k) as a node of the certificate with that function, argument
        and modulus (each recomputed there from the addition theorems), or of a base
        argument u at modulus k, as its `base` line states it (k up to its sign: the
        functions depend on k² only); the other twelve
        Jacobi functions as their quotients (DLMF 22.2)."""
        num, den = ELLIPTIC[name]
        out = []
        # sn, cn, dn depend on the modulus through k² only (DLMF 22.2)
        k2 = self.c.mul(k, k)
        same_k = lambda kk: kk is not None and self.c.eq(self.c.mul(kk, kk), k2)  # noqa: E731
        for f in (num, den):
            f = {"s": "sn", "c": "cn", "d": "dn"}.get(f, f)
            if f == "n":
                out.append(self.c.one)
                continue
            hit = next((val for g, arg, kk, val in self.c.elliptic_nodes
                        if g == f and self.c.eq(arg, u) and same_k(kk)), None)
            if hit is None:
                hit = self.of_bases(f, u, same_k)
            if hit is None:
                raise Unsupported(f"{f} of an argument that is no elliptic node of the certificate")
            out.append(hit)
        return self.c.div(out[0], out[1])

    def of_bases(self, f, u, same_k):
        """f (sn, cn or dn) at u = Σ n_b b (integers n_b) for base arguments b that are
        symbols of one table at the modulus: the checker's own addition formulae on the
        values the `base` lines state (those its elliptic nodes start from), or None."""
        if u.den != self.c.ring.one:
            return None
        combo, table = [], None
        for monom, coef in u.num.terms():
            used = [i for i, e in enumerate(monom) if e]
            if len(used) != 1 or monom[used[0]] != 1 or int(coef) != coef:
                return None
            name = str(self.c.ring.symbols[used[0]])
            base = next((h for h, b in self.c.bases.items()
                         if b["z"] is None and same_k(b["k"]) and self.c.eq(b["arg"], self.c.frac(name))), None)
            if base is None or (table is not None and base.split("_")[1] != table):
                return None
            table = base.split("_")[1]
            combo.append(f"{base}:{int(coef)}")
        if not combo:
            return None
        try:
            return self.c.elliptic(f, u, table, combo, 0, 0)
        except Exception:  # noqa: BLE001 - not the stated combination: not evaluated here
            return None

    def call_symbol(self, name, args):
        """ln x or am(u, k): the certificate's opaque symbol of that call (a `call` line,
        whose derivative the recheck checks), or am(u, 0) = u (DLMF 22.16.4)."""
        if name == "am" and len(args) == 2 and self.c.rational(args[1]) == 0:
            return args[0]
        for sym, (fn, argv) in getattr(self.c, "calls", {}).items():
            if fn == name and len(argv) == len(args) and all(self.c.eq(a, b) for a, b in zip(argv, args)):
                return self.c.frac(sym)
        raise Unsupported(f"{name} at arguments of no call line")

    def implicit(self, name, args):
        """An implicit map's value where the certificate's chart gives it: at arguments
        equal to the chart's, component by component."""
        comps = [self.components(a) for a in args]
        for argv, value in self.c.charts[name]:
            if [len(a) for a in argv] == [len(a) for a in comps] and all(
                    self.c.eq(x, y) for a, b in zip(argv, comps) for x, y in zip(a, b)):
                if len(value) == 1:
                    return value[0]
                if len(value) == 3:
                    return (VEC, tuple(value))
                if len(value) == 9:
                    return (MAT, tuple(tuple(value[3 * i:3 * i + 3]) for i in range(3)))
        raise Unsupported(f"{name} at arguments that are not its chart's")

    def det(self, m):
        c = self.c
        acc = c.zero
        for j in range(3):
            minor = c.add(c.mul(m[1][(j + 1) % 3], m[2][(j + 2) % 3]), c.mul(m[1][(j + 2) % 3], m[2][(j + 1) % 3]), -1)
            acc = c.add(acc, c.mul(m[0][j], minor))
        return acc

    def inverse(self, m):
        """The inverse of a 3x3 matrix: the adjugate over the determinant."""
        c = self.c
        d = c.inv(self.det(m))
        cof = [[c.add(c.mul(m[(i + 1) % 3][(j + 1) % 3], m[(i + 2) % 3][(j + 2) % 3]),
                      c.mul(m[(i + 1) % 3][(j + 2) % 3], m[(i + 2) % 3][(j + 1) % 3]), -1)
                for j in range(3)] for i in range(3)]
        return (MAT, tuple(tuple(c.mul(cof[j][i], d) for j in range(3)) for i in range(3)))

    def hat(self, m):
        """The paper's hat: [[0, M3, -M2], [-M3, 0, M1], [M2, -M1, 0]]."""
        z, n = self.c.zero, self.c.neg
        return (MAT, ((z, m[2], n(m[1])), (n(m[2]), z, m[0]), (m[1], n(m[0]), z)))

    def let(self, text, env, own=()):
        """Adds the `let` bindings to env (local functions as closures); a name of `own`
        is the certificate's symbol of that name."""
        for name, params, tree in bindings(text):
            if name in own:
                env[name] = self.c.frac(name)
            elif params is None:
                # evaluated where it is first used: a binding the sides do not use may
                # stay beyond this evaluator
                env[name] = Lazy(self, tree, env)
            else:
                glob = {k: f for k, f in env.items() if callable(f)}
                env[name] = (lambda p, t, g: lambda vals: self.eval(t, {**g, **dict(zip(p, vals))}))(params, tree, glob)


class Lazy:
    """A `let` binding not evaluated yet (in the environment of its line)."""

    def __init__(self, ev, tree, env):
        self.ev, self.tree, self.env, self.value = ev, tree, dict(env), None

    def force(self):
        if self.value is None:
            self.value = self.ev.eval(self.tree, self.env)
        return self.value


def _isqrt(n):
    import math
    return math.isqrt(n)
