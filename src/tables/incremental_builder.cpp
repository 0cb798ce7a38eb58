#include "vri/tables/incremental_builder.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "vri/tables/slab_integral.hpp"

namespace vri {

namespace {

void store(float* e, const SlabRgba& v) {
  e[0] = static_cast<float>(v.r);
  e[1] = static_cast<float>(v.g);
  e[2] = static_cast<float>(v.b);
  e[3] = static_cast<float>(v.a);
}

// The subrange integrals of one diagonal m (Lum et al. 2004, Fig. 5): piece k
// joins table scalars k and k+1 and has length l/m; bins are pieces
// [b m, (b+1) m). Within each bin, for piece k:
//   head[k] = pieces bin_start..k   (left-hand subrange grown to the right)
//   tail[k] = pieces k..bin_end-1   (right-hand subrange grown to the left)
// forward (front = lower scalar) and backward (front = higher scalar).
struct Subranges {
  std::vector<SlabRgba> head_f, tail_f, head_b, tail_b;
  void resize(int pieces) {
    for (auto* v : {&head_f, &tail_f, &head_b, &tail_b}) v->resize(pieces);
  }
};

void build_diagonal(const DiscreteTf& tf, double length, int m, Subranges& s, PreintegrationTable& table) {
  const int n = tf.size(), pieces = n - 1;
  const double d = length / m;
  for (int k = 0; k < pieces; ++k) {
    const PiecePair p = linear_piece(tf[k], tf[k + 1], d);
    s.head_f[k] = s.tail_f[k] = p.forward;
    s.head_b[k] = s.tail_b[k] = p.backward;
  }
  for (int start = 0; start < pieces; start += m) {
    const int end = std::min(start + m, pieces);
    for (int k = start + 1; k < end; ++k) {
      s.head_f[k] = over(s.head_f[k - 1], s.head_f[k]);
      s.head_b[k] = over(s.head_b[k], s.head_b[k - 1]);
    }
    for (int k = end - 2; k >= start; --k) {
      s.tail_f[k] = over(s.tail_f[k], s.tail_f[k + 1]);
      s.tail_b[k] = over(s.tail_b[k + 1], s.tail_b[k]);
    }
  }
  // Entry (i, i+m) covers pieces i .. e = i+m-1: a whole bin, or the tail of
  // one bin followed by the head of the next.
  for (int i = 0; i + m < n; ++i) {
    const int e = i + m - 1;
    if (i % m == 0) {
      store(table.entry(i, i + m), s.tail_f[i]);
      store(table.entry(i + m, i), s.tail_b[i]);
    } else {
      store(table.entry(i, i + m), over(s.tail_f[i], s.head_f[e]));
      store(table.entry(i + m, i), over(s.head_b[e], s.tail_b[i]));
    }
  }
}

}  // namespace

PreintegrationTable IncrementalBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  for (int i = 0; i < n; ++i) store(table.entry(i, i), homogeneous_slab(tf[i], length));
  tbb::parallel_for(tbb::blocked_range<int>(1, n), [&](const tbb::blocked_range<int>& r) {
    Subranges s;
    s.resize(n - 1);
    for (int m = r.begin(); m != r.end(); ++m) build_diagonal(tf, length, m, s, table);
  });
  return table;
}

}  // namespace vri
