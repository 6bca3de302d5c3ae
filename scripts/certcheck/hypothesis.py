"""The signs a certificate decides by a hypothesis the claim states.

A line `sign tN > 0 [square (A)/(B)] hypothesis hypothesis.NAME factor (F)/(G)` says:
the value tN (or A/B, whose square tN is) equals the hypothesis' value times F/G, and
F/G has a sign the recheck proved.  The hypothesis' value is read from the catalogue
itself (identities/hypotheses.toml, `when = "a > b"`: a - b, positive; `a < b`: a - b,
negative) and evaluated here, from the certificate's symbols, in the claim's scope.
The hypothesis must be the catalogue's table verbatim (the certificate's `source` line),
the claim must state it, and it must be a premise of the theorem; the sign it gives
must be the one stated (for a square: nonzero).
"""

from .exprlang import Parser
from .formula import claim_scope


class HypothesisMismatch(Exception):
    pass


def quantity(cert, src, when):
    """(a - b, +1 or -1) of the condition `a > b` or `a < b`, evaluated in the claim's
    scope."""
    tree = Parser(when).whole()
    if tree[0] != "bin" or tree[1] not in (">", "<"):
        raise HypothesisMismatch(f"the condition '{when}' is not a > b or a < b")
    ev, env = claim_scope(cert, src)
    a, b = (ev.components(ev.eval(t, env)) for t in tree[2:4])
    if len(a) != 1 or len(b) != 1:
        raise HypothesisMismatch(f"the condition '{when}' does not compare two numbers")
    return cert.add(a[0], b[0], -1), 1 if tree[1] == ">" else -1


def source_table(catalogue, src, claim, label):
    """The hypothesis' table in the catalogue, checked: a sign hypothesis, stated by the
    claim, written in the certificate as the catalogue has it."""
    name = label[len("hypothesis."):] if label.startswith("hypothesis.") else None
    table = catalogue.tables.get(label) if name else None
    if not isinstance(table, dict) or "when" not in table:
        raise HypothesisMismatch(f"{label} is no sign hypothesis of the catalogue")
    if name not in (claim or {}).get("hypotheses", []):
        raise HypothesisMismatch(f"the claim does not state hypothesis {name}")
    if src.get(label) != table:
        raise HypothesisMismatch(f"the certificate does not state {label} as the catalogue does")
    return table


def check(cert, src, catalogue, claim, premises):
    """Checks every sign the certificate decides by a hypothesis (see the module);
    returns the hypotheses used as {label: its table}."""
    used = {}
    for t, label, base, factor, fsign, want in cert.hyp_signs:
        if catalogue is None:
            raise HypothesisMismatch(f"sign {t}: a sign by {label} is checked against the catalogue only")
        table = source_table(catalogue, src, claim, label)
        if not any(k == "sign" and s == label for k, s, _ in premises):
            raise HypothesisMismatch(f"sign {t}: {label} is no premise of the theorem")
        try:
            q, hsign = quantity(cert, src, table["when"])
        except HypothesisMismatch:
            raise
        except Exception as e:  # noqa: BLE001 - a condition not evaluated here is no evidence
            raise HypothesisMismatch(f"sign {t}: the condition of {label} is not evaluated here ({type(e).__name__} {e})")
        if not cert.eq(base, cert.mul(q, factor)):
            raise HypothesisMismatch(f"sign {t}: its value is not the value of {label} ('{table['when']}') "
                                     "times the stated factor")
        if want is not None and hsign * fsign != want:
            raise HypothesisMismatch(f"sign {t}: {label} gives the sign {hsign * fsign:+d}, the certificate "
                                     f"states {want:+d}")
        used[label] = table
    return used
