"""Evaluates a claim's lhs and rhs (or d(expr, wrt) and 0) from a certificate's symbols
and compares them with the sides of the derivation's `claim` lines."""

import re

from .evaluate import Evaluator
from .exprlang import Parser, Unsupported, bindings


class FormulaMismatch(Exception):
    pass


def var_pairs(src):
    """(name, sampler) of the domain's and the claim's sampled variables (an entry may
    carry a third string, the variable's description)."""
    domain = next((v for k, v in src.items() if k.startswith("domain.")), {})
    return [(e[0], e[1]) for e in list(domain.get("vars", [])) + list(src.get("claim.vars", []))]


def environment(cert, src, charts=True):
    """The claim's sampled variables as the certificate's symbols: a scalar by its name,
    a vector M as (M1, M2, M3).  A variable the certificate does not declare as an
    indeterminate is left out (using it is then Unsupported)."""
    env = {}
    for name, sampler in var_pairs(src):
        if "cplx(" in sampler and not complex_free(cert, name):
            continue  # a complex variable where the derivation may use that it is real
        comps = [f"{name}{j}" for j in (1, 2, 3)] if sampler.strip().startswith("vec(") else [name]
        if all(cert.kinds.get(c) == "indeterminate" or is_sign_symbol(cert, c) for c in comps):
            syms = [cert.frac(c) for c in comps]
            env[name] = syms[0] if len(syms) == 1 else ("vec", tuple(syms))
    return chart_variables(cert, src, env) if charts else env


def complex_free(cert, name):
    """Does the derivation hold for complex values of the indeterminate `name`: has no
    check used that it is real (module recheck-certificates, `sym_real`: sn of a real
    argument, a root of a real radicand)?  It has no image in the domain's
    parametrization either (module domain: a complex variable is not parametrized), so
    no sign rests on it, and the derivation's identities are identities of rational
    functions, true for complex values: a claim over a complex variable may bind it."""
    return cert.kinds.get(name) == "indeterminate" and name not in cert.real_assumed \
        and name not in cert.images


def own_symbols(cert, src, env):
    """The `let` names the certificate declares as indeterminates of its own: the
    derivation proves its identity for every value of such a symbol, so it holds at the
    value the `let` line gives.  Where a check used that the symbol is real, its
    definition must be real by construction (real sampled variables and earlier such
    names, numbers, + - * /)."""
    real = {n for n, smp in var_pairs(src) if "cplx(" not in smp and "sign(" not in smp}
    own = set()
    texts = " ".join(str(src.get(f"claim.{k}") or "") for k in ("let", "lhs", "rhs", "expr"))
    if src.get("claim.kind") != "identity" or re.search(r"\b(d|grad)\(", texts):
        return own  # a derivative would differentiate the symbol as independent
    for name, params, tree in bindings(src.get("claim.let")):
        if params is not None or name in env or cert.kinds.get(name) != "indeterminate" or name in cert.images:
            continue
        if name not in cert.real_assumed or real_by_construction(tree, real):
            own.add(name)
            real.add(name)
    return own


def real_by_construction(tree, real):
    """Is the expression real by its form: numbers and real names under + - * /?"""
    tag = tree[0]
    if tag == "num":
        return True
    if tag == "var":
        return tree[1] in real
    if tag == "un":
        return tree[1] == "-" and real_by_construction(tree[2], real)
    if tag == "bin" and tree[1] in ("+", "-", "*", "/"):
        return real_by_construction(tree[2], real) and real_by_construction(tree[3], real)
    return False


def complex_bound(cert, src):
    """Has environment() bound a variable the catalogue samples as complex?"""
    return any("cplx(" in s and complex_free(cert, n) for n, s in var_pairs(src))


def interleave_zero(cert, comps):
    """Each component followed by 0 (its imaginary part in the derivation)."""
    return [x for c in comps for x in (c, cert.zero)]


