// DiagonalSweep (incremental_diagonals.hpp): incremental subrange integration
// along one diagonal (Lum, Wilson & Ma 2004, §4.2, Figs. 4-5), each piece's
// premultiplied (C, alpha) one vector of 4 doubles.
// 4-double vectors must never cross a call: the AVX2 clone passes them in ymm
// registers, a baseline callee expects them in memory. So the cloned
// functions are `flatten` (thin_piece_weights and every helper inlined into
// each clone, at any optimisation level - without it an -O2 sanitizer build
// called an out-of-line baseline thin_piece_weights from the AVX2 clone and
// got wrong tables). GCC's -Wpsabi remarks on the always-inline helpers'
// signatures are therefore moot and off for this file (src/CMakeLists.txt).

#include "incremental_diagonals.hpp"

#include <cmath>
#include <cstring>
#include <span>

#include "core/simd.hpp"
#include "tables/slab_integral.hpp"

namespace vri {

namespace {

using V4 = double __attribute__((vector_size(32)));
using F4 = float __attribute__((vector_size(16)));
using I4 = long long __attribute__((vector_size(32)));

// Vectors stay inside these always-inlined helpers and the cloned functions
// below: no vector crosses a call.
#define VRI_INLINE __attribute__((always_inline)) inline

VRI_INLINE V4 load(const void* p) {
  V4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
VRI_INLINE void store(const V4& v, SlabRgba& out) { std::memcpy(static_cast<void*>(&out), &v, sizeof v); }
VRI_INLINE void store(const V4& v, float& out) {  // out and the 3 floats after it
  const F4 f = __builtin_convertvector(v, F4);
  std::memcpy(&out, &f, sizeof f);
}
VRI_INLINE V4 splat(double x) { return V4{x, x, x, x}; }
// over(front, back) = front + (1 - front.a) back (slab_rgba.hpp).
VRI_INLINE V4 over(const V4& front, const V4& back) {
  return front + (1.0 - __builtin_shuffle(front, I4{3, 3, 3, 3})) * back;
}

// The series (piece_weights.hpp) four pieces at a time, then the pieces too
// thick for it again by quadrature: thick_piece_weights.
VRI_TARGET_CLONES __attribute__((flatten)) void diagonal_weights(const Pieces& pieces, double d,
                                                                 DiagonalSweep::Weights& w) {
  const int count = pieces.size() - 1;
  const double* tau = pieces.tau.data();
  // Local pointers: the stores below cannot change them, so they stay in registers.
  double *fp = w.fp.data(), *fq = w.fq.data(), *bq = w.bq.data(), *bp = w.bp.data(), *alpha = w.alpha.data();
  const auto set = [&](int k, const PieceWeights& p) {
    fp[k] = p.fp, fq[k] = p.fq, bq[k] = p.bq, bp[k] = p.bp, alpha[k] = p.alpha;
  };
  const double thin = piece_series::kThin;
  int k = 0;
  for (; k + 3 < count; k += 4) {
    const V4 a = load(tau + k) * d, b = load(tau + k + 1) * d;
    const auto p = thin_piece_weights(a < thin ? a : thin, b < thin ? b : thin);
    std::memcpy(fp + k, &p.fp, sizeof(V4));
    std::memcpy(fq + k, &p.fq, sizeof(V4));
    std::memcpy(bq + k, &p.bq, sizeof(V4));
    std::memcpy(bp + k, &p.bp, sizeof(V4));
    std::memcpy(alpha + k, &p.alpha, sizeof(V4));
  }
  for (; k < count; ++k) set(k, thin_piece_weights(std::min(tau[k] * d, thin), std::min(tau[k + 1] * d, thin)));
  for (int k : pieces.by_thickness) {
    if (pieces.thickest(k) * d <= thin) break;
    set(k, thick_piece_weights(tau[k] * d, tau[k + 1] * d));
  }
}

constexpr int kAhead = 16;  // how many entries ahead the table is prefetched

// Entry (i, i+m) covers pieces i .. e = i+m-1: a whole bin, or the tail of
// one bin followed by the head of the next; entry (i+m, i) the same pieces
// integrated backwards and composited in the opposite order. Entry i of the
// diagonal goes to upper[i * stride] and lower[i * stride].
template <class Out>
VRI_INLINE void composite_diagonal(const TfSample* c, int m, const DiagonalSweep::Weights& w,
                                   DiagonalSweep::Subranges& s, const DiagonalSweep::SplitBins& split, Out* upper,
                                   Out* lower, std::ptrdiff_t stride) {
  const int count = static_cast<int>(w.fp.size()), n = count + 1;
  // Local pointers: the stores below cannot change them, so they stay in registers.
  const double *fp = w.fp.data(), *fq = w.fq.data(), *bq = w.bq.data(), *bp = w.bp.data(), *alpha = w.alpha.data();
  SlabRgba *piece_f = s.piece_f.data(), *piece_b = s.piece_b.data();
  SlabRgba *head_f = s.head_f.data(), *head_b = s.head_b.data(), *tail_f = s.tail_f.data(), *tail_b = s.tail_b.data();
  const V4 rgb{1, 1, 1, 0}, a_lane{0, 0, 0, 1};
  for (int k = 0; k < count; ++k) {
    const V4 p = load(&c[k]) * rgb, q = load(&c[k + 1]) * rgb, a = a_lane * alpha[k];
    store(p * fp[k] + q * fq[k] + a, piece_f[k]);
    store(q * bq[k] + p * bp[k] + a, piece_b[k]);
  }
  for (int j = 0; j < split.count; ++j) {  // the super-segments of split bins
    piece_f[split.bins[j]] = split.f[j];
    piece_b[split.bins[j]] = split.b[j];
  }
  for (int start = 0; start < count; start += m) {
    const int end = std::min(start + m, count);
    // The four chains in one loop, so they overlap in the pipeline. Each
    // carries its own transmittance where the new piece lies behind it, so
    // every step is one dependent multiply-add.
    V4 hf = load(&piece_f[start]), hb = load(&piece_b[start]);
    V4 tf = load(&piece_f[end - 1]), tb = load(&piece_b[end - 1]);
    V4 hf_t = splat(1 - alpha[start]), tb_t = splat(1 - alpha[end - 1]);
    store(hf, head_f[start]), store(hb, head_b[start]);
    store(tf, tail_f[end - 1]), store(tb, tail_b[end - 1]);
    for (int h = start + 1, t = end - 2; h < end; ++h, --t) {
      const V4 e_h = splat(1 - alpha[h]), e_t = splat(1 - alpha[t]);
      hf += hf_t * load(&piece_f[h]), hf_t *= e_h;  // head_f[h] = over(head_f[h-1], piece)
      hb = load(&piece_b[h]) + e_h * hb;            // head_b[h] = over(piece, head_b[h-1])
      tf = load(&piece_f[t]) + e_t * tf;            // tail_f[t] = over(piece, tail_f[t+1])
      tb += tb_t * load(&piece_b[t]), tb_t *= e_t;  // tail_b[t] = over(tail_b[t+1], piece)
      store(hf, head_f[h]), store(hb, head_b[h]);
      store(tf, tail_f[t]), store(tb, tail_b[t]);
    }
  }
  for (int i = 0, in_bin = 0; i + m < n; ++i, in_bin = in_bin + 1 == m ? 0 : in_bin + 1) {
    const int e = i + m - 1;
    // Table entries lie a row apart, each on its own cache line: fetch the
    // lines ahead of the stores.
    const std::ptrdiff_t ahead = std::min(i + kAhead, n - 1 - m) * stride;
    __builtin_prefetch(&upper[ahead], 1);
    __builtin_prefetch(&lower[ahead], 1);
    if (in_bin == 0) {  // i % m == 0, without a division per entry
      store(load(&tail_f[i]), upper[i * stride]);
      store(load(&tail_b[i]), lower[i * stride]);
    } else {
      store(over(load(&tail_f[i]), load(&head_f[e])), upper[i * stride]);
      store(over(load(&head_b[e]), load(&tail_b[i])), lower[i * stride]);
    }
  }
}

VRI_TARGET_CLONES __attribute__((flatten)) void composite_doubles(
    const TfSample* c, int m, const DiagonalSweep::Weights& w, DiagonalSweep::Subranges& s,
    const DiagonalSweep::SplitBins& split, SlabRgba* upper, SlabRgba* lower) {
  composite_diagonal(c, m, w, s, split, upper, lower, 1);
}

VRI_TARGET_CLONES __attribute__((flatten)) void composite_floats(
    const TfSample* c, int m, const DiagonalSweep::Weights& w, DiagonalSweep::Subranges& s,
    const DiagonalSweep::SplitBins& split, float* upper, float* lower, std::ptrdiff_t stride) {
  composite_diagonal(c, m, w, s, split, upper, lower, stride);
}

}  // namespace

DiagonalSweep::DiagonalSweep(int n) {
  const std::size_t count = n - 1;
  for (auto* v : {&w_.fp, &w_.fq, &w_.bq, &w_.bp, &w_.alpha}) v->resize(count);
  for (auto* v : {&s_.piece_f, &s_.piece_b, &s_.head_f, &s_.tail_f, &s_.head_b, &s_.tail_b}) v->resize(count);
}

void DiagonalSweep::weights(const Pieces& pieces, double length, int m) {
  pieces_ = &pieces;
  d_ = length / m;
  diagonal_weights(pieces, d_, w_);
  const auto& bins = pieces.tf->split_bins();
  for (std::size_t j = 0; j < bins.size(); ++j) w_.alpha[bins[j]] = -std::expm1(-pieces.split_depth[j] * d_);
}

// Each split bin's sub-pieces composited exactly at piece length d_, both ways
// (Lum et al.'s recurrence then joins them as any other piece).
void DiagonalSweep::split_pieces(const SubPiece* subs) {
  const DiscreteTf& tf = *pieces_->tf;
  const auto& bins = tf.split_bins();
  split_.bins = bins.data();
  split_.count = static_cast<int>(bins.size());
  split_.f.resize(bins.size());
  split_.b.resize(bins.size());
  const auto forward = [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; };
  for (std::size_t j = 0; j < bins.size(); ++j) {
    const int k = bins[j];
    const std::span<const SubPiece> span(subs + tf.sub_begin(k), subs + tf.sub_begin(k + 1));
    split_.f[j] = integrate_sub_pieces(span, k, k + 1, 1, d_, forward);
    split_.b[j] = integrate_sub_pieces(span, k, k + 1, -1, d_, forward);
    // The same alpha as weights() gave the bin, so the chains' transmittance agrees with it.
    split_.f[j].a = split_.b[j].a = w_.alpha[k];
  }
}

void DiagonalSweep::composite(const TfSample* c, const SubPiece* subs, int m, SlabRgba* upper, SlabRgba* lower) {
  split_pieces(subs);
  composite_doubles(c, m, w_, s_, split_, upper, lower);
}

void DiagonalSweep::composite(const TfSample* c, const SubPiece* subs, int m, PreintegrationTable& table) {
  split_pieces(subs);
  // Entry (i, i+m) is 4 (n + 1) floats after entry (i-1, i-1+m).
  composite_floats(c, m, w_, s_, split_, table.entry(0, m), table.entry(m, 0), 4 * (table.size() + 1));
}

}  // namespace vri
