#!/usr/bin/env python3
"""Generates the reference tables for the Jacobi elliptic function tests (run once; the
outputs are committed):

  tests/data/jacobi_ref_real.csv     sn, cn, dn of real u
  tests/data/jacobi_ref_complex.csv  sn, cn, dn of complex u (incl. points near the poles iK')
  tests/data/ellint_ref.csv          K(k), K'(k), F(phi, k)
  tests/data/jacobi_ref_twelve.csv   the twelve Jacobi functions (sn cn dn cd dc ns nc nd
                                     sc sd cs ds) for a modulus k >= 0 (also k = 1, k > 1)
                                     or a parameter m (also m < 0, m > 1)

Requirements: pip install mpmath python-flint.  Usage: python3 scripts/gen_jacobi_ref.py

Sources: sn, cn, dn from mpmath.ellipfun (theta-function quotients, independent of the
Landen/AGM code under test), with modulus k passed as parameter m = k^2; K, K', F from
python-flint (Arb: acb.elliptic_k / acb.elliptic_f), cross-checked against mpmath.
All inputs are doubles, written as their EXACT decimal expansion, so every precision on
the Rust side reads the same number.  Each row has a `digits` column: the number of
significant digits given (30 for most rows, 330 or 1250 for the subsets used by the
1024- and 4096-bit tests).  Values are computed at 200 / 1200 / 4400 bits for the three
tiers (complex: +200 bits) and each row is recomputed with 256 more bits; the script
stops unless both agree to the digits written (relative to max(1, |value|)).
The random arguments use a fixed seed, so re-running reproduces the files.
"""
import csv, random, sys, os
from decimal import Decimal
import mpmath as mp
import flint

KS = [0.0, 1e-10, 0.3, 0.5, 0.9, 0.99, 1 - 1e-6, 1 - 1e-12]
TIER_PREC = {30: 200, 330: 1200, 1250: 4400}  # digits -> working bits


def ex(x: float) -> str:
    """Exact decimal expansion of a double."""
    s = str(Decimal(x)).lower()
    return s


def fmt(v, digits):
    return mp.nstr(v, digits, strip_zeros=False, min_fixed=1, max_fixed=0) if v != 0 else "0"


def check(f, vals, d):
    """Recomputes with 256 more bits and insists on agreement to the digits written
    (relative to max(1, |value|))."""
    p = mp.mp.prec
    mp.mp.prec = p + 256
    again = f()
    mp.mp.prec = p
    for a, b in zip(vals, again):
        if abs(a - b) > mp.mpf(10) ** (-(d + 2)) * max(1, abs(b)):
            raise SystemExit("precision check failed: %s vs %s" % (a, b))


def kk(k):
    return mp.ellipk(mp.mpf(k) ** 2)


def kkp(k):
    return mp.ellipk(1 - mp.mpf(k) ** 2)


def real_rows():
    rows = []
    rng = random.Random(20261121)
    fr_c = {0.5, 3.99, 9999.7}
    fr_b = {0.1, 1.0, 7.3, 31.7, 1000.5}
    fracs = [0.0, 0.1, 0.5, 0.9, 0.999, 1.0, 1.5, 2.0, 3.0, 3.99, 4.0, -0.7, -2.3, 7.3,
             31.7, -63.9, 64.0, 100.3, 1000.5, -4321.1, 9999.7, 10000.0]
    for k in KS:
        mp.mp.prec = 200
        K = float(kk(k))
        us = [(float(f * K) if f != 0 else 0.0, f) for f in fracs]
        us.append((2.0 ** -30, None))
        us.append((1.0, None))
        for i in range(8):
            us.append((rng.uniform(-64 * K, 64 * K), "rnd%d" % i))
        for (u, f) in us:
            d = 1250 if f in fr_c else (330 if (f in fr_b or f in ("rnd0", "rnd1")) else 30)
            mp.mp.prec = TIER_PREC[d]
            m = mp.mpf(k) ** 2
            uu = mp.mpf(u)
            vals = [mp.ellipfun(w, uu, m=m) for w in ("sn", "cn", "dn")]
            check(lambda: [mp.ellipfun(w, mp.mpf(u), m=mp.mpf(k) ** 2) for w in ("sn", "cn", "dn")], vals, d)
            rows.append([ex(k), ex(u), d] + [fmt(v, d) for v in vals])
        print("real k=%r done" % k, file=sys.stderr)
    return rows


def complex_rows():
    rows = []
    grid = [(0.3, 0.2), (1.0, 0.5), (2.5, 0.9), (-1.7, 1.3), (5.2, -0.6), (0.7, 2.7),
            (-3.3, -1.9), (12.6, 4.4)]
    for k in [0.0, 1e-10, 0.3, 0.5, 0.9, 0.99, 1 - 1e-6]:
        mp.mp.prec = 200
        K = float(kk(k))
        Kp = float(kkp(k)) if k > 0 else 1.0
        pts = [(float(a * K), float(b * Kp), 30) for (a, b) in grid]
        pts[1] = (pts[1][0], pts[1][1], 1250)
        pts[2] = (pts[2][0], pts[2][1], 330)
        if k > 0:
            # near the poles 2jK + (2l+1) i K' and the zero of dn at K + iK'
            pts += [(0.0, Kp, 1250), (2.0 ** -20, Kp, 330), (2.0 ** -40, Kp + 2.0 ** -30, 30),
                    (float(2 * K), Kp - 2.0 ** -20, 330), (K, Kp, 30), (0.0, float(3 * Kp), 30),
                    (float(-2 * K) + 2.0 ** -25, float(-Kp), 30)]
        for (x, y, d) in pts:
            mp.mp.prec = TIER_PREC[d] + 200
            m = mp.mpf(k) ** 2
            z = mp.mpc(x, y)
            vals = [mp.ellipfun(w, z, m=m) for w in ("sn", "cn", "dn")]
            check(lambda: [mp.ellipfun(w, mp.mpc(x, y), m=mp.mpf(k) ** 2) for w in ("sn", "cn", "dn")], vals, d)
            out = []
            for v in vals:
                out += [fmt(v.real, d), fmt(v.imag, d)]
            rows.append([ex(k), ex(x), ex(y), d] + out)
        print("complex k=%r done" % k, file=sys.stderr)
    return rows