def chart_variables(cert, src, env):
    """The claim's variables at which it calls an implicit map of the certificate's one
    chart of that map, bound to the chart's arguments: the change of variables the proof
    makes (the chart itself is checked against the map's equations)."""
    text = "\n".join(str(src.get(f"claim.{k}") or "") for k in ("let", "lhs", "rhs", "expr"))
    for name, entries in cert.charts.items():
        m = re.search(rf"\b{re.escape(name)}\(([^()]*)\)", text)
        if m is None or len(entries) != 1:
            continue
        params = [p.strip() for p in m.group(1).split(",")]
        argv = entries[0][0]
        if len(params) == len(argv) and all(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", p) for p in params):
            for p, a in zip(params, argv):
                env[p] = a[0] if len(a) == 1 else ("vec", tuple(a))
    return env


def coordinate_binding(cert, src):
    """Where the derivation takes a derivative of a chart parameter (a phase step), the
    claim's variables at which the claim calls an implicit map are bound to the chart's
    arguments (chart_variables): each one the chart replaces (bound to another value
    than its own symbol) needs a `coord` line with that value, which the recheck holds
    fixed (Cert.check_coordinates); and each coord line must be such a variable, so that
    the variables held fixed are the claim's."""
    if not getattr(cert, "param_dvars", None):
        return
    names = {n for n, _ in var_pairs(src)}
    bound = chart_variables(cert, src, {})
    for name in cert.coords:
        if name not in names or name not in bound:
            raise FormulaMismatch(f"coord {name}: not a variable of the claim at which it calls a map of "
                                  "the certificate's charts")
    for name, val in bound.items():
        if name not in names or isinstance(val, tuple):
            continue
        if cert.kinds.get(name) == "indeterminate" and cert.eq(val, cert.frac(name)):
            continue
        if name not in cert.coords:
            raise FormulaMismatch(f"the chart replaces the claim's variable {name}, whose derivative the "
                                  "derivation's chart parameter keeps fixed, and no coord line states it")
        if not cert.eq(cert.coords[name], val):
            raise FormulaMismatch(f"coord {name}: the value is not the chart's argument at {name}")


def claim_scope(cert, src):
    """(evaluator, environment) of the claim: its variables as the certificate's
    symbols and its `let` names bound, the definitions its formulas call."""
    ev = Evaluator(cert, [v for k, v in sorted(src.items()) if k.startswith("define.")])
    env = environment(cert, src)
    ev.let(src.get("claim.let"), env, own=own_symbols(cert, src, env))
    return ev, env


def sides(cert, src):
    """The components of (lhs, rhs) of the claim, evaluated here."""
    ev, env = claim_scope(cert, src)
    kind = src.get("claim.kind")
    if kind == "negation":
        # "lhs = rhs fails somewhere": the derivation is that of the inner identity
        inner = src.get("claim.inner")
        if not isinstance(inner, dict) or not {"kind", "lhs", "rhs"} <= set(inner) <= {"kind", "lhs", "rhs", "scale"} or inner["kind"] != "identity":
            raise Unsupported("a negation of other than an identity's lhs and rhs")
        src = dict(src, **{"claim.lhs": inner["lhs"], "claim.rhs": inner["rhs"]})
        kind = "identity"
    if kind == "identity":
        lhs = ev.eval(Parser(src["claim.lhs"]).whole(), env)
        rhs = ev.eval(Parser(src["claim.rhs"]).whole(), env)
        return ev.components(lhs), ev.components(rhs)
    if kind == "independence":
        wrt = src.get("claim.wrt")
        if cert.kinds.get(wrt) != "indeterminate":
            raise Unsupported(f"a derivative with respect to {wrt}")
        vals = ev.components(ev.eval(Parser(src["claim.expr"]).whole(), env))
        return [cert.dfrac(v, wrt) for v in vals], [cert.zero for _ in vals]
    raise Unsupported(f"a claim of kind {kind}")


def chart_checks(cert, catalogue):
    """Each chart of an implicit map, substituted into the map's equations as the
    catalogue states them (the claims whose `construction` names the map, where the map is
    called at bare variables): (verified, not reached) counts; FormulaMismatch when an
    equation fails."""
    done = skipped = 0
    for name, entries in cert.charts.items():
        claims = construction_claims(catalogue, name)
        for argv, _ in entries:
            for c in claims:
                try:
                    ok = chart_claim(cert, catalogue, name, argv, c)
                except Unsupported:
                    skipped += 1
                    continue
                except Exception:  # noqa: BLE001 - not evaluated here
                    skipped += 1
                    continue
                if not ok:
                    raise FormulaMismatch(f"the chart of {name} does not satisfy {c['id']}, its equation in the catalogue")
                done += 1
    return done, skipped


def construction_claims(catalogue, name):
    """The identities of the catalogue whose `construction` names the map: its equations."""
    return [c for _, c in catalogue.claims.values()
            if str(c.get("construction", "")).startswith(f"{name} ") and c.get("kind") == "identity"]


def map_parameters(name, claim, n):
    """The bare variables at which the claim calls the map `name` with n arguments;
    Unsupported when it calls it at expressions."""
    text = (claim.get("let") or "") + "\n" + claim["lhs"] + "\n" + claim["rhs"]
    m = re.search(rf"\b{re.escape(name)}\(([^()]*)\)", text)
    params = [p.strip() for p in m.group(1).split(",")] if m else []
    if m is None or len(params) != n or not all(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", p) for p in params):
        raise Unsupported(f"{claim['id']} calls {name} at expressions")
    return params


def chart_claim(cert, catalogue, name, argv, claim):
    """True when claim's lhs = rhs holds with the map's arguments set to the chart's."""
    params = map_parameters(name, claim, len(argv))
    domain = f"domain.{claim.get('domain')}"
    env = environment(cert, {domain: catalogue.tables.get(domain, {}), "claim.vars": claim.get("vars", [])},
                      charts=False)
    env.update({p: (a[0] if len(a) == 1 else ("vec", tuple(a))) for p, a in zip(params, argv)})
    ev = Evaluator(cert, [t for _, t in catalogue.defines.values()])
    ev.let(claim.get("let"), env)
    lhs = ev.components(ev.eval(Parser(claim["lhs"]).whole(), env))
    rhs = ev.components(ev.eval(Parser(claim["rhs"]).whole(), env))
    return len(lhs) == len(rhs) and all(cert.eq(x, y) for x, y in zip(lhs, rhs))


def peeled(expr):
    """The expression whose coefficients a proof of `expr = O(h^p)` examines, and the
    factor of the order: ||X||, ||X||_inf and |x| are O(h^p) exactly when every real
    component of X (or x) is, and sqrt(x) is O(h^p) exactly when x is O(h^(2p))."""
    tree, factor = Parser(expr).whole(), 1
    while tree[0] == "call" and len(tree[2]) == 1 and tree[1] in ("norm", "vnorm_inf", "abs", "sqrt"):
        if tree[1] == "sqrt":
            factor *= 2
        tree = tree[2][0]
    return tree, factor


def series_binding(cert, src, catalogue=None):
    """An asymptotic claim `expr = O(var^order)` proved by power series: the series line
    names the claim's variable and order, and the sclaim lines claim, for components
    1..n of the examined value, every coefficient of t^e with e < order * factor * step
    (h = t^step; factor from peeled) to be 0.  The components' series are bound by
    the text of the formulas (this evaluator does not compute power series)."""
    import math
    from fractions import Fraction
    tr = cert.trace
    if tr is None or tr.header is None:
        raise FormulaMismatch("an asymptotic claim whose certificate has no series line")
    hd = tr.header
    if hd["var"] != src.get("claim.var"):
        raise FormulaMismatch(f"the series variable {hd['var']} is not the claim's {src.get('claim.var')}")
    order = Fraction(str(src.get("claim.order")))
    if hd["order"] != order:
        raise FormulaMismatch(f"the series line's order {hd['order']} is not the claim's {order}")
    _, factor = peeled(src["claim.expr"])
    below = math.ceil(order * factor * hd["step"])
    if tr.refuted is not None:
        return refuted_series_binding(cert, src, below)
    comps = sorted(j for j, _, _ in tr.claims)
    if comps != list(range(1, len(comps) + 1)) or not comps:
        raise FormulaMismatch(f"the sclaim lines name components {comps}, not 1..n once each")
    for j, b, name in tr.claims:
        if b != below:
            raise FormulaMismatch(f"sclaim {name}: coefficients below t^{b} claimed 0, where O({hd['var']}^{order}) "
                                  f"needs those below t^{below}")
    if catalogue is not None and tr.charts:
        from . import series_eval

        def env_of(c):
            domain = f"domain.{c.get('domain')}"
            return environment(cert, {domain: catalogue.tables.get(domain, {}), "claim.vars": c.get("vars", [])},
                               charts=False)
        try:
            cert.chart_counts = series_eval.chart_residuals(tr, catalogue, env_of)
        except ValueError as e:
            raise FormulaMismatch(str(e))
    comps, text = evaluated_components(cert, src, "coefficients")
    if text:
        return text
    if len(comps) != len(tr.claims):
        raise FormulaMismatch(f"the formula has {len(comps)} component(s), the sclaim lines {len(tr.claims)}")
    z = cert.zero
    for j, b, name in tr.claims:
        mine, stated = comps[j - 1], tr.series[name]
        for e in range(min(mine.lo, stated.lo, 0), b):
            if not cert.eq(mine.coef(e, z), stated.coef(e, z)):
                raise FormulaMismatch(f"sclaim {name}: its coefficient of t^{e} is not the formula's, evaluated here")
        if mine.hi < b:
            raise FormulaMismatch(f"component {j}: evaluated here, the formula is known to O(t^{mine.hi}) only")
    return "evaluated"


def refuted_series_binding(cert, src, below):
    """A refuted order: the srefute line's coefficient of t^E lies below the claimed
    order (E < below), so where it is not 0 (the witness point) the claim fails; where
    the evaluator reaches the formula, the coefficient is the formula's, evaluated
    here."""
    tr = cert.trace
    j, e, name, coef = tr.refuted
    if e >= below:
        raise FormulaMismatch(f"srefute {name}: the coefficient of t^{e} is not below the claimed order "
                              f"(t^{below}), so it cannot refute it")
    comps, text = evaluated_components(cert, src, "coefficient")
    if text:
        return text
    if not 1 <= j <= len(comps):
        raise FormulaMismatch(f"srefute {name}: component {j} of a formula with {len(comps)}")
    if comps[j - 1].hi <= e or not cert.eq(comps[j - 1].coef(e, cert.zero), coef):
        raise FormulaMismatch(f"srefute {name}: its coefficient of t^{e} is not the formula's, evaluated here")
    return "evaluated"


def existence_binding(cert, src, catalogue=None):
    """An existence claim proved for small h by the implicit function theorem: its
    solution's power series X (the ssolution line) solves the claim's equations,
    evaluated here (every known coefficient 0, so E(X(0), 0) = 0); the Jacobian
    dE/dx at (X(0), h = 0), the t coefficients of E(X(0) + t e_j, 0), has a determinant
    whose sign the certificate proves, so a solution x(h) = X + O(t^n) exists for small
    h; and the claim's set condition, evaluated on X, holds (each comparison decided by
    a coefficient below the precision).  Unlike the other kinds, an existence claim the
    evaluator does not reach is rejected: its formulas are its proof."""
    from . import series_eval
    tr = cert.trace
    if tr is None or tr.header is None or tr.solution is None:
        raise FormulaMismatch("an existence claim whose certificate has no series solution")
    unknowns = list(src.get("claim.unknowns") or [])
    if [u for u, _ in tr.solution] != unknowns:
        raise FormulaMismatch(f"the ssolution line names {[u for u, _ in tr.solution]}, not the claim's unknowns")
    try:
        ev = series_eval.SeriesEvaluator(tr, [v for k, v in sorted(src.items()) if k.startswith("define.")])
        base = series_eval.environment(tr, environment(cert, src, charts=False))
        eqs = [Parser(e).whole() for e in src.get("claim.equations") or []]

        def residuals(h, xs):
            env = dict(base)
            env["h"] = h
            ev.let(src.get("claim.let"), env)
            env.update(dict(zip(unknowns, xs)))
            return env, [ev.scalar(ev.eval(e, env)) for e in eqs]
        env, res = residuals(series_eval.small_variable(tr), [x for _, x in tr.solution])
        for j, r in enumerate(res, 1):
            if r.c or r.hi < 1:
                raise FormulaMismatch(f"equation {j} at the series solution: a known coefficient is not 0 "
                                      f"(or nothing is known)")
        x0 = [ev.c.const_of(x.coef(0, cert.zero)) for _, x in tr.solution]
        t = series_eval.small_variable(tr)
        cols = []
        for j in range(len(x0)):
            moved = [ev.c.add(x, t) if i == j else x for i, x in enumerate(x0)]
            cols.append([r.coef(1, cert.zero) for r in residuals(ev.c.zero, moved)[1]])
        jac = [[cols[j][i] for j in range(len(x0))] for i in range(len(x0))]
        if len(jac) not in (1, 3):
            raise Unsupported(f"a system of {len(jac)} unknowns")
        det = jac[0][0] if len(jac) == 1 else ev.base.det(jac)
        if ev.sign(det) == 0:
            raise FormulaMismatch("the Jacobian at h = 0 is singular")
        in_set = src.get("claim.in")
        if in_set and not ev.boolean(ev.eval(Parser(in_set).whole(), env)):
            raise FormulaMismatch("the set condition fails on the series solution")
    except Unsupported as e:
        raise FormulaMismatch(f"the existence proof is not evaluated here: {e}")
    return "evaluated"


def evaluated_components(cert, src, what):
    """(the components of series_components, None), or (None, the text binding) where
    the evaluator does not reach the formula on power series."""
    try:
        return series_components(cert, src), None
    except Unsupported as e:
        return None, f"text (order, variable and {what} bound; on power series: {e})"
    except Exception as e:  # noqa: BLE001 - whatever the evaluator cannot do binds by text only
        return None, f"text (order, variable and {what} bound; not evaluated: {type(e).__name__} {e})"


def series_components(cert, src):
    """The components of the peeled formula of an asymptotic claim, evaluated here on
    power series (module series_eval)."""
    from . import series_eval
    tr = cert.trace
    ev = series_eval.SeriesEvaluator(tr, [v for k, v in sorted(src.items()) if k.startswith("define.")])
    env = series_eval.environment(tr, environment(cert, src, charts=False))
    env[tr.header["var"]] = series_eval.small_variable(tr)
    ev.let(src.get("claim.let"), env)
    tree, _ = peeled(src["claim.expr"])
    return ev.components(ev.eval(tree, env))


def check(cert, src, catalogue=None):
    """'evaluated' when the derivation's claim lines are the claim's sides evaluated
    here, 'text' when the evaluator does not cover the claim (it is then bound by the
    text of its formulas only); FormulaMismatch with the first difference otherwise."""
    if src.get("claim.kind") == "existence":
        return existence_binding(cert, src, catalogue)
    inner = src.get("claim.inner")
    if src.get("claim.kind") == "negation" and isinstance(inner, dict) and inner.get("kind") == "asymptotic":
        # "f = O(h^p) fails": the certificate refutes the inner order
        if cert.trace is None or cert.trace.refuted is None:
            raise FormulaMismatch("a negated order whose certificate refutes no coefficient")
        src = dict(src, **{f"claim.{k}": inner.get(k) for k in ("kind", "expr", "var", "order")})
    if src.get("claim.kind") == "asymptotic" or cert.trace is not None:
        if src.get("claim.kind") != "asymptotic":
            raise FormulaMismatch("power series in the certificate of a claim that is not asymptotic")
        return series_binding(cert, src, catalogue)
    cert.chart_counts = chart_checks(cert, catalogue) if catalogue is not None and cert.charts else (0, 0)
    coordinate_binding(cert, src)
    try:
        lhs, rhs = sides(cert, src)
    except Unsupported as e:
        return f"text ({e})"
    except Exception as e:  # noqa: BLE001 - whatever the evaluator cannot do binds by text only
        return f"text (not evaluated: {type(e).__name__} {e})"
    pairs = cert.claim_pairs
    orders = [(lhs, rhs)]
    if complex_bound(cert, src) and len(pairs) == 2 * len(lhs) and not cert.charts:
        # a claim over a complex variable, derived as real and imaginary parts: each
        # real part's line is the claim's component (the variable a formal symbol), each
        # imaginary part's line states 0 = 0; the parts component by component or all
        # real parts first
        zero = [cert.zero] * len(lhs)
        orders = [(interleave_zero(cert, lhs), interleave_zero(cert, rhs)), (lhs + zero, rhs + zero)]
    # after the claim's components, a proof through a chart claims the map's equations at
    # the chart (each rechecked as an equality; the chart is verified against the catalogue)
    extra = len(pairs) - len(lhs)
    if extra > 0 and cert.charts:
        pairs = pairs[:len(lhs)]
    if len(pairs) != len(orders[0][0]):
        raise FormulaMismatch(f"the claim has {len(lhs)} component(s), the derivation {len(pairs)} claim line(s)")
    why = [mismatch(cert, pairs, l, r) for l, r in orders]
    if all(why):
        raise FormulaMismatch(why[0])
    return "evaluated"


def mismatch(cert, pairs, lhs, rhs):
    """The first claim line whose sides are not (lhs, rhs)'s component, or None."""
    for j, ((a, b), l, r) in enumerate(zip(pairs, lhs, rhs), 1):
        tried = [(a, b)] + [split_difference(cert, a, b)]
        if not any(cert.eq(cert.vals[x], l) and cert.eq(cert.vals[y], r) for x, y in tried):
            x, y = tried[-1]
            side = "left" if not cert.eq(cert.vals[x], l) else "right"
            return (f"component {j}: the derivation's {side} side "
                    f"({x if side == 'left' else y}) is not the catalogue's "
                    f"{'lhs' if side == 'left' else 'rhs'} evaluated from the certificate's symbols")
    return None


def split_difference(cert, a, b):
    """The sides of a claim line `tA = tB`: for `tA = tX - tY` claimed equal to 0, the
    derivation's lhs - rhs, the pair (tX, tY); else (tA, tB)."""
    op = cert.ops.get(a, [])
    r = cert.rational(cert.vals[b])
    if len(op) == 3 and op[1] == "-" and r == 0:
        return op[0], op[2]
    return a, b


def is_sign_symbol(cert, name):
    """A root with radicand 1: a variable drawn as a sign, both signs at once."""
    return any(r == name and a == cert.ring.one for r, _, a in cert.roots)
