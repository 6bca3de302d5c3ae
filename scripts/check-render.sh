#!/usr/bin/env bash
# Renders reports/README.md, a section report and a proof page to HTML with KaTeX (pandoc),
# loads the pages in headless Chromium and asserts that the formulas typeset, every SVG
# loads and every Mermaid diagram draws. Installs pandoc and chromium (Debian packages,
# when root) and katex + mermaid + playwright-core (npm) on first use. Screenshots land in
# target/render-check/.
# Usage: scripts/check-render.sh [reports/README.md reports/02-euler-top.md ...]
set -euo pipefail
cd "$(dirname "$0")/.."
need=()
command -v pandoc >/dev/null || need+=(pandoc)
[ -x /usr/bin/chromium ] || need+=(chromium)
if [ "${#need[@]}" -gt 0 ]; then
  if [ "$(id -u)" = "0" ]; then
    (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}") >/dev/null
  else
    echo "check-render: install ${need[*]} first (sudo apt-get install ${need[*]})" >&2; exit 2
  fi
fi
out=target/render-check
mkdir -p "$out"
cp scripts/render-check/package.json scripts/render-check/check.mjs "$out/"
[ -d "$out/node_modules/katex" ] && [ -d "$out/node_modules/mermaid" ] || (cd "$out" && npm install --silent --no-audit --no-fund >/dev/null)
[ "$#" -gt 0 ] || set -- reports/README.md reports/02-euler-top.md reports/proofs/theorem-2.md
pages=()
for md in "$@"; do
  html="reports/.$(basename "$md" .md).render.html"
  pandoc "$md" -f gfm+tex_math_dollars -t html5 -s --metadata title="$(basename "$md")" \
    --katex="file://$(pwd)/$out/node_modules/katex/dist/" -o "$html"
  pages+=("$html")
done
status=0
node "$out/check.mjs" "$out" "${pages[@]}" || status=$?
rm -f "${pages[@]}"
exit $status
