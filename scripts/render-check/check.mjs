// Loads rendered report pages in headless Chromium and asserts that the math typeset
// (no raw `$$` or `\(` left, no KaTeX errors), that every image loaded, that every
// Mermaid diagram renders (with the mermaid package, as GitHub does), that no text is
// drawn smaller than MIN_PX pixels (HTML text, Mermaid labels and the text of SVG
// figures, each at the scale it is shown at) and that nothing runs past the right edge
// of the page's text column or scrolls sideways.  Writes screenshots of every page
// checked: the top of the page, each diagram and each figure, and each element that
// fails a size or overflow check.
// Usage: node check.mjs OUTDIR page1.html page2.html ...
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import path from 'node:path';

const MIN_PX = 8;
const [outDir, ...pages] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--no-first-run'],
});
let failures = 0;

// Replaces every `<pre class="mermaid">` block (pandoc's rendering of a mermaid code
// block) by its SVG; returns the number drawn and the parse errors.
async function renderMermaid(p) {
  const n = await p.evaluate(() => document.querySelectorAll('pre.mermaid').length);
  if (n === 0) return { ok: 0, errors: [] };
  await p.addScriptTag({ path: path.join(outDir, 'node_modules/mermaid/dist/mermaid.min.js') });
  return await p.evaluate(async () => {
    mermaid.initialize({ startOnLoad: false, securityLevel: 'strict' });
    let ok = 0;
    const errors = [];
    const blocks = [...document.querySelectorAll('pre.mermaid')];
    for (const [k, pre] of blocks.entries()) {
      try {
        const { svg } = await mermaid.render('mermaid-' + k, pre.textContent);
        const div = document.createElement('div');
        div.className = 'mermaid-drawn';
        div.innerHTML = svg;
        pre.replaceWith(div);
        ok++;
      } catch (e) {
        errors.push(String(e && e.message ? e.message : e).slice(0, 300));
      }
    }
    return { ok, errors };
  });
}

// The smallest text drawn on the page, in screen pixels: every visible element that
// holds text, its computed font size times the scale of the SVG it sits in (Mermaid
// labels, SVG text).  Marks the elements below `min` with data-small for screenshots.
function smallText(min) {
  const small = [];
  let least = Infinity;
  const seen = new Set();
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  while (walker.nextNode()) {
    const t = walker.currentNode;
    const el = t.parentElement;
    if (!/[^\s\u200b]/.test(t.nodeValue) || !el || seen.has(el) || el.closest('.katex-mathml')) continue;
    seen.add(el);
    const r = el.getBoundingClientRect();
    const cs = getComputedStyle(el);
    if (r.width <= 1 || r.height <= 1 || cs.visibility === 'hidden') continue;
    let px = parseFloat(cs.fontSize);
    const svg = el.closest('svg');
    if (svg) {
      const m = (el instanceof SVGGraphicsElement ? el : svg).getScreenCTM();
      if (m) px *= Math.hypot(m.a, m.b);
    }
    least = Math.min(least, px);
    if (px < min) {
      const box = svg ? svg.closest('.mermaid-drawn') || svg : el;
      box.setAttribute('data-small', '1');
      small.push(`${px.toFixed(1)} px: "${t.nodeValue.trim().slice(0, 50)}"`);
    }
  }
  return { least, small };
}

// Elements that run past the right edge of the text column (body's content box) or
// that scroll sideways; marks them with data-overflow for screenshots.
function overflow() {
  const body = document.body;
  const cs = getComputedStyle(body);
  // a few pixels of an inline element's padding at a line's end are not an overflow
  const right = body.getBoundingClientRect().right - parseFloat(cs.paddingRight) + 4;
  const out = [];
  for (const el of body.querySelectorAll('*')) {
    if (el.closest('svg, .katex, details:not([open]) > :not(summary)')) continue;
    const r = el.getBoundingClientRect();
    const st = getComputedStyle(el);
    const ox = st.overflowX;
    const scrolls = (ox === 'auto' || ox === 'scroll') && el.scrollWidth > el.clientWidth + 1;
    // an inline element that wraps may hang a space past the line's end
    const slack = st.display === 'inline' ? 8 : 0;
    if ((r.width > 0 && r.right > right + slack) || scrolls) {
      // report the outermost offender only
      if (el.parentElement && el.parentElement.hasAttribute('data-overflow')) {
        el.setAttribute('data-overflow', '1');
        continue;
      }
      el.setAttribute('data-overflow', '1');
      const what = scrolls ? `scrolls sideways by ${el.scrollWidth - el.clientWidth} px`
                           : `runs ${Math.round(r.right - right)} px past the column`;
      out.push(`<${el.tagName.toLowerCase()}> ${what}: "${el.textContent.trim().slice(0, 60)}"`);
    }
  }
  return out;
}

