// viewer_latency.mjs VRI_BINARY [SCENE.json ...]: how fast `vri view` answers
// a user, measured in headless Chromium (issue 18, item 8; docs/PERFORMANCE.md,
// "Viewer"). For each scene (default: neghip and bonsai), with the viewer's
// method (preint1 for both) and a 512 x 512 image:
//  - transfer-function edit -> frame: EDITS drags of a control point (two
//    moves and a release, as a user makes them); the time from the release's
//    final request leaving the page to the full-resolution frame drawn on the
//    page's canvas; median and 95th percentile;
//  - orbiting: a drag across the image with a move every 16 ms (a 60 Hz
//    mouse) for ORBIT_S seconds; preview frames drawn per second.
// Prints one markdown table row per scene. Needs `npm ci` in viewer/tests/e2e.
import { createRequire } from 'node:module';
import { spawn } from 'node:child_process';
import os from 'node:os';

const require = createRequire(new URL('../tests/e2e/package.json', import.meta.url));
const puppeteer = require('puppeteer-core');
const [vri, ...argScenes] = process.argv.slice(2);
if (!vri) { console.error('usage: node viewer_latency.mjs VRI_BINARY [SCENE.json ...]'); process.exit(2); }
const root = new URL('../../', import.meta.url).pathname;
const scenes = argScenes.length ? argScenes : [`${root}scenes/neghip.json`, `${root}scenes/bonsai.json`];
const EDITS = Number(process.env.EDITS ?? 30), ORBIT_S = Number(process.env.ORBIT_S ?? 3), SIZE = 512;
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const quantile = (xs, q) => { const s = [...xs].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(q * s.length))]; };
const median = (xs) => quantile(xs, 0.5);

// Polls every 100 ms: the times measured are the page's own, so polling
// faster would only load the page's thread.
async function waitFor(page, fn, args, ms, what) {
  try {
    await page.waitForFunction(fn, { polling: 100, timeout: ms }, ...args);
  } catch (e) {
    throw new Error(`${what}: nothing within ${ms} ms`);
  }
}

// The drawn final frame of request seq: [latency ms, header].
async function finalOf(page, seq) {
  await waitFor(page, (s) => window.vriViewer.frames.some((f) => f.seq === s && f.stage === 'final' && f.drawn), [seq], 30000, `final ${seq}`);
  return page.evaluate((s) => {
    const f = window.vriViewer.frames.find((x) => x.seq === s && x.stage === 'final');
    return [f.drawnAt - window.vriViewer.sentAt.get(s), { ...f, server: f.receivedAt - window.vriViewer.sentAt.get(s), page: f.drawnAt - f.receivedAt }];
  }, seq);
}

