"""The catalogue's expression language (identities/README.md), read and evaluated here
with the recheck's own arithmetic, independently of the Rust parser and prover.

Values are the certificate's quotients (scalars), tuples of three (vectors) and tuples
of three rows (3x3 matrices), and Python booleans.  What this evaluator does not cover
(the elliptic functions, the implicit maps, complex values, ...) raises Unsupported:
the claim is then bound to the catalogue by its text only, never accepted by guess.
"""

import re
from fractions import Fraction


class Unsupported(Exception):
    """The expression uses something this evaluator does not evaluate."""


class ExprError(Exception):
    """The expression is malformed."""


TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)|([A-Za-z_][A-Za-z0-9_]*)"
                   r"|(<=|>=|==|!=|[-+*/^()\[\],<>]))")
KEYWORDS = {"if", "then", "else", "and", "or", "not"}


def tokens(text):
    out, pos = [], 0
    text = text.rstrip()
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            if text[pos:].strip() == "":
                break
            raise ExprError(f"unexpected '{text[pos:pos + 10]}' in '{text[:60]}'")
        pos = m.end()
        if m.group(1) is not None:
            out.append(("n", m.group(1)))
        elif m.group(2) is not None:
            out.append(("k" if m.group(2) in KEYWORDS else "s", m.group(2)))
        else:
            out.append(("o", m.group(3)))
    return out


class Parser:
    """Reads one expression into a tree: ('num', Fraction), ('var', name),
    ('call', name, [args]), ('list', [items]), ('index', e, [i...]), ('un', op, e),
    ('bin', op, a, b), ('if', c, a, b)."""

    def __init__(self, text):
        self.toks, self.i, self.text = tokens(text), 0, text

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else ("e", None)

    def take(self, kind, val):
        if self.peek() == (kind, val):
            self.i += 1
            return True
        return False

    def expect(self, kind, val):
        if not self.take(kind, val):
            raise ExprError(f"expected '{val}' in '{self.text[:60]}'")

    def whole(self):
        e = self.expr()
        if self.i != len(self.toks):
            raise ExprError(f"unexpected '{self.peek()[1]}' in '{self.text[:60]}'")
        return e

    def expr(self):
        if self.take("k", "if"):
            c = self.expr()
            self.expect("k", "then")
            a = self.expr()
            self.expect("k", "else")
            return ("if", c, a, self.expr())
        return self.binary(0)

    LEVELS = [("k", ["or"]), ("k", ["and"]), None, ("o", ["<", ">", "<=", ">=", "==", "!="]),
              ("o", ["+", "-"]), ("o", ["*", "/"])]

    def binary(self, level):
        if level == 2:
            if self.take("k", "not"):
                return ("un", "not", self.binary(2))
            return self.binary(3)
        if level == len(self.LEVELS):
            return self.unary()
        kind, ops = self.LEVELS[level]
        a = self.binary(level + 1)
        while self.peek()[0] == kind and self.peek()[1] in ops:
            op = self.peek()[1]
            self.i += 1
            a = ("bin", op, a, self.binary(level + 1))
            if level == 3:
                break
        return a

    def unary(self):
        if self.take("o", "-"):
            return ("un", "-", self.unary())
        if self.take("o", "+"):
            return self.unary()
        base = self.postfix()
        if self.take("o", "^"):
            return ("bin", "^", base, self.unary())
        return base

    def postfix(self):
        e = self.primary()
        while self.take("o", "["):
            idx = [self.expr()]
            if self.take("o", ","):
                idx.append(self.expr())
            self.expect("o", "]")
            e = ("index", e, idx)
        return e

    def args(self, close):
        out = []
        if self.take("o", close):
            return out
        while True:
            out.append(self.expr())
            if self.take("o", close):
                return out
            self.expect("o", ",")

    def primary(self):
        kind, t = self.peek()
        self.i += 1
        if kind == "n":
            return ("num", Fraction(t))
        if kind == "s":
            if self.take("o", "("):
                return ("call", t, self.args(")"))
            return ("var", t)
        if (kind, t) == ("o", "("):
            e = self.expr()
            self.expect("o", ")")
            return e
        if (kind, t) == ("o", "["):
            return ("list", self.args("]"))
        raise ExprError(f"unexpected '{t}' in '{self.text[:60]}'")


def strip_comment(line):
    return line.split("#", 1)[0].rstrip()


FUNC = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\(([^)]*)\))?\s*=(?!=)(.*)$")


def bindings(text):
    """The lines of a `let` or `define` text: (name, params or None, tree)."""
    out = []
    for line in (text or "").splitlines():
        line = strip_comment(line)
        if not line.strip():
            continue
        m = FUNC.match(line)
        if m is None:
            raise ExprError(f"not a binding: '{line[:60]}'")
        params = None if m.group(2) is None else [p.strip() for p in m.group(2).split(",") if p.strip()]
        out.append((m.group(1), params, Parser(m.group(3)).whole()))
    return out
