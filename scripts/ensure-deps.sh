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
# flint-sys keeps a built FLINT under $FLINT_SYS_CACHE or the user cache directory.
cache="${FLINT_SYS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/flint-sys}"
if ! ls "$cache"/*/libflint.a >/dev/null 2>&1 && ! ls target/release/build/flint-sys-*/out/lib/libflint.a >/dev/null 2>&1; then
  echo "eulertop: the first build compiles FLINT 3 (bundled by flint-sys); this takes a few minutes" >&2
  echo "eulertop: (about 4 minutes of CPU time); later builds reuse $cache" >&2
fi
