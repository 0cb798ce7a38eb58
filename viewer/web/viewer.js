// vri view, the page: one WebSocket to the server (docs/VIEWER.md), the image,
// the camera, the controls and the status line.
import { TfEditor, toHex, fromHex } from './tf_editor.js';
import { orbit, zoom, pan } from './camera.js';
import { colorize, drawColorbar } from './errormap.js';

const $ = (id) => document.getElementById(id);
const MAX_SIZE = 2048;         // the largest image side the page asks for
const PREVIEW_RESEND_MS = 500; // a preview unanswered this long no longer holds the next back
const MAX_FRAMES_KEPT = 5000;  // test log of frame headers; bounded for long sessions

let ws = null;
let welcome = null;
let scene = null;              // the request scene: the scene file without its volume
let welcomeCamera = null;      // for "reset view"
let seq = 0;                   // last seq sent
let minSeq = 1;                // frames older than the last welcome are stale
let sentFinals = new Map();    // seq → scene of a final request still unanswered
let lastFinalScene = null;     // the request scene of lastFinal: what "save scene" writes
let shown = { seq: -1, stage: null, bitmap: null, header: null };  // the drawn image
let overlay = null;            // {seq, canvas, header}: the coloured error map of a final
let errorTolerance = 1e-3;
let errorText = '', errorSeq = -1, closed = false;
let camDrag = null, wheelTimer = null;
const preview = { outstanding: null, dirty: false, timer: null, sent: '' };

// Hooks for viewer/tests/e2e (keep them stable): every frame header received
// (+ bytes: its image's length, drawn: true once drawn), the last final frame,
// its PNG and request scene, the error replies, the socket, and geometry.
const hooks = window.vriViewer = {
  frames: [], welcome: null, lastFinal: null, lastFinalBytes: null, lastFinalScene: null,
  errors: [], socket: null,
  sentAt: new Map(),  // seq -> performance.now() when the request left
  tfPointClientXY: (i) => editor.pointClientXY(i),
  imageRect: () => $('image').getBoundingClientRect(),
  state: () => structuredClone(scene),
  lastSentSeq: () => seq,
  sceneText: () => sceneText(),
};

const editor = new TfEditor($('tf-canvas'), $('tf-color'), (quality) => {
  scene.transfer_function = editor.value();
  if (quality === 'preview') wantPreview(); else sendFinal();
});

// ---- requests and flow control ---------------------------------------------

function request(quality) {
  if (!ws || ws.readyState !== WebSocket.OPEN || !scene) return null;
  const s = ++seq;
  const snapshot = structuredClone(scene);
  ws.send(JSON.stringify({
    type: 'render', seq: s, quality, scene: snapshot,
    error_map: { enabled: $('error-map').checked, tolerance: errorTolerance },
    refine: $('refine').checked,
  }));
  hooks.sentAt.set(s, performance.now());
  if (hooks.sentAt.size > MAX_FRAMES_KEPT) hooks.sentAt.delete(hooks.sentAt.keys().next().value);
  if (quality === 'final') {
    sentFinals.set(s, snapshot);
    // A final the server dropped (refused, or cancelled by a newer one) would stay forever.
    for (const k of sentFinals.keys()) if (sentFinals.size > 32) sentFinals.delete(k);
  }
  return s;
}

// At most one preview in flight: while one is, remember that the state moved on.
function wantPreview() {
  if (preview.outstanding !== null) { preview.dirty = true; return; }
  sendPreview();
}

function sendPreview() {
  preview.dirty = false;
  preview.sent = JSON.stringify(scene);
  preview.outstanding = request('preview');
  clearTimeout(preview.timer);
  if (preview.outstanding === null) return;
  // Nothing came in time (a slow or dropped preview): stop waiting for it. The
  // newest state goes out if it moved on; resending an unchanged one would
  // only cancel the render the server is still busy with.
  preview.timer = setTimeout(() => {
    preview.outstanding = null;
    if (preview.dirty && JSON.stringify(scene) !== preview.sent) sendPreview();
  }, PREVIEW_RESEND_MS);
}

// A preview frame, or an error, for seq s: the next preview may go.
function previewAnswered(s) {
  if (preview.outstanding === null || !(s >= preview.outstanding)) return;
  preview.outstanding = null;
  clearTimeout(preview.timer);
  if (preview.dirty && JSON.stringify(scene) !== preview.sent) sendPreview();
  preview.dirty = false;
}

