// End-to-end test of `vri view` in headless Chromium (docs/VIEWER.md).
//
//   node viewer_e2e.mjs VRI_BINARY SCENE_JSON ARTIFACT_DIR
//
// Starts the server on a free port, opens the page, and checks: the token is
// required, TF and camera drags give previews then a new final, the error map,
// an error reply to a bad message, a clip plane dragged, "save scene" + `vri render` = "save image"
// byte for byte, and a clean exit on SIGINT. One line per check passed; on a
// failure one line "FAIL: ..." and exit 1. Everything is killed after 120 s.
import { spawn, execFile } from 'node:child_process';
import { createInterface } from 'node:readline';
import fs from 'node:fs';
import path from 'node:path';
import puppeteer from 'puppeteer-core';

const GLOBAL_TIMEOUT_MS = 120_000;
const CHROMIUM = '/usr/bin/chromium';

const [VRI, SCENE, ARTIFACT_ARG] = process.argv.slice(2);
if (!VRI || !SCENE || !ARTIFACT_ARG) {
  console.error('usage: node viewer_e2e.mjs VRI_BINARY SCENE_JSON ARTIFACT_DIR');
  process.exit(2);
}
const ART = path.resolve(ARTIFACT_ARG);
fs.mkdirSync(ART, { recursive: true });
const art = (name) => path.join(ART, name);

let server = null, browser = null, serverExitExpected = false;
const serverLog = [], consoleLog = [], pageErrors = [];

function saveLogs() {
  try { fs.writeFileSync(art('server.log'), serverLog.join('\n') + '\n'); } catch { /* best effort */ }
  try { fs.writeFileSync(art('console.log'), consoleLog.join('\n') + '\n'); } catch { /* best effort */ }
}

function killAll() {
  try { browser?.process()?.kill('SIGKILL'); } catch { /* already gone */ }
  try { if (server && server.exitCode === null && server.signalCode === null) server.kill('SIGKILL'); } catch { /* already gone */ }
}

function fail(message) {
  console.error(`FAIL: ${message}`);
  saveLogs();
  killAll();
  process.exit(1);
}

const globalTimer = setTimeout(() => fail(`global timeout: the test ran over ${GLOBAL_TIMEOUT_MS / 1000} s`), GLOBAL_TIMEOUT_MS);
process.on('unhandledRejection', (e) => fail(`unexpected: ${e?.message ?? e}`.split('\n')[0]));
process.on('uncaughtException', (e) => fail(`unexpected: ${e?.message ?? e}`.split('\n')[0]));

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const pass = (line) => console.log(`ok ${line}`);

function withTimeout(promise, ms, message) {
  let timer;
  return Promise.race([promise, new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(message)), ms); })])
    .finally(() => clearTimeout(timer));
}

// Poll a predicate in the page; a timeout fails the test with `message`.
async function waitFor(page, fn, args, ms, message) {
  try {
    await page.waitForFunction(fn, { timeout: ms, polling: 50 }, ...args);
  } catch (e) {
    fail(e.name === 'TimeoutError' || /timeout/i.test(e.message) ? message : `${message} (${e.message.split('\n')[0]})`);
  }
}

const viewer = (page, fn, ...args) => page.evaluate(fn, ...args);
const lastSentSeq = (page) => viewer(page, () => window.vriViewer.lastSentSeq());

// The last final frame: its seq, and a hash of its bytes (FNV-1a + length),
// computed in the page so the PNG need not cross the protocol each time.
const finalInfo = (page) => viewer(page, () => {
  const v = window.vriViewer, b = v.lastFinalBytes;
  let h = 0x811c9dc5;
  for (let i = 0; i < b.length; i++) h = Math.imul(h ^ b[i], 0x01000193) >>> 0;
  const png = b.length > 8 && b[0] === 0x89 && b[1] === 0x50 && b[2] === 0x4e && b[3] === 0x47;
  return { seq: v.lastFinal.seq, format: v.lastFinal.format, png, hash: `${h.toString(16)}:${b.length}`,
    width: v.lastFinal.width, height: v.lastFinal.height };
});

// Wait for a final frame newer than request `afterSeq` that answers the last
// request sent (so no newer one is under way), received and drawn.
async function waitForFinal(page, what, afterSeq, ms = 30_000) {
  await waitFor(page, (after) => {
    const v = window.vriViewer, f = v.lastFinal;
    return f != null && f.seq > after && f.seq >= v.lastSentSeq() &&
      v.frames.some((x) => x.stage === 'final' && x.seq === f.seq && x.drawn);
  }, [afterSeq], ms, `${what}: no final frame within ${ms / 1000} s`);
  return finalInfo(page);
}

