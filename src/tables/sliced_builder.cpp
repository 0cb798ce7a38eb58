#include "tables/sliced_builder.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vri/error.hpp"

namespace vri {

Accumulation parse_accumulation(const std::string& name) {
  if (name == "8bit") return Accumulation::Fixed8;
  if (name == "12bit") return Accumulation::Fixed12;
  if (name == "fp16") return Accumulation::Half;
  if (name == "fp32") return Accumulation::Single;
  throw Error("unknown accumulation '" + name + "' (known: 8bit, 12bit, fp16, fp32)");
}

double quantize(double x, Accumulation format) {
  switch (format) {
    case Accumulation::Fixed8: return std::nearbyint(x * 255) / 255;
    case Accumulation::Fixed12: return std::nearbyint(x * 4095) / 4095;
    case Accumulation::Half: {
      // 11 significant bits; below 2^-14 the subnormal spacing 2^-24.
      if (x < std::ldexp(1.0, -14)) return std::ldexp(std::nearbyint(std::ldexp(x, 24)), -24);
      int e;
      std::frexp(x, &e);  // x = m 2^e, m in [0.5, 1)
      return std::ldexp(std::nearbyint(std::ldexp(x, 11 - e)), e - 11);
    }
    case Accumulation::Single: return static_cast<float>(x);
  }
  return x;
}

SlicedBuilder::SlicedBuilder(int steps, Accumulation accumulation) : steps_(steps), accumulation_(accumulation) {
  if (steps < 0 || steps > (1 << 20))
    throw Error("sliced: steps must be in [0, 1048576], got " + std::to_string(steps));
}

PreintegrationTable SlicedBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  const int n = tf.size();
  const int steps = steps_ > 0 ? steps_ : 2 * n;
  const double dl = length / steps;
  const auto q = [this](double x) { return quantize(x, accumulation_); };
  PreintegrationTable table(tf.axis(), length);
  tbb::parallel_for(0, n, [&](int f) {
    // One row of the frame buffer: entries (f, b), b = 0 .. n-1.
    struct Pixel {
      double r = 0, g = 0, b = 0, t = 1;  // colour and transparency
    };
    std::vector<Pixel> fb(n);
    for (int k = steps - 1; k >= 0; --k) {  // back to front
      const double w = (k + 0.5) / steps;
      for (int b = 0; b < n; ++b) {
        const TfSample v = tf.at_index(f + (b - f) * w);
        const double x = v.tau * dl;
        // 1 - exp(-x); the series is exact to 1e-13 below 0.01, where most steps are.
        const double a = q(x < 0.01 ? x * (1 - x * (0.5 - x * (1.0 / 6 - x / 24))) : -std::expm1(-x));
        Pixel& p = fb[b];
        p.r = q(q(v.r * a) + (1 - a) * p.r);
        p.g = q(q(v.g * a) + (1 - a) * p.g);
        p.b = q(q(v.b * a) + (1 - a) * p.b);
        p.t = q((1 - a) * p.t);
      }
    }
    for (int b = 0; b < n; ++b) {
      float* e = table.entry(f, b);
      e[0] = static_cast<float>(fb[b].r);
      e[1] = static_cast<float>(fb[b].g);
      e[2] = static_cast<float>(fb[b].b);
      e[3] = static_cast<float>(1 - fb[b].t);
    }
  });
  return table;
}

}  // namespace vri
