// Loads an HTML report of dlpverify in headless Chromium (Debian's chromium, driven by
// puppeteer-core from .deps/node, scripts/install-deps.sh) and checks what a reader sees:
//   - no console message of level error or warning, no page error, no failed request, and no
//     request for anything outside the file (the page is self-contained);
//   - every <figure> holds an SVG that is laid out (width and height > 0) and drawn (it has paths);
//   - the verdict (#verdict) lies inside the first 1280 x 800 viewport, and reads VERDICT.
// Writes a screenshot of the first viewport to SCREENSHOT (kept as the test's artefact).
// usage: node html_report.cjs DEPS_DIR PAGE.html SCREENSHOT.png FIGURES VERDICT
const path = require('path');
const [deps, page_file, screenshot, figures_wanted, verdict_wanted] = process.argv.slice(2);
const puppeteer = require(path.resolve(deps, 'node', 'node_modules', 'puppeteer-core'));

function fail(message) {
  console.error('FAIL: ' + message);
  process.exit(1);
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
  });
  const page = await browser.newPage();
  await page.setViewport({width: 1280, height: 800});
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warn') problems.push(`console ${m.type()}: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));
  page.on('requestfailed', (r) => problems.push('request failed: ' + r.url()));
  const url = 'file://' + path.resolve(page_file);
  page.on('request', (r) => { if (r.url() !== url && !r.url().startsWith('data:')) problems.push('outside request: ' + r.url()); });
  await page.goto(url, {waitUntil: 'load'});
  const figures = await page.$$eval('figure', (list) => list.map((f) => {
    const svg = f.querySelector('svg');
    if (!svg) return {width: 0, height: 0, drawn: 0};
    const box = svg.getBoundingClientRect();
    return {width: box.width, height: box.height, drawn: svg.querySelectorAll('path, polyline, line, use').length};
  }));
  const verdict = await page.$eval('#verdict', (e) => {
    const box = e.getBoundingClientRect();
    return {top: box.top, bottom: box.bottom, text: e.innerText};
  });
  await page.screenshot({path: screenshot});
  await browser.close();

  if (problems.length) fail(problems.join('\n'));
  if (figures.length !== Number(figures_wanted)) fail(`${figures.length} figures, expected ${figures_wanted}`);
  figures.forEach((f, i) => {
    if (!(f.width > 0 && f.height > 0 && f.drawn > 0)) fail(`figure ${i} not drawn: ${JSON.stringify(f)}`);
  });
  if (!(verdict.top >= 0 && verdict.bottom <= 800)) fail(`the verdict is not in the first viewport: ${JSON.stringify(verdict)}`);
  if (!verdict.text.startsWith(verdict_wanted)) fail(`the verdict reads "${verdict.text}", expected "${verdict_wanted}…"`);
  console.log(`ok: ${figures.length} figure(s) drawn, the verdict "${verdict.text.split('\n')[0]}" in view, no console error; ${screenshot}`);
})().catch((e) => fail(e.stack || String(e)));