// Drag with the left button, in `steps` moves, holding still `pause` ms between them.
async function drag(page, from, dx, dy, steps, pause, beforeRelease) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(from.x + dx * k / steps, from.y + dy * k / steps);
    await sleep(pause);
  }
  if (beforeRelease) await beforeRelease();
  await page.mouse.up();
}

// ---- the server --------------------------------------------------------------

async function startServer() {
  server = spawn(VRI, ['view', SCENE, '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  server.on('error', (e) => fail(`cannot start ${VRI}: ${e.message}`));
  server.on('exit', (code, signal) => {
    serverLog.push(`[exit code=${code} signal=${signal}]`);
    if (!serverExitExpected) fail(`the server exited during the test (code ${code}, signal ${signal}); see server.log`);
  });
  createInterface({ input: server.stderr }).on('line', (l) => serverLog.push(`stderr: ${l}`));
  const lines = createInterface({ input: server.stdout });
  const first = new Promise((resolve) => lines.once('line', resolve));
  lines.on('line', (l) => serverLog.push(`stdout: ${l}`));
  const url = (await withTimeout(first, 20_000, 'the server printed no address within 20 s')).trim();
  const m = /^http:\/\/127\.0\.0\.1:(\d+)\/\?token=([0-9A-Za-z_-]+)$/.exec(url);
  if (!m) fail(`the server's first line is not http://127.0.0.1:PORT/?token=T: ${JSON.stringify(url)}`);
  return { url, port: Number(m[1]), token: m[2] };
}

// ---- downloads -----------------------------------------------------------------

// Chromium saves downloads into ART and reports their progress on this session.
async function allowDownloads() {
  const session = await browser.target().createCDPSession();
  const names = new Map(), done = new Map();
  session.on('Browser.downloadWillBegin', (e) => names.set(e.guid, e.suggestedFilename));
  session.on('Browser.downloadProgress', (e) => { if (e.state !== 'inProgress') done.set(e.guid, e.state); });
  await session.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: ART, eventsEnabled: true });
  return async (name, ms) => {
    const end = Date.now() + ms;
    while (Date.now() < end) {
      for (const [guid, state] of done) {
        if (names.get(guid) === name) return state === 'completed' && fs.existsSync(art(name));
      }
      await sleep(50);
    }
    return false;
  };
}

// Click a save button; read the file it downloads, or, where the download
// does not come through, what the page would have downloaded.
async function save(page, waitDownload, button, name, fromPage) {
  fs.rmSync(art(name), { force: true });  // else Chromium names it "name (1)"
  await page.click(button);
  if (await waitDownload(name, 10_000)) return { bytes: fs.readFileSync(art(name)), downloaded: true };
  const bytes = Buffer.from(await viewer(page, fromPage));
  fs.writeFileSync(art(name), bytes);
  return { bytes, downloaded: false };
}

// ---- the test ----------------------------------------------------------------------

const { url, port } = await startServer();

// (a) the token guards every request
{
  for (const [what, target] of [['no token', `http://127.0.0.1:${port}/`], ['a wrong token', `http://127.0.0.1:${port}/?token=0123456789abcdef0123456789abcdef`]]) {
    const res = await withTimeout(fetch(target, { redirect: 'manual' }), 10_000, `(a) GET with ${what} got no answer within 10 s`)
      .catch((e) => fail(`(a) GET with ${what}: ${e.message}`));
    if (res.status !== 403) fail(`(a) GET / with ${what} answered ${res.status}, expected 403`);
  }
  pass('(a) requests without the token (or with a wrong one) get 403');
}

browser = await puppeteer.launch({
  executablePath: CHROMIUM,
  headless: true,
  args: ['--no-sandbox', '--disable-gpu'],
  defaultViewport: { width: 800, height: 600 },
}).catch((e) => fail(`cannot launch ${CHROMIUM}: ${e.message.split('\n')[0]}`));
const waitDownload = await allowDownloads();
const page = await browser.newPage();
page.on('console', (m) => consoleLog.push(`${m.type()}: ${m.text()}`));
page.on('pageerror', (e) => { pageErrors.push(e.message); consoleLog.push(`pageerror: ${e.message}`); });

const res = await page.goto(url, { waitUntil: 'load', timeout: 20_000 }).catch((e) => fail(`cannot open ${url}: ${e.message}`));
if (!res || res.status() !== 200) fail(`GET ${url} answered ${res?.status()}, expected 200`);
await waitFor(page, () => window.vriViewer?.lastFinal != null, [], 30_000, 'no final frame within 30 s of opening the page');
const first = await waitForFinal(page, 'first frame', 0);
if (first.format !== 'png' || !first.png) fail(`the first final frame is not a PNG (format ${first.format})`);
await page.screenshot({ path: art('first_frame.png') });
pass(`first final frame: ${first.width}x${first.height} PNG`);

