// Opens the HTML pages uvtk writes in Debian's headless Chromium and checks what a user would see
// (docs/robustness.md, "The browser test"). One line per problem, naming the page; exit 1 if any.
//
// Usage: node check_pages.mjs [--modules DIR] [--screenshot FILE] [--report PAGE]... [PAGE]...
//   --report PAGE     a report page (uvtk report --html): its #verdict must be on the first screen
//   PAGE              a gallery page (index.html of uvtk run): verdict badges and links to reports
//   --modules DIR     the folder whose node_modules holds puppeteer-core (default: this script's)
//   --screenshot FILE the first page's first screen (1280x800) as PNG
// Every page must hold a .view3d that draws a mesh and answers to the mouse and its layer menu.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { fileURLToPath, pathToFileURL } from 'node:url';

const kViewport = { width: 1280, height: 800 };
const kReadyMs = 30000;
const kSettleMs = 400;          // after an input, for OrbitControls' damping and the next frame
const kMeshFraction = 0.02;     // of the canvas's pixels unlike its corner: a mesh is drawn
const kChangeFraction = 0.01;   // of the pixels changed by a drag or a layer switch
// puppeteer's headless mode is Chromium's own (--headless=new; the old one left Chromium in 132).
// --no-sandbox: the sandbox needs user namespaces, which root in a container lacks; the pages are ours
// and the network is closed to them. WebGL on SwiftShader (software) through ANGLE on every machine, GPU
// or not: headless Chromium 156 without a GPU picks it unasked, but that fallback is deprecated since 137
// and --enable-unsafe-swiftshader is its replacement.
const kChromiumFlags = ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'];

function usage(message) {
  console.error(`check_pages: ${message}\n` +
                'usage: node check_pages.mjs [--modules DIR] [--screenshot FILE] [--report PAGE]... [PAGE]...');
  process.exit(2);
}

function parseArgs(argv) {
  const options = { modules: path.dirname(fileURLToPath(import.meta.url)), screenshot: null, pages: [] };
  for (let i = 0; i < argv.length; ++i) {
    const value = () => (i + 1 < argv.length ? argv[++i] : usage(`${argv[i]} needs a value`));
    if (argv[i] === '--modules') options.modules = value();
    else if (argv[i] === '--screenshot') options.screenshot = value();
    else if (argv[i] === '--report') options.pages.push({ file: value(), report: true });
    else if (argv[i].startsWith('--')) usage(`unknown option '${argv[i]}'`);
    else options.pages.push({ file: argv[i], report: false });
  }
  if (options.pages.length === 0) usage('no pages given');
  for (const page of options.pages) {
    if (!fs.existsSync(page.file)) usage(`${page.file}: no such file`);
  }
  return options;
}

function loadPuppeteer(modules) {
  try {
    return createRequire(path.join(path.resolve(modules), 'package.json'))('puppeteer-core');
  } catch {
    console.error(`check_pages: puppeteer-core is not installed in ${modules}/node_modules ` +
                  '(scripts/setup.sh --validator installs it)');
    process.exit(2);
  }
}

// In the page: the canvas's pixels, read by drawing the WebGL canvas (preserveDrawingBuffer) onto a
// 2D canvas; kept in window.__uvtkShots[name] so that comparisons stay in the page.
function shoot(name) {
  const canvas = document.querySelector('.view3d canvas');
  const copy = document.createElement('canvas');
  copy.width = canvas.width;
  copy.height = canvas.height;
  const context = copy.getContext('2d', { willReadFrequently: true });
  context.drawImage(canvas, 0, 0);
  window.__uvtkShots = window.__uvtkShots || {};
  window.__uvtkShots[name] = context.getImageData(0, 0, copy.width, copy.height).data;
  return [copy.width, copy.height];
}

// In the page: the fraction of pixels of shot a whose colour differs from shot b's (b: null, the
// corner pixel of a: the background), and the centroid of those pixels in canvas pixels.
function differ(a, b) {
  const tolerance = 6;  // per channel: antialiasing and dithering are not a change
  const p = window.__uvtkShots[a];
  const q = b ? window.__uvtkShots[b] : null;
  const width = document.querySelector('.view3d canvas').width;
  let count = 0, sx = 0, sy = 0;
  for (let i = 0; i < p.length; i += 4) {
    const j = q ? i : 0;
    const r = q || p;
    if (Math.abs(p[i] - r[j]) > tolerance || Math.abs(p[i + 1] - r[j + 1]) > tolerance ||
        Math.abs(p[i + 2] - r[j + 2]) > tolerance) {
      ++count;
      sx += (i / 4) % width;
      sy += Math.floor(i / 4 / width);
    }
  }
  return { fraction: count / (p.length / 4), x: count ? sx / count : 0, y: count ? sy / count : 0 };
}

