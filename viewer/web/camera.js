// Orbit, zoom and pan of a SPEC §6 camera ({eye, target, up, fov_y, width,
// height, projection, ortho_height}). Every function returns a new camera and
// leaves its argument alone, so the page can keep the welcome camera for "reset".

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const scale = (a, k) => [a[0] * k, a[1] * k, a[2] * k];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const length = (a) => Math.sqrt(dot(a, a));
const normalize = (a) => scale(a, 1 / (length(a) || 1));

// Rodrigues: v rotated by `angle` (radians) about the unit axis k.
function rotate(v, k, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}

// The camera's frame as SPEC §6 defines it: w points from the target to the
// eye, u to the image's right, v to its top.
export function frame(cam) {
  const w = normalize(sub(cam.eye, cam.target));
  const u = normalize(cross(cam.up, w));
  const v = cross(w, u);
  return { w, u, v };
}

function copy(cam) {
  return { ...cam, eye: [...cam.eye], target: [...cam.target], up: [...cam.up] };
}

// The elevation stays this far from the poles: at a pole the frame (up × w)
// degenerates and the renderer refuses the camera.
const MAX_ELEVATION = 89 * Math.PI / 180;

// Drag by (dx, dy) CSS pixels over a view `viewPx` pixels high: a drag over the
// whole height turns the camera by 180°. Azimuth turns about `up`, elevation
// towards `up`, clamped short of the poles; `up` itself never changes.
export function orbit(cam, dx, dy, viewPx) {
  const out = copy(cam);
  const k = Math.PI / Math.max(viewPx, 1);
  const up = normalize(cam.up);
  const offset = sub(cam.eye, cam.target);
  const dist = length(offset);
  const along = dot(offset, up);
  const flat = sub(offset, scale(up, along));
  if (length(flat) < 1e-12 * dist) return out;  // looking along up: no azimuth to turn
  // Dragging right turns the object right, so the eye goes left.
  const h = normalize(rotate(flat, up, -dx * k));
  // Dragging down shows the object's top: the eye goes up.
  const elevation = Math.atan2(along, length(flat));
  const limit = Math.max(MAX_ELEVATION, Math.abs(elevation));  // never jump back into range
  const e = Math.min(limit, Math.max(-limit, elevation + dy * k));
  out.eye = add(cam.target, scale(add(scale(h, Math.cos(e)), scale(up, Math.sin(e))), dist));
  return out;
}

// factor > 1 moves away. Perspective scales the eye–target distance,
// orthographic the visible height (moving an orthographic eye changes nothing).
export function zoom(cam, factor) {
  const out = copy(cam);
  if (cam.projection === 'orthographic') {
    out.ortho_height = cam.ortho_height * factor;
  } else {
    out.eye = add(cam.target, scale(sub(cam.eye, cam.target), factor));
  }
  return out;
}

// Move eye and target in the view plane so that the point under the mouse (at
// the target's depth) follows it.
export function pan(cam, dx, dy, viewPx) {
  const out = copy(cam);
  const { u, v } = frame(cam);
  const visible = cam.projection === 'orthographic'
    ? cam.ortho_height
    : 2 * length(sub(cam.eye, cam.target)) * Math.tan((cam.fov_y ?? 30) * Math.PI / 360);
  const k = visible / Math.max(viewPx, 1);
  const shift = add(scale(u, -dx * k), scale(v, dy * k));
  out.eye = add(cam.eye, shift);
  out.target = add(cam.target, shift);
  return out;
}
