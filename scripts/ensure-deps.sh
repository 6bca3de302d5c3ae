#!/usr/bin/env bash
# Makes sure the system tools that the bundled builds need are present:
#   m4    for GMP/MPFR (gmp-mpfr-sys),
#   clang for the small C wrapper of FLINT's inline functions (flint-sys).
# Installs the missing ones with apt-get when running as root; otherwise stops with
# one line saying what to install.  Announces the one-time FLINT build, which takes a
# few minutes and is then cached.
set -euo pipefail
missing=()
command -v m4 >/dev/null 2>&1 || missing+=(m4)
command -v clang >/dev/null 2>&1 || missing+=(clang)
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    echo "eulertop: installing ${missing[*]} (needed by the bundled GMP and FLINT builds)" >&2
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}") >/dev/null
  else
    echo "eulertop: ${missing[*]} missing; install first (sudo apt-get install ${missing[*]}), needed to build GMP and FLINT" >&2
    exit 2
  fi
fi
# The second system that rechecks the certificates (scripts/recheck-certificates.py)
# needs Python 3.11 or later (tomllib) and SymPy.  pip installs SymPy for the user (on a
# system that marks its Python as externally managed, with --break-system-packages);
# where there is no pip, apt-get installs python3-sympy when running as root.
if command -v python3 >/dev/null 2>&1 && ! python3 -c 'import sympy, tomllib' >/dev/null 2>&1; then
  echo "eulertop: installing SymPy (for the recheck of the certificates)" >&2
  if python3 -m pip --version >/dev/null 2>&1; then
    python3 -m pip install -q sympy >/dev/null 2>&1 ||
      python3 -m pip install -q --break-system-packages sympy >/dev/null
  elif [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-sympy) >/dev/null
  else
    echo "eulertop: SymPy missing; install it first (python3 -m pip install sympy), needed to recheck certificates" >&2
    exit 2
  fi
elif ! command -v python3 >/dev/null 2>&1; then
  if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    echo "eulertop: installing python3 and SymPy (for the recheck of the certificates)" >&2
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3 python3-sympy) >/dev/null
  else
    echo "eulertop: python3 missing; install it first (sudo apt-get install python3 python3-sympy), needed to recheck certificates" >&2
    exit 2
  fi
fi
# The Coq proof assistant compiles the Coq scripts of the proofs (scripts/check-coq.sh,
# `eulertop prove ID --coq FILE`); apt-get installs it when running as root.
if ! command -v coqc >/dev/null 2>&1; then
  if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    echo "eulertop: installing coq (for the Coq check of the proofs)" >&2
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq coq) >/dev/null
  else
    # not needed to build or test: only scripts/check-coq.sh stops without it
    echo "eulertop: coq missing; install it (sudo apt-get install coq) to check the Coq scripts" >&2
  fi
fi
# flint-sys keeps a built FLINT under $FLINT_SYS_CACHE or the user cache directory.
cache="${FLINT_SYS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/flint-sys}"
if ! ls "$cache"/*/libflint.a >/dev/null 2>&1 && ! ls target/release/build/flint-sys-*/out/lib/libflint.a >/dev/null 2>&1; then
  echo "eulertop: the first build compiles FLINT 3 (bundled by flint-sys); this takes a few minutes" >&2
  echo "eulertop: (about 4 minutes of CPU time); later builds reuse $cache" >&2
fi
