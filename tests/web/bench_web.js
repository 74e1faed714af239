// Frame time at 512 x 320 (scripts/bench-web, docs/web.md "Speed"): the same
// --script (the spec example, then m (size) set to another value every frame,
// each frame a render of the changed scene) run by the native explorer on this
// machine's OpenGL (Mesa llvmpipe under Xvfb) and by the page on SwiftShader
// and on ANGLE over the same OpenGL, all in one run, the window and the canvas
// both 1280 x 720. Each frame that rendered the scene reports its CPU time
// (--stats' render_frame_ms, the page's m3055.frameTimes()); printed: medians,
// p90s and the page/native ratios. A measurement, not a test: nothing is asserted.
// Usage: node bench_web.js --m3055 BUILD/m3055 --site build-web/site [--frames N]
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const http = require('http');
const { execFileSync } = require('child_process');
const puppeteer = require('puppeteer-core');

function option(name, fallback) {
  const i = process.argv.indexOf('--' + name);
  return i > 0 ? process.argv[i + 1] : fallback;
}
const repo = path.resolve(__dirname, '..', '..');
const m3055 = path.resolve(option('m3055', path.join(repo, 'build', 'm3055')));
const site = path.resolve(option('site', path.join(repo, 'build-web', 'site')));
const frames = Number(option('frames', '80'));
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'm3055-bench-web-'));
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// The spec example; a screenshot, which compiles its specialized program (a
// script's idle time does not: the explorer compiles deferred programs only
// when nothing else is due, so without it every frame would use the general
// program); then one render a frame.
const lines = ['figure spec_example', 'screenshot warm.png', 'idle 0.5'];
for (let i = 0; i < frames; ++i) lines.push(`set objects[0].material.m ${10 + (i % 20)}`);
lines.push('idle 0.5');
const script = lines.join('\n') + '\n';
fs.writeFileSync(path.join(work, 'bench.txt'), script);

const skip = 3;  // the first renders after a load (programs, buffers) are not the steady state
function summary(samples) {
  const s = samples.slice(skip).sort((a, b) => a - b);
  const at = (q) => s[Math.min(s.length - 1, Math.floor(q * s.length))];
  return { n: s.length, median: at(0.5), p90: at(0.9) };
}

function native() {
  const stats = path.join(work, 'native-stats.json');
  execFileSync('xvfb-run', ['-a', '-s', '-screen 0 1280x720x24', m3055, 'explore', '--window-size', '1280', '720',
    '--script', path.join(work, 'bench.txt'), '--exit-after-script', '--stats', stats], { cwd: work, stdio: 'ignore' });
  return JSON.parse(fs.readFileSync(stats, 'utf8')).render_frame_ms;
}

function serve() {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.json': 'application/json' };
  const server = http.createServer((req, res) => {
    const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (url === '/bench.txt') { res.writeHead(200, { 'Content-Type': 'text/plain' }); return res.end(script); }
    let file = path.join(site, path.normalize(url));
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    if (!file.startsWith(site) || !fs.existsSync(file)) { res.writeHead(404); return res.end(); }
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

const BACKENDS = {
  swiftshader: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  angle: ['--enable-gpu', '--ignore-gpu-blocklist', '--use-gl=angle', '--use-angle=gl-egl'],
};
async function inPage(base, backend) {
  const browser = await puppeteer.launch({
    executablePath: process.env.M3055_CHROMIUM || '/usr/bin/chromium',
    args: ['--headless=new', '--no-sandbox', '--window-size=1280,750', ...BACKENDS[backend]],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 750 });  // the canvas: 1280 x 720 under the bar
    await page.goto(base + '?script=bench.txt', { waitUntil: 'load' });
    await page.evaluate(() => window.m3055.ready);
    let samples = [];
    for (let waited = 0; waited < 120000 && samples.length < frames; waited += 250) {
      await sleep(250);
      samples = await page.evaluate(() => window.m3055.frameTimes());
    }
    return samples;
  } finally {
    await browser.close();
  }
}

(async () => {
  const server = await serve();
  const base = `http://127.0.0.1:${server.address().port}/`;
  const results = { 'native (llvmpipe)': summary(native()) };
  results['page, SwiftShader'] = summary(await inPage(base, 'swiftshader'));
  results['page, ANGLE/llvmpipe'] = summary(await inPage(base, 'angle'));
  server.close();
  const nativeMedian = results['native (llvmpipe)'].median;
  console.log(`frame time at 512 x 320 (spec example, m (size) changed every frame; window/canvas 1280 x 720; ` +
              `CPU time of each frame that rendered the scene, first ${skip} left out)`);
  for (const [name, r] of Object.entries(results)) {
    console.log(`  ${name.padEnd(22)} ${String(r.n).padStart(3)} frames  median ${r.median.toFixed(1).padStart(6)} ms  ` +
                `p90 ${r.p90.toFixed(1).padStart(6)} ms  x${(r.median / nativeMedian).toFixed(2)} native`);
  }
  fs.rmSync(work, { recursive: true, force: true });
})().catch((e) => { console.error(e); process.exit(1); });
