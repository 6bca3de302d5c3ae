#!/usr/bin/env python3
"""Tests of the second system (scripts/recheck-certificates.py): what it must reject.

Usage: scripts/test-recheck-certificates.py [--all CERT_DIR] [--all-dlmf DLMF_CERT_DIR]

Each case is a certificate that must fail the recheck, for the reason named; the
certificates are the small files of tests/data/certificates/ or copies of certificates
that target/release/eulertop writes, changed in one place.  With --all, also: after the
right side (or the expression) of every claim is changed in a copy of the catalogue,
every certificate of CERT_DIR fails; with --all-dlmf, the same for the certificates of
examples/dlmf-jacobi in DLMF_CERT_DIR against a changed copy of that catalogue.  Exit
status 0 when every case behaves; not run by `cargo test` (CI runs it as its own step).
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RECHECK = os.path.join(ROOT, "scripts", "recheck-certificates.py")
BIN = os.path.join(ROOT, "target", "release", "eulertop")
DATA = os.path.join(ROOT, "tests", "data", "certificates")


def recheck(paths, *opts):
    """(exit status, output) of the recheck."""
    p = subprocess.run([sys.executable, RECHECK, *opts, *paths], capture_output=True, text=True, cwd=ROOT)
    return p.returncode, p.stdout + p.stderr


def prove(cid, tmp, catalogue=None):
    path = os.path.join(tmp, f"{cid}.cert")
    extra = ["--catalogue", catalogue] if catalogue else []
    p = subprocess.run([BIN, "prove", cid, "--certificate", path, *extra], capture_output=True, text=True, cwd=ROOT)
    if p.returncode != 0 or not os.path.exists(path):
        raise SystemExit(f"cannot write the certificate of {cid}: {p.stderr.strip()}")
    with open(path, encoding="utf-8") as fh:
        return fh.read()


def write(tmp, name, text):
    path = os.path.join(tmp, name)
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    return path


def without(text, pattern):
    """The text with the first line matching pattern deleted."""
    lines = text.splitlines()
    i = next(i for i, ln in enumerate(lines) if re.match(pattern, ln))
    return "\n".join(lines[:i] + lines[i + 1:]) + "\n"


def changed_catalogue(tmp, claim_ids=None, source="identities"):
    """A copy of the catalogue (identities, or the directory source) with the right side
    (or expr, or an existence claim's first equation) of the claims changed."""
    cat = os.path.join(tempfile.mkdtemp(dir=tmp), os.path.basename(source))
    shutil.copytree(os.path.join(ROOT, source), cat)
    for f in os.listdir(cat):
        if not f.endswith(".toml"):
            continue
        path = os.path.join(cat, f)
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        out, cur = [], None
        for line in text.splitlines():
            m = re.match(r'id = "([^"]+)"', line)
            if m:
                cur = m.group(1)
            m = re.match(r"""(rhs|expr) = ("|'|''')(.*)$""", line)
            if m and (claim_ids is None or cur in claim_ids):
                line = f"{m.group(1)} = {m.group(2)}2 * {m.group(3)}"
            # an existence claim's first equation
            m = re.match(r"""equations = \[("|')(.*)$""", line)
            if m and (claim_ids is None or cur in claim_ids):
                line = f"equations = [{m.group(1)}2 * {m.group(2)}"
            out.append(line)
        with open(path, "w", encoding="utf-8") as fh:
            fh.write("\n".join(out) + "\n")
    return cat


EVALUATIONS = [  # (expression of the catalogue's language, its value as a certificate writes it)
    ("-x^2", "-x**2"), ("2^-1", "1/2"), ("x - y - 1", "x - y - 1"), ("x / y / 2", "x/(2*y)"),
    ("f(x + 1)", "x**2 + 2*x + 2"), ("if 1 > 0 and not 2 < 1 then x else y", "x"),
    ("dot(vec(x, y, 1), [1, 2, 3])", "x + 2*y + 3"), ("cross([1, 0, 0], [0, 1, 0])[3]", "1"),
    ("([[1, 2, 0], [0, 1, 0], [0, 0, 1]] * vec(x, y, 1))[1]", "x + 2*y"),
    ("inv([[2, 0, 0], [0, x, 0], [0, 0, 1]])[2, 2]", "1/x"), ("det(diag(x, y, 2))", "2*x*y"),
    ("1e-3 + .5", "501/1000"), ("(x + y)^2 - x^2", "2*x*y + y**2"), ("1 - 2 * 3^2", "-17"),
    ("if 2 == 2 then x else y", "x"), ("if 1 != 1 then x else y", "y"), ("if 1 <= 1 and 2 >= 2 then x else y", "x"),
]


def evaluator_cases():
    """(expression, expected, got or error) of each evaluation that differs."""
    import importlib.util
    sys.path.insert(0, os.path.join(ROOT, "scripts"))
    spec = importlib.util.spec_from_file_location("recheck", RECHECK)
    rc = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(rc)
    from certcheck.evaluate import Evaluator
    from certcheck.exprlang import Parser
    cert = rc.Cert("evaluator")
    cert.run("field x indeterminate\nfield y indeterminate\nnode t1 = x\nclaim t1 = t1\n")
    ev = Evaluator(cert, ["f(a) = a^2 + 1"])
    env = {"x": cert.frac("x"), "y": cert.frac("y")}
    bad = []
    for text, want in EVALUATIONS:
        try:
            got = ev.eval(Parser(text).whole(), env)
            if not cert.eq(got, cert.frac(want)):
                bad.append((text, want, f"{got.num.as_expr()}/{got.den.as_expr()}"))
        except Exception as e:  # noqa: BLE001 - reported as a failed case
            bad.append((text, want, f"{type(e).__name__} {e}"))
    return bad


class Cases:
    def __init__(self, tmp):
        self.tmp, self.failures, self.count = tmp, [], 0

    def expect(self, what, status_output, ok, reason):
        status, output = status_output
        self.count += 1
        good = (status == 0) == ok and reason in output
        print(f"{'ok  ' if good else 'FAIL'}  {what}")
        if not good:
            self.failures.append(what)
            print("      " + "\n      ".join(output.strip().splitlines()[-4:]))

    def run(self):
        t = self.tmp
        bad = evaluator_cases()
        self.expect(f"the evaluator of the expression language: {len(EVALUATIONS) - len(bad)} of "
                    f"{len(EVALUATIONS)} expressions as the language defines them",
                    (0 if not bad else 1, "\n".join(f"{a}: want {b}, got {c}" for a, b, c in bad)), True, "")
        self.expect("the wrong square-root branch of the issue is rejected",
                    recheck([os.path.join(DATA, "wrong-branch.cert")], "--unbound"), False,
                    "square-root branch has no evidence")
        self.expect("sn² of a real argument at 0 < k² < 1 is a parameter in (0, 1): 1 - sn² > 0",
                    recheck([os.path.join(DATA, "sn-square.cert")], "--unbound"), True, "1 of 1")
        for name, why in (("modulus-2", "at k = 2"), ("odd-power", "for sn itself (an odd power)"),
                          ("opaque-argument", "for an argument not known to be real")):
            self.expect(f"sn² as a parameter is refused {why}",
                        recheck([os.path.join(DATA, f"sn-square-{name}.cert")], "--unbound"), False,
                        "is not proved by the parametrization")
        self.expect("a sign proved with the second parametrization (the box x in (1/5, 1/2)): 1 - x² > 0",
                    recheck([os.path.join(DATA, "alt-box.cert")], "--unbound"), True, "1 of 1")
        self.expect("a second parametrization that does not prove the sign (x in (1/2, 2)) is refused",
                    recheck([os.path.join(DATA, "alt-box-wide.cert")], "--unbound"), False,
                    "is not proved by the parametrization")
        self.expect("a chart parameter with a false derivative is rejected",
                    recheck([os.path.join(DATA, "param-derivative.cert")], "--unbound"), False,
                    "chart parameter y")
        self.expect("a chart parameter y with h = x + y held fixed: dy/dx = -1 is accepted",
                    recheck([os.path.join(DATA, "param-coord.cert")], "--unbound"), True, "1 of 1")
        self.expect("a chart parameter held fixed (dy/dx = 0) where h = x + y moves with x is rejected",
                    recheck([os.path.join(DATA, "param-coord-moves.cert")], "--unbound"), False,
                    "the chart does not hold the claim's other variables fixed")
        self.bound()

    def bound(self):
        """Certificates the prover writes, bound to the catalogue, and their corruptions."""
        t = self.tmp
        et = prove("sec2.ET-v.corrected", t)
        self.expect("a certificate as written rechecks, its formulas evaluated",
                    recheck([write(t, "et.cert", et)]), True, "formulas: evaluated")
        self.expect("a deleted claim line is rejected",
                    recheck([write(t, "et-claim.cert", without(et, r"claim t"))]), False,
                    "claim line(s) where the certificate announces 3")
        self.expect("a certificate without its claim is rejected",
                    recheck([write(t, "et-unbound.cert", without(et, r"source id "))]), False,
                    "not bound to a claim")
        self.expect("a changed formula in the catalogue is rejected",
                    recheck([write(t, "et2.cert", et)], "--catalogue", changed_catalogue(t, {"sec2.ET-v.corrected"})),
                    False, "claim.rhs differs")
        wrong = re.sub(r"node t14 = dot \+ t12 t10 - t13 t8 -> .*",
                       "node t14 = dot + t13 t8 - t12 t10 -> (B*M2*M3 - C*M2*M3)/(C*B)", et)
        wrong = wrong.replace("node t15 = t11 - t14", "node t15 = t11 + t14")
        self.expect("a derivation that does not start from the formula is rejected",
                    recheck([write(t, "et-formula.cert", wrong)]), False, "is not the catalogue's")
        ws = prove("sec5.ws.w1-w3", t)
        self.expect("a claim over a complex variable u (derived as real and imaginary parts) is evaluated",
                    recheck([write(t, "ws.cert", ws)]), True, "formulas: evaluated")
        lines = re.findall(r"^claim t\d+ = t\d+$", ws, re.M)
        swapped = ws.replace(lines[0], "@").replace(lines[1], lines[0]).replace("@", lines[1])
        self.expect("its imaginary part's line in place of the real part's is rejected",
                    recheck([write(t, "ws-swapped.cert", swapped)]), False, "is not the catalogue's")
        mm = prove("sec6.M-M-1.up", t)
        self.expect("sn, cn, dn at a sum of base arguments by the checker's addition formulae: evaluated",
                    recheck([write(t, "mm.cert", mm)]), True, "formulas: evaluated")
        master = prove("sec7.master12.g1.up", t)
        self.expect("the premises are printed",
                    recheck([write(t, "m.cert", master)]), True,
                    "premise [branch: hypothesis.branch-delta1]")
        narrowed = re.sub(r"^image C = \(t1_C\)/\(1\)$", "image C = (t1_C + 1)/(1)", master, flags=re.M)
        self.expect("a parametrization narrower than the catalogue's domain (C > 1) is rejected",
                    recheck([write(t, "m-domain.cert", narrowed)]), False,
                    "is not the catalogue's t1_C (the domain's parametrization)")
        box = re.sub(r"^(alt image dl = \(20\*t1_dl \+ )1\)", r"\g<1>2)", master, flags=re.M)
        self.expect("a box that is not the catalogue's interval is rejected",
                    recheck([write(t, "m-box.cert", box)]), False, "(the box of the intervals)")
        self.expect("a deleted hypothesis is rejected",
                    recheck([write(t, "m-premise.cert", without(master, r"premise branch"))]), False,
                    "which is no premise of the theorem")
        self.expect("a premise the claim does not state is rejected",
                    recheck([write(t, "m-stated.cert", master.replace(
                        "premise branch hypothesis.branch-delta1", "premise branch hypothesis.branch-delta2"))]),
                    False, "the claim does not state hypothesis branch-delta2")
        self.charts_and_lemmas(et)

    def charts_and_lemmas(self, et):
        """Charts of implicit maps, lemmas, and the self-test corruptions."""
        t = self.tmp
        step = prove("sec3.int.g2", t)
        self.expect("a chart of an implicit map is verified against the map's equations in the catalogue",
                    recheck([write(t, "int.cert", step)]), True, "equation(s) of the catalogue verified")
        m = re.search(r"^(chart \S+\(.*\) value=)(t\d+),(t\d+),", step, re.M)
        swapped = step.replace(m.group(0), f"{m.group(1)}{m.group(3)},{m.group(2)},")
        self.expect("a chart that does not satisfy the map's equations is rejected",
                    recheck([write(t, "int-chart.cert", swapped)]), False, "does not satisfy")
        status, output = recheck(["x.cert"], "--catalogue", os.path.join(t, "no-such-dir"))
        self.expect("a missing catalogue: one line, exit status 2",
                    (0 if status == 2 and len(output.strip().splitlines()) == 1 else 1, output), True,
                    "no catalogue directory")
        casimir = prove("sec2.M2.casimir", t)
        lemma = et.replace("\nclaims 3", '\npremise lemma sec2.M2.casimir "the Casimir"\nclaims 3')
        self.expect("a lemma used without its certificate is rejected",
                    recheck([write(t, "et-lemma.cert", lemma)]), False,
                    "lemma sec2.M2.casimir is used without its certificate")
        self.expect("a lemma with its certificate in the run is accepted",
                    recheck([write(t, "et-lemma.cert", lemma), write(t, "casimir.cert", casimir)]), True,
                    "2 of 2 certificates recheck")
        for cid in ("sec2.ET-v.corrected", "sec7.master12.g1.up", "sec6.discr-eq.corrected.up"):
            path = write(t, f"self-{cid}.cert", prove(cid, t))
            self.expect(f"--self-test {cid}: each corruption is rejected",
                        recheck([], "--self-test", path), True, "self-test passes")

    def chart_parameters(self):
        """Proposition 3: the phase shift of step_gamma1 does not depend on phi, through the
        phase step delta of the chart, which moves so that h stays fixed (`coord h`)."""
        t = self.tmp
        ps = prove("sec4.prop3.poisson-shift.g1.up", t)
        lemma = write(t, "master-step.cert", prove("sec7.master12.step.up", t))
        self.expect("a derivative in phi with the chart's phase step delta (coord h) rechecks",
                    recheck([write(t, "ps.cert", ps), lemma]), True, "2 of 2 certificates recheck")
        line = re.search(r"^coord h = (t\d+)$", ps, re.M)
        phi = re.search(r"^node (t\d+) = phi$", ps, re.M)
        self.expect("the coord line of h deleted is rejected",
                    recheck([write(t, "ps-bad.cert", without(ps, r"coord h ")), lemma]), False,
                    "no coord line gives a claim's variable the chart replaces")
        self.expect("the coord line naming no variable of the claim is rejected",
                    recheck([write(t, "ps-bad.cert", ps.replace(line.group(0), f"coord hh = {line.group(1)}")),
                             lemma]), False, "coord hh: not a variable of the claim")
        self.expect("the coord line naming the claim's variable A instead of h is rejected",
                    recheck([write(t, "ps-bad.cert", ps.replace(line.group(0), f"coord A = {line.group(1)}")),
                             lemma]), False, "the chart replaces the claim's variable h")
        moved = ps.replace(line.group(0), f"coord h = {phi.group(1)}")
        self.expect("the coord line of h at a value that moves with phi is rejected",
                    recheck([write(t, "ps-bad.cert", moved), lemma]), False,
                    "the chart does not hold the claim's other variables fixed")

    def root_part_signs(self):
        """Signs of values in a square root decided from the signs of their parts, some
        by the condition of the part of the domain (`sign ... parts`), and the cover of
        the domain by the parts of a proof by parts."""
        def data(name):
            return recheck([os.path.join(DATA, f"{name}.cert")], "--unbound")
        self.expect("x + sqrt(2) y > 0 on the part x > 0, y > 0 is accepted", data("parts-sign"), True, "1 of 1")
        self.expect("x - sqrt(2) y > 0 on the part x > 0, y > 0 is not decided by its parts",
                    data("parts-sign-undecided"), False, "is not decided by the signs of its parts")
        self.expect("x + sqrt(2) y < 0 on the part x > 0, y > 0 is rejected", data("parts-sign-opposite"), False,
                    "is not decided by the signs of its parts")
        self.expect("parts of the domain that leave out x < 0, y < 0 are rejected", data("parts-uncovered"), False,
                    "the parts of the domain do not cover it")
        t = self.tmp
        sec = prove("sec4.sectors.up", t)
        self.expect("sec4.sectors.up (its comparisons decided by the parts' conditions) rechecks, evaluated",
                    recheck([write(t, "sec.cert", sec)]), True, "formulas: evaluated")
        line = re.search(r"^sign value \(r_1\*M1\)/\(1\) > 0 parts$", sec, re.M).group(0)
        self.expect("sec4.sectors.up with a sign by parts stated opposite is rejected",
                    recheck([write(t, "sec-bad.cert", sec.replace(line, line.replace("> 0", "< 0"), 1))]), False,
                    "is not decided by the signs of its parts")
        self.expect("sec4.sectors.up with a part's condition negated is rejected",
                    recheck([write(t, "sec-bad.cert", sec.replace('part "M1" > 0', 'part "M1" < 0', 1))]), False,
                    "is not decided by the signs of its parts")
        last = sec.rindex("# eulertop certificate")
        self.expect("sec4.sectors.up without its last part is rejected",
                    recheck([write(t, "sec-bad.cert", sec[:last])]), False, "the parts of the domain do not cover it")

    def dominant_sides(self):
        """sec4.sectors.boundary: signs of a + b*r decided by the side that wins (rule 2b),
        whose `dominance` lines state the sign of q = a**2 - b**2 * radicand with its
        factors, and the corruptions of that evidence."""
        t = self.tmp
        bd = prove("sec4.sectors.boundary", t)
        self.expect("sec4.sectors.boundary (signs by the side that wins) rechecks",
                    recheck([write(t, "bd.cert", bd)]), True, "1 of 1 certificates recheck")
        line = re.search(r"^dominance \([^)]*\) [<>] 0 constant .*$", bd, re.M).group(0)
        rel = re.search(r"\) ([<>]) 0 constant", line).group(1)
        other = "<" if rel == ">" else ">"
        reversed_line = line.replace(f") {rel} 0 constant", f") {other} 0 constant", 1)
        negated = re.sub(r" constant (-?)(\d+) ", lambda m: f" constant {'' if m.group(1) else '-'}{m.group(2)} ",
                         reversed_line, count=1)
        proved = re.findall(r"^sign t\d+ [<>] 0$", bd, re.M)
        cases = [
            ("the dominance inequality reversed", bd.replace(line, reversed_line), "factors' signs give the other sign"),
            ("the dominance inequality reversed with its constant negated", bd.replace(line, negated),
             "Q is not the product of its factors"),
            ("a factor's power changed", bd.replace(line, re.sub(r"\^ 1$", "^ 3", line)),
             "Q is not the product of its factors"),
            ("the dominance lines deleted", "\n".join(ln for ln in bd.splitlines() if not ln.startswith("dominance ")),
             "is not proved by the parametrization"),
        ] + [(f"the dominant side's sign flipped ({ln})", bd.replace(ln, ln.replace(" > 0", " @ 0").replace(
            " < 0", " > 0").replace(" @ 0", " < 0")), "is not proved by the parametrization") for ln in proved[-2:]]
        for what, text, why in cases:
            self.expect(f"sec4.sectors.boundary: {what} is rejected", recheck([write(t, "bd-bad.cert", text)]),
                        False, why)

    def hypothesis_signs(self):
        """Lemma 2: a square-root branch decided by the stated hypothesis
        omega-near-identity (tr omega > 1), and the corruptions of that evidence."""
        t = self.tmp
        lem = prove("sec8.lemma2.model", t)
        self.expect("Lemma 2's branch by its stated hypothesis rechecks, printed as a premise with its condition",
                    recheck([write(t, "l2.cert", lem)]), True,
                    "premise [sign: hypothesis.omega-near-identity] tr(vm_omega(M, h, A, B, C)) > 1: ")
        label = "hypothesis.omega-near-identity"
        m = re.search(rf"^sign (t\d+) > 0 hypothesis {re.escape(label)} factor \(1\)/\(2\)$", lem, re.M)
        line = m.group(0)
        cases = [
            ("the hypothesis deleted from the premises", without(lem, rf"premise sign {re.escape(label)}"),
             "is no premise of the theorem"),
            ("the hypothesis' condition altered in the certificate",
             lem.replace('"when":"tr(vm_omega(M, h, A, B, C)) > 1"', '"when":"tr(vm_omega(M, h, A, B, C)) > 0"'),
             "differs"),
            ("the evidence naming a hypothesis the claim does not state",
             lem.replace(line, line.replace(label, "hypothesis.W-small")), "the claim does not state hypothesis W-small"),
            ("the evidence with a factor of the wrong sign", lem.replace(line, line.replace("(1)/(2)", "(-1)/(2)")),
             "times the stated factor"),
            ("the evidence stating the opposite sign", lem.replace(line, line.replace("> 0", "< 0")),
             "square-root branch has no evidence"),
            ("the evidence with a wrong factor", lem.replace(line, line.replace("(1)/(2)", "(1)/(3)")),
             "times the stated factor"),
            ("the evidence line deleted", lem.replace(line + "\n", ""), "square-root branch has no evidence"),
            ("a square's quotient changed", re.sub(r"^(sign t\d+ > 0 square \()v1\*\*2", r"\g<1>2*v1**2", lem,
                                                    count=1, flags=re.M), "is not the square of"),
        ]
        for what, text, why in cases:
            self.expect(f"Lemma 2: {what} is rejected", recheck([write(t, "l2-bad.cert", text)]), False, why)
        cat = changed_catalogue(t, set())
        path = os.path.join(cat, "hypotheses.toml")
        with open(path, encoding="utf-8") as fh:
            text = fh.read()
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text.replace('when = "tr(vm_omega(M, h, A, B, C)) > 1"', 'when = "tr(vm_omega(M, h, A, B, C)) > 2"'))
        self.expect("Lemma 2 against a catalogue whose hypothesis says tr omega > 2 is rejected",
                    recheck([write(t, "l2.cert", lem)], "--catalogue", cat), False,
                    "hypothesis.omega-near-identity differs")
        both = lem.replace('"when":"tr(vm_omega(M, h, A, B, C)) > 1"', '"when":"tr(vm_omega(M, h, A, B, C)) > 2"')
        self.expect("Lemma 2 with tr omega > 2 in both the catalogue and the certificate is rejected",
                    recheck([write(t, "l2-both.cert", both)], "--catalogue", cat), False, "times the stated factor")
        self.expect("a sign by a hypothesis is not accepted without the catalogue",
                    recheck([os.path.join(DATA, "hypothesis-sign.cert")], "--unbound"), False,
                    "checked against the catalogue only")

    def multiples_of_roots(self):
        """A square root c * r (r a root symbol of one sign throughout, c of a sign proved
        here): accepted, and rejected where r would need both signs or c has no proved sign."""
        self.expect("sqrt(x^2 y) = x r with x > 0 proved by the parametrization is accepted",
                    recheck([os.path.join(DATA, "sqrt-multiple.cert")], "--unbound"), True, "1 of 1")
        self.expect("c * r where r would need both signs is rejected",
                    recheck([os.path.join(DATA, "sqrt-multiple-contradiction.cert")], "--unbound"), False,
                    "which the certificate contradicts")
        self.expect("c * r where the sign of c is not proved is rejected",
                    recheck([os.path.join(DATA, "sqrt-multiple-unsigned.cert")], "--unbound"), False,
                    "square-root branch has no evidence")
        self.expect("c * r with c = -x/z > 0 by the sign lines of x and z is accepted",
                    recheck([os.path.join(DATA, "sqrt-multiple-stated.cert")], "--unbound"), True, "1 of 1")
        self.expect("c * r with c = x/z < 0 by the sign lines of x and z, r a positive root, is rejected",
                    recheck([os.path.join(DATA, "sqrt-multiple-stated-wrong.cert")], "--unbound"), False,
                    "which the certificate contradicts")
        t = self.tmp
        gm = prove("sec8.GammaMV.up", t)
        self.expect("(GammaMV): its root c * sqrt(a) with c > 0 rechecks, evaluated",
                    recheck([write(t, "gm.cert", gm)]), True, "formulas: evaluated")

    def sign_evidence(self):
        """The sign evidence of sign symbols, of dn of a real argument and of values
        written out: accepted as stated, rejected when corrupted."""
        def data(name):
            return recheck([os.path.join(DATA, f"{name}.cert")], "--unbound")
        self.expect("sqrt(x^2) = s x with the sign symbol s = sign(x) is accepted", data("sign-symbol"), True, "1 of 1")
        self.expect("a sign symbol defined as sign(-x) does not prove s x > 0", data("sign-symbol-negated"), False,
                    "sign t3 > 0 is not proved by the parametrization")
        self.expect("a sign symbol defined as the sign of another variable does not prove s x > 0",
                    data("sign-symbol-other"), False, "sign t3 > 0 is not proved by the parametrization")
        self.expect("dn of a real argument at k = 1/2, as a base and as a dn node, is positive", data("dn-fact"), True,
                    "1 of 1")
        self.expect("dn > 0 is refused for a complex argument (i x)", data("dn-fact-complex"), False,
                    "fact F1: dn of an argument that is not real by construction")
        self.expect("dn > 0 is refused at k = 2 (k**2 outside (0, 1))", data("dn-fact-modulus-2"), False,
                    "fact F0: dn at a modulus not proved real with 0 < k**2 < 1")
        self.expect("a dn fact whose value is not the base's dn is refused", data("dn-fact-base-value"), False,
                    "fact F0: the value is not dn of base b_1_1")
        self.expect("a sign by a dn fact with a wrong factor is refused", data("dn-fact-factor"), False,
                    "the value is not the fact F1 times the stated factor")
        self.expect("the sign of a value written out (x + 1 > 0 for x > 0) is accepted", data("sign-value"), True,
                    "1 of 1")
        self.expect("the sign of a value written out that the parametrization does not prove is refused",
                    data("sign-value-unproved"), False, "sign value (x - 2)/(1) > 0 is not proved")
        t = self.tmp
        rt = prove("sec4.ell-coord.roundtrip", t)
        self.expect("sec4.ell-coord.roundtrip (signs by the sign symbols sgnM1, sgnM3) rechecks",
                    recheck([write(t, "rt.cert", rt)]), True, "1 of 1")
        self.expect("sec4.ell-coord.roundtrip with sgnM3 defined as sign(-M3) is rejected",
                    recheck([write(t, "rt-bad.cert", rt.replace("signsym sgnM3 = sign (M3)/(1)",
                                                                 "signsym sgnM3 = sign (-M3)/(1)"))]), False,
                    "is not proved by the parametrization")
        self.expect("sec4.ell-coord.roundtrip without the definition of sgnM3 is rejected",
                    recheck([write(t, "rt-none.cert", without(rt, r"signsym sgnM3 "))]), False,
                    "is not proved by the parametrization")

    def power_series(self):
        """Proofs by power series: every series operation redone here from the leaves."""
        def data(name):
            return recheck([os.path.join(DATA, f"{name}.cert")], "--unbound")
        self.expect("sn(t, k) - t = O(t^3) by integrating DLMF 22.13.1-3 is accepted", data("series-sn"), True,
                    "1 of 1")
        self.expect("sn(t, k) - t = O(t^4) is rejected: its t^3 coefficient is not 0", data("series-sn-order"), False,
                    "the coefficient of t^3 is not 0")
        self.expect("sn, cn, dn(0) stated as (1, 0, 1) are rejected", data("series-sn-base"), False,
                    "the base values are not sn, cn, dn at the constant term")
        self.expect("sqrt(1 + t) - 1 - t/2 = O(t^2) is accepted", data("series-sqrt"), True, "1 of 1")
        self.expect("the square root of 1 + t with the root -1 stated is rejected", data("series-sqrt-branch"), False,
                    "is no square-root node")
        self.expect("sn at a modulus 1/2 + t^2 known to O(t^2) from sn at 1/2 is accepted", data("series-moving"),
                    True, "1 of 1")
        self.expect("sn at a modulus 1/2 + t^2 is not known to O(t^3)", data("series-moving-order"), False,
                    "is not known (O(t^2))")
        self.expect("sn at 1/2 does not stand for sn at a modulus 1/3 + t^2", data("series-moving-other"), False,
                    "the modulus's constant term is not")
        t = self.tmp
        cid = "sec3.as.g1.corrected"
        cert = prove(cid, t)
        self.expect(f"{cid} (a map's order, by its power series) rechecks, evaluated through the map's series "
                    "chart, which satisfies (impl spec)",
                    recheck([write(t, "as.cert", cert)]), True, "formulas: evaluated; charts: 4 equation(s)")
        self.expect(f"{cid} with its coefficients claimed 0 below h^1 only (O(h^1.5) needs h^0, h^1) is rejected",
                    recheck([write(t, "as-short.cert", cert.replace(" below 2", " below 1"))]), False,
                    "needs those below t^2")
        self.expect(f"{cid} with an sclaim line deleted is rejected",
                    recheck([write(t, "as-del.cert", without(cert, r"sclaim "))]), False, "claim line(s) where")
        lines = cert.splitlines()
        last = max(i for i, ln in enumerate(lines) if re.match(r"sseries s\d+ = mul ", ln))
        lines[last] = lines[last].replace(" = mul ", " = add ")
        self.expect(f"{cid} with its last product turned into a sum is rejected",
                    recheck([write(t, "as-op.cert", "\n".join(lines) + "\n")]), False, "is not 0")
        dl = prove("sec7.delta12-asym.g1.up", t)
        self.expect("sec7.delta12-asym.g1.up: the phase step's series chart satisfies (master12) and the formula "
                    "evaluates", recheck([write(t, "dl.cert", dl)]), True, "formulas: evaluated; charts: 8 equation(s)")
        wrong = re.sub(r"^(schart delta1\(.*\) value=)s\d+$", r"\1s1", dl, count=1, flags=re.M)
        self.expect("sec7.delta12-asym.g1.up with the phase step's series chart replaced by t is rejected",
                    recheck([write(t, "dl-bad.cert", wrong)]), False, "does not satisfy sec7.master12")
        ex = prove("sec3.impl-map.existence", t)
        self.expect("sec3.impl-map.existence: the series solution solves (impl), its Jacobian at h = 0 has a "
                    "proved sign, and it lies in the stated set", recheck([write(t, "ex.cert", ex)]), True,
                    "formulas: evaluated")
        moved = re.sub(r"^ssolution x1 = s\d+", "ssolution x1 = s1", ex, count=1, flags=re.M)
        self.expect("sec3.impl-map.existence with the solution's first component replaced by h is rejected",
                    recheck([write(t, "ex-bad.cert", moved)]), False, "at the series solution: a known coefficient")
        cat = changed_catalogue(t, {cid})
        self.expect(f"{cid} against a catalogue copy whose expr is changed is rejected",
                    recheck([write(t, "as-cat.cert", cert)], "--catalogue", cat), False, "claim.expr")

    def witnesses(self):
        """Refutations certified at a point, and negations proved so."""
        def data(name):
            return recheck([os.path.join(DATA, f"{name}.cert")], "--unbound")
        self.expect("(x + 1)^2 = x^2 + 2x refuted at x = 3/4 (lhs - rhs = 1) is accepted",
                    data("witness-square"), True, "REFUTED")
        self.expect("a witness of (x + 1)^2 = x^2 + 2x + 1, which holds, is rejected", data("witness-true"), False,
                    "not certified nonzero")
        self.expect("a witness of sqrt(x^2) = x at the negative root (x = 3/4, r = -3/4) is rejected",
                    data("witness-root"), False, "not the principal root")
        t, cid = self.tmp, "sec5.ident2.123.printed"
        path = os.path.join(t, f"{cid}.cert")
        subprocess.run([BIN, "prove", cid, "--certificate", path], capture_output=True, cwd=ROOT)
        with open(path, encoding="utf-8") as fh:
            cert = fh.read()
        self.expect(f"{cid} (a misprint) is refuted at its witness point, the point's sn, cn, dn checked "
                    "against mpmath", recheck([path]), True, "REFUTED, component 1")
        flip = re.sub(r"^at cn_1 ~ (-?)(\S+) (-?)(\S+)$",
                      lambda m: f"at cn_1 ~ {'' if m[1] else '-'}{m[2]} {'' if m[3] else '-'}{m[4]}",
                      cert, count=1, flags=re.M)
        self.expect(f"{cid} with the other branch of cn at the point is rejected",
                    recheck([write(t, "w-branch.cert", flip)]), False, "is not mpmath's cn")
        moved = re.sub(r"^at sn_1 = (-?\d+)\*", lambda m: f"at sn_1 = {int(m[1]) + 2**200}*", cert, count=1, flags=re.M)
        self.expect(f"{cid} with the point's sn value moved off sn of its argument is rejected",
                    recheck([write(t, "w-sn.cert", moved)]), False, "is not mpmath's sn")
        claimed = re.sub(r"^side (t\d+) (t\d+)$", r"claim \1 = \2", cert, flags=re.M)
        self.expect(f"{cid} with its sides claimed equal is rejected", recheck([write(t, "w-claim.cert", claimed)]),
                    False, "fails")
        self.expect(f"{cid} without its witness line is rejected",
                    recheck([write(t, "w-none.cert", without(cert, r"witness "))]), False, "and a `witness` line")
        neg = "sec6.aux3.gamma0.lo"
        npath = os.path.join(t, f"{neg}.cert")
        subprocess.run([BIN, "prove", neg, "--certificate", npath], capture_output=True, cwd=ROOT)
        self.expect(f"{neg} (a negation: gamma_0 is not Poisson) is proved by its inner identity's witness",
                    recheck([npath]), True, "PROVED (negation)")
        so = "sec3.as.g1.printed"
        spath = os.path.join(t, f"{so}.cert")
        subprocess.run([BIN, "prove", so, "--certificate", spath], capture_output=True, cwd=ROOT)
        with open(spath, encoding="utf-8") as fh:
            scert = fh.read()
        self.expect(f"{so} (a misprinted order) is refuted by its coefficient of h^1, computed by the checker "
                    "and nonzero at the point", recheck([spath]), True, "the coefficient of t^1")
        zero = re.sub(r"^(srefute s\d+ component 1 coefficient) 1$", r"\1 0", scert, count=1, flags=re.M)
        self.expect(f"{so} refuted by its coefficient of h^0 (which is 0) is rejected",
                    recheck([write(t, "s-zero.cert", zero)]), False, "not certified nonzero")
        above = re.sub(r"^(series h step 1 order) 1\.5 ", r"\1 1 ", scert, count=1, flags=re.M)
        self.expect(f"{so} with the order in its series line lowered to 1 (h^1 no longer below it) is rejected",
                    recheck([write(t, "s-order.cert", above)]), False, "is not the claim's")
        both = scert + "".join(ln + "\n" for ln in scert.splitlines() if ln.startswith("srefute "))
        self.expect(f"{so} with a second srefute line is rejected",
                    recheck([write(t, "s-two.cert", both)]), False, "a second srefute line")
        cn = "sec3.impl-map.counter.as"
        cpath = os.path.join(t, f"{cn}.cert")
        subprocess.run([BIN, "prove", cn, "--certificate", cpath], capture_output=True, cwd=ROOT)
        self.expect(f"{cn} (a negated order) is proved by a nonzero coefficient below the order",
                    recheck([cpath]), True, "PROVED (negation)")
        ob = "sec8.lemma2.obtuse"
        opath = os.path.join(t, f"{ob}.cert")
        subprocess.run([BIN, "prove", ob, "--certificate", opath], capture_output=True, cwd=ROOT)
        with open(opath, encoding="utf-8") as fh:
            ocert = fh.read()
        self.expect(f"{ob} (a square-root branch decided by its part's condition) is proved at a point of "
                    "the domain", recheck([opath]), True, "1 of 1 domain condition(s) hold at the point")
        flipped = re.sub(r"^(sign t\d+ > 0 hypothesis part:\d+ factor) \(1\)/\(1\)$", r"\1 (-1)/(1)", ocert,
                         count=1, flags=re.M)
        self.expect(f"{ob} with the part condition's factor negated is rejected",
                    recheck([write(t, "w-part.cert", flipped)]), False, "is not the condition of part:")
        # a point with |v|^2 = 1.1: cos(theta) < 0 still (the parts hold), outside where |v|^2 > 1.2
        inside = re.sub(r"^at v1 = .*$\n^at v2 = .*$\n^at v3 = .*$",
                        "at v1 = 1 0\nat v2 = 1*2^-2 0\nat v3 = 1*2^-2 0", ocert, count=1, flags=re.M)
        self.expect(f"{ob} at a point outside the domain's condition |v|^2 > 1.2 is rejected",
                    recheck([write(t, "w-where.cert", inside)]), False, "not shown to satisfy the domain's condition")

    def complementary_periods(self):
        """A shift by iK': the quarter period K'(k) is the K of the table of modulus
        k' = sqrt(1 - k^2), one symbol in both period lines."""
        t, dlmf, cid = self.tmp, "examples/dlmf-jacobi", "dlmf.t22.4.3-sn-ikp"
        d = tempfile.mkdtemp(dir=t)
        cert = prove(cid, d, dlmf)
        self.expect(f"{cid} (sn(u + iK') = 1/(k sn u), with K'(k) the K of the modulus k') rechecks",
                    recheck([os.path.join(d, f"{cid}.cert")], "--catalogue", dlmf), True, "1 of 1 certificates")
        other = re.sub(r"^(period table 2 k=)\(r_4\*r_3\)/\(1\) kp=\(k\)/\(1\)", r"\1(r_4)/(1) kp=none", cert,
                       count=1, flags=re.M)
        self.expect(f"{cid} with the second table's modulus sqrt(1 + k), not k', sharing K'(k) is rejected",
                    recheck([write(t, "kp-link.cert", other)], "--catalogue", dlmf), False,
                    "the moduli are not complementary")

    def ode_proofs(self):
        """Proofs by the uniqueness of the solution of an ODE (module certcheck.ode), on
        the DLMF catalogue of examples/dlmf-jacobi."""
        t, dlmf = self.tmp, "examples/dlmf-jacobi"
        ids = [f"dlmf.22.7.{n}" for n in ("2.sn", "3.cn", "4.dn", "6.sn", "7.cn", "8.dn")] + \
              [f"dlmf.22.17.{n}" for n in ("2.sn", "3.cn", "4.dn")]
        d = tempfile.mkdtemp(dir=t)
        certs = {cid: prove(cid, d, dlmf) for cid in ids}
        self.expect("the 9 proofs by the ODE method of the DLMF catalogue (Landen, Gauss, the reciprocal "
                    "modulus) recheck, their formulas evaluated", recheck([d], "--catalogue", dlmf), True,
                    "9 of 9 certificates recheck (9 evaluated")
        cid = "dlmf.22.7.2.sn"
        cert = certs[cid]

        def ode_case(what, text, why, catalogue=dlmf):
            self.expect(f"{cid} {what} is rejected", recheck([write(t, "ode.cert", text)], "--catalogue", catalogue),
                        False, why)
        ode_case("with y'(0) stated 2", cert.replace("ode initial y0=(0)/(1) y1=(1)/(1)",
                                                     "ode initial y0=(0)/(1) y1=(2)/(1)"), "the `ode initial` values")
        singular = re.sub(r"^ode equation (.*)$", r"ode equation y0*(\1)", cert, count=1, flags=re.M)
        ode_case("with the ODE multiplied by y (dP/dy'' = y = 0 at u = 0: a singular starting point)",
                 singular.replace("ode nonsingular (1)/(1)", "ode nonsingular (0)/(1)"),
                 "singular starting point: dP/dy2 vanishes")
        ode_case("with the ODE multiplied by y and dP/dy'' stated 1", singular, "is not dP/dy2 at the initial point")
        ode_case("with the lhs's y'' stated as that of -sn", re.sub(r"^(ode side lhs y0=\S+ y1=\S+ y2=\()",
                                                                      r"\1-1*", cert, count=1, flags=re.M),
                 "the lhs's y2 is not its derivative computed here")
        ode_case("with the variable k (a root's radicand depends on it)",
                 cert.replace("ode var u at 0", "ode var k at 0"), "depends on k")
        cat = changed_catalogue(t, {cid}, dlmf)
        ode_case("against a catalogue copy whose rhs is changed", cert, "claim.rhs differs", cat)
        ode_case("with the same change in its source line and the catalogue copy",
                 cert.replace('source claim.rhs "', 'source claim.rhs "2 * '),
                 "the rhs's y0 is not the claim's formula evaluated here", cat)
        ctl = certs["dlmf.22.17.2.sn"].replace('"dlmf.22.17.2.sn"', '"dlmf.22.17.2.control"')
        ctl = ctl.replace('source claim.rhs "k * sn(u/k, k)"', 'source claim.rhs "sn(u/k, k) / k"')
        self.expect("the certificate of DLMF 22.17.2 bound to its misprinted control claim is rejected",
                    recheck([write(t, "ode.cert", ctl)], "--catalogue", dlmf), False,
                    "the rhs's y0 is not the claim's formula evaluated here")
        ode_case("with the ODE's cubic coefficient 2k^2 changed to 3k^2",
                 cert.replace("(2*k**2)/(1)*y0**3", "(3*k**2)/(1)*y0**3"), "does not satisfy the ODE")
        self.odd_solution(certs["dlmf.22.17.2.sn"], t)
        self.calls(t, dlmf)

    def calls(self, t, dlmf):
        """ln x and am(u, k) as opaque symbols of `call` lines, their derivatives checked:
        x'/x and dn(u, k) (DLMF 22.16.3); am(u, 0) = u (DLMF 22.16.4)."""
        ln = prove("dlmf.22.14.1", t, dlmf)
        am = prove("dlmf.22.16.3", t, dlmf)
        am0 = prove("dlmf.22.16.4", t, dlmf)
        self.expect("dlmf.22.14.1 (d/du of ln(dn - k cn)/k), dlmf.22.16.3 (d/du am = dn) and dlmf.22.16.4 "
                    "(am(u, 0) = u) recheck, evaluated", recheck([write(t, "ln.cert", ln), write(t, "am.cert", am),
                                                                   write(t, "am0.cert", am0)], "--catalogue", dlmf),
                    True, "3 of 3 certificates recheck (3 evaluated")
        arg = re.search(r"^call (\w+) = ln \((.*)\)/\((.*)\)$", ln, flags=re.M)
        # ln(X + 1) in place of ln X
        wrong = ln.replace(arg.group(0), f"call {arg.group(1)} = ln ({arg.group(2)} + {arg.group(3)})/({arg.group(3)})")
        self.expect("dlmf.22.14.1 with the argument of its ln changed is rejected",
                    recheck([write(t, "ln-bad.cert", wrong)], "--catalogue", dlmf), False, "is not X'/X of ln X")
        dv = re.search(r"^dvar u (am\w*) = .*$", am, flags=re.M)
        self.expect("dlmf.22.16.3 with d(am)/du stated as 2 is rejected",
                    recheck([write(t, "am-bad.cert", am.replace(dv.group(0), f"dvar u {dv.group(1)} = (2)/(1)"))],
                            "--catalogue", dlmf), False, "is not dn(u, k) u'")
        self.expect("dlmf.22.16.3 without its call line is rejected",
                    recheck([write(t, "am-none.cert", without(am, r"call "))], "--catalogue", dlmf), False,
                    "cannot check the derivative")

    def odd_solution(self, cert, t):
        """sn(u, 1/k) = -k sn(u/k, k): both sides solve the same ODE (its cubic is odd),
        with y'(0) = 1 and -1."""
        cat = os.path.join(tempfile.mkdtemp(dir=t), "dlmf-jacobi")
        shutil.copytree(os.path.join(ROOT, "examples", "dlmf-jacobi"), cat)
        path = os.path.join(cat, "22.x17-reciprocal-modulus.toml")
        with open(path, encoding="utf-8") as fh:
            toml = fh.read()
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(toml.replace('rhs = "k * sn(u/k, k)"', 'rhs = "-k * sn(u/k, k)"'))
        lines = []
        for ln in cert.splitlines():
            if ln.startswith("ode side rhs "):
                ln = ln.replace(")/(1)", ")/(-1)").replace(")/(k)", ")/(-k)")
            lines.append(ln.replace('source claim.rhs "k * sn', 'source claim.rhs "-k * sn'))
        self.expect("dlmf.22.17.2.sn against a copy with the rhs negated (the same ODE, y'(0) = 1 and -1) is "
                    "rejected", recheck([write(t, "odd.cert", "\n".join(lines) + "\n")], "--catalogue", cat), False,
                    "the initial values differ at u = 0")

    def all_changed(self, cert_dir, source="identities"):
        certs = [f for f in os.listdir(cert_dir) if f.endswith(".cert")]
        cat = changed_catalogue(self.tmp, source=source)
        status, output = recheck([cert_dir], "--catalogue", cat)
        passed = [ln for ln in output.splitlines() if ln.startswith("OK")]
        self.expect(f"with every claim's rhs/expr changed in a catalogue copy, none of the {len(certs)} "
                    f"certificates rechecks ({len(passed)} do)", (status, output), False, "\n0 of ")


def main(argv):
    if not os.path.exists(BIN):
        print(f"build first: {BIN} is missing", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        cases = Cases(tmp)
        cases.run()
        cases.chart_parameters()
        cases.root_part_signs()
        cases.dominant_sides()
        cases.hypothesis_signs()
        cases.multiples_of_roots()
        cases.sign_evidence()
        cases.power_series()
        cases.witnesses()
        cases.ode_proofs()
        cases.complementary_periods()
        opts = dict(zip(argv[1::2], argv[2::2]))
        if "--all" in opts:
            cases.all_changed(opts["--all"])
        if "--all-dlmf" in opts:
            cases.all_changed(opts["--all-dlmf"], os.path.join("examples", "dlmf-jacobi"))
    print(f"{cases.count - len(cases.failures)} of {cases.count} recheck tests pass")
    return 1 if cases.failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