// (b) drag TF control point 1 vertically: previews while dragging, then a new final
let previous = first;
{
  const before = await viewer(page, () => window.vriViewer.state().transfer_function.points);
  if (before.length < 2) fail(`(b) the scene's transfer function has ${before.length} control point(s); the test drags point 1`);
  const p1 = await viewer(page, () => window.vriViewer.tfPointClientXY(1));
  const top = await viewer(page, () => document.getElementById('tf-canvas').getBoundingClientRect().top);
  const dy = p1.y - top > 50 ? -40 : 40;  // up, unless the point is already near the top
  const s0 = await lastSentSeq(page);
  await drag(page, p1, 0, dy, 8, 40, () => waitFor(page, (s) => window.vriViewer.frames.some((f) => f.stage === 'preview' && f.seq > s),
    [s0], 15_000, '(b) no preview frame arrived while dragging TF point 1'));
  const after = await waitForFinal(page, '(b) after the TF drag', s0);
  if (after.hash === first.hash) fail('(b) the final frame after the TF drag has the same bytes as the first one');
  const pts = await viewer(page, () => window.vriViewer.state().transfer_function.points);
  if (pts.length !== before.length) fail(`(b) the drag changed the number of points (${before.length} -> ${pts.length})`);
  if (pts[1][4] === before[1][4]) fail('(b) dragging point 1 did not change its tau');
  if (pts[1][0] !== before[1][0]) fail(`(b) a vertical drag moved point 1 in s (${before[1][0]} -> ${pts[1][0]})`);
  for (let i = 0; i < pts.length; i++) {
    if (i !== 1 && JSON.stringify(pts[i]) !== JSON.stringify(before[i])) fail(`(b) point ${i} changed though it was not dragged`);
  }
  pass(`(b) TF point 1 drag: previews, then final ${after.seq} with new bytes; other points unchanged`);
  previous = after;
}

// (c) orbit: drag across the image
{
  const eye0 = await viewer(page, () => window.vriViewer.state().camera.eye);
  const s0 = await lastSentSeq(page);
  const r = await viewer(page, () => { const b = window.vriViewer.imageRect(); return { x: b.left + b.width / 2, y: b.top + b.height / 2 }; });
  await drag(page, r, 120, 0, 6, 40);
  const after = await waitForFinal(page, '(c) after the orbit', s0);
  const eye1 = await viewer(page, () => window.vriViewer.state().camera.eye);
  if (JSON.stringify(eye0) === JSON.stringify(eye1)) fail('(c) orbiting did not change camera.eye');
  if (after.hash === previous.hash) fail('(c) the final frame after orbiting has the same bytes as before');
  pass(`(c) orbit: eye moved, final ${after.seq} with new bytes`);
  previous = after;
}

// (d) the error map
{
  const s0 = await lastSentSeq(page);
  await page.click('#error-map');
  await waitFor(page, (s) => window.vriViewer.frames.some((f) => f.stage === 'error_map' && f.seq > s && f.drawn),
    [s0], 60_000, '(d) no error_map frame within 60 s of turning the error map on');
  const h = await viewer(page, (s) => window.vriViewer.frames.find((f) => f.stage === 'error_map' && f.seq > s), s0);
  const e = h.error;
  if (!e || typeof e.share_over !== 'number' || !(e.share_over >= 0 && e.share_over <= 1)) {
    fail(`(d) the error_map header's error.share_over is not a number in [0, 1]: ${JSON.stringify(e)}`);
  }
  if (h.format !== 'png') fail(`(d) the error_map frame is ${h.format}, expected png`);
  const status = await viewer(page, () => document.getElementById('status').textContent);
  if (!status.includes('share over tol')) fail(`(d) the status line does not show the error statistics: ${JSON.stringify(status)}`);
  await page.screenshot({ path: art('error_map.png') });
  pass(`(d) error map: share over ${e.tolerance}: ${(100 * e.share_over).toFixed(2)}%, max ${e.max}, rms ${e.rms}`);
}

// (e) a malformed message gets an error reply, and the session goes on
{
  const n0 = await viewer(page, () => window.vriViewer.errors.length);
  await viewer(page, () => window.vriViewer.socket.send('{"type":"render","seq":"x"}'));
  await waitFor(page, (n) => window.vriViewer.errors.length > n, [n0], 10_000, '(e) no error reply to {"type":"render","seq":"x"} within 10 s');
  const shown = await viewer(page, () => document.getElementById('status-error').textContent);
  if (!shown) fail('(e) the error reply is not shown in the status line');
  const s0 = await lastSentSeq(page);
  await page.click('#error-map');  // off again: a new final request
  const after = await waitForFinal(page, '(e) after the error reply', s0);
  pass(`(e) malformed message: error reply shown, then final ${after.seq} still rendered`);
  previous = after;
}

