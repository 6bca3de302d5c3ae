#!/usr/bin/env bash
# Regenerates the verification reports and the accuracy tables into a temporary
# directory and fails when the committed reports/ (or the README's verdict block)
# differ. performance.md holds measured timings (see its commands) and is not compared.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo build --release --quiet
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp README.md "$tmp/README.md"
./target/release/eulertop report --out "$tmp/reports" --readme "$tmp/README.md" --jobs 2
status=0
diff -r --exclude=accuracy.md --exclude=performance.md --exclude='.*' reports "$tmp/reports" >"$tmp/diff" || status=$?
diff README.md "$tmp/README.md" >>"$tmp/diff" || status=$?
cargo run --release --quiet --example accuracy >"$tmp/accuracy.md"
diff reports/accuracy.md "$tmp/accuracy.md" >>"$tmp/diff" || status=$?
if [ "$status" -ne 0 ]; then
  head -40 "$tmp/diff"
  echo "reports/ or README.md is stale: run 'scripts/eulertop.sh report' (and, for accuracy.md, 'cargo run --release --example accuracy > reports/accuracy.md') and commit the result" >&2
  exit 1
fi
echo "reports are fresh"