def ellint_rows():
    rows = []
    phis = [0.3, 1.0, 1.5707963267948966, 2.0, -3.5, 10.0, 100.7, -1234.5]
    for k in KS:
        for (name, phi, d) in [("K", None, 1250), ("Kp", None, 1250)] + \
                [("F", p, 330 if p in (1.0, -3.5, 100.7) else 30) for p in phis]:
            if name == "Kp" and k == 0.0:
                continue
            bits = TIER_PREC[d] + 64
            flint.ctx.prec = bits
            mp.mp.prec = bits
            m = flint.arb(ex(k)) ** 2
            if name == "K":
                v = flint.acb(m).elliptic_k()
                ref = kk(k)
            elif name == "Kp":
                v = flint.acb(1 - m).elliptic_k()
                ref = kkp(k)
            else:
                v = flint.acb.elliptic_f(flint.acb(ex(phi)), flint.acb(m))
                ref = mp.ellipf(mp.mpf(phi), mp.mpf(k) ** 2)
            vm = mp.mpf(v.real.mid().str(d + 20, radius=False))
            # independent cross-check (mpmath vs Arb)
            if abs(vm - ref) > mp.mpf(10) ** (-(d - 2)) * max(1, abs(ref)):
                raise SystemExit("mismatch %s k=%r phi=%r: %s vs %s" % (name, k, phi, vm, ref))
            rows.append([name, ex(k), ex(phi) if phi is not None else "", d, fmt(vm, d)])
        print("ellint k=%r done" % k, file=sys.stderr)
    return rows


TWELVE = ["sn", "cn", "dn", "cd", "dc", "ns", "nc", "nd", "sc", "sd", "cs", "ds"]


def twelve_rows():
    """All twelve functions at 200 bits (40 digits), rechecked at 456 bits; 'pole' where
    the denominator vanishes (u = 0 for ns, cs, ds)."""
    rows = []
    rng = random.Random(20261123)
    specs = [("k", k) for k in [0.3, 0.8, 1.0, 1.5, 3.0, 10.0]] + \
            [("m", m) for m in [-30.0, -2.0, -0.5, -1e-6, 0.0, 0.25, 0.64, 0.999, 1.0, 1.5, 9.0]]
    d = 40
    for (kind, val) in specs:
        us = [0.0, 0.37, -1.3, 2.9, 7.1, 25.3] + [rng.uniform(-20, 20) for _ in range(3)]
        for u in us:
            def compute():
                m = mp.mpf(val) ** 2 if kind == "k" else mp.mpf(val)
                out = []
                for f in TWELVE:
                    if u == 0.0 and f in ("ns", "cs", "ds"):
                        out.append(None)
                        continue
                    if u == 0.0 and f in ("sn", "sc", "sd"):
                        out.append(mp.mpf(0))  # odd functions (mpmath leaves ~1e-67 here)
                        continue
                    v = mp.ellipfun(f, mp.mpf(u), m=m)
                    if isinstance(v, mp.mpc):
                        if abs(v.imag) > mp.mpf(10) ** -(d + 10) * max(1, abs(v.real)):
                            raise SystemExit("complex value %s %r %r %s" % (f, val, u, v))
                        v = v.real
                    out.append(v)
                return out
            mp.mp.prec = 200
            vals = compute()
            mp.mp.prec = 456
            again = compute()
            mp.mp.prec = 200
            for a, b in zip(vals, again):
                if a is not None and abs(a - b) > mp.mpf(10) ** (-(d + 2)) * max(1, abs(b)):
                    raise SystemExit("precision check failed: %s vs %s" % (a, b))
            rows.append([kind, ex(val), ex(u), d] + ["pole" if v is None else fmt(v, d) for v in vals])
        print("twelve %s=%r done" % (kind, val), file=sys.stderr)
    return rows


def write(path, header, rows):
    with open(path, "w", newline="") as f:
        f.write("# generated by scripts/gen_jacobi_ref.py; modulus k (mpmath m = k^2)\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


if __name__ == "__main__":
    root = os.path.join(os.path.dirname(__file__), "..", "tests", "data")
    what = sys.argv[1:] or ["ellint", "real", "complex", "twelve"]
    if "ellint" in what:
        write(os.path.join(root, "ellint_ref.csv"), ["func", "k", "phi", "digits", "value"], ellint_rows())
    if "real" in what:
        write(os.path.join(root, "jacobi_ref_real.csv"), ["k", "u", "digits", "sn", "cn", "dn"], real_rows())
    if "complex" in what:
        write(os.path.join(root, "jacobi_ref_complex.csv"),
              ["k", "re_u", "im_u", "digits", "sn_re", "sn_im", "cn_re", "cn_im", "dn_re", "dn_im"],
              complex_rows())
    if "twelve" in what:
        write(os.path.join(root, "jacobi_ref_twelve.csv"), ["kind", "value", "u", "digits"] + TWELVE,
              twelve_rows())
