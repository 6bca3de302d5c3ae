"""Binds a certificate to its claim in the catalogue.

The certificate's `source` lines carry the claim's fields verbatim (JSON): its id and
file, the fields that say what is claimed (kind, domain, vars, where, let, lhs, rhs,
expr, wrt, hypotheses), the tables of its domain and hypotheses, and every definition
its formulas call.  This module reads the same from the catalogue with tomllib and
reports the first difference.
"""

import json
import os
import re
import tomllib

CLAIM_FIELDS = ["kind", "domain", "vars", "where", "let", "lhs", "rhs", "expr", "wrt", "var", "order",
                "unknowns", "equations", "start", "in", "hypotheses", "inner"]
IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


class BindError(Exception):
    pass


def scanned(v):
    """The text scanned for the names of definitions: a string as written, else JSON."""
    return v if isinstance(v, str) else json.dumps(v, ensure_ascii=False)


def defined_names(text):
    out = []
    for line in text.splitlines():
        m = re.match(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*\(", line)
        if m:
            out.append(m.group(1))
    return out


class Catalogue:
    """Every claim by id (with its file name), definitions by the names they define, the
    domain and hypothesis tables."""

    def __init__(self, path):
        self.path, self.claims, self.defines, self.tables = path, {}, {}, {}
        if not os.path.isdir(path):
            raise BindError(f"no catalogue directory {path}")
        for f in sorted(os.listdir(path)):
            if f.endswith(".toml"):
                self.add(f)

    def add(self, f):
        try:
            with open(os.path.join(self.path, f), "rb") as fh:
                data = tomllib.load(fh)
        except (OSError, tomllib.TOMLDecodeError) as e:
            raise BindError(f"{os.path.join(self.path, f)}: {e}")
        for group in ("domain", "hypothesis"):
            for k, v in data.get(group, {}).items():
                self.tables[f"{group}.{k}"] = v
        for c in data.get("claim", []):
            if "id" not in c:
                continue
            if isinstance(c.get("define"), str):
                for name in defined_names(c["define"]):
                    self.defines[name] = (c["id"], c["define"])
            self.claims[c["id"]] = (f, c)

    def expected(self, cid):
        """The source lines the catalogue implies for claim cid: [(key, value)]."""
        if cid not in self.claims:
            raise BindError(f"claim {cid} is not in the catalogue {self.path}")
        f, c = self.claims[cid]
        out = [("id", cid), ("file", f)]
        texts = []
        for k in CLAIM_FIELDS:
            if k in c:
                out.append((f"claim.{k}", c[k]))
                texts.append(scanned(c[k]))
        tables = [f"domain.{c['domain']}"] if isinstance(c.get("domain"), str) else []
        tables += [f"hypothesis.{h}" for h in c.get("hypotheses", []) if isinstance(h, str)]
        for t in tables:
            if t in self.tables:
                out.append((t, self.tables[t]))
                texts.append(scanned(self.tables[t]))
        used, seen, todo = {}, set(), [n for t in texts for n in IDENT.findall(t)]
        while todo:
            name = todo.pop()
            if name in seen:
                continue
            seen.add(name)
            if name in self.defines:
                did, text = self.defines[name]
                if did not in used:
                    used[did] = text
                    todo.extend(IDENT.findall(text))
        for did in sorted(used):
            out.append((f"define.{did}", used[did]))
        return out


def source_lines(text):
    """The certificate's `source` lines as [(key, value)], in order."""
    out = []
    for ln, line in enumerate(text.splitlines(), 1):
        if line.startswith("source "):
            key, _, val = line[len("source "):].partition(" ")
            try:
                out.append((key, json.loads(val)))
            except json.JSONDecodeError as e:
                raise BindError(f"line {ln}: source {key}: not a JSON value ({e})")
    return out


def short(v):
    s = json.dumps(v, ensure_ascii=False)
    return s if len(s) <= 100 else s[:97] + "..."


def compare(got, want):
    """None when the certificate's source lines are the catalogue's, else the first
    difference as one sentence."""
    for i in range(max(len(got), len(want))):
        g = got[i] if i < len(got) else None
        w = want[i] if i < len(want) else None
        if g == w:
            continue
        if g is None:
            return f"the certificate lacks source {w[0]} = {short(w[1])} of the catalogue"
        if w is None:
            return f"the certificate's source {g[0]} = {short(g[1])} is not in the catalogue"
        if g[0] != w[0]:
            return f"the certificate has source {g[0]} where the catalogue has {w[0]} = {short(w[1])}"
        return f"{g[0]} differs: the certificate has {short(g[1])}, the catalogue {short(w[1])}"
    return None


def bind(text, catalogue):
    """(claim id, its catalogue table, the source dict) of a certificate text, or
    BindError with the first difference."""
    got = source_lines(text)
    if not got or got[0][0] != "id" or not isinstance(got[0][1], str):
        raise BindError("no `source id` line: the certificate is not bound to a claim")
    cid = got[0][1]
    diff = compare(got, catalogue.expected(cid))
    if diff:
        raise BindError(f"claim {cid}: {diff}")
    return cid, catalogue.claims[cid][1], dict(got)


def premises(text):
    """The certificate's premise lines: [(kind, source, statement)]."""
    out = []
    for ln, line in enumerate(text.splitlines(), 1):
        if line.startswith("premise "):
            parts = line.split(" ", 3)
            if len(parts) != 4:
                raise BindError(f"line {ln}: malformed premise")
            try:
                out.append((parts[1], parts[2], json.loads(parts[3])))
            except json.JSONDecodeError as e:
                raise BindError(f"line {ln}: premise statement is not a JSON string ({e})")
    return out
