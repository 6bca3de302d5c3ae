#!/usr/bin/env bash
# The test command: sets up what the build needs, then runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
cargo test --release "$@"
