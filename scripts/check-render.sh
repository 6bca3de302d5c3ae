#!/usr/bin/env bash
# Renders reports/README.md, a section report and proof pages to HTML with KaTeX (pandoc),
# in a text column of GitHub's width (830 px), loads the pages in headless Chromium and
# asserts that the formulas typeset, every SVG loads, every Mermaid diagram draws, no text
# is shown smaller than 8 px (diagrams and figures at the scale they are shown) and nothing
# runs past the column or scrolls sideways. Installs pandoc and chromium (Debian packages,
# when root) and katex + mermaid + playwright-core (npm) on first use. Screenshots of every
# page checked (its top, each diagram, each figure, each failing element) land in
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
[ "$#" -gt 0 ] || set -- reports/README.md reports/02-euler-top.md reports/04-elliptic-coordinates.md \
  reports/proofs/theorem-2.md reports/proofs/proposition-6.md reports/proofs/lemma-2.md
# GitHub shows a Markdown file in a column about 830 px wide (pandoc's own is 36em), scales
# images down to it and lays a table out at the width of its unwrapped content, scrolling
# when that is wider than the column
printf '%s\n' 'body { max-width: 830px; }' 'img { max-width: 100%; }' \
  'table { display: block; width: max-content; max-width: 100%; overflow: auto; }' >"$out/page.css"
rm -f "$out"/*.png
pages=()
for md in "$@"; do
  # next to the Markdown file, so that its relative links and images resolve
  html="$(dirname "$md")/.$(basename "$md" .md).render.html"
  pandoc "$md" -f gfm+tex_math_dollars -t html5 -s --metadata title="$(basename "$md")" \
    --katex="file://$(pwd)/$out/node_modules/katex/dist/" -c "file://$(pwd)/$out/page.css" -o "$html"
  pages+=("$html")
done
status=0
node "$out/check.mjs" "$out" "${pages[@]}" || status=$?
rm -f "${pages[@]}"
exit $status
