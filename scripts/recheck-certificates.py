#!/usr/bin/env python3
"""Rechecks eulertop's algebraic certificates with SymPy, independently of FLINT.

Usage: scripts/recheck-certificates.py PATH...   (files, or directories of *.cert / *.txt)

A certificate (written by the algebra layer, src/algebra/certificate.rs) declares the
symbols, the root relations r**2 = a, the elliptic base arguments and the derivation DAG.
A root with radicand 1 is a sign symbol: arithmetic modulo r**2 - 1 is arithmetic for
r = 1 and r = -1 at once, so a claim checked modulo it holds for both signs.
This script:
  * checks every base (c**2 = 1 - s**2, d**2 = 1 - k**2 s**2) and the quarter-period
    data (kp**2 = 1 - k**2 and the half-period values of DLMF 22.5.1 squared);
  * recomputes every node from its arguments with its own rational-function arithmetic
    modulo the relations, and compares with the stated normal form where one is given;
  * square roots: the stated root squared equals the radicand (the sign is an assumption
    of the proof and is only printed);
  * sn, cn, dn: recomputed from the base symbols with the addition theorems
    (DLMF 22.8.1-3), the quarter-period shifts (DLMF 22.4.3) and the half-period values,
    and the argument is checked to be the stated combination of the bases;
  * derivatives: recomputed by the chain rule from the `dvar` table, whose entries are
    checked (roots: 2 r r' = a'; sn: s' = c d u' (+ the modulus terms); indeterminates);
  * finally every claim lhs = rhs.
Exit status 0 when every certificate checks, 1 otherwise.  Optional; not run by CI.
"""

import os
import re
import sys

import sympy as sp
from sympy.parsing.sympy_parser import parse_expr


class CheckError(Exception):
    pass


class Frac:
    """num/den, both polynomials in the certificate's symbols."""

    def __init__(self, num, den=sp.Integer(1)):
        self.num, self.den = num, den


