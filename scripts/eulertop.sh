#!/usr/bin/env bash
# The main command: sets up what the build needs, builds eulertop in release mode
# and runs it with the given arguments (default: the verification report).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo build --release
if [ "$#" -eq 0 ]; then set -- report; fi
exec ./target/release/eulertop "$@"
