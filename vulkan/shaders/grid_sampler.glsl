// The volume's samples and their trilinear interpolation, as FloatSampler
// (src/volume/float_sampler.hpp) does on the CPU: the cell of a grid
// position clamped onto the box, float fractions, the eight corners
// converted to float exactly and interpolated in the same order. The samples
// stay in their stored type, packed in 32-bit words (uint8 four to a word,
// 16-bit two): a 256^3 uint8 volume takes 16 MiB on the GPU, not 64.
// Needs before it: SPLIT_INPUT(uint, volume, ...) (split_array.glsl) and the
// push-constant block `p` with the volume's layout (grid.type, sy, sz,
// last_cell; GRID_TOP).

// The storage types of GridVolume (other file types are converted on loading).
const int kUInt8 = 0, kUInt16 = 1, kInt16 = 2, kFloat32 = 3;

float voxel(uint i) {
  switch (p.type) {
    case kUInt8: return float((volume_at(i >> 2) >> ((i & 3u) * 8u)) & 0xffu);
    case kUInt16: return float((volume_at(i >> 1) >> ((i & 1u) * 16u)) & 0xffffu);
    case kInt16: return float(bitfieldExtract(int(volume_at(i >> 1)), int((i & 1u) * 16u), 16));
    default: return uintBitsToFloat(volume_at(i));
  }
}

struct Cell {
  uint offset;
  vec3 f;
  ivec3 index;  // the cell's lower corner (clamped to the last cell)
};

// The cell of grid position (x, y, z) in double-float, clamped as FloatSampler::cell.
Cell grid_cell(DF u[3]) {
  Cell c;
  int idx[3];
  for (int a = 0; a < 3; ++a) {
    DF x = u[a];
    if (x.hi < 0.0 || (x.hi == 0.0 && x.lo < 0.0)) x = DF(0.0, 0.0);
    if (x.hi > GRID_TOP(a) || (x.hi == GRID_TOP(a) && x.lo > 0.0)) x = DF(GRID_TOP(a), 0.0);
    float fl = floor(x.hi);
    if (fl == x.hi && x.lo < 0.0) fl -= 1.0;  // hi an integer, the value just below it
    int i = int(fl);
    precise float f = (x.hi - fl) + x.lo;  // x.hi - fl is exact
    if (i > p.last_cell[a]) {
      f += float(i - p.last_cell[a]);
      i = p.last_cell[a];
    }
    idx[a] = i;
    c.f[a] = f;
  }
  c.offset = uint(idx[0]) + p.sy * uint(idx[1]) + p.sz * uint(idx[2]);
  c.index = ivec3(idx[0], idx[1], idx[2]);
  return c;
}

// Trilinear in a cell's corner values c000, c100, c010, c110, c001, ... (x
// fastest), in FloatSampler::interpolate's order; the gradient's components
// (shading.glsl) use it too.
float trilinear(float v0, float v1, float v2, float v3, float v4, float v5, float v6, float v7, vec3 f) {
  precise float c00 = v0 + f.x * (v1 - v0);
  precise float c10 = v2 + f.x * (v3 - v2);
  precise float c01 = v4 + f.x * (v5 - v4);
  precise float c11 = v6 + f.x * (v7 - v6);
  precise float c0 = c00 + f.y * (c10 - c00);
  precise float c1 = c01 + f.y * (c11 - c01);
  precise float s = c0 + f.z * (c1 - c0);
  return s;
}

float interpolate(Cell c) {
  const uint o = c.offset, y = p.sy, z = p.sz;
  return trilinear(voxel(o), voxel(o + 1u), voxel(o + y), voxel(o + y + 1u), voxel(o + z), voxel(o + z + 1u),
                   voxel(o + z + y), voxel(o + z + y + 1u), c.f);
}

// The gradient in a cell, from the host's gradient field (three floats a grid
// point: SPLIT_INPUT(float, gradients, ...) before this file, read by lit
// shaders only), trilinear as the CPU float paths' (float_shading.hpp).
vec3 gradient_at(Cell c) {
  const uint y = 3u * p.sy, z = 3u * p.sz;
  vec3 g;
  for (int a = 0; a < 3; ++a) {
    const uint i = 3u * c.offset + uint(a);
    g[a] = trilinear(gradients_at(i), gradients_at(i + 3u), gradients_at(i + y), gradients_at(i + y + 3u),
                     gradients_at(i + z), gradients_at(i + z + 3u), gradients_at(i + z + y), gradients_at(i + z + y + 3u),
                     c.f);
  }
  return g;
}
