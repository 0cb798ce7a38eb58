// The error map's colours. The server sends an 8-bit grey PNG whose value v
// stands for the error 10^(6·v/255 − 6): 0 is at most 1e-6, 255 is 1 or more.
// The page colours it with inferno (perceptually uniform, readable in grey).

// matplotlib's inferno at 0, 0.1, ..., 1.
const INFERNO = ['#000004', '#160b39', '#420a68', '#6a176e', '#932667', '#bc3754',
  '#dd513a', '#f37819', '#fca50a', '#f6d746', '#fcffa4'];

function rgb(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
}

// 256 entries, linear between the stops.
export const LUT = (() => {
  const stops = INFERNO.map(rgb), out = [];
  for (let v = 0; v < 256; v++) {
    const t = v / 255 * (stops.length - 1), i = Math.min(Math.floor(t), stops.length - 2), f = t - i;
    out.push(stops[i].map((c, k) => Math.round(c + f * (stops[i + 1][k] - c))));
  }
  return out;
})();

// The error a grey value stands for, and back (for the tolerance mark).
export const errorOf = (v) => Math.pow(10, 6 * v / 255 - 6);
export const positionOf = (err) => Math.min(1, Math.max(0, (Math.log10(err) + 6) / 6));

// A canvas of the map in colour. Pixels at the floor (error ≤ 1e-6) stay
// transparent so the image shows where the method is as good as exact.
export function colorize(bitmap) {
  const c = document.createElement('canvas');
  c.width = bitmap.width;
  c.height = bitmap.height;
  const g = c.getContext('2d', { willReadFrequently: true });
  g.drawImage(bitmap, 0, 0);
  const img = g.getImageData(0, 0, c.width, c.height), d = img.data;
  for (let p = 0; p < d.length; p += 4) {
    const v = d[p];  // grey: r = g = b
    const [r, gr, b] = LUT[v];
    d[p] = r; d[p + 1] = gr; d[p + 2] = b;
    d[p + 3] = v === 0 ? 0 : 255;
  }
  g.putImageData(img, 0, 0);
  return c;
}

// The colour bar: 1e-6 … 1 in decades, with a mark at the tolerance.
export function drawColorbar(canvas, tolerance) {
  const dpr = window.devicePixelRatio || 1;
  const W = canvas.clientWidth, H = canvas.clientHeight;
  canvas.width = Math.round(W * dpr);
  canvas.height = Math.round(H * dpr);
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, W, H);
  const x0 = 14, x1 = W - 14, barH = 12;
  for (let x = x0; x < x1; x++) {
    const [r, gr, b] = LUT[Math.round((x - x0) / (x1 - x0 - 1) * 255)];
    g.fillStyle = `rgb(${r},${gr},${b})`;
    g.fillRect(x, 2, 1, barH);
  }
  g.strokeStyle = '#aaa';
  g.strokeRect(x0 - 0.5, 1.5, x1 - x0 + 1, barH + 1);
  g.fillStyle = '#ddd';
  g.font = '10px sans-serif';
  g.textAlign = 'center';
  for (let k = 0; k <= 6; k++) {
    const x = x0 + k / 6 * (x1 - x0);
    g.fillRect(Math.round(x), barH + 3, 1, 3);
    g.fillText(k === 6 ? '1' : `1e-${6 - k}`, x, barH + 16);
  }
  if (tolerance > 0) {
    const x = Math.round(x0 + positionOf(tolerance) * (x1 - x0));
    g.fillStyle = '#4cf';
    g.fillRect(x - 1, 0, 2, barH + 4);
  }
}
