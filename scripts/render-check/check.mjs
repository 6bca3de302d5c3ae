// Loads rendered report pages in headless Chromium and asserts that the math typeset
// (no raw `$$` or `\(` left, no KaTeX errors) and that every image loaded.
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
for (const page of pages) {
  const p = await browser.newPage({ viewport: { width: 1100, height: 1400 } });
  await p.goto('file://' + path.resolve(page), { waitUntil: 'load' });
  await p.waitForTimeout(500);
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
  const ok = r.rawDisplay === 0 && r.rawInline === 0 && r.katexErrors.length === 0 && bad.length === 0;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${page}: ${r.katex} formulas typeset, ${r.katexErrors.length} KaTeX errors, ` +
              `${r.rawDisplay} raw $$, ${r.imgs.length - bad.length}/${r.imgs.length} images loaded`);
  for (const e of r.katexErrors) console.log(`     KaTeX error: ${e}`);
  for (const b of bad) console.log(`     image failed: ${b.src}`);
  if (!ok) failures++;
  await p.screenshot({ path: path.join(outDir, path.basename(page, '.html') + '.png'), fullPage: false });
  await p.close();
}
await browser.close();
console.log(`${pages.length - failures} passed, ${failures} failed`);
process.exit(failures ? 1 : 0);
