"""Binds a certificate's parametrization of the domain to the catalogue.

A `sign` line is checked with the certificate's `param` and `image` lines: each
indeterminate is a rational function of parameters t > 0 (and mu != 0).  Such a sign
holds on the claim's domain only if the parametrized set contains the domain.  This
module rebuilds the parametrization from the catalogue's own definitions of the sampled
variables (the claim's domain table, then the claim's `vars`), with the rules of
identities/README.md, and requires every `image` and `param` line (and every `alt`
line, the box of the intervals) to be the one it implies:

    uniform(lo, hi), 0 <= lo, hi < 1   ->  t/(1 + t)
    uniform(lo, hi), 0 <= lo           ->  t
    uniform(lo, hi), hi <= 0           ->  -t
    uniform(lo, hi), otherwise         ->  mu (nonzero)
    uniform(lo, hi) in the box (alt)   ->  (lo + hi t)/(1 + t)

with t named t{j}_{var} for the j-th draw in the definition of var, and +, -, *, /,
integer powers and vec(...) of earlier variables and numbers.  A variable defined
otherwise has no image.  Every such set contains the draws, so a sign proved on it
holds on the domain (its `where` conditions only narrow the domain further).
"""

import sympy

from .exprlang import ExprError, Parser


class DomainMismatch(Exception):
    """The certificate's parametrization is not the one the catalogue implies."""


class Skip(Exception):
    """A definition that is not parametrized."""


def definitions(src):
    """The (name, definition) pairs of the sampled variables, from the source lines."""
    out = []
    domain = next((v for k, v in src.items() if k.startswith("domain.")), None)
    for table in (domain or {}, {"vars": src.get("claim.vars", [])}):
        for pair in table.get("vars", []):
            # [name, sampler] or [name, sampler, description]
            if isinstance(pair, list) and len(pair) in (2, 3):
                out.append((pair[0], pair[1]))
    return out


def expected(src, exact):
    """({indeterminate: sympy expression}, {parameter: kind}) the catalogue implies."""
    images, kinds, env = {}, {}, {}
    for name, text in definitions(src):
        try:
            tree = Parser(text).whole()
            draws = []
            v = value(tree, env, (name, draws, kinds, exact))
        except (Skip, ExprError, ZeroDivisionError):
            continue
        env[name] = v
        if isinstance(v, tuple):
            for j, x in enumerate(v):
                images[f"{name}{j + 1}"] = x
        else:
            images[name] = v
    return images, kinds


def value(e, env, ctx):
    tag = e[0]
    if tag == "num":
        return sympy.Rational(e[1].numerator, e[1].denominator)
    if tag == "var":
        if e[1] not in env:
            raise Skip()
        return env[e[1]]
    if tag == "un" and e[1] == "-":
        return -scalar(value(e[2], env, ctx))
    if tag == "bin" and e[1] in "+-*/^":
        a, b = scalar(value(e[2], env, ctx)), scalar(value(e[3], env, ctx))
        if e[1] == "^":
            if not (b.is_Integer and abs(int(b)) <= 64):
                raise Skip()
            return a ** int(b)
        if e[1] == "/" and b == 0:
            raise Skip()
        return {"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: a / b}[e[1]]()
    if tag == "call" and e[1] == "vec" and len(e[2]) == 3:
        return tuple(scalar(value(x, env, ctx)) for x in e[2])
    if tag == "call" and e[1] == "uniform" and len(e[2]) == 2:
        lo, hi = (scalar(value(x, env, ctx)) for x in e[2])
        if not (lo.is_Rational and hi.is_Rational):
            raise Skip()
        return draw(lo, hi, ctx)
    raise Skip()


def scalar(v):
    if isinstance(v, tuple):
        raise Skip()
    return v


def draw(lo, hi, ctx):
    var, draws, kinds, exact = ctx
    name = f"t{len(draws) + 1}_{var}"
    draws.append(name)
    t = sympy.Symbol(name)
    if exact:
        kinds[name] = "positive"
        return (lo + hi * t) / (1 + t)
    if lo >= 0 and hi < 1:
        kinds[name] = "positive"
        return t / (1 + t)
    if lo >= 0:
        kinds[name] = "positive"
        return t
    if hi <= 0:
        kinds[name] = "positive"
        return -t
    kinds[name] = "nonzero"
    return t


def check(cert, src):
    """Raises DomainMismatch unless every parametrization line of the certificate (its
    first parametrization and the `alt` one) is the catalogue's."""
    first = ([(n, k) for n, k in cert.params], cert.image_texts)
    alt_params = [tuple(m.split()) for s, m in cert.alt_lines if s == "param"]
    alt_images = {}
    for s, m in cert.alt_lines:
        if s == "image":
            n, _, v = m.partition("=")
            alt_images[n.strip()] = v.strip()
    for (params, imgs), exact in ((first, False), ((alt_params, alt_images), True)):
        want, kinds = expected(src, exact)
        which = "the box of the intervals" if exact else "the domain's parametrization"
        for name, kind in params:
            if kinds.get(name) != kind:
                raise DomainMismatch(f"param {name} {kind} is not a parameter of {which} in the catalogue")
        for name, text in imgs.items():
            if name not in want:
                raise DomainMismatch(f"image of {name}: {which} in the catalogue gives it none")
            got = sympy.sympify(text, locals={n: sympy.Symbol(n) for n, _ in params})
            if sympy.cancel(got - want[name]) != 0:
                raise DomainMismatch(f"image {name} = {text[:60]} is not the catalogue's {want[name]} ({which})")
