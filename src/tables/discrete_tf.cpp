#include "tables/discrete_tf.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vri/error.hpp"

namespace vri {

double ScalarAxis::index(double s) const {
  if (!(s_hi > s_lo)) return 0;
  const double u = (s - s_lo) / (s_hi - s_lo) * (n - 1);
  return std::clamp(u, 0.0, double(n - 1));
}

namespace {

bool same(const TfSample& a, const TfSample& b) { return a.r == b.r && a.g == b.g && a.b == b.b && a.tau == b.tau; }

// (1-w) a + w b: exactly a at w = 0 and exactly b at w = 1.
TfSample lerp(const TfSample& a, const TfSample& b, double w) {
  return {(1 - w) * a.r + w * b.r, (1 - w) * a.g + w * b.g, (1 - w) * a.b + w * b.b, (1 - w) * a.tau + w * b.tau};
}

}  // namespace

ScalarAxis table_axis(const TransferFunction& tf, int n, std::optional<DataRange> data) {
  if (!data) return {tf.s_lo(), tf.s_hi(), n};
  return {std::min(tf.s_lo(), data->lo), std::max(tf.s_hi(), data->hi), n};
}

DiscreteTf::DiscreteTf(const TransferFunction& tf, int n, std::optional<DataRange> data) {
  if (n < 2 || n > kMaxSize)
    throw Error("table size must be in [2, " + std::to_string(kMaxSize) + "], got " + std::to_string(n));
  axis_ = table_axis(tf, n, data);
  samples_.reserve(n);
  for (int i = 0; i < n; ++i) samples_.push_back(tf(axis_.scalar(i)));
  sub_begin_.assign(n + 1, 0);
  linear_begin_.resize(n - 1);
  linear_end_.resize(n - 1);
  for (int k = 0; k + 1 < n; ++k) linear_begin_[k] = k, linear_end_[k] = k + 1;
  if (!(axis_.s_hi > axis_.s_lo)) return;  // one scalar: every bin is empty
  // Walk the transfer function's segments across each bin: a breakpoint inside
  // the bin ends a sub-piece (left value) and starts the next (right value);
  // the last sub-piece ends at the left limit of x_{k+1}, which differs from
  // the sample there only at a step exactly on x_{k+1}.
  const auto& segments = tf.segments();
  std::vector<SubPiece> bin;
  std::vector<int> line(n - 1, -1);  // a plain bin's segment, -1 for a split one
  for (int k = 0; k + 1 < n; ++k) {
    sub_begin_[k] = static_cast<int>(subs_.size());
    const double x0 = axis_.scalar(k), x1 = axis_.scalar(k + 1);
    bin.clear();
    int seg = tf.segment_index(x0);
    double u = k;
    TfSample v = samples_[k];
    while (segments[seg].s_hi < x1) {
      const double bp = segments[seg].s_hi;
      const double ub = std::clamp(axis_.index(bp), u, double(k + 1));
      bin.push_back({u, ub, v, segments[seg].at(bp)});
      ++seg;
      u = ub;
      v = segments[seg].at(bp);
    }
    bin.push_back({u, double(k + 1), v, segments[seg].at(x1)});
    if (bin.size() == 1 && same(bin[0].q, samples_[k + 1])) {  // plain: linear sample to sample
      line[k] = seg;
      continue;
    }
    split_.push_back(k);
    subs_.insert(subs_.end(), bin.begin(), bin.end());
  }
  sub_begin_[n - 1] = sub_begin_[n] = static_cast<int>(subs_.size());
  // Neighbouring plain bins on one segment make one straight run. A control
  // point exactly on the scalar between them starts the next segment there
  // (segment_index: the later point holds), so it ends the run.
  for (int k = 1; k + 1 < n; ++k)
    if (line[k] >= 0 && line[k] == line[k - 1]) linear_begin_[k] = linear_begin_[k - 1];
  for (int k = n - 3; k >= 0; --k)
    if (line[k] >= 0 && line[k] == line[k + 1]) linear_end_[k] = linear_end_[k + 1];
}

TfSample DiscreteTf::at_index(double u) const {
  const int i = std::min(static_cast<int>(u), size() - 2);
  const auto subs = sub_pieces(i);
  if (subs.empty()) return lerp(samples_[i], samples_[i + 1], u - i);
  // The first sub-piece that reaches u (the last one at u = i + 1).
  auto it = std::find_if(subs.begin(), subs.end() - 1, [u](const SubPiece& s) { return s.u1 > u; });
  const double w = it->u1 > it->u0 ? std::clamp((u - it->u0) / (it->u1 - it->u0), 0.0, 1.0) : 1.0;
  return lerp(it->p, it->q, w);
}

}  // namespace vri
