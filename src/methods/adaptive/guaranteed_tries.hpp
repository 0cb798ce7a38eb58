#pragma once
// The first Simpson try of four smooth pieces at once, for `adaptive
// --strategy guaranteed` (adaptive_guaranteed.cpp). Unlit, a piece is a cell's
// stretch of ray on one transfer-function segment, and its first try (the
// whole piece, when the step cap allows) is nearly always accepted: that try
// is most of the method's time per cell. A try does not depend on T
// (simpson_colour_step.hpp), so the tries of the next four pieces of a ray
// are made together, lanes over the pieces, and the integrator then adds
// them front to back. Each lane does what colour_step does, in the same
// order, on the samples seg.at(s(u + h k / 4)): the same bytes as one piece
// at a time.
#include "methods/exact/cubic.hpp"
#include "vri/transfer_function.hpp"

namespace vri::simpson5 {

struct PieceTries {
  static constexpr int kLanes = 4;
  // Input, lane by lane: the cubic s (coefficients c[j]), the segment's
  // s_ref, values ref and slopes (r, g, b, tau), and the step [u, u + h].
  double c[4][kLanes], s_ref[kLanes], ref[4][kLanes], slope[4][kLanes], u[kLanes], h[kLanes];
  // Output, at T = 1: the largest error(D, S) over the channels, the
  // optical depth's error(halves, whole), each channel's error(D, S) and
  // Boole value corrected(D, S), and the step's transmittance.
  double err[kLanes], depth_err[kLanes], channel_err[4][kLanes], boole[4][kLanes], attenuation[kLanes];

  // Fills lane l's input.
  void set(int l, const Cubic& s, const TfSegment& seg, double u0, double h0) {
    for (int j = 0; j < 4; ++j) c[j][l] = s.c[j];
    s_ref[l] = seg.s_ref;
    const double r[4] = {seg.ref.r, seg.ref.g, seg.ref.b, seg.ref.tau};
    const double d[4] = {seg.slope.r, seg.slope.g, seg.slope.b, seg.slope.tau};
    for (int ch = 0; ch < 4; ++ch) ref[ch][l] = r[ch], slope[ch][l] = d[ch];
    u[l] = u0, h[l] = h0;
  }
  // Fills the output of every lane; lanes from `used` on (idle at a ray's
  // end) first repeat lane 0's input.
  void run(int used = kLanes) {
    for (int l = used; l < kLanes; ++l) {
      for (int j = 0; j < 4; ++j) c[j][l] = c[j][0], ref[j][l] = ref[j][0], slope[j][l] = slope[j][0];
      s_ref[l] = s_ref[0], u[l] = u[0], h[l] = h[0];
    }
    run_lanes();
  }

 private:
  void run_lanes();
};

}  // namespace vri::simpson5