// In the page: the drawn pixel of shot `name` (unlike the corner) nearest to (x, y), for hovering.
function nearestDrawn(name, x, y) {
  const p = window.__uvtkShots[name];
  const width = document.querySelector('.view3d canvas').width;
  let best = null, bestDistance = Infinity;
  for (let i = 0; i < p.length; i += 4) {
    if (Math.abs(p[i] - p[0]) + Math.abs(p[i + 1] - p[1]) + Math.abs(p[i + 2] - p[2]) <= 18) continue;
    const px = (i / 4) % width, py = Math.floor(i / 4 / width);
    const d = (px - x) ** 2 + (py - y) ** 2;
    if (d < bestDistance) [best, bestDistance] = [[px, py], d];
  }
  return best;
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const percent = (f) => `${(100 * f).toFixed(2)} %`;

async function checkVerdict(page, problem) {
  const verdict = await page.evaluate((viewport) => {
    const section = document.querySelector('section#verdict');
    if (!section) return 'no <section id="verdict">';
    const badge = section.querySelector('span.verdict');
    if (!badge || !['pass', 'warn', 'fail'].some((c) => badge.classList.contains(c))) {
      return '#verdict holds no <span class="verdict pass|warn|fail">';
    }
    for (const e of [section, badge]) {
      const style = getComputedStyle(e);
      const box = e.getBoundingClientRect();
      if (style.display === 'none' || style.visibility !== 'visible' || Number(style.opacity) === 0 ||
          box.width === 0 || box.height === 0) {
        return `${e === section ? '#verdict' : 'its badge'} is hidden`;
      }
      if (box.left < 0 || box.top < 0 || box.right > viewport.width || box.bottom > viewport.height) {
        return `${e === section ? '#verdict' : 'its badge'} is off the first screen (box ${Math.round(box.left)},` +
               `${Math.round(box.top)} to ${Math.round(box.right)},${Math.round(box.bottom)}, screen ` +
               `${viewport.width}x${viewport.height})`;
      }
    }
    return null;
  }, kViewport);
  if (verdict) problem(verdict);
}

async function checkGallery(page, file, problem) {
  const found = await page.evaluate(() => ({
    badges: [...document.querySelectorAll('.verdict')].filter(
        (e) => ['pass', 'warn', 'fail'].some((c) => e.classList.contains(c))).length,
    links: [...document.querySelectorAll('a[href]')].map((a) => a.href),
  }));
  if (found.badges === 0) problem('no .verdict badge (pass, warn or fail)');
  const pages = found.links.filter((href) => href.startsWith('file:') && /\.html?$/.test(new URL(href).pathname));
  if (pages.length === 0) problem('no link to a report page (<a href="....html">)');
  for (const href of found.links.filter((h) => h.startsWith('file:'))) {
    if (!fs.existsSync(fileURLToPath(href))) {  // the path alone: no query, no fragment
      problem(`link to a missing file: ${path.relative(path.dirname(file), fileURLToPath(href))}`);
    }
  }
}

// The first .view3d: drawn, and changed by a layer switch and a drag; hovering the mesh names a face.
async function checkView3d(page, ready, problem, measured) {
  const views = await page.$$eval('.view3d', (divs) => divs.length);
  if (views === 0) return problem('no .view3d');
  const errors = await page.$$eval('.view3d[data-error]', (divs) => divs.map((d) => d.getAttribute('data-error')));
  for (const error of errors) problem(`.view3d data-error: ${error}`);
  if (!ready) problem(`.view3d not ready (data-ready="1") after ${kReadyMs / 1000} s`);
  if (errors.length > 0 || !ready) return;
  if (!(await page.$('.view3d canvas'))) return problem('.view3d holds no <canvas>');

  await page.$eval('.view3d', (d) => d.scrollIntoView({ block: 'center' }));
  await sleep(kSettleMs);
  const [width, height] = await page.evaluate(shoot, 'drawn');
  const drawn = await page.evaluate(differ, 'drawn', null);
  measured.push(`mesh ${percent(drawn.fraction)}`);
  if (drawn.fraction < kMeshFraction) {
    return problem(`.view3d canvas shows no mesh: ${percent(drawn.fraction)} of its ${width}x${height} ` +
                   `pixels differ from the background (at least ${percent(kMeshFraction)})`);
  }
  const canvas = await page.$eval('.view3d canvas', (c) => {
    const r = c.getBoundingClientRect();
    return { left: r.left, top: r.top, width: r.width, height: r.height };
  });
  const toPage = ([x, y]) => [canvas.left + (x + 0.5) * canvas.width / width,
                              canvas.top + (y + 0.5) * canvas.height / height];

  // Hover the mesh's middle: the drawn pixel nearest to the drawn pixels' centroid.
  const [hx, hy] = toPage(await page.evaluate(nearestDrawn, 'drawn', drawn.x, drawn.y));
  await page.mouse.move(hx - 20, hy, { steps: 1 });
  await page.mouse.move(hx, hy, { steps: 5 });
  try {
    await page.waitForFunction(() => {
      const hover = document.querySelector('.view3d .hover');
      return hover && hover.textContent.startsWith('face ');
    }, { timeout: 3000 });
  } catch {
    const text = await page.evaluate(() => document.querySelector('.view3d .hover')?.textContent ?? null);
    problem(text === null ? 'no .hover in .view3d'
                          : `hovering the mesh at (${Math.round(hx)}, ${Math.round(hy)}) left .hover at ` +
                            `${JSON.stringify(text.slice(0, 40))}, not "face ..."`);
  }

  const options = await page.$$eval('.view3d select.layers option', (o) => o.map((e) => e.value));
  if (options.length < 2) {
    problem(`.view3d select.layers has ${options.length} option(s), expected at least 2`);
  } else {
    await page.evaluate(shoot, 'before-layer');
    await page.select('.view3d select.layers', options[1]);
    await sleep(kSettleMs);
    await page.evaluate(shoot, 'after-layer');
    const changed = await page.evaluate(differ, 'after-layer', 'before-layer');
    measured.push(`layer ${percent(changed.fraction)}`);
    if (changed.fraction < kChangeFraction) {
      problem(`switching the layer to "${options[1]}" changed ${percent(changed.fraction)} of the pixels ` +
              `(at least ${percent(kChangeFraction)})`);
    }
  }

  // A left drag across the middle third of the canvas: orbit.
  await page.evaluate(shoot, 'before-drag');
  const y = canvas.top + canvas.height / 2;
  await page.mouse.move(canvas.left + canvas.width / 3, y);
  await page.mouse.down({ button: 'left' });
  await page.mouse.move(canvas.left + 2 * canvas.width / 3, y + canvas.height / 10, { steps: 12 });
  await page.mouse.up({ button: 'left' });
  await sleep(kSettleMs);
  await page.evaluate(shoot, 'after-drag');
  const dragged = await page.evaluate(differ, 'after-drag', 'before-drag');
  measured.push(`drag ${percent(dragged.fraction)}`);
  if (dragged.fraction < kChangeFraction) {
    problem(`a left drag across the canvas changed ${percent(dragged.fraction)} of the pixels ` +
            `(at least ${percent(kChangeFraction)})`);
  }
}

async function checkPage(browser, { file, report }, screenshot) {
  const problems = [], measured = [];
  const problem = (text) => problems.push(`${file}: ${text}`);
  const page = await browser.newPage();
  await page.setViewport(kViewport);
  // Pages must be whole in themselves: nothing from the network, nothing the user must serve.
  const blocked = new Set();
  await page.setRequestInterception(true);
  page.on('request', (request) => {
    const url = request.url();
    if (/^(file|data|blob|about):/.test(url)) return request.continue();
    blocked.add(url);
    problem(`requested ${url.slice(0, 200)} (only file:, data:, blob: and about: are allowed)`);
    return request.abort();
  });
  page.on('requestfailed', (request) => {
    if (!blocked.has(request.url())) {
      blocked.add(request.url());
      problem(`failed to load ${request.url().slice(0, 200)}: ${request.failure()?.errorText}`);
    }
  });
  page.on('console', (message) => {
    // A blocked or failed request's console line is already reported, once.
    if (message.type() === 'error' && !blocked.has(message.location()?.url)) {
      problem(`console error: ${message.text().replace(/\s*\n\s*/g, ' | ').slice(0, 400)}`);
    }
  });
  page.on('pageerror', (error) => problem(`page error: ${String(error.message ?? error).split('\n')[0]}`));

  try {
    await page.goto(pathToFileURL(path.resolve(file)).href, { waitUntil: 'load', timeout: 60000 });
    // Every view drawn or failed first, so that the first screen is what the user sees.
    const ready = await page.waitForFunction(() => [...document.querySelectorAll('.view3d')].every(
        (d) => d.getAttribute('data-ready') === '1' || d.hasAttribute('data-error')), { timeout: kReadyMs })
        .then(() => true, () => false);
    if (report) await checkVerdict(page, problem);
    else await checkGallery(page, file, problem);
    if (screenshot) await page.screenshot({ path: screenshot, type: 'png', clip: { x: 0, y: 0, ...kViewport } });
    await checkView3d(page, ready, problem, measured);
  } catch (error) {
    problem(`could not be checked: ${String(error.message ?? error).split('\n')[0]}`);
  }
  await page.close();
  return { problems, measured };
}

const options = parseArgs(process.argv.slice(2));
const puppeteer = loadPuppeteer(options.modules);
const executablePath = process.env.UVTK_CHROMIUM || '/usr/bin/chromium';
const browser = await puppeteer.launch({ executablePath, headless: true, args: kChromiumFlags,
                                         defaultViewport: kViewport });
let problems = [];
try {
  for (const [i, page] of options.pages.entries()) {
    const started = Date.now();
    const found = await checkPage(browser, page, i === 0 ? options.screenshot : null);
    // The pixels unlike the background, and those a layer switch and a drag changed.
    console.log(`check_pages: ${page.file}: ${found.problems.length ? `${found.problems.length} problem(s)` : 'ok'}, ` +
                `${((Date.now() - started) / 1000).toFixed(1)} s${found.measured.map((m) => `, ${m}`).join('')}`);
    problems = problems.concat(found.problems);
  }
} finally {
  await browser.close();
}
for (const line of problems) console.error(line);
process.exit(problems.length ? 1 : 0);