function resetPreview() {
  clearTimeout(preview.timer);
  preview.outstanding = null;
  preview.dirty = false;
}

function sendFinal() {
  resetPreview();
  request('final');
}

// ---- frames -----------------------------------------------------------------

let drawQueue = Promise.resolve();  // frames are decoded and drawn in arrival order

function onFrame(buf) {
  const n = new DataView(buf).getUint32(0, true);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, 4, n)));
  const bytes = new Uint8Array(buf, 4 + n);
  const entry = { ...header, bytes: bytes.length, receivedAt: performance.now() };
  hooks.frames.push(entry);
  if (hooks.frames.length > MAX_FRAMES_KEPT) hooks.frames.shift();
  if (header.stage === 'preview') previewAnswered(header.seq);
  drawQueue = drawQueue
    .then(() => showFrame(header, bytes, entry))
    .catch((e) => showError(`frame ${header.seq}: ${e.message || e}`, header.seq));
}

async function showFrame(h, bytes, entry) {
  if (!(h.seq >= minSeq)) return;
  const type = h.format === 'jpeg' ? 'image/jpeg' : 'image/png';
  if (h.stage === 'final' && !(h.seq <= (hooks.lastFinal?.seq ?? -1))) {
    // Kept whether drawn or not: "save image" and "save scene" must stay a pair.
    hooks.lastFinal = h;
    hooks.lastFinalBytes = bytes.slice();
    lastFinalScene = hooks.lastFinalScene = sentFinals.get(h.seq) ?? null;
    for (const k of sentFinals.keys()) if (k <= h.seq) sentFinals.delete(k);
    $('save-scene').disabled = $('save-image').disabled = lastFinalScene === null;
  }
  if (h.stage === 'error_map') {
    if (h.seq < shown.seq) return;
    const bmp = await createImageBitmap(new Blob([bytes], { type }),
      { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
    overlay = { seq: h.seq, canvas: colorize(bmp), header: h };
    bmp.close();
  } else {
    if (h.seq < shown.seq) return;
    if (h.stage === 'exact' && !$('refine').checked) return;
    const bmp = await createImageBitmap(new Blob([bytes], { type }));
    if (shown.bitmap) shown.bitmap.close();
    shown = { seq: h.seq, stage: h.stage, bitmap: bmp, header: h };
    if (overlay && overlay.seq !== h.seq) overlay = null;
  }
  if (h.seq > errorSeq) errorText = '';
  paint();
  updateStatus();
  entry.drawn = true;
  entry.drawnAt = performance.now();  // bench/viewer_latency.mjs: request sent -> frame on screen
}

// The image scaled to the canvas, and the error map over it when asked for.
function paint() {
  const c = $('image'), g = c.getContext('2d');
  const bg = scene?.background ?? [0, 0, 0];
  g.fillStyle = toHex(bg[0], bg[1], bg[2]);
  g.fillRect(0, 0, c.width, c.height);
  if (!shown.bitmap) return;
  g.imageSmoothingEnabled = true;
  g.drawImage(shown.bitmap, 0, 0, c.width, c.height);
  if (overlayShown()) {
    g.imageSmoothingEnabled = false;  // the map is per pixel: don't blur it
    g.globalAlpha = 0.85;
    g.drawImage(overlay.canvas, 0, 0, c.width, c.height);
    g.globalAlpha = 1;
  }
}

const overlayShown = () => $('error-map').checked && overlay !== null && overlay.seq === shown.seq;

const ms = (x) => (typeof x === 'number' ? x.toFixed(1) : '–') + ' ms';
const sci = (x) => (typeof x === 'number' ? x.toExponential(2) : '–');

function updateStatus() {
  const h = shown.header;
  $('status-frame').textContent = h
    ? `${h.stage}  render ${ms(h.render_ms)}  table/setup ${ms(h.setup_ms)}  ${h.method ?? ''}  ${h.width}×${h.height}`
    : (welcome ? 'waiting for the first frame…' : 'connecting…');
  const e = overlayShown() ? overlay.header.error : null;
  $('status-errmap').textContent = e
    ? `share over tol: ${(100 * e.share_over).toFixed(2)}%  max: ${sci(e.max)}  rms: ${sci(e.rms)}`
    : ($('error-map').checked ? 'error map: waiting…' : '');
  $('status-error').textContent = errorText;
}

function showError(message, s) {
  errorText = message;
  errorSeq = typeof s === 'number' ? s : seq;
  updateStatus();
}

// ---- the connection ------------------------------------------------------------

function connect() {
  const token = new URLSearchParams(location.search).get('token');
  // Without a token in the address, the cookie the page's load set is the credential.
  const query = token ? `?token=${encodeURIComponent(token)}` : '';
  ws = hooks.socket = new WebSocket(`ws://${location.host}/ws${query}`);
  ws.binaryType = 'arraybuffer';
  ws.onmessage = (ev) => {
    if (typeof ev.data !== 'string') { onFrame(ev.data); return; }
    let msg;
    try { msg = JSON.parse(ev.data); } catch { showError('unreadable message from the server'); return; }
    if (msg.type === 'welcome') onWelcome(msg);
    else if (msg.type === 'error') {
      hooks.errors.push(msg);
      showError(`error${typeof msg.seq === 'number' ? ` (request ${msg.seq})` : ''}: ${msg.message}`, msg.seq);
      if (typeof msg.seq === 'number') previewAnswered(msg.seq);
    }
  };
  ws.onclose = (ev) => {
    closed = true;
    showError(`connection closed${ev.code ? ` (${ev.code}${ev.reason ? ': ' + ev.reason : ''})` : ''}; reload the page to reconnect`, Infinity);
  };
}

// A welcome starts everything anew: first connect, or after "open".
function onWelcome(w) {
  welcome = hooks.welcome = w;
  minSeq = seq + 1;
  scene = structuredClone(w.scene);
  scene.lighting ??= {};
  scene.method ??= {};
  welcomeCamera = structuredClone(w.scene.camera);
  sentFinals = new Map();
  lastFinalScene = hooks.lastFinalScene = null;
  hooks.lastFinal = hooks.lastFinalBytes = null;
  $('save-scene').disabled = $('save-image').disabled = true;
  if (shown.bitmap) shown.bitmap.close();
  shown = { seq: -1, stage: null, bitmap: null, header: null };
  overlay = null;
  if (!closed) errorText = '';
  resetPreview();

  options($('dataset'), (w.datasets ?? []).map((d) => [d.id, d.name ?? d.id]), w.current);
  options($('preset'), [['', '—'], ...(w.presets ?? []).map((p, i) => [String(i), p.name])], '');
  const methods = [...(w.methods ?? [])];
  if (scene.method.name && !methods.includes(scene.method.name)) methods.push(scene.method.name);
  options($('method'), methods.map((m) => [m, m]), scene.method.name);
  for (const [id, key] of METHOD_FIELDS) $(id).value = scene.method[key] ?? '';
  for (const [id, key] of LIGHT_FIELDS) $(id).value = scene.lighting[key] ?? '';
  $('lighting-enabled').checked = !!scene.lighting.enabled;
  $('lighting-mode').value = scene.lighting.mode ?? 'sampled';
  const bg = scene.background ?? [0, 0, 0];
  $('background').value = toHex(bg[0], bg[1], bg[2]);

  clipControls(scene.clip, w.volume?.bounds);

  let [lo, hi] = w.volume?.range ?? w.histogram?.range ?? [0, 1];
  if (!(hi > lo)) hi = lo + 1;  // a constant volume still needs an axis
  $('range-lo').value = lo;
  $('range-hi').value = hi;
  editor.set(scene.transfer_function?.points ?? [], w.histogram, [lo, hi], w.volume?.unit_distance);
  scene.transfer_function = editor.value();

  setSize();
  updateStatus();
  sendFinal();
}

function options(select, entries, value) {
  select.replaceChildren(...entries.map(([v, text]) => new Option(text, v)));
  select.value = value;
}

// ---- image size and camera -------------------------------------------------------

// The canvas holds the camera's pixels: CSS size × devicePixelRatio, at most MAX_SIZE.
function imageSize() {
  const r = $('image-area').getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  let w = r.width * dpr, h = r.height * dpr;
  const k = Math.min(1, MAX_SIZE / Math.max(w, h, 1));  // keep the aspect when clamping
  return [Math.max(1, Math.round(w * k)), Math.max(1, Math.round(h * k))];
}

function setSize() {
  const [w, h] = imageSize();
  const c = $('image');
  if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
  if (scene) { scene.camera.width = w; scene.camera.height = h; }
  paint();
}

let resizeTimer = null;
new ResizeObserver(() => {
  clearTimeout(resizeTimer);
  resizeTimer = setTimeout(() => {
    const [w, h] = imageSize();
    if (!scene || (w === scene.camera.width && h === scene.camera.height)) return;
    setSize();
    sendFinal();
  }, 150);
}).observe($('image-area'));

const image = $('image');
const viewHeight = () => image.getBoundingClientRect().height;

image.addEventListener('pointerdown', (e) => {
  if (e.button !== 0 || !scene) return;
  camDrag = { x: e.clientX, y: e.clientY, camera: structuredClone(scene.camera), pan: e.shiftKey, moved: false };
  image.setPointerCapture(e.pointerId);
});
image.addEventListener('pointermove', (e) => {
  if (!camDrag) return;
  const dx = e.clientX - camDrag.x, dy = e.clientY - camDrag.y;
  if (dx === 0 && dy === 0) return;
  camDrag.moved = true;
  // From the camera at the press: no drift however many events come.
  scene.camera = (camDrag.pan ? pan : orbit)(camDrag.camera, dx, dy, viewHeight());
  wantPreview();
});
const endDrag = (e) => {
  if (!camDrag) return;
  const moved = camDrag.moved;
  camDrag = null;
  if (image.hasPointerCapture(e.pointerId)) image.releasePointerCapture(e.pointerId);
  if (moved) sendFinal();
};
image.addEventListener('pointerup', endDrag);
image.addEventListener('pointercancel', endDrag);
image.addEventListener('wheel', (e) => {
  if (!scene) return;
  e.preventDefault();
  const delta = e.deltaY * (e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1);
  scene.camera = zoom(scene.camera, Math.exp(delta * 0.0015));
  wantPreview();
  clearTimeout(wheelTimer);
  wheelTimer = setTimeout(() => { wheelTimer = null; sendFinal(); }, 250);
}, { passive: false });

$('reset-view').addEventListener('click', () => {
  if (!scene) return;
  scene.camera = { ...structuredClone(welcomeCamera), width: scene.camera.width, height: scene.camera.height };
  sendFinal();
});

// ---- controls ------------------------------------------------------------------------

const METHOD_FIELDS = [['step', 'step'], ['table-size', 'table_size'], ['tolerance', 'tolerance'], ['iterations', 'iterations']];
const LIGHT_FIELDS = [['lighting-ambient', 'ambient'], ['lighting-diffuse', 'diffuse'],
  ['lighting-specular', 'specular'], ['lighting-shininess', 'shininess']];

// A number field: empty leaves the key out (the server's default); the server
// judges the value, and its error reply shows in the status line.
function numberField(id, target, key) {
  $(id).addEventListener('change', () => {
    if (!scene) return;
    const text = $(id).value.trim(), v = Number(text);
    $(id).classList.toggle('bad', text !== '' && !Number.isFinite(v));
    if (text !== '' && !Number.isFinite(v)) return;
    if (text === '') delete target()[key]; else target()[key] = v;
    sendFinal();
  });
}
for (const [id, key] of METHOD_FIELDS) numberField(id, () => scene.method, key);
for (const [id, key] of LIGHT_FIELDS) numberField(id, () => scene.lighting, key);

function onChange(id, apply) {
  $(id).addEventListener('change', () => { if (scene) { apply($(id)); sendFinal(); } });
}
onChange('method', (el) => { scene.method.name = el.value; });
onChange('lighting-enabled', (el) => { scene.lighting.enabled = el.checked; });
onChange('lighting-mode', (el) => { scene.lighting.mode = el.value; });
onChange('background', (el) => { scene.background = fromHex(el.value); });
onChange('refine', () => {});
onChange('error-map', (el) => {
  $('colorbar-box').hidden = !el.checked;
  if (el.checked) drawColorbar($('colorbar'), errorTolerance);
  paint();
  updateStatus();
});
onChange('error-tolerance', (el) => {
  const v = Number(el.value);
  el.classList.toggle('bad', !(v > 0));
  if (v > 0) errorTolerance = v;
  if ($('error-map').checked) drawColorbar($('colorbar'), errorTolerance);
});

// ---- clip (SPEC §12 "clip", docs/CLIPPING.md) ------------------------------------------
// One plane across an axis and a crop box, each slider a thousandth of the
// volume's box; dragging previews, letting go renders the final frame.

let bounds = [[0, 0, 0], [1, 1, 1]];
const CROP = [0, 1, 2].map((a) => [`crop-lo-${a}`, `crop-hi-${a}`]);
const at = (a, v) => bounds[0][a] + (bounds[1][a] - bounds[0][a]) * Number(v) / 1000;
const slider = (a, x) => String(Math.round(1000 * (x - bounds[0][a]) / ((bounds[1][a] - bounds[0][a]) || 1)));

// The controls from a scene's clip: a plane across an axis and a box they
// show; anything else (oblique or several planes) is kept and noted.
function clipControls(clip, box) {
  if (Array.isArray(box) && box.length === 2) bounds = box;
  const planes = clip?.planes ?? [];
  const axis = planes.length === 1 ? planes[0].slice(0, 3).findIndex((x) => x !== 0) : -1;
  const simple = planes.length === 0 ||
    (planes.length === 1 && planes[0].slice(0, 3).filter((x) => x !== 0).length === 1);
  $('clip-custom').hidden = simple;
  $('clip-axis').value = axis >= 0 && simple ? String(axis) : '';
  $('clip-flip').checked = axis >= 0 && planes[0][axis] < 0;
  $('clip-at').value = axis >= 0 ? slider(axis, -planes[0][3] / planes[0][axis]) : '500';
  $('crop').checked = !!clip?.box;
  $('crop-sliders').hidden = !clip?.box;
  CROP.forEach(([lo, hi], a) => {
    $(lo).value = clip?.box ? slider(a, clip.box[0][a]) : '0';
    $(hi).value = clip?.box ? slider(a, clip.box[1][a]) : '1000';
  });
}

// The scene's clip from the controls (none: the key left out).
function clipFromControls() {
  const clip = {};
  const axis = $('clip-axis').value;
  if (axis !== '') {
    const a = Number(axis), sign = $('clip-flip').checked ? -1 : 1, n = [0, 0, 0];
    n[a] = sign;
    clip.planes = [[...n, -sign * at(a, $('clip-at').value)]];
  }
  if ($('crop').checked) {
    const lo = CROP.map(([l, h], a) => at(a, Math.min(Number($(l).value), Number($(h).value))));
    const hi = CROP.map(([l, h], a) => at(a, Math.max(Number($(l).value), Number($(h).value))));
    clip.box = [lo, hi];
  }
  if (Object.keys(clip).length) scene.clip = clip; else delete scene.clip;
  $('clip-custom').hidden = true;
}

for (const id of ['clip-axis', 'clip-flip', 'crop', 'clip-at', ...CROP.flat()]) {
  const el = $(id);
  el.addEventListener('input', () => {
    if (!scene) return;
    $('crop-sliders').hidden = !$('crop').checked;
    clipFromControls();
    if (el.type === 'range') wantPreview();  // a drag: previews until let go
  });
  el.addEventListener('change', () => { if (scene) { clipFromControls(); sendFinal(); } });
}

$('preset').addEventListener('change', () => {
  const p = welcome?.presets?.[Number($('preset').value)];
  if (!p || $('preset').value === '') return;
  if (!Array.isArray(p.transfer_function?.points)) { showError(`preset ${p.name}: no "points"`); return; }
  editor.setPoints(p.transfer_function.points);
  scene.transfer_function = editor.value();
  sendFinal();
});

for (const id of ['range-lo', 'range-hi']) {
  $(id).addEventListener('change', () => {
    const ok = editor.setRange(Number($('range-lo').value), Number($('range-hi').value));
    $('range-lo').classList.toggle('bad', !ok);
    $('range-hi').classList.toggle('bad', !ok);
  });
}

$('dataset').addEventListener('change', () => {
  if (ws?.readyState === WebSocket.OPEN) ws.send(JSON.stringify({ type: 'open', dataset: $('dataset').value }));
});

$('panel-toggle').addEventListener('click', () => document.body.classList.toggle('collapsed'));

// ---- saving ---------------------------------------------------------------------------

// Exactly the scene of the last final frame: `vri render` of it gives its bytes.
function sceneText() {
  if (!lastFinalScene || !welcome) return null;
  return JSON.stringify({ volume: welcome.volume.json, ...lastFinalScene }, null, 2) + '\n';
}

function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 60_000);  // revoking at once can cancel it
}

$('save-scene').addEventListener('click', () => {
  const text = sceneText();
  if (text) download('scene.json', new Blob([text], { type: 'application/json' }));
});
$('save-image').addEventListener('click', () => {
  if (hooks.lastFinalBytes) download('image.png', new Blob([hooks.lastFinalBytes], { type: 'image/png' }));
});

setSize();
updateStatus();
connect();
