#!/usr/bin/env python3
"""Times sn+cn+dn on one input batch through eulertop and its peers, each in its own
process, and writes the section `## Jacobi elliptic functions` of reports/performance.md.

Usage:  python3 scripts/bench_peers.py            (needs: pip install mpmath python-flint scipy)

Batch (same everywhere): u_i = -10 + 20 (i + 0.5)/n, modulus k = 0.8 (parameter m = 0.64).
  * eulertop  f64 / 1024 bits: examples/bench_batch.rs (in-process loop over the batch)
  * scipy     f64: scipy.special.ellipj on the whole array (vectorised C, Cephes)
  * mpmath    1024 bits: mpmath.ellipfun for 'sn', 'cn', 'dn' (three calls per input)
  * flint     1024 bits (Arb via python-flint): per input one acb.modular_theta(u/(2K), iK'/K)
              call and the theta quotients sn = θ3(0)/θ2(0)·θ1/θ4, cn = θ4(0)/θ2(0)·θ2/θ4,
              dn = θ4(0)/θ3(0)·θ3/θ4; K, K', τ and the theta-nulls are computed once per k
              outside the timed loop (as eulertop caches its Landen chain per k).
Timing: wall-clock time of the batch divided by n (Rust std::time::Instant, Python
time.perf_counter_ns).  The per-thread CPU clocks (/proc/thread-self/schedstat,
CLOCK_THREAD_CPUTIME_ID) advance in 4 ms scheduler ticks on this virtual machine, far too
coarse for batches of a few milliseconds (an earlier version of this script used them and
reported multiples of 40 ns).  The tools run in ROUNDS interleaved rounds (each round
starts every tool once, REPEATS batches per start), so slow phases of the shared machine
hit all of them alike; each figure is the median (and the minimum) over all batches.
"""
import os, statistics, subprocess, sys, textwrap

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
ROUNDS = 5
REPEATS = 21
N_F64 = 20000
N_MP = 200
N_MPMATH = 20

PY_SCIPY = """
import time, numpy as np, statistics
from scipy.special import ellipj
n, reps = {n}, {reps}
u = np.array([-10 + 20 * (i + 0.5) / n for i in range(n)])
ts = []
for _ in range(reps):
    t = time.perf_counter_ns(); s, c, d, ph = ellipj(u, 0.8 * 0.8); ts.append((time.perf_counter_ns() - t) / n)
print(*ts)
"""

PY_MPMATH = """
import time, mpmath as mp, statistics
mp.mp.prec = 1024
n, reps = {n}, {reps}
us = [mp.mpf(-10 + 20 * (i + 0.5) / n) for i in range(n)]
m = mp.mpf(0.8) ** 2
ts = []
for _ in range(reps):
    t = time.perf_counter_ns()
    for u in us:
        s, c, d = (mp.ellipfun(w, u, m=m) for w in ("sn", "cn", "dn"))
    ts.append((time.perf_counter_ns() - t) / n)
print(*ts)
"""

PY_FLINT = """
import time, flint, statistics, mpmath as mp
flint.ctx.prec = 1024
n, reps = {n}, {reps}
us = [flint.acb(-10 + 20 * (i + 0.5) / n) for i in range(n)]
m = flint.arb(0.8) ** 2
K = flint.acb(m).elliptic_k(); Kp = flint.acb(1 - m).elliptic_k()
tau = flint.acb(0, 1) * Kp / K
t1, t2, t3, t4 = flint.acb.modular_theta(flint.acb(0), tau)
a, b, c = t3 / t2, t4 / t2, t4 / t3
inv2K = 1 / (2 * K)
ts = []
for _ in range(reps):
    t = time.perf_counter_ns()
    for u in us:
        q1, q2, q3, q4 = flint.acb.modular_theta(u * inv2K, tau)
        r = 1 / q4
        sn, cn, dn = a * q1 * r, b * q2 * r, c * q3 * r
    ts.append((time.perf_counter_ns() - t) / n)
# sanity: last value against mpmath
mp.mp.prec = 200
ref = mp.ellipfun('sn', -10 + 20 * (n - 0.5) / n, m=mp.mpf(0.8) ** 2)
assert abs(mp.mpf(sn.real.mid().str(50, radius=False)) - ref) < mp.mpf(10) ** -40, (sn, ref)
print(*ts)
"""


def py(code):
    out = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], check=True,
                         capture_output=True, text=True).stdout
    return tuple(float(x) for x in out.split())