async function measure(browser, scene) {
  const server = spawn(vri, ['view', scene, '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve) => server.stdout.once('data', (d) => resolve(String(d).split('\n')[0])));
  const page = await browser.newPage();
  try {
    await page.setViewport({ width: 1000, height: SIZE });
    await page.goto(url);
    await waitFor(page, () => window.vriViewer?.lastFinal != null, [], 30000, 'first frame');
    // Size the window so the image area is SIZE x SIZE.
    const rect = await page.evaluate(() => { const r = window.vriViewer.imageRect(); return [r.width, r.height]; });
    await page.setViewport({ width: 1000 + SIZE - Math.round(rect[0]), height: SIZE + SIZE - Math.round(rect[1]) });
    await waitFor(page, (n) => { const c = window.vriViewer.lastFinal; return c && c.width === n && c.height === n; }, [SIZE], 30000, 'a 512 x 512 frame');
    const method = await page.evaluate(() => window.vriViewer.state().method.name);

    const latencies = [], finals = [];
    for (let i = 0; i < EDITS + 3; ++i) {  // the first 3 warm up
      const p = await page.evaluate(() => window.vriViewer.tfPointClientXY(1));
      const dy = i % 2 ? 6 : -6;
      await page.mouse.move(p.x, p.y);
      await page.mouse.down();
      await page.mouse.move(p.x, p.y + dy / 2);
      await sleep(16);
      await page.mouse.move(p.x, p.y + dy);
      await page.mouse.up();
      const seq = await page.evaluate(() => window.vriViewer.lastSentSeq());
      const [ms, header] = await finalOf(page, seq);
      if (i >= 3) { latencies.push(ms); finals.push(header); }
      await sleep(50);
    }

    // A mouse at 60 Hz: the press from puppeteer, then a pointermove every
    // 16 ms dispatched in the page (puppeteer's own moves wait for each other
    // and arrive slower than a hand's).
    const r = await page.evaluate(() => { const b = window.vriViewer.imageRect(); return { x: b.left + b.width / 2, y: b.top + b.height / 2 }; });
    await page.mouse.move(r.x - 100, r.y);
    await page.mouse.down();
    const [t0, t1] = await page.evaluate((x0, y0, seconds) => new Promise((resolve) => {
      const canvas = document.getElementById('image'), start = performance.now();
      const tick = () => {
        const t = performance.now() - start;
        if (t > seconds * 1000) return resolve([start, performance.now()]);
        canvas.dispatchEvent(new PointerEvent('pointermove', { pointerId: 1, bubbles: true, clientX: x0 + 200 * t / (seconds * 1000), clientY: y0 + 30 * Math.sin(t / 300) }));
        setTimeout(tick, 16);
      };
      tick();
    }), r.x - 100, r.y, ORBIT_S);
    await page.mouse.up();
    const previews = await page.evaluate((a, b) => window.vriViewer.frames
      .filter((f) => f.stage === 'preview' && f.drawn && f.drawnAt >= a && f.drawnAt <= b)
      .map((f) => ({ ...f, roundTrip: f.receivedAt - window.vriViewer.sentAt.get(f.seq), page: f.drawnAt - f.receivedAt })), t0, t1);
    const sent = await page.evaluate((a, b) => [...window.vriViewer.sentAt.values()].filter((t) => t >= a && t <= b).length, t0, t1);
    console.error(`orbit: ${sent} requests sent, ${previews.length} previews drawn; request -> received ${median(previews.map((f) => f.roundTrip))} ms, received -> drawn ${median(previews.map((f) => f.page))} ms`);
    return {
      scene: scene.split('/').pop().replace('.json', ''), method, n: latencies.length,
      median: median(latencies), p95: quantile(latencies, 0.95),
      render: median(finals.map((f) => f.render_ms)), encode: median(finals.map((f) => f.encode_ms)),
      server: median(finals.map((f) => f.server)), pageMs: median(finals.map((f) => f.page)), setup: median(finals.map((f) => f.setup_ms)),
      fps: previews.length / ((t1 - t0) / 1000),
      preview: previews.length ? `${previews[0].width}x${previews[0].height}` : '-',
      previewRender: previews.length ? median(previews.map((f) => f.render_ms)) : NaN,
    };
  } finally {
    await page.close();
    server.kill('SIGINT');
  }
}

const browser = await puppeteer.launch({ executablePath: '/usr/bin/chromium', headless: true, args: ['--no-sandbox', '--disable-gpu'] });
try {
  console.log(`# ${new Date().toISOString().slice(0, 16).replace('T', ' ')} UTC, ${os.cpus().length} cores, load ${os.loadavg().map((x) => x.toFixed(2)).join(' ')}`);
  console.log('| scene | method | edits | edit -> final frame drawn, median ms | p95 ms | final render ms (median) | table + setup ms (median) | orbit: previews drawn / s | preview size | preview render ms (median) |');
  console.log('|---|---|---|---|---|---|---|---|---|---|');
  for (const s of scenes) {
    const m = await measure(browser, s);
    const f = (x) => x.toFixed(1);
    console.error(`${m.scene}: request -> frame received ${m.server} ms (render ${m.render}, encode ${m.encode}), received -> drawn ${m.pageMs} ms`);
    console.log(`| ${m.scene} | ${m.method} | ${m.n} | ${f(m.median)} | ${f(m.p95)} | ${f(m.render)} | ${f(m.setup)} | ${f(m.fps)} | ${m.preview} | ${f(m.previewRender)} |`);
  }
} finally {
  await browser.close();
}
