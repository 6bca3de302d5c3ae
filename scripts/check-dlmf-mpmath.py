#!/usr/bin/env python3
"""Checks every claim of examples/dlmf-jacobi against mpmath, independently of eulertop:
each claim's `let` bindings, `lhs` and `rhs` are evaluated with mpmath at random points
of its domain (50 digits), and a statement must agree to 1e-25 (relative to
max(1, |lhs|, |rhs|)) while a control (`expect = "refuted"`) must differ by more than
1e-6 at some point.  Python never runs in `cargo test`; this is how the catalogue was
checked when it was written.

Requirements: pip install mpmath.  Usage: python3 scripts/check-dlmf-mpmath.py [DIR]

Sources: sn, cn, dn and their quotients from mpmath.ellipfun with the parameter m = k^2
(theta-function quotients, independent of the code under test); K, K' = K(sqrt(1-k^2)),
E, E(phi, k), F from mpmath.ellipk/ellipe/ellipf; the nome from mpmath.qfrom; theta
functions from mpmath.jtheta; am(u, k) as the integral of dn from 0 to u (DLMF 22.16.3);
d(expr, x) by mpmath.diff.
"""
import glob, os, random, re, sys, tomllib
import mpmath as mp

mp.mp.dps = 50


def jacobi(name):
    return lambda u, k: mp.ellipfun(name, u, m=k**2)


NS = {p + q: jacobi(p + q) for p in "scdn" for q in "scdn" if p != q}
NS.update(
    sqrt=mp.sqrt, sin=mp.sin, cos=mp.cos, tan=mp.tan, tanh=mp.tanh, cosh=mp.cosh,
    sinh=mp.sinh, ln=mp.log, exp=mp.exp, asin=mp.asin, atan=mp.atan, atan2=mp.atan2,
    pi=mp.pi, i=mp.mpc(0, 1),
    K=lambda k: mp.ellipk(k**2), Kp=lambda k: mp.ellipk(1 - k**2),
    ellipe=lambda k: mp.ellipe(k**2), ellipeinc=lambda phi, k: mp.ellipe(phi, k**2),
    F=lambda phi, k: mp.ellipf(phi, k**2), nome=lambda k: mp.qfrom(k=k),
    jtheta=lambda j, z, q: mp.jtheta(j, z, q),
    am=lambda u, k: mp.quad(lambda t: mp.ellipfun("dn", t, m=k**2), [0, u]),
    D=lambda f, x: mp.diff(f, x),
)


def to_python(e):
    """The claim language as Python: `^` is `**`, `d(expr, x)` a numerical derivative."""
    e = e.replace("^", "**")
    while (m := re.search(r"\bd\(", e)):
        i, depth, j = m.end(), 1, m.end()
        while depth:
            depth += {"(": 1, ")": -1}.get(e[j], 0)
            j += 1
        inner, depth, cut = e[i:j - 1], 0, None
        for t, ch in enumerate(inner):
            depth += {"(": 1, ")": -1}.get(ch, 0)
            if ch == "," and depth == 0:
                cut = t
        expr, var = inner[:cut], inner[cut + 1:].strip()
        e = e[:m.start()] + f"D(lambda {var}: {expr}, {var})" + e[j:]
    return e


def domains(files):
    out = {}
    for data in files:
        for name, d in data.get("domain", {}).items():
            out[name] = {}
            for var, spec in d["vars"]:
                a, b = re.match(r"uniform\(([^,]+),([^)]+)\)", spec).groups()
                out[name][var] = (float(a), float(b))
    return out


def worst(claim, dom, n=5, seed=1):
    rnd, w = random.Random(seed), 0
    lets = [l.split("=", 1) for l in claim.get("let", "").strip().splitlines() if l.strip()]
    for _ in range(n):
        env = dict(NS)
        for v, (a, b) in dom.items():
            env[v] = mp.mpf(rnd.uniform(a, b))
        for name, ex in lets:
            env[name.strip()] = eval(to_python(ex.strip()), env)
        l, r = eval(to_python(claim["lhs"]), env), eval(to_python(claim["rhs"]), env)
        w = max(w, abs(l - r) / max(1, abs(l), abs(r)))
    return w


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "examples", "dlmf-jacobi")
    files = [tomllib.load(open(f, "rb")) for f in sorted(glob.glob(os.path.join(root, "*.toml")))]
    doms, bad, n = domains(files), 0, 0
    for data in files:
        for c in data.get("claim", []):
            w = worst(c, doms[c["domain"]])
            control = c["expect"] == "refuted"
            ok = w > 1e-6 if control else w < 1e-25
            n += 1
            if not ok:
                bad += 1
                print(f"FAIL {c['id']}: {'agrees' if control else 'differs'} ({mp.nstr(w, 3)})")
    print(f"{n - bad} of {n} claims as expected against mpmath")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
