#!/usr/bin/env python3
"""Times sn+cn+dn of a real argument through eulertop and its peers, each in its own
process, and writes the section `## Jacobi elliptic functions` of reports/performance.md.

Usage:  python3 scripts/bench_peers.py [--quick]
        python3 scripts/bench_peers.py --f64 [--quick]   (sn, cn, dn in f64 against GSL
        only, three separate interleaved runs with their medians and ratios; writes the
        section `## f64 against GSL, a new modulus per call`)
        python3 scripts/bench_peers.py --toolkit [--quick]   (the elliptic integrals:
        E(k), E(phi, k), Pi(n, phi, k) against GSL, theta_3 and E at 256 bits against
        mpmath; writes the section `## Elliptic integrals and theta functions`)

Needs: pip install mpmath python-flint scipy; GSL (apt libgsl-dev, installed by this
script when missing) and gcc for scripts/bench_gsl.c.

Batch (the same everywhere): u_i = -10 + 20 (i + 0.5)/n, and either one modulus
k = 0.8 for the whole batch ("fixed"; for eulertop and GSL also k = 0.95, where
eulertop takes the imaginary-argument series) or a new modulus for every call
k_i = 0.05 + 0.94 frac(i phi), phi the golden ratio ("fresh"); peers that take the
parameter get m = k^2.
  * eulertop   f64 and MPFR: examples/bench_batch.rs (in-process loop, one sncndn call
               per input; "slice": one sncndn_many call for the batch)
  * GSL        f64: gsl_sf_elljac_e through scripts/bench_gsl.c (one call per input)
  * scipy      f64: scipy.special.ellipj on the whole arrays (vectorised C, Cephes)
  * flint      1024 / 4096 bits (Arb through python-flint): per input one
               acb.modular_theta(u/(2K), tau) call and the theta quotients
               sn = t3(0)/t2(0) t1/t4, cn = t4(0)/t2(0) t2/t4, dn = t4(0)/t3(0) t3/t4;
               "fixed": K, K', tau and the theta-nulls once for the batch; "fresh": all
               of them per input (K and K' included)
  * mpmath     1024 bits: mpmath.ellipfun for 'sn', 'cn', 'dn' (three calls per input)
Timing: wall-clock time of a batch divided by n (Rust std::time::Instant, C
clock_gettime, Python time.perf_counter_ns).  The tools run in ROUNDS interleaved rounds
(each round starts every tool once in a new process, REPEATS batches per start), so slow
phases of the shared machine hit all of them alike; each figure is the median (and the
minimum) over all batches.
"""
import os, shutil, statistics, subprocess, sys, textwrap

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
QUICK = "--quick" in sys.argv
ROUNDS = 3 if QUICK else 5
REPEATS = 11 if QUICK else 21
N_F64 = 20000
N_MP = {1024: 200, 4096: 40}
N_MPMATH = 10
# --f64 and --toolkit (f64): short batches (0.2 ms), many of them.  On a loaded shared machine the
# scheduler takes the CPU away for 4 ms at a time: in one run with N_F64 it hit about
# half of eulertop's 2 ms fresh-modulus batches (batch times 100, 300, 500, 700 ns per
# evaluation), which moved their median to 221-284 ns.  With short batches an
# interrupted batch is an outlier that the median drops.
N_SHORT, REPEATS_SHORT = 2000, 201

PY_SCIPY = """
import time, numpy as np
from scipy.special import ellipj
n, reps, fresh = {n}, {reps}, {fresh}
i = np.arange(n)
u = -10 + 20 * (i + 0.5) / n
k = 0.05 + 0.94 * np.mod(i * 0.6180339887498949, 1.0) if fresh else np.full(n, 0.8)
m = k * k
ts = []
for _ in range(reps):
    t = time.perf_counter_ns(); s, c, d, ph = ellipj(u, m); ts.append((time.perf_counter_ns() - t) / n)
print(*ts)
"""

PY_MPMATH = """
import time, mpmath as mp
mp.mp.prec = {bits}
n, reps, fresh = {n}, {reps}, {fresh}
us = [mp.mpf(-10 + 20 * (i + 0.5) / n) for i in range(n)]
ks = [mp.mpf(0.05 + 0.94 * ((i * 0.6180339887498949) % 1.0)) if fresh else mp.mpf(0.8) for i in range(n)]
ts = []
for _ in range(reps):
    t = time.perf_counter_ns()
    for u, k in zip(us, ks):
        s, c, d = (mp.ellipfun(w, u, m=k * k) for w in ("sn", "cn", "dn"))
    ts.append((time.perf_counter_ns() - t) / n)
print(*ts)
"""

