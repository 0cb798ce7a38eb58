// The transfer function in float, as FloatTransferFunction
// (src/transfer/float_transfer_function.hpp): a uniform grid of bins
// over the breakpoints names a segment near the scalar, a short walk finds
// the one that holds it, and its channels are value + slope (s - s_ref).
// Needs before it: buffer Tf { float tf[]; } (breakpoints, then s_ref, then
// value r g b tau, then slope r g b tau, each `segments` long; breakpoints
// end with +inf), buffer TfBins { int first[]; }, and in `p`: tf_lo,
// tf_scale, tf_bins, segments.

int tf_segment(float s) {
  precise float u = min(max((s - p.tf_lo) * p.tf_scale, 0.0), float(p.tf_bins - 1));
  int i = bins.first[int(u)];
  while (tf.v[i] <= s) ++i;  // breakpoints end with +inf
  while (i > 0 && tf.v[i - 1] > s) --i;
  return i;
}

// (r, g, b, tau) at scalar s.
vec4 tf_at(float s) {
  const int i = tf_segment(s);
  const int n = p.segments;
  precise float ds = s - tf.v[n + i];
  vec4 v;
  for (int c = 0; c < 4; ++c) {
    precise float x = tf.v[(2 + c) * n + i] + tf.v[(6 + c) * n + i] * ds;
    v[c] = x;
  }
  return v;
}
