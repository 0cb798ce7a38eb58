// The transfer-function editor: control points over the volume's histogram.
//
// vri stores each point as [s, r, g, b, tau] (SPEC §3). The vertical axis shows
// the opacity of one voxel, α = 1 − exp(−tau·u) with u the volume's unit
// distance. Only a point dragged vertically gets a new tau; every other point
// keeps the numbers it came with, so a function survives the round trip exactly.

const PAD_X = 7;       // room for the points at both ends of the axis
const PAD_TOP = 7;
const STRIP = 10;      // colour strip under the plot
const HIT = 7;         // pick radius, CSS pixels
const ALPHA_MAX = 0.999;

const clamp = (x, lo, hi) => Math.min(hi, Math.max(lo, x));

export function toHex(r, g, b) {
  const h = (c) => Math.round(clamp(c, 0, 1) * 255).toString(16).padStart(2, '0');
  return '#' + h(r) + h(g) + h(b);
}

export function fromHex(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [((n >> 16) & 255) / 255, ((n >> 8) & 255) / 255, (n & 255) / 255];
}

export class TfEditor {
  // onChange(quality): 'preview' while dragging, 'final' when an edit ends.
  constructor(canvas, colorInput, onChange) {
    this.canvas = canvas;
    this.colorInput = colorInput;
    this.onChange = onChange;
    this.points = [];
    this.counts = [];
    this.histRange = [0, 1];
    this.range = [0, 1];
    this.unit = 1;
    this.selected = -1;
    this.drag = null;

    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
    canvas.addEventListener('pointercancel', (e) => this.up(e));
    canvas.addEventListener('dblclick', (e) => this.remove(e));
    canvas.addEventListener('contextmenu', (e) => { e.preventDefault(); this.remove(e); });
    colorInput.addEventListener('input', () => this.recolor('preview'));
    colorInput.addEventListener('change', () => this.recolor('final'));
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  // points: [[s, r, g, b, tau], ...], copied; histogram: {range, counts}.
  set(points, histogram, range, unitDistance) {
    this.points = points.map((p) => [...p]);
    this.counts = histogram?.counts ?? [];
    this.histRange = histogram?.range ?? range;
    this.range = [...range];
    this.unit = unitDistance > 0 ? unitDistance : 1;
    this.drag = null;
    this.select(this.points.length > 1 ? 1 : 0);
  }

  setPoints(points) {
    this.points = points.map((p) => [...p]);
    this.drag = null;
    this.select(Math.min(this.selected, this.points.length - 1));
  }

  setRange(lo, hi) {
    if (!(hi > lo)) return false;
    this.range = [lo, hi];
    this.draw();
    return true;
  }

  // The function as the scene file writes it.
  value() { return { points: this.points.map((p) => [...p]) }; }

  alphaOf(tau) { return 1 - Math.exp(-tau * this.unit); }
  tauOf(alpha) { return -Math.log(1 - clamp(alpha, 0, ALPHA_MAX)) / this.unit; }

  // Plot area in CSS pixels, relative to the canvas.
  box() {
    const r = this.canvas.getBoundingClientRect();
    return { x0: PAD_X, x1: r.width - PAD_X, y0: PAD_TOP, y1: r.height - STRIP - 3, rect: r };
  }
  xOf(s, b) { return b.x0 + (s - this.range[0]) / (this.range[1] - this.range[0]) * (b.x1 - b.x0); }
  sOf(x, b) { return this.range[0] + (x - b.x0) / (b.x1 - b.x0) * (this.range[1] - this.range[0]); }
  yOf(alpha, b) { return b.y1 - alpha * (b.y1 - b.y0); }
  alphaAt(y, b) { return clamp((b.y1 - y) / (b.y1 - b.y0), 0, ALPHA_MAX); }

  // Page coordinates (clientX, clientY) of point i: the e2e test drags it.
  pointClientXY(i) {
    const b = this.box(), p = this.points[i];
    if (!p) return null;
    return { x: b.rect.left + this.xOf(p[0], b), y: b.rect.top + this.yOf(this.alphaOf(p[4]), b) };
  }

  // Nearest point within the pick radius, or -1.
  hit(e) {
    const b = this.box();
    const x = e.clientX - b.rect.left, y = e.clientY - b.rect.top;
    let best = -1, bestD = HIT;
    this.points.forEach((p, i) => {
      const d = Math.hypot(this.xOf(p[0], b) - x, this.yOf(this.alphaOf(p[4]), b) - y);
      if (d <= bestD) { best = i; bestD = d; }
    });
    return best;
  }

  // r, g, b (and tau as given) interpolated linearly in s, as the renderer does.
  sample(s) {
    const P = this.points;
    if (P.length === 0) return [0, 0, 0, 0];
    if (s <= P[0][0]) return P[0].slice(1);
    for (let i = 1; i < P.length; i++) {
      if (s < P[i][0]) {
        const a = P[i - 1], c = P[i];
        const t = c[0] > a[0] ? (s - a[0]) / (c[0] - a[0]) : 1;
        return [1, 2, 3, 4].map((k) => a[k] + t * (c[k] - a[k]));
      }
    }
    return P[P.length - 1].slice(1);
  }

  select(i) {
    this.selected = i;
    const p = this.points[i];
    this.colorInput.disabled = !p;
    if (p) this.colorInput.value = toHex(p[1], p[2], p[3]);
    this.draw();
  }

  down(e) {
    if (e.button !== 0) return;
    const b = this.box();
    let i = this.hit(e);
    if (i < 0) {
      // A click on an empty place adds a point there, ready to be dragged.
      const s = clamp(this.sOf(e.clientX - b.rect.left, b), this.range[0], this.range[1]);
      const [r, g, bl] = this.sample(s);
      const tau = this.tauOf(this.alphaAt(e.clientY - b.rect.top, b));
      i = this.points.findIndex((p) => p[0] > s);
      if (i < 0) i = this.points.length;
      this.points.splice(i, 0, [s, r, g, bl, tau]);
      this.drag = { i, added: true, moved: false };
    } else {
      this.drag = { i, added: false, moved: false };
    }
    const p = this.points[i];
    Object.assign(this.drag, { x: e.clientX, y: e.clientY, s: p[0], alpha: this.alphaOf(p[4]), tau: p[4] });
    this.canvas.setPointerCapture(e.pointerId);
    this.select(i);
    if (this.drag.added) this.onChange('preview');
  }

  move(e) {
    const d = this.drag;
    if (!d) {
      this.canvas.style.cursor = this.hit(e) >= 0 ? 'grab' : 'crosshair';
      return;
    }
    const dx = e.clientX - d.x, dy = e.clientY - d.y;
    if (!d.moved && Math.hypot(dx, dy) < 3) return;  // a click, not a drag
    d.moved = true;
    const b = this.box(), P = this.points, p = P[d.i];
    // A point cannot pass its neighbours: the list stays sorted by s.
    const lo = d.i > 0 ? P[d.i - 1][0] : this.range[0];
    const hi = d.i < P.length - 1 ? P[d.i + 1][0] : this.range[1];
    p[0] = dx === 0 ? d.s : clamp(d.s + dx / (b.x1 - b.x0) * (this.range[1] - this.range[0]), Math.min(lo, d.s), Math.max(hi, d.s));
    // Only a vertical move changes tau; otherwise the stored value stays exact.
    p[4] = dy === 0 ? d.tau : this.tauOf(d.alpha - dy / (b.y1 - b.y0));
    this.draw();
    this.onChange('preview');
  }

  up(e) {
    const d = this.drag;
    if (!d) return;
    this.drag = null;
    if (this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
    if (d.moved || d.added) this.onChange('final');
  }

  remove(e) {
    const i = this.hit(e);
    if (i < 0 || this.points.length <= 1) return;  // vri needs one point at least
    this.points.splice(i, 1);
    this.drag = null;
    this.select(Math.min(i, this.points.length - 1));
    this.onChange('final');
  }

  recolor(quality) {
    const p = this.points[this.selected];
    if (!p) return;
    [p[1], p[2], p[3]] = fromHex(this.colorInput.value);
    this.draw();
    this.onChange(quality);
  }

  draw() {
    const c = this.canvas, dpr = window.devicePixelRatio || 1;
    const b = this.box();
    const W = Math.round(b.rect.width * dpr), H = Math.round(b.rect.height * dpr);
    if (W === 0 || H === 0) return;
    if (c.width !== W || c.height !== H) { c.width = W; c.height = H; }
    const g = c.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, b.rect.width, b.rect.height);
    g.fillStyle = '#181818';
    g.fillRect(b.x0, b.y0, b.x1 - b.x0, b.y1 - b.y0);

    // Histogram: log counts as a filled grey area, mapped onto the editor's axis.
    const n = this.counts.length;
    if (n > 0) {
      const top = Math.log1p(Math.max(...this.counts)) || 1;
      const [h0, h1] = this.histRange;
      g.save();
      g.beginPath();
      g.rect(b.x0, b.y0, b.x1 - b.x0, b.y1 - b.y0);
      g.clip();
      g.beginPath();
      g.moveTo(this.xOf(h0, b), b.y1);
      this.counts.forEach((count, i) => {
        const y = b.y1 - Math.log1p(count) / top * (b.y1 - b.y0);
        g.lineTo(this.xOf(h0 + i / n * (h1 - h0), b), y);
        g.lineTo(this.xOf(h0 + (i + 1) / n * (h1 - h0), b), y);
      });
      g.lineTo(this.xOf(h1, b), b.y1);
      g.closePath();
      g.fillStyle = 'rgba(150,150,150,0.45)';
      g.fill();
      g.restore();
    }

    // Opacity curve: tau is linear in s, so α is sampled per pixel.
    g.save();
    g.beginPath();
    g.rect(b.x0 - PAD_X, 0, b.x1 - b.x0 + 2 * PAD_X, b.rect.height);
    g.clip();
    g.beginPath();
    for (let x = Math.floor(b.x0); x <= Math.ceil(b.x1); x++) {
      const y = this.yOf(this.alphaOf(this.sample(this.sOf(x, b))[3]), b);
      if (x === Math.floor(b.x0)) g.moveTo(x, y); else g.lineTo(x, y);
    }
    g.strokeStyle = '#e8e8e8';
    g.lineWidth = 1.5;
    g.stroke();

    // Colour strip: the function's colour at each s.
    for (let x = Math.floor(b.x0); x < Math.ceil(b.x1); x++) {
      const [r, gr, bl] = this.sample(this.sOf(x + 0.5, b));
      g.fillStyle = toHex(r, gr, bl);
      g.fillRect(x, b.y1 + 3, 1, STRIP);
    }

    this.points.forEach((p, i) => {
      const x = this.xOf(p[0], b), y = this.yOf(this.alphaOf(p[4]), b);
      g.beginPath();
      g.arc(x, y, i === this.selected ? 5.5 : 4.5, 0, 2 * Math.PI);
      g.fillStyle = toHex(p[1], p[2], p[3]);
      g.fill();
      g.lineWidth = i === this.selected ? 2 : 1;
      g.strokeStyle = i === this.selected ? '#ffffff' : '#808080';
      g.stroke();
    });
    g.restore();
  }
}