PY_FLINT = """
import time, flint, mpmath as mp
flint.ctx.prec = {bits}
n, reps, fresh = {n}, {reps}, {fresh}
us = [flint.acb(-10 + 20 * (i + 0.5) / n) for i in range(n)]
ks = [flint.arb(0.05 + 0.94 * ((i * 0.6180339887498949) % 1.0)) if fresh else flint.arb(0.8)
      for i in range(n)]

def setup(k):
    m = k * k
    K = flint.acb(m).elliptic_k(); Kp = flint.acb(1 - m).elliptic_k()
    tau = flint.acb(0, 1) * Kp / K
    t1, t2, t3, t4 = flint.acb.modular_theta(flint.acb(0), tau)
    return tau, t3 / t2, t4 / t2, t4 / t3, 1 / (2 * K)

fixed = setup(ks[0])
ts = []
for _ in range(reps):
    t = time.perf_counter_ns()
    for u, k in zip(us, ks):
        tau, a, b, c, inv2K = setup(k) if fresh else fixed
        q1, q2, q3, q4 = flint.acb.modular_theta(u * inv2K, tau)
        r = 1 / q4
        sn, cn, dn = a * q1 * r, b * q2 * r, c * q3 * r
    ts.append((time.perf_counter_ns() - t) / n)
# sanity: last value against mpmath
mp.mp.prec = 200
kl = 0.05 + 0.94 * (((n - 1) * 0.6180339887498949) % 1.0) if fresh else 0.8
ref = mp.ellipfun('sn', -10 + 20 * (n - 0.5) / n, m=mp.mpf(kl) ** 2)
assert abs(mp.mpf(sn.real.mid().str(50, radius=False)) - ref) < mp.mpf(10) ** -40, (sn, ref)
print(*ts)
"""


def py(code):
    out = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], check=True,
                         capture_output=True, text=True).stdout
    return tuple(float(x) for x in out.split())


def rust(bits, n, *flags, reps=None):
    exe = os.path.join(ROOT, "target", "release", "examples", "bench_batch")
    reps = reps or REPEATS
    out = subprocess.run([exe, str(bits), str(n), str(reps), "all", *flags], check=True,
                         capture_output=True, text=True).stdout
    return tuple(float(x) for x in out.split())


def gsl_harness():
    """Builds scripts/bench_gsl.c (installing libgsl-dev when missing); None if that fails."""
    exe = os.path.join(ROOT, "target", "bench_gsl")
    src = os.path.join(ROOT, "scripts", "bench_gsl.c")
    if not os.path.exists("/usr/include/gsl/gsl_sf_elljac.h") and shutil.which("apt-get"):
        subprocess.run(["apt-get", "update", "-qq"], check=False)
        subprocess.run(["apt-get", "install", "-y", "-qq", "libgsl-dev"], check=False)
    r = subprocess.run(["gcc", "-O2", "-o", exe, src, "-lgsl", "-lgslcblas", "-lm"])
    return exe if r.returncode == 0 else None


def gsl(exe, mode, *k, n=N_F64, reps=None):
    out = subprocess.run([exe, str(n), str(reps or REPEATS), mode, *k], check=True,
                         capture_output=True, text=True).stdout
    return tuple(float(x) for x in out.split())


def gsl_version():
    r = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libgsl-dev"],
                       capture_output=True, text=True)
    return r.stdout.split("+")[0] if r.returncode == 0 else "?"


PY_MPMATH_TOOLKIT = """
import time, mpmath as mp
mp.mp.prec = {bits}
n, reps = {n}, {reps}
us = [mp.mpf(-10 + 20 * (i + 0.5) / n) for i in range(n)]
ks = [mp.mpf(0.05 + 0.94 * ((i * 0.6180339887498949) % 1.0)) for i in range(n)]
f = {{"ellipeinc": lambda u, k: mp.ellipe(u / 4, k * k),
     "jtheta": lambda u, k: mp.jtheta(3, u, k / 2)}}["{fn}"]
ts = []
for _ in range(reps):
    t = time.perf_counter_ns()
    for u, k in zip(us, ks):
        f(u, k)
    ts.append((time.perf_counter_ns() - t) / n)
print(*ts)
"""

TOOLKIT = [("E(k)", "ellipe", "E"), ("E(φ, k)", "ellipeinc", "Einc"),
           ("Π(n, φ, k)", "ellippi", "Pi"), ("θ₃(z, q)", "jtheta", None)]


