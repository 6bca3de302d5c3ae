#!/usr/bin/env bash
# Makes sure the system tools that the bundled GMP/MPFR build needs are present.
# Installs m4 with apt-get when running as root; otherwise stops with one line.
set -euo pipefail
if ! command -v m4 >/dev/null 2>&1; then
  if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    echo "eulertop: installing m4 (needed by the bundled GMP build)" >&2
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq m4) >/dev/null
  else
    echo "eulertop: m4 is missing; install it first (sudo apt-get install m4), it is needed to build GMP" >&2
    exit 2
  fi
fi
