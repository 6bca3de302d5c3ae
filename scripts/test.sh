#!/usr/bin/env bash
# The test command: sets up what the build needs, then runs the whole test suite of the
# workspace (the eulertop crate and crates/eulertop-numerics, its default members).
# Arguments are passed to `cargo test --release` (a filter, `--test paper`, ...).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
if [ "$#" -gt 0 ]; then
  exec cargo test --release "$@"
fi
# Without arguments: what `cargo test --release` runs, with the documentation examples
# compiled and run beside the test binaries rather than after them.  Most of the
# examples' time is rustdoc and rustc on one core, so on 2 cores this takes about
# 0.3 s less wall time (reports/performance.md).  Their report follows the others'.
cargo test --release --no-run
doc_log="$(mktemp)"
trap 'rm -f "$doc_log"' EXIT
cargo test --release --doc >"$doc_log" 2>&1 &
doc=$!
status=0
cargo test --release --lib --bins --tests || status=$?
doc_status=0
wait "$doc" || doc_status=$?
cat "$doc_log"
[ "$status" -ne 0 ] && exit "$status"
exit "$doc_status"