// The smallest font size of each SVG figure shown with <img>, at the scale it is shown.
async function figureText(p, page) {
  const imgs = await p.evaluate(() => [...document.images].map(i => ({
    src: i.getAttribute('src'), shown: i.getBoundingClientRect().width, natural: i.naturalWidth,
  })));
  const out = [];
  for (const im of imgs) {
    if (!im.src || !im.src.endsWith('.svg') || !im.natural) continue;
    const file = path.resolve(path.dirname(page), decodeURIComponent(im.src));
    if (!fs.existsSync(file)) continue;
    const text = fs.readFileSync(file, 'utf8');
    const sizes = [...text.matchAll(/font-size(?:="|:\s*)([\d.]+)/g)].map(m => parseFloat(m[1]));
    if (sizes.length === 0) continue;
    const px = Math.min(...sizes) * im.shown / im.natural;
    out.push({ src: im.src, px });
  }
  return out;
}

// Screenshots: the top of the page, each diagram, each figure and each offender.
async function screenshots(p, base) {
  await p.screenshot({ path: path.join(outDir, base + '.png'), fullPage: false });
  const shoot = async (sel, tag, limit) => {
    const els = await p.$$(sel);
    for (const [k, el] of els.slice(0, limit).entries()) {
      await el.screenshot({ path: path.join(outDir, `${base}.${tag}-${k + 1}.png`) }).catch(() => {});
    }
  };
  await shoot('.mermaid-drawn', 'diagram', 20);
  await shoot('img', 'figure', 20);
  await shoot('[data-small]', 'small-text', 5);
  await shoot('[data-overflow]:not([data-overflow] *)', 'overflow', 5);
}

for (const page of pages) {
  const p = await browser.newPage({ viewport: { width: 1100, height: 1400 } });
  await p.goto('file://' + path.resolve(page), { waitUntil: 'load' });
  await p.waitForTimeout(500);
  const diagrams = await renderMermaid(p);
  const r = await p.evaluate(() => {
    const text = document.body.innerText;
    const imgs = [...document.images].map(i => ({ src: i.getAttribute('src'), ok: i.complete && i.naturalWidth > 0 }));
    return {
      rawDisplay: (text.match(/\$\$/g) || []).length,
      rawInline: (text.match(/\\\(|\\\[/g) || []).length,
      katex: document.querySelectorAll('.katex').length,
      katexErrors: [...document.querySelectorAll('.katex-error')].map(e => e.getAttribute('title') || e.textContent).slice(0, 5),
      imgs,
    };
  });
  const sizes = await p.evaluate(smallText, MIN_PX);
  const wide = await p.evaluate(overflow);
  const figs = await figureText(p, page);
  const smallFigs = figs.filter(f => f.px < MIN_PX);
  const least = Math.min(sizes.least, ...figs.map(f => f.px));
  const bad = r.imgs.filter(i => !i.ok);
  const ok = r.rawDisplay === 0 && r.rawInline === 0 && r.katexErrors.length === 0 && bad.length === 0 &&
             diagrams.errors.length === 0 && sizes.small.length === 0 && smallFigs.length === 0 &&
             wide.length === 0;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${page}: ${r.katex} formulas typeset, ${r.katexErrors.length} KaTeX errors, ` +
              `${r.rawDisplay} raw $$, ${r.imgs.length - bad.length}/${r.imgs.length} images loaded, ` +
              `${diagrams.ok} diagrams drawn, smallest text ${least.toFixed(1)} px (at least ${MIN_PX}), ` +
              `${wide.length} elements too wide`);
  for (const e of r.katexErrors) console.log(`     KaTeX error: ${e}`);
  for (const e of diagrams.errors) console.log(`     Mermaid error: ${e}`);
  for (const b of bad) console.log(`     image failed: ${b.src}`);
  for (const s of sizes.small.slice(0, 5)) console.log(`     text too small: ${s}`);
  if (sizes.small.length > 5) console.log(`     ... ${sizes.small.length - 5} more texts too small`);
  for (const f of smallFigs) console.log(`     figure text too small: ${f.src}: ${f.px.toFixed(1)} px`);
  for (const w of wide.slice(0, 5)) console.log(`     too wide: ${w}`);
  if (wide.length > 5) console.log(`     ... ${wide.length - 5} more elements too wide`);
  if (!ok) failures++;
  // visible names: `.README.render.html` gives README.png, README.diagram-1.png, ...
  await screenshots(p, path.basename(page, '.html').replace(/^\./, '').replace(/\.render$/, ''));
  await p.close();
}
await browser.close();
console.log(`${pages.length - failures} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);
