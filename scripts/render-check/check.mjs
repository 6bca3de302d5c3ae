// Loads rendered report pages in headless Chromium and asserts that the math typeset
// (no raw `$$` or `\(` left, no KaTeX errors), that every image loaded and that every
// Mermaid diagram renders (with the mermaid package, as GitHub does).
// Usage: node check.mjs OUTDIR page1.html page2.html ...
import { chromium } from 'playwright-core';
import path from 'node:path';

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
  const bad = r.imgs.filter(i => !i.ok);
  const ok = r.rawDisplay === 0 && r.rawInline === 0 && r.katexErrors.length === 0 && bad.length === 0 &&
             diagrams.errors.length === 0;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${page}: ${r.katex} formulas typeset, ${r.katexErrors.length} KaTeX errors, ` +
              `${r.rawDisplay} raw $$, ${r.imgs.length - bad.length}/${r.imgs.length} images loaded, ` +
              `${diagrams.ok} diagrams drawn`);
  for (const e of r.katexErrors) console.log(`     KaTeX error: ${e}`);
  for (const e of diagrams.errors) console.log(`     Mermaid error: ${e}`);
  for (const b of bad) console.log(`     image failed: ${b.src}`);
  if (!ok) failures++;
  await p.screenshot({ path: path.join(outDir, path.basename(page, '.html') + '.png'), fullPage: false });
  const drawn = await p.$$('.mermaid-drawn');
  if (drawn.length > 0) {
    await drawn[drawn.length - 1].screenshot({ path: path.join(outDir, path.basename(page, '.html') + '.diagram.png') });
  }
  await p.close();
}
await browser.close();
console.log(`${pages.length - failures} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);
