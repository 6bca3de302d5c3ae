"""Evaluates a claim's lhs and rhs (or d(expr, wrt) and 0) from a certificate's symbols
and compares them with the sides of the derivation's `claim` lines."""

from .evaluate import Evaluator
from .exprlang import Parser, Unsupported


class FormulaMismatch(Exception):
    pass


def environment(cert, src):
    """The claim's sampled variables as the certificate's symbols: a scalar by its name,
    a vector M as (M1, M2, M3).  A variable the certificate does not declare as an
    indeterminate is left out (using it is then Unsupported)."""
    env = {}
    domain = next((v for k, v in src.items() if k.startswith("domain.")), {})
    for name, sampler in list(domain.get("vars", [])) + list(src.get("claim.vars", [])):
        if "cplx(" in sampler:
            continue  # a complex variable: not a real indeterminate of this evaluator
        comps = [f"{name}{j}" for j in (1, 2, 3)] if sampler.strip().startswith("vec(") else [name]
        if all(cert.kinds.get(c) == "indeterminate" or is_sign_symbol(cert, c) for c in comps):
            syms = [cert.frac(c) for c in comps]
            env[name] = syms[0] if len(syms) == 1 else ("vec", tuple(syms))
    return env


def sides(cert, src):
    """The components of (lhs, rhs) of the claim, evaluated here."""
    ev = Evaluator(cert, [v for k, v in sorted(src.items()) if k.startswith("define.")])
    env = environment(cert, src)
    ev.let(src.get("claim.let"), env)
    kind = src.get("claim.kind")
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


def check(cert, src):
    """'evaluated' when the derivation's claim lines are the claim's sides evaluated
    here, 'text' when the evaluator does not cover the claim (it is then bound by the
    text of its formulas only); FormulaMismatch with the first difference otherwise."""
    try:
        lhs, rhs = sides(cert, src)
    except Unsupported as e:
        return f"text ({e})"
    except Exception as e:  # noqa: BLE001 - whatever the evaluator cannot do binds by text only
        return f"text (not evaluated: {type(e).__name__} {e})"
    pairs = cert.claim_pairs
    if len(pairs) != len(lhs):
        raise FormulaMismatch(f"the claim has {len(lhs)} component(s), the derivation {len(pairs)} claim line(s)")
    for j, ((a, b), l, r) in enumerate(zip(pairs, lhs, rhs), 1):
        tried = [(a, b)] + [split_difference(cert, a, b)]
        if not any(cert.eq(cert.vals[x], l) and cert.eq(cert.vals[y], r) for x, y in tried):
            x, y = tried[-1]
            side = "left" if not cert.eq(cert.vals[x], l) else "right"
            raise FormulaMismatch(f"component {j}: the derivation's {side} side "
                                  f"({x if side == 'left' else y}) is not the catalogue's "
                                  f"{'lhs' if side == 'left' else 'rhs'} evaluated from the certificate's symbols")
    return "evaluated"


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