def toolkit():
    """E, E(phi), Pi against GSL in f64, E(phi) and theta_3 against mpmath at 256 bits,
    a new modulus for every call, interleaved rounds; writes the section."""
    subprocess.run(["cargo", "build", "--release", "--quiet", "--example", "bench_batch"],
                   cwd=ROOT, check=True)
    exe = gsl_harness()
    import mpmath
    jobs = []
    for label, name, g in TOOLKIT:
        # short batches, as for --f64 (a batch the scheduler interrupts is an outlier)
        jobs.append((("eulertop", label, "f64"),
                     lambda n=name: rust(53, N_SHORT, "fresh", "fn=" + n, reps=REPEATS_SHORT)))
        if exe and g:
            jobs.append((("GSL", label, "f64"),
                         lambda g=g: gsl(exe, "fresh", "0.8", g, n=N_SHORT, reps=REPEATS_SHORT)))
    for label, name in [("E(φ, k)", "ellipeinc"), ("θ₃(z, q)", "jtheta")]:
        jobs.append((("eulertop", label, "256 bits"), lambda n=name: rust(256, 200, "fresh", "fn=" + n)))
        jobs.append((("mpmath", label, "256 bits"),
                     lambda n=name: py(PY_MPMATH_TOOLKIT.format(bits=256, n=50, reps=3, fn=n))))
    samples = {}
    for _ in range(ROUNDS):
        for key, job in jobs:
            samples.setdefault(key, []).extend(job())
    r = {key: statistics.median(ts) for key, ts in samples.items()}
    lines = [
        "## Elliptic integrals and theta functions",
        "",
        "A new modulus for every call: u_i = -10 + 20(i+1/2)/n, k_i = 0.05 + 0.94·frac(i·φ),",
        "n = %d in f64 (%d batches per round: short, so that a batch the scheduler" % (N_SHORT, REPEATS_SHORT),
        "interrupts is an outlier the median drops; with n = %d GSL's E(k) read 445 ns" % N_F64,
        "on this loaded machine, with short batches 237 ns);",
        "E(k_i), E(u_i/4, k_i), Π(0.3, u_i/8, k_i) (GSL: `gsl_sf_ellint_Ecomp`, `_E`, `_P`",
        "with its characteristic −0.3) and θ₃(u_i, k_i/2).  Wall-clock time per evaluation,",
        "median over %d interleaved rounds; ratio: eulertop's time / the peer's.  GSL %s," % (ROUNDS, gsl_version()),
        "mpmath %s.  Reproduce: `python3 scripts/bench_peers.py --toolkit`." % mpmath.__version__,
        "",
        "| function | precision | eulertop | peer | ratio |",
        "|---|---|---|---|---|",
    ]
    for (tool, label, prec), t in r.items():
        if tool == "eulertop":
            for peer in ("GSL", "mpmath"):
                p = r.get((peer, label, prec))
                if p:
                    lines.append("| %s | %s | %s | %s %s | %.2f |" % (label, prec, fmt(t), peer, fmt(p), t / p))
            if not any((peer, label, prec) in r for peer in ("GSL", "mpmath")):
                lines.append("| %s | %s | %s | – | – |" % (label, prec, fmt(t)))
    lines.append("")
    replace_section("## Elliptic integrals and theta functions", "\n".join(lines))


def replace_section(head, section):
    """Replaces (or appends) the section `head` of reports/performance.md."""
    path = os.path.join(ROOT, "reports", "performance.md")
    old = open(path).read() if os.path.exists(path) else "# Performance\n\n"
    if head in old:
        pre, rest = old.split(head, 1)
        nxt = rest.find("\n## ")
        post = rest[nxt + 1:] if nxt >= 0 else ""
        new = pre + section + ("\n" + post if post else "")
    else:
        new = old.rstrip("\n") + "\n\n" + section
    open(path, "w").write(new)
    print(section)


F64_JOBS = [("eulertop", "fresh", ("fresh",)), ("GSL", "fresh", ("fresh",)),
            ("eulertop", "fixed", ()), ("GSL", "fixed", ("fixed",)),
            ("eulertop", "fixed 0.95", ("k=0.95",)), ("GSL", "fixed 0.95", ("fixed", "0.95"))]