class Cert:
    def __init__(self, name):
        self.name = name
        self.syms = {}
        self.kinds = {}
        self.roots = []  # (symbol, radicand), creation order
        self.named = {}
        self.bases = {}
        self.periods = {}
        self.dvar = {}
        self.vals = {}
        self.checked = 0

    # ---- parsing -----------------------------------------------------------------
    def expr(self, text):
        try:
            return parse_expr(text.strip(), local_dict=self.syms, evaluate=True)
        except Exception as e:  # noqa: BLE001 - any parse failure is a bad certificate
            raise CheckError(f"cannot parse '{text[:80]}': {e}")

    def frac(self, text):
        n, d = sp.fraction(sp.together(self.expr(text)))
        return self.norm(Frac(sp.expand(n), sp.expand(d)))

    def triple(self, text):
        inner = text.strip()
        if inner == "none":
            return None
        if not (inner.startswith("[") and inner.endswith("]")):
            raise CheckError(f"bad triple {text[:60]}")
        parts = split_top(inner[1:-1])
        return [self.frac(p) for p in parts]

    def symbol(self, name):
        if name not in self.syms:
            self.syms[name] = sp.Symbol(name)
        return self.syms[name]

    # ---- arithmetic modulo the relations ----------------------------------------
    def reduce(self, e):
        e = sp.expand(e)
        for r, a in reversed(self.roots):
            if not e.has(r):
                continue
            p = sp.Poly(e, r)
            out = sp.Integer(0)
            for (k,), c in p.terms():
                out += c * a ** (k // 2) * r ** (k % 2)
            e = sp.expand(out)
        return e

    def norm(self, f):
        n, d = self.reduce(f.num), self.reduce(f.den)
        if d == 0:
            raise CheckError("division by zero")
        g = sp.gcd(n, d)
        if g != 1 and g != 0:
            n, d = sp.expand(sp.cancel(n / g)), sp.expand(sp.cancel(d / g))
        return Frac(n, d)

    def add(self, a, b, sign=1):
        return self.norm(Frac(a.num * b.den + sign * b.num * a.den, a.den * b.den))

    def mul(self, a, b):
        return self.norm(Frac(a.num * b.num, a.den * b.den))

    def div(self, a, b):
        if self.reduce(b.num) == 0:
            raise CheckError("division by zero")
        return self.norm(Frac(a.num * b.den, a.den * b.num))

    def neg(self, a):
        return Frac(-a.num, a.den)

    def const(self, c):
        return Frac(sp.Integer(c))

    def eq(self, a, b):
        self.checked += 1
        return self.reduce(a.num * b.den - b.num * a.den) == 0

    def need(self, ok, what):
        if not ok:
            raise CheckError(what)

    # ---- declarations -------------------------------------------------------------
    def field(self, rest):
        parts = rest.split()
        self.symbol(parts[0])
        self.kinds[parts[0]] = parts[1] if len(parts) > 1 else "indeterminate"

    def root(self, rest):
        name, rad = rest.split("=", 1)
        r = self.symbol(name.strip())
        self.roots.append((r, sp.expand(self.expr(rad))))
        self.kinds[name.strip()] = "root"

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
             "z": self.symbol(v["z"]) if "z" in v else None}
        one, s = self.const(1), b["s"]
        k2 = self.mul(b["k"], b["k"])
        self.need(self.eq(self.mul(b["c"], b["c"]), self.add(one, self.mul(s, s), -1)), f"{head}: c**2 != 1 - s**2")
        self.need(self.eq(self.mul(b["d"], b["d"]), self.add(one, self.mul(k2, self.mul(s, s)), -1)),
                  f"{head}: d**2 != 1 - k**2 s**2")
        self.bases[head] = b

    def period(self, rest):
        head, v = self.keyed(rest, ["k", "kp", "K", "Kp", "i", "halfK", "halfiKp"])
        table = head.split()[1]
        p = {"k": self.frac(v["k"]), "kp": None if v["kp"] == "none" else self.frac(v["kp"]),
             "K": None if v["K"] == "none" else self.symbol(v["K"]),
             "Kp": None if v["Kp"] == "none" else self.symbol(v["Kp"]),
             "i": None if v["i"] == "none" else self.symbol(v["i"]),
             "halfK": self.triple(v["halfK"]), "halfiKp": self.triple(v["halfiKp"])}
        one, k = self.const(1), p["k"]
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
        self.periods[table] = p

    # ---- elliptic functions -------------------------------------------------------
    def tadd(self, a, b, k2):
        s1, c1, d1 = a
        s2, c2, d2 = b
        one = self.const(1)
        s1s2 = self.mul(s1, s2)
        den = self.add(one, self.mul(k2, self.mul(s1s2, s1s2)), -1)
        sn = self.add(self.mul(s1, self.mul(c2, d2)), self.mul(s2, self.mul(c1, d1)))
        cn = self.add(self.mul(c1, c2), self.mul(s1s2, self.mul(d1, d2)), -1)
        dn = self.add(self.mul(d1, d2), self.mul(k2, self.mul(s1s2, self.mul(c1, c2))), -1)
        return [self.div(sn, den), self.div(cn, den), self.div(dn, den)]

    def elliptic(self, f, argv, table, combo, hk, hkp):
        one, zero = self.const(1), self.const(0)
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
            for _ in range((hk // 2) % 4):
                s, c, d = trip
                trip = [self.div(c, d), self.neg(self.div(self.mul(p["kp"], s), d)), self.div(p["kp"], d)]
            if hkp % 2:
                trip = self.tadd(trip, p["halfiKp"], k2)
            for _ in range((hkp // 2) % 4):
                s, c, d = trip
                i = Frac(p["i"])
                ks = self.mul(k, s)
                trip = [self.div(one, ks), self.neg(self.div(self.mul(i, d), ks)), self.neg(self.div(self.mul(i, c), s))]
            half = sp.Rational(1, 2)
            if hk:
                arg = self.add(arg, Frac(half * hk * p["K"]))
            if hkp:
                arg = self.add(arg, Frac(half * hkp * p["i"] * p["Kp"]))
        self.need(self.eq(arg, argv), "argument is not the stated combination of the bases")
        return trip[["sn", "cn", "dn"].index(f)]

    # ---- derivatives --------------------------------------------------------------
    def dpoly(self, e, x):
        out = Frac(sp.Integer(0))
        for v in sorted(e.free_symbols, key=lambda s: s.name):
            dv = self.dsym(v.name, x)
            if dv.num != 0:
                out = self.add(out, self.mul(Frac(sp.diff(e, v)), dv))
        return out

    def dfrac(self, f, x):
        dn, dd = self.dpoly(f.num, x), self.dpoly(f.den, x)
        top = self.add(self.mul(dn, Frac(f.den)), self.mul(Frac(f.num), dd), -1)
        return self.div(top, Frac(f.den * f.den))

    def dsym(self, v, x):
        if (x, v) in self.dvar:
            return self.dvar[(x, v)]
        kind = self.kinds.get(v)
        if kind == "indeterminate":
            return self.const(1 if v == x else 0)
        raise CheckError(f"no derivative of {v} with respect to {x}")

    def check_dvar(self, x, v, val):
        kind = self.kinds.get(v)
        one = self.const(1)
        if kind == "indeterminate":
            self.need(self.eq(val, self.const(1 if v == x else 0)), f"d{v}/d{x}")
        elif kind == "constant":
            self.need(self.eq(val, self.const(0)), f"d{v}/d{x} of a constant")
        elif kind == "root":
            r, a = next((r, a) for r, a in self.roots if r.name == v)
            self.need(self.eq(self.mul(self.const(2), self.mul(Frac(r), val)), self.dpoly(a, x)), f"2 {v} {v}' != a'")
        elif kind == "named":
            self.need(self.eq(val, self.dfrac(self.named[v], x)), f"d{v}/d{x} != derivative of its definition")
        elif kind in ("sn", "zeta"):
            b = next(b for b in self.bases.values() if (b["s_name"] == v if kind == "sn" else (b["z"] is not None and b["z"].name == v)))
            k, s, c, d, u = b["k"], b["s"], b["c"], b["d"], b["arg"]
            du, dk = self.dfrac(u, x), self.dfrac(k, x)
            cd = self.mul(c, d)
            k2 = self.mul(k, k)
            along = self.mul(cd, du) if kind == "sn" else self.mul(self.mul(k2, self.mul(c, c)), du)
            if dk.num != 0:
                self.need(b["z"] is not None, f"{v}: modulus varies but no Z symbol")
                z, kp2 = Frac(b["z"]), self.add(one, k2, -1)
                c2 = self.mul(c, c)
                if kind == "sn":
                    part = self.add(self.div(self.mul(self.mul(k, s), c2), kp2), self.div(self.mul(cd, z), self.mul(k, kp2)), -1)
                else:
                    t = self.add(self.mul(self.mul(k, s), cd), self.mul(self.mul(k, c2), z), -1)
                    part = self.add(self.div(t, kp2), self.mul(k, u))
                along = self.add(along, self.mul(part, dk))
            self.need(self.eq(val, along), f"d{v}/d{x} is not the derivative of sn/Z")
        elif kind in ("K", "Kp"):
            self.need(self.eq(val, self.const(0)), f"d{v}/d{x} must be 0")
        else:
            raise CheckError(f"cannot check the derivative of {v} ({kind})")

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
                return Frac(self.syms[t])
            return Frac(sp.Rational(t))
        if len(toks) == 3 and toks[1] in "+-*/^":
            a = v[toks[0]]
            if toks[1] == "^":
                e = int(toks[2])
                num, den = (a.num, a.den) if e >= 0 else (a.den, a.num)
                return self.norm(Frac(num ** abs(e), den ** abs(e)))
            b = v[toks[2]]
            return {"+": lambda: self.add(a, b), "-": lambda: self.add(a, b, -1),
                    "*": lambda: self.mul(a, b), "/": lambda: self.div(a, b)}[toks[1]]()
        if toks[0] == "-" and len(toks) == 2:
            return self.neg(v[toks[1]])
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

    def run(self, text):
        claims = 0
        for ln, line in enumerate(text.splitlines(), 1):
            line = line.split("  #", 1)[0].rstrip() if not line.startswith("#") else ""
            if not line:
                continue
            word, _, rest = line.partition(" ")
            try:
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
                elif word == "claim":
                    a, b = [s.strip() for s in rest.split("=")]
                    self.need(self.eq(self.vals[a], self.vals[b]), f"claim {a} = {b} fails")
                    claims += 1
                else:
                    raise CheckError(f"unknown statement '{word}'")
            except CheckError as e:
                raise CheckError(f"line {ln}: {e}")
        if claims == 0:
            raise CheckError("no claim")
        return claims


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


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    bad = 0
    n = 0
    for path in files(argv[1:]):
        n += 1
        cert = Cert(path)
        try:
            with open(path, encoding="utf-8") as fh:
                claims = cert.run(fh.read())
            print(f"OK    {path}: {claims} claim(s), {cert.checked} equalities checked")
        except (CheckError, KeyError) as e:
            bad += 1
            print(f"FAIL  {path}: {e}")
    print(f"{n - bad} of {n} certificates recheck")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
