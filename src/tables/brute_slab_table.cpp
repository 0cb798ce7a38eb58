#include "vri/tables/brute_slab_table.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "vri/core/error.hpp"
#include "vri/integrators/piece_integrator.hpp"

namespace vri {

BruteSlabTable::BruteSlabTable(const TransferFunction& tf, int size, int lengths, double max_length)
    : n_(size), m_(lengths), max_length_(max_length) {
  if (size < 2 || size > 4096) throw Error("table size must be in [2, 4096], got " + std::to_string(size));
  if (lengths < 2 || lengths > 4096)
    throw Error("table length samples must be in [2, 4096], got " + std::to_string(lengths));
  if (!(max_length > 0) || !std::isfinite(max_length)) throw Error("table max length must be positive");
  if (double(size) * size * lengths > 1 << 28) throw Error("table is too large");
  s_lo_ = tf.s_lo();
  const double span = tf.s_hi() - tf.s_lo();
  s_scale_ = span > 0 ? (n_ - 1) / span : 0;
  data_.assign(std::size_t(m_) * n_ * n_ * 4, 0.f);
  const PieceIntegrator pieces(tf);
  auto s_of = [&](int i) { return s_lo_ + (span > 0 ? i * span / (n_ - 1) : 0.0); };
  tbb::parallel_for(tbb::blocked_range<int>(0, m_ * n_), [&](const tbb::blocked_range<int>& r) {
    for (int mi = r.begin(); mi != r.end(); ++mi) {
      const int m = mi / n_, i = mi % n_;
      const double l = max_length_ * m / (m_ - 1);
      for (int j = 0; j < n_; ++j) {
        PieceIntegrator::Accumulator acc;
        pieces.integrate_linear(s_of(i), s_of(j), l, 1e-7 / max_length_, acc);
        float* e = &data_[((std::size_t(m) * n_ + i) * n_ + j) * 4];
        for (int c = 0; c < 3; ++c) e[c] = static_cast<float>(acc.C[c]);
        e[3] = static_cast<float>(1 - acc.T);
      }
    }
  });
}

Rgba BruteSlabTable::lookup(double l, double s_f, double s_b) const {
  // Continuous indices, clamped to the table, and their cell corners.
  auto cell = [](double x, int n, int& i0, double& w) {
    x = std::clamp(x, 0.0, double(n - 1));
    i0 = std::min(static_cast<int>(x), n - 2);
    w = x - i0;
  };
  int m0, i0, j0;
  double wm, wi, wj;
  cell(l * (m_ - 1) / max_length_, m_, m0, wm);
  cell((s_f - s_lo_) * s_scale_, n_, i0, wi);
  cell((s_b - s_lo_) * s_scale_, n_, j0, wj);
  Rgba out{0, 0, 0, 0};
  for (int dm = 0; dm < 2; ++dm)
    for (int di = 0; di < 2; ++di)
      for (int dj = 0; dj < 2; ++dj) {
        const double w = (dm ? wm : 1 - wm) * (di ? wi : 1 - wi) * (dj ? wj : 1 - wj);
        const float* e = &data_[((std::size_t(m0 + dm) * n_ + i0 + di) * n_ + j0 + dj) * 4];
        for (int c = 0; c < 4; ++c) out[c] += w * e[c];
      }
  return out;
}

}  // namespace vri