// (e2) clip: a plane across x, then its slider dragged: previews, then a final
// with new bytes; (f) then renders the clipped scene with `vri render`
{
  const s0 = await lastSentSeq(page);
  await page.select('#clip-axis', '0');
  const cut = await waitForFinal(page, '(e2) after choosing a clip plane', s0);
  if (cut.hash === previous.hash) fail('(e2) the final frame with a clip plane has the same bytes as without');
  const r = await viewer(page, () => {
    const b = document.getElementById('clip-at').getBoundingClientRect();
    return { x: b.left + b.width / 2, y: b.top + b.height / 2 };
  });
  const s1 = await lastSentSeq(page);
  await drag(page, r, -50, 0, 6, 40, () => waitFor(page, (s) => window.vriViewer.frames.some((f) => f.stage === 'preview' && f.seq > s),
    [s1], 15_000, '(e2) no preview frame arrived while dragging the clip plane'));
  const moved = await waitForFinal(page, '(e2) after dragging the clip plane', s1);
  const clip = await viewer(page, () => window.vriViewer.state().clip);
  if (!(clip?.planes?.length === 1 && clip.planes[0][0] === 1)) fail(`(e2) the scene's clip is ${JSON.stringify(clip)}`);
  if (moved.hash === cut.hash) fail('(e2) moving the clip plane left the final frame as it was');
  pass(`(e2) clip plane x >= ${(-clip.planes[0][3]).toFixed(2)}: previews while dragged, final ${moved.seq} with new bytes`);
  previous = moved;
}

// (f) save scene + save image; `vri render` of the scene gives the image's bytes
{
  const scene = await save(page, waitDownload, '#save-scene', 'scene.json',
    () => Array.from(new TextEncoder().encode(window.vriViewer.sceneText())));
  const image = await save(page, waitDownload, '#save-image', 'image.png', () => Array.from(window.vriViewer.lastFinalBytes));
  if (!scene.downloaded || !image.downloaded) console.log('note: a download did not complete; its file was written from window.vriViewer');
  const expected = await viewer(page, () => ({ text: window.vriViewer.sceneText(), bytes: Array.from(window.vriViewer.lastFinalBytes) }));
  if (scene.bytes.toString('utf8') !== expected.text) fail('(f) the saved scene.json differs from the scene of the last final frame');
  if (!image.bytes.equals(Buffer.from(expected.bytes))) fail('(f) the saved image.png differs from the last final frame');
  JSON.parse(scene.bytes.toString('utf8'));
  await page.screenshot({ path: art('final.png') });

  fs.rmSync(art('cli.png'), { force: true });
  const cli = await new Promise((resolve) => {
    execFile(VRI, ['render', art('scene.json'), '-o', art('cli.png')], { timeout: 60_000 }, (err, stdout, stderr) => resolve({ err, stderr }));
  });
  if (cli.err) fail(`(f) vri render of the saved scene failed: ${(cli.stderr || cli.err.message).trim().split('\n').pop()}`);
  const png = fs.readFileSync(art('cli.png'));
  if (!png.equals(image.bytes)) {
    let i = 0;
    while (i < png.length && i < image.bytes.length && png[i] === image.bytes[i]) i++;
    fail(`(f) cli.png (${png.length} bytes) differs from image.png (${image.bytes.length} bytes) from byte ${i}`);
  }
  pass(`(f) save scene + vri render = save image, byte for byte (${png.length} bytes)`);
}

if (pageErrors.length) fail(`the page threw: ${pageErrors[0]}`);

// (g) close the browser; SIGINT stops the server with exit code 0 within 5 s
{
  await browser.close();
  browser = null;
  serverExitExpected = true;
  const exited = new Promise((resolve) => server.once('exit', (code, signal) => resolve({ code, signal })));
  server.kill('SIGINT');
  const { code, signal } = await withTimeout(exited, 5_000, 'x').catch(() => fail('(g) the server did not exit within 5 s of SIGINT'));
  if (code !== 0) fail(`(g) the server exited with code ${code} (signal ${signal}) on SIGINT, expected 0`);
  pass('(g) SIGINT: the server exited 0');
}

saveLogs();
clearTimeout(globalTimer);
console.log('all checks passed');
process.exit(0);
