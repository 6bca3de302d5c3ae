#!/usr/bin/env bash
# Writes the Coq script of proved claims (`eulertop prove ID --coq FILE`) and compiles
# each with coqc, the Coq kernel checking every step.  Usage:
#   scripts/check-coq.sh [OUT_DIR]        (default target/coq)
# The claims: the four families of the design (the addition formulae, the (ws)
# identities with (ident 1) and (ident 2), G1 - k^2 sn^2 G0 = k^2 nu^2 cn^2 dn^2, and
# Lemma 2) and then further proved claims while the budget lasts (COQ_BUDGET seconds of
# wall time, default 180, on JOBS parallel coqc, default 2; each coqc at most
# COQ_TIMEOUT seconds, default 20, and a family's at most COQ_FAMILY_TIMEOUT, default 120,
# as the families must compile: a longer one is listed as a timeout).  Every compiled script's
# `Print Assumptions` must list only the variables and hypotheses it declares and the
# axioms of Coq's real numbers.  A negative check: a script with one relation's sign
# flipped, and one with its claim changed, must fail to compile.  Exit status 0 when no written script fails to compile
# (a timeout is listed, not a failure) and both corrupted ones do.

set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-target/coq}"
jobs="${JOBS:-2}"
budget="${COQ_BUDGET:-180}"
bin=target/release/eulertop
command -v coqc >/dev/null 2>&1 || { echo "check-coq: coqc missing (scripts/ensure-deps.sh installs coq)" >&2; exit 2; }
[ -x "$bin" ] || cargo build --release --quiet
rm -rf "$out" && mkdir -p "$out"
SECONDS=0
# the families
families="bg.dlmf-22.8.1.sn-addition bg.dlmf-22.8.2.cn-addition bg.dlmf-22.8.3.dn-addition
sec5.ws.w1-w3 sec5.ws.w1-w2 sec5.ident1.123 sec5.ident1.132 sec5.ident1.213 sec5.ident1.231
sec5.ident1.312 sec5.ident1.321 sec5.ident2.123.corrected sec5.ident2.132.corrected
sec5.ident2.213.corrected sec5.ident2.231.corrected sec5.ident2.312.corrected
sec5.ident2.321.corrected sec8.G0G1.up sec8.G0G1.lo sec8.lemma2.model"
# then the other proved claims, the smallest certificates first when
# scripts/recheck-all-certificates.sh has written them (target/certificates), else the
# proved claims of `eulertop verify` in catalogue order
certs="${CERTS:-target/certificates}"
if [ -s "$certs/proved.list" ]; then
  # the proofs' certificates only (not the witness certificates of refutations)
  proved=$(ls -S -r "$certs"/*.cert 2>/dev/null | xargs -r -n1 basename | sed 's/\.cert$//' |
    grep -x -F -f "$certs/proved.list" || true)
else
  proved=$("$bin" verify --format json --jobs "$jobs" | python3 -c '
import json, sys
for c in json.load(sys.stdin)["claims"]:
    if c.get("verdict") in ("proved", "construction") and c.get("proof", {}).get("method") == "symbolic":
        print(c["id"])' || true)
fi
others=$(printf '%s\n' "$proved" | grep -v -x -F -f <(tr ' ' '\n' <<<"$families" | sed '/^$/d') || true)
deadline=$(($(date +%s) + budget))
# one claim: write its script, compile it, check its assumptions; one line of result
# (a claim of the budget's part is skipped once the deadline has passed)
one() {
  local id="$1" dir="$2" bin="$3" deadline="$4" limit="$5"
  local name
  name="c_$(printf '%s' "$id" | tr -c 'A-Za-z0-9_' '_')"
  if [ "$deadline" != 0 ] && [ "$(date +%s)" -ge "$deadline" ]; then
    echo "skipped $id"
    return 0
  fi
  if ! "$bin" prove "$id" --coq "$dir/$name.v" >/dev/null 2>"$dir/$name.err"; then
    echo "nocoq $id: $(sed 's/.*no Coq script written to [^:]*: //' "$dir/$name.err" | head -c 200)"
    return 0
  fi
  local t0=$SECONDS rc=0
  (cd "$dir" && timeout "$limit" coqc "$name.v" >"$name.log" 2>&1) || rc=$?
  if [ "$rc" = 124 ]; then
    echo "timeout $id: coqc takes more than $limit s"
    return 0
  elif [ "$rc" != 0 ]; then
    echo "FAIL $id: $(grep -m1 -A2 'Error' "$dir/$name.log" | tr '\n' ' ' | head -c 200)"
    return 0
  fi
  if ! python3 scripts/coq-assumptions.py "$dir/$name.v" "$dir/$name.log"; then
    echo "FAIL $id (assumptions)"
    return 0
  fi
  echo "OK $id $((SECONDS - t0)) s"
}
export -f one
tr ' ' '\n' <<<"$families" | sed '/^$/d' |
  xargs -P "$jobs" -I{} bash -c 'one "$@"' _ {} "$out" "$bin" 0 "${COQ_FAMILY_TIMEOUT:-120}" >"$out/results.txt"
family_ok=$(grep -c '^OK' "$out/results.txt" || true)
family_time=$SECONDS
printf '%s\n' "$others" | sed '/^$/d' |
  xargs -P "$jobs" -I{} bash -c 'one "$@"' _ {} "$out" "$bin" "$deadline" "${COQ_TIMEOUT:-20}" >>"$out/results.txt"
status=0
negative=rejected
grep -v '^OK\|^skipped' "$out/results.txt" | sort || true
grep -q '^FAIL' "$out/results.txt" && status=1
# a family's script that is written must compile (a timeout of one is a failure)
if grep -q '^timeout' <(head -n "$(tr ' ' '\n' <<<"$families" | sed '/^$/d' | wc -l)" "$out/results.txt"); then
  echo "check-coq: a script of the families takes more than ${COQ_FAMILY_TIMEOUT:-120} s"; status=1
fi
# the negative check, on sn^2 + cn^2 = 1 (whose proof uses the relation
# cn_1^2 = 1 - sn_1^2): the script compiles; with that relation's sign flipped, or with
# the claim stated as lhs - rhs = 1, it must fail to compile
neg="c_negative_check"
"$bin" prove bg.dlmf-22.6.1.sn-cn --coq "$out/$neg.v" >/dev/null
# (the relation flipped in the hypothesis and in the steps that use it, consistently)
sed '/rel_cn_1/s/(- sn_1 ^ 2 + 1)/(sn_1 ^ 2 + 1)/g' "$out/$neg.v" >"$out/c_corrupt_relation.v"
sed 's/^\(Theorem claim_holds : .*\) = 0\.$/\1 = 1./' "$out/$neg.v" >"$out/c_corrupt_claim.v"
if ! (cd "$out" && coqc "$neg.v" >"$neg.log" 2>&1); then
  echo "check-coq: the script of the negative check does not compile"; status=1; negative=failed
fi
for c in c_corrupt_relation c_corrupt_claim; do
  if cmp -s "$out/$neg.v" "$out/$c.v"; then
    echo "check-coq: the corruption $c changed nothing"; status=1; negative=failed
  elif (cd "$out" && coqc "$c.v" >"$c.log" 2>&1); then
    echo "check-coq: the corrupted script $c compiles"; status=1; negative=failed
  fi
done
ok=$(grep -c '^OK' "$out/results.txt" || true)
count() { grep -c "^$1" "$out/results.txt" || true; }
echo "check-coq: the families: $family_ok scripts compile in ${family_time} s wall"
echo "check-coq: $ok Coq scripts compile, $(count FAIL) fail, $(count timeout) take more than ${COQ_TIMEOUT:-20} s, $(count nocoq) claims have none, $(count skipped) skipped for the budget; the corrupted scripts: $negative; ${SECONDS} s wall"
exit "$status"