def rust(bits, n, *flags):
    exe = os.path.join(ROOT, "target", "release", "examples", "bench_batch")
    out = subprocess.run([exe, str(bits), str(n), str(REPEATS), "all", *flags], check=True,
                         capture_output=True, text=True).stdout
    return tuple(float(x) for x in out.split())


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet", "--example", "bench_batch"],
                   cwd=ROOT, check=True)
    samples = {}
    jobs = [
        ("eulertop f64", lambda: rust(53, N_F64)),
        ("eulertop f64 slice", lambda: rust(53, N_F64, "many")),
        ("scipy f64", lambda: py(PY_SCIPY.format(n=5 * N_F64, reps=REPEATS))),
        ("eulertop 1024", lambda: rust(1024, N_MP)),
        ("flint 1024", lambda: py(PY_FLINT.format(n=N_MP, reps=REPEATS))),
        ("mpmath 1024", lambda: py(PY_MPMATH.format(n=N_MPMATH, reps=3))),
    ]
    for _ in range(ROUNDS):
        for name, job in jobs:
            samples.setdefault(name, []).extend(job())
    r = {name: (statistics.median(ts), min(ts)) for name, ts in samples.items()}
    load = os.getloadavg()[0]

    def row(prec, ours, peer_name, peer, goal_text, goal_ok):
        med = peer[0] / ours[0]
        mn = peer[1] / ours[1]
        unit = (lambda t: "%.0f ns" % t) if prec.startswith("f64") else (lambda t: "%.1f µs" % (t / 1e3))
        return "| %s | %s (%s) | %s | %s (%s) | %.2f× (%.2f×) | %s: %s |" % (
            prec, unit(ours[0]), unit(ours[1]), peer_name, unit(peer[0]), unit(peer[1]),
            med, mn, goal_text, "met" if goal_ok(med) else "**missed**")

    lines = [
        "## Jacobi elliptic functions",
        "",
        "sn + cn + dn of a real argument, batch u_i = -10 + 20(i+1/2)/n, modulus k = 0.8",
        "(m = 0.64); each tool in its own process; wall-clock time per input, median (and",
        "minimum) over %d rounds × %d batches, the tools interleaved round by round (the" % (ROUNDS, REPEATS),
        "per-thread CPU clocks of this VM tick in 4 ms, too coarse; see the script).",
        "Reproduce: `python3 scripts/bench_peers.py` (writes this section; peers need",
        "`pip install mpmath python-flint scipy`).  Criterion: `cargo bench --bench jacobi`.",
        "Load average at the end of the run: %.2f on 2 cores (shared machine: figures are" % load,
        "noisy; medians include slow phases, minima show the unloaded machine).",
        "",
        "| precision | eulertop median (min) | peer | peer median (min) | speed-up median (min) | goal |",
        "|---|---|---|---|---|---|",
        "| f64, `sncndn` per call | %.0f ns (%.0f ns) | – | – | – | ≤ 60 ns/eval: median %s, minimum %s |" % (
            r["eulertop f64"][0], r["eulertop f64"][1],
            "met" if r["eulertop f64"][0] <= 60 else "**missed**",
            "met" if r["eulertop f64"][1] <= 60 else "**missed**"),
        "| f64, `sncndn_many` (slice) | %.0f ns (%.0f ns) | – | – | – | ≤ 60 ns/eval: median %s, minimum %s |" % (
            r["eulertop f64 slice"][0], r["eulertop f64 slice"][1],
            "met" if r["eulertop f64 slice"][0] <= 60 else "**missed**",
            "met" if r["eulertop f64 slice"][1] <= 60 else "**missed**"),
        row("f64, per call", r["eulertop f64"], "scipy.special.ellipj (vectorised)", r["scipy f64"],
            "(no goal)", lambda x: True),
        row("f64, slice", r["eulertop f64 slice"], "scipy.special.ellipj (vectorised)",
            r["scipy f64"], "(no goal)", lambda x: True),
        row("1024 bits", r["eulertop 1024"], "mpmath ellipfun (×3)", r["mpmath 1024"],
            "≥ 40×", lambda x: x >= 40),
        row("1024 bits", r["eulertop 1024"], "python-flint (Arb theta quotients)", r["flint 1024"],
            "≥ 2×", lambda x: x >= 2),
        "",
        "`sncndn` is one call per argument (modulus checked and its cached chain looked up",
        "each time); `sncndn_many(&us, k)` does both once per slice, like scipy's vectorised",
        "call.  The slow phases of this shared machine (a busy sibling hyperthread, judging by",
        "a latency-bound calibration loop that keeps its speed) cost the throughput-bound",
        "per-call path up to 1.6×, hence its median well above its minimum.",
        "",
        "Notes: eulertop caches the Landen chain of moduli per k (flint's K, K', τ and",
        "theta-nulls are likewise computed once, outside the loop).  The Python peers pay",
        "interpreter overhead per call (well under 1 µs; irrelevant at 1024 bits); scipy is",
        "timed vectorised, so it pays none.",
        "",
    ]
    section = "\n".join(lines)
    path = os.path.join(ROOT, "reports", "performance.md")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    old = open(path).read() if os.path.exists(path) else "# Performance\n\n"
    head = "## Jacobi elliptic functions"
    if head in old:
        pre, rest = old.split(head, 1)
        nxt = rest.find("\n## ")
        post = rest[nxt + 1:] if nxt >= 0 else ""
        new = pre + section + ("\n" + post if post else "")
    else:
        new = old.rstrip("\n") + "\n\n" + section
    open(path, "w").write(new)
    print(section)


if __name__ == "__main__":
    main()
