#!/usr/bin/env bash
# Writes the certificate of every proved claim of the catalogue, and of every refutation
# and negation certified at a witness point, and rechecks them all
# with the second system (scripts/recheck-certificates.py, SymPy), bound to the claims as
# the catalogue writes them.  Usage:
#   scripts/recheck-all-certificates.sh [--catalogue DIR] [OUT_DIR]
# (default: the paper's catalogue, identities/, into target/certificates; with
# --catalogue, e.g. examples/dlmf-jacobi, that catalogue's claims).  Exit status 0 when
# every certificate rechecks.  A proved claim whose proof takes a step the certificate
# format does not record has no certificate; those are listed and counted, not rechecked.
set -euo pipefail
cd "$(dirname "$0")/.."
catalogue=identities
if [ "${1:-}" = "--catalogue" ]; then
  catalogue="${2:?--catalogue takes a directory}"
  shift 2
fi
out="${1:-target/certificates}"
jobs="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
bin=target/release/eulertop
[ -x "$bin" ] || cargo build --release --quiet
# the paper's catalogue is built into the binary; another one is read from its directory
cat_opt=()
[ "$catalogue" = identities ] || cat_opt=(--catalogue "$catalogue")
rm -rf "$out" && mkdir -p "$out"
SECONDS=0
"$bin" verify --format json --jobs "$jobs" "${cat_opt[@]}" >"$out/verify.json" || true
python3 - "$out/verify.json" "$out/witness.list" >"$out/proved.list" <<'PY'
import json, sys
with open(sys.argv[2], "w") as witnessed:
    for c in json.load(open(sys.argv[1]))["claims"]:
        method = c.get("proof", {}).get("method")
        if c.get("verdict") in ("proved", "construction") and method in ("symbolic", "series", "ode"):
            print(c["id"])
        elif method == "witness":  # a refutation, or a negation, certified at a point
            print(c["id"], file=witnessed)
PY
# one prove per claim, $jobs at a time; a claim without a certificate says why on stderr
cat "$out/proved.list" "$out/witness.list" |
  xargs -P "$jobs" -I{} bash -c '"$0" prove "$1" --certificate "$2/$1.cert" "${@:3}" >/dev/null 2>"$2/$1.err"' \
  "$bin" {} "$out" "${cat_opt[@]}" || true
written=$(for id in $(cat "$out/proved.list"); do [ -f "$out/$id.cert" ] && echo; done | wc -l)
proved=$(wc -l <"$out/proved.list")
witnessed=$(for id in $(cat "$out/witness.list"); do [ -f "$out/$id.cert" ] && echo; done | wc -l)
echo "recheck: $written certificates written for $proved proved claims; $witnessed witness certificates for $(wc -l <"$out/witness.list") refutations and negations certified at a point"
for f in "$out"/*.err; do
  [ -s "$f" ] && echo "  no certificate: $(basename "$f" .err): $(head -c 300 "$f" | sed 's/.*: no certificate written to [^:]*: //')"
done
python3 scripts/recheck-certificates.py --catalogue "$catalogue" --jobs "$jobs" "$out" >"$out/recheck.log" && status=0 || status=$?
# a proof must not depend on whether a certificate is asked for
while read -r id; do
  if grep -q "the claim is not proved" "$out/$id.err" 2>/dev/null; then
    echo "recheck: $id is proved by verify but not by prove --certificate"
    status=1
  fi
done <"$out/proved.list"
grep -v -e '^OK' -e '^      ' "$out/recheck.log" || true
echo "recheck: $(tail -1 "$out/recheck.log"); ${SECONDS} s wall for verify, writing and rechecking"
exit "$status"
