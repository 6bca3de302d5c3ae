#!/usr/bin/env python3
"""Checks what a compiled Coq export rests on (scripts/check-coq.sh).

Usage: coq-assumptions.py SCRIPT.v COQC_OUTPUT

The script must hold no Admitted, admit, Axiom, Parameter or Conjecture, and the output
of its `Print Assumptions` must list only section variables and hypotheses the script
declares (Variable(s), Hypothesis) and, as axioms, only those of Coq's real numbers.
Exit status 0 when it does; otherwise one line saying what is wrong.
"""
import re
import sys

REAL_AXIOMS = {
    "ClassicalDedekindReals.sig_forall_dec",
    "ClassicalDedekindReals.sig_not_dec",
    "FunctionalExtensionality.functional_extensionality_dep",
}


def declared(script):
    """The names the script declares as section variables or hypotheses."""
    names = set()
    for m in re.finditer(r"^Variables? ([^:]+):", script, re.M):
        names.update(m.group(1).split())
    for m in re.finditer(r"^Hypothesis (\S+) :", script, re.M):
        names.add(m.group(1))
    return names


def printed(output):
    """The (section variables, axioms) that `Print Assumptions` lists."""
    groups = {"Section Variables:": set(), "Axioms:": set()}
    current = None
    for line in output.splitlines():
        if line in groups:
            current = groups[line]
        elif current is not None and line and not line[0].isspace() and line[0] != ":":
            current.add(line.split(" :")[0].strip())
    return groups["Section Variables:"], groups["Axioms:"]


def main():
    script = open(sys.argv[1]).read()
    output = open(sys.argv[2]).read()
    bad = re.search(r"\b(Admitted|admit|Axiom|Parameter|Conjecture)\b", script)
    if bad:
        sys.exit(f"{sys.argv[1]}: the script uses {bad.group(1)}")
    heads = ("Section Variables:", "Axioms:", "Closed under the global context")
    if not any(h in output for h in heads):
        sys.exit(f"{sys.argv[2]}: no output of Print Assumptions")
    variables, axioms = printed(output)
    undeclared = variables - declared(script)
    if undeclared:
        sys.exit(f"{sys.argv[1]}: rests on undeclared {sorted(undeclared)}")
    if axioms - REAL_AXIOMS:
        sys.exit(f"{sys.argv[1]}: rests on the axioms {sorted(axioms - REAL_AXIOMS)}")


if __name__ == "__main__":
    main()