def f64_vs_gsl():
    """sn+cn+dn in f64, eulertop against GSL on the same batch: RUNS separate runs, each
    ROUNDS rounds of the six jobs interleaved (eulertop and GSL alternating); per run the
    median over its batches of each job and the ratios eulertop / GSL; writes the section
    `## f64 against GSL, a new modulus per call`."""
    subprocess.run(["cargo", "build", "--release", "--quiet", "--example", "bench_batch"],
                   cwd=ROOT, check=True)
    exe = gsl_harness()
    if not exe:
        raise SystemExit("GSL harness did not build")
    runs = []
    for _ in range(3):
        samples = {}
        for _ in range(ROUNDS):
            for tool, mode, flags in F64_JOBS:
                if tool == "GSL":
                    ts = gsl(exe, *flags, n=N_SHORT, reps=REPEATS_SHORT)
                else:
                    ts = rust(53, N_SHORT, *flags, reps=REPEATS_SHORT)
                samples.setdefault((tool, mode), []).extend(ts)
        runs.append({key: statistics.median(ts) for key, ts in samples.items()})
    load = os.getloadavg()[0]
    lines = [
        "## f64 against GSL, a new modulus per call",
        "",
        "sn + cn + dn, the batch of the section above with n = %d (short batches of" % N_SHORT,
        "about 0.2 ms, so that a batch the scheduler interrupts is an outlier the median",
        "drops): *fresh* a new modulus k_i = 0.05 + 0.94·frac(i·φ) for every call, *fixed*",
        "k = 0.8 (or 0.95) for the batch.  Three runs; in each, %d rounds of the six jobs," % ROUNDS,
        "eulertop and GSL alternating, %d batches per job and round; per run the median" % REPEATS_SHORT,
        "time per evaluation and the ratio eulertop / GSL.  GSL %s `gsl_sf_elljac_e`" % gsl_version(),
        "(scripts/bench_gsl.c).  Load average at the end: %.2f on 2 cores.  Reproduce:" % load,
        "`python3 scripts/bench_peers.py --f64` (writes this section).",
        "",
        "| run | fresh: eulertop / GSL | ratio | fixed k = 0.8: eulertop / GSL | ratio | fixed k = 0.95: eulertop / GSL | ratio |",
        "|---|---|---|---|---|---|---|",
    ]
    for i, r in enumerate(runs + [None]):
        if r is None:
            r = {key: statistics.median(run[key] for run in runs) for key in runs[0]}
            label = "median of the runs"
        else:
            label = str(i + 1)
        cells = []
        for mode in ("fresh", "fixed", "fixed 0.95"):
            e, g = r[("eulertop", mode)], r[("GSL", mode)]
            cells += ["%s / %s" % (fmt(e), fmt(g)), "%.2f" % (e / g)]
        lines.append("| %s | %s |" % (label, " | ".join(cells)))
    lines.append("")
    replace_section("## f64 against GSL, a new modulus per call", "\n".join(lines))


def main():
    if "--toolkit" in sys.argv:
        return toolkit()
    if "--f64" in sys.argv:
        return f64_vs_gsl()
    subprocess.run(["cargo", "build", "--release", "--quiet", "--example", "bench_batch"],
                   cwd=ROOT, check=True)
    exe = gsl_harness()
    import flint, mpmath, scipy
    versions = {"gsl": gsl_version(), "scipy": scipy.__version__,
                "flint": flint.__version__, "mpmath": mpmath.__version__}
    fl = lambda fresh: "True" if fresh else "False"
    jobs = [
        ("eulertop f64 fixed", lambda: rust(53, N_F64)),
        ("eulertop f64 fixed 0.95", lambda: rust(53, N_F64, "k=0.95")),
        ("eulertop f64 fresh", lambda: rust(53, N_F64, "fresh")),
        ("eulertop f64 slice", lambda: rust(53, N_F64, "many")),
        ("scipy f64 fixed", lambda: py(PY_SCIPY.format(n=5 * N_F64, reps=REPEATS, fresh=False))),
        ("scipy f64 fresh", lambda: py(PY_SCIPY.format(n=5 * N_F64, reps=REPEATS, fresh=True))),
        ("mpmath 1024 fresh", lambda: py(PY_MPMATH.format(bits=1024, n=N_MPMATH, reps=3, fresh=True))),
    ]
    if exe:
        jobs += [("GSL f64 fixed", lambda: gsl(exe, "fixed")),
                 ("GSL f64 fixed 0.95", lambda: gsl(exe, "fixed", "0.95")),
                 ("GSL f64 fresh", lambda: gsl(exe, "fresh"))]
    for bits in (1024, 4096):
        n = N_MP[bits]
        for fresh in (False, True):
            mode = "fresh" if fresh else "fixed"
            flags = ("fresh",) if fresh else ()
            jobs.append(("eulertop %d %s" % (bits, mode), lambda b=bits, n=n, f=flags: rust(b, n, *f)))
            jobs.append(("flint %d %s" % (bits, mode),
                         lambda b=bits, n=n, f=fresh: py(PY_FLINT.format(bits=b, n=n, reps=REPEATS, fresh=fl(f)))))
    samples = {}
    for _ in range(ROUNDS):
        for name, job in jobs:
            samples.setdefault(name, []).extend(job())
    r = {name: (statistics.median(ts), min(ts)) for name, ts in samples.items()}
    load = os.getloadavg()[0]
    write(r, versions, load)


