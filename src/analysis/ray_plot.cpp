#include "vri/analysis.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace vri {

std::string ray_signal_svg(const RaySignal& sig) {
  const int W = 900, panel_h = 220, margin = 50;
  const int points = 1500;
  double smin = 1e300, smax = -1e300;
  std::vector<double> ts(points), ss(points);
  for (int i = 0; i < points; ++i) {
    ts[i] = sig.t0() + (sig.t1() - sig.t0()) * i / (points - 1);
    ss[i] = sig.signal(ts[i]);
    smin = std::min(smin, ss[i]);
    smax = std::max(smax, ss[i]);
  }
  if (smax == smin) smax = smin + 1;
  const double pad = 0.08 * (smax - smin);
  smin -= pad;
  smax += pad;
  std::ostringstream o;
  o.precision(6);
  o << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << 3 * panel_h + 30
    << "' font-family='sans-serif' font-size='13'>\n<rect width='100%' height='100%' fill='white'/>\n";
  const char* names[3] = {"0th order (nearest-sample hold)", "1st order (trapezoid)", "2nd order (parabola)"};
  for (int order = 0; order < 3; ++order) {
    const double y0 = 20 + order * panel_h;
    auto X = [&](double t) { return margin + (W - 2 * margin) * (t - sig.t0()) / (sig.t1() - sig.t0()); };
    auto Y = [&](double s) { return y0 + (panel_h - 30) * (1 - (s - smin) / (smax - smin)); };
    o << "<rect x='" << margin << "' y='" << y0 << "' width='" << W - 2 * margin << "' height='" << panel_h - 30
      << "' fill='none' stroke='#888'/>\n";
    // the difference, shaded: a polygon along the signal and back along the approximation
    o << "<polygon fill='#4c4' fill-opacity='0.45' stroke='none' points='";
    for (int i = 0; i < points; ++i) o << X(ts[i]) << "," << Y(ss[i]) << " ";
    for (int i = points - 1; i >= 0; --i) o << X(ts[i]) << "," << Y(sig.approximation(order, ts[i])) << " ";
    o << "'/>\n<polyline fill='none' stroke='black' stroke-width='1.5' points='";
    for (int i = 0; i < points; ++i) o << X(ts[i]) << "," << Y(ss[i]) << " ";
    o << "'/>\n<polyline fill='none' stroke='red' stroke-width='1.2' points='";
    for (int i = 0; i < points; ++i) o << X(ts[i]) << "," << Y(sig.approximation(order, ts[i])) << " ";
    o << "'/>\n";
    for (std::size_t k = 0; k < sig.sample_t().size(); ++k)
      o << "<circle cx='" << X(sig.sample_t()[k]) << "' cy='" << Y(sig.sample_s()[k]) << "' r='2.2'/>\n";
    char label[160];
    std::snprintf(label, sizeof label, "%s   xi = %.6g", names[order], sig.xi(order));
    o << "<text x='" << margin + 8 << "' y='" << y0 + 16 << "'>" << label << "</text>\n";
  }
  o << "<text x='" << W / 2 - 60 << "' y='" << 3 * panel_h + 20 << "'>t (world units along the ray)</text>\n</svg>\n";
  return o.str();
}

}  // namespace vri