def fmt(t):
    return "%.0f ns" % t if t < 1e4 else "%.1f µs" % (t / 1e3)


def write(r, v, load):
    cmd = {
        "eulertop": "`target/release/examples/bench_batch BITS N REPEATS [fresh|many|k=K]`",
        "GSL": "`target/bench_gsl N REPEATS fixed|fresh [K]` (scripts/bench_gsl.c)",
        "scipy": "`scipy.special.ellipj(u, m)` on the arrays",
        "flint": "`acb.modular_theta(u/(2K), τ)` and theta quotients",
        "mpmath": "`mpmath.ellipfun` for sn, cn, dn",
    }
    peer = {"eulertop": "eulertop `sncndn`", "GSL": "GSL %s `gsl_sf_elljac_e`" % v["gsl"],
            "scipy": "scipy %s `ellipj` (vectorised)" % v["scipy"],
            "flint": "python-flint %s (Arb)" % v["flint"], "mpmath": "mpmath %s" % v["mpmath"]}
    lines = [
        "## Jacobi elliptic functions",
        "",
        "sn + cn + dn of a real argument, batch u_i = -10 + 20(i+1/2)/n, either one modulus",
        "k = 0.8 for the batch (*fixed*; also k = 0.95, where eulertop takes the",
        "imaginary-argument series) or a new modulus for every call,",
        "k_i = 0.05 + 0.94·frac(i·φ) (*fresh*; peers taking the parameter get m = k²).",
        "Wall-clock time per evaluation, median (minimum) over %d rounds × %d batches; each" % (ROUNDS, REPEATS),
        "tool in its own process, the tools interleaved round by round.  Reproduce:",
        "`python3 scripts/bench_peers.py` (writes this section).  Load average at the end",
        "of the run: %.2f on 2 cores (a shared machine: medians include slow phases, minima" % load,
        "show the unloaded machine).",
        "",
        "| implementation | precision | modulus | time per evaluation | command |",
        "|---|---|---|---|---|",
    ]
    order = [("eulertop f64 fixed", "eulertop", "f64", "fixed"),
             ("eulertop f64 fixed 0.95", "eulertop", "f64", "fixed, k = 0.95"),
             ("eulertop f64 fresh", "eulertop", "f64", "fresh"),
             ("eulertop f64 slice", "eulertop", "f64", "fixed, `sncndn_many`"),
             ("GSL f64 fixed", "GSL", "f64", "fixed"),
             ("GSL f64 fixed 0.95", "GSL", "f64", "fixed, k = 0.95"),
             ("GSL f64 fresh", "GSL", "f64", "fresh"),
             ("scipy f64 fixed", "scipy", "f64", "fixed"), ("scipy f64 fresh", "scipy", "f64", "fresh"),
             ("eulertop 1024 fixed", "eulertop", "1024 bits", "fixed"),
             ("eulertop 1024 fresh", "eulertop", "1024 bits", "fresh"),
             ("flint 1024 fixed", "flint", "1024 bits", "fixed"),
             ("flint 1024 fresh", "flint", "1024 bits", "fresh (K, K′ per call)"),
             ("mpmath 1024 fresh", "mpmath", "1024 bits", "fresh"),
             ("eulertop 4096 fixed", "eulertop", "4096 bits", "fixed"),
             ("eulertop 4096 fresh", "eulertop", "4096 bits", "fresh"),
             ("flint 4096 fixed", "flint", "4096 bits", "fixed"),
             ("flint 4096 fresh", "flint", "4096 bits", "fresh (K, K′ per call)")]
    for key, tool, prec, mode in order:
        if key in r:
            med, mn = r[key]
            lines.append("| %s | %s | %s | %s (%s) | %s |" % (peer[tool], prec, mode, fmt(med), fmt(mn), cmd[tool]))
    lines.append("")
    ratios = []
    for bits in (1024, 4096):
        a, b = r.get("eulertop %d fresh" % bits), r.get("flint %d fresh" % bits)
        if a and b:
            ratios.append("%d bits: %.2f× (median), %.2f× (minimum)" % (bits, b[0] / a[0], b[1] / a[1]))
    if ratios:
        lines += ["Fresh modulus, python-flint time / eulertop time: " + "; ".join(ratios) + ".", ""]
    replace_section("## Jacobi elliptic functions", "\n".join(lines))


if __name__ == "__main__":
    main()
