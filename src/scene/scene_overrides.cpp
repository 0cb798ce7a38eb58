#include "vri/scene.hpp"

#include "vri/camera.hpp"

namespace vri {

void apply_method_overrides(MethodSpec& m, const SceneOverrides& o) {
  if (o.method && *o.method != m.name) {
    m.name = *o.method;
    m.table_size_given = false;
  }
  if (o.table_size) {
    m.table_size = *o.table_size;
    m.table_size_given = true;
  }
  if (o.step) m.step = *o.step;
  if (o.tolerance) m.tolerance = *o.tolerance;
  if (o.iterations) m.iterations = *o.iterations;
  if (o.h0) m.h0 = *o.h0;
  if (o.hmin) m.hmin = *o.hmin;
  if (o.hmax) m.hmax = *o.hmax;
  if (o.strategy) m.strategy = *o.strategy;
  if (o.termination) m.fast.termination = *o.termination;
  if (o.skip_empty) m.fast.skip_empty = *o.skip_empty;
  if (o.float_math) m.fast.float_math = *o.float_math;
  if (o.max_samples) m.max_samples = *o.max_samples;
  if (o.max_work) m.max_work = *o.max_work;
  if (o.jitter) m.jitter = *o.jitter;
}

void apply_overrides(Scene& scene, const SceneOverrides& o) {
  apply_method_overrides(scene.method, o);
  if (o.clip) set_clip(scene.volume, *o.clip);
  if (o.width) scene.camera.width = *o.width;
  if (o.height) scene.camera.height = *o.height;
  if (o.fit.value_or(false)) {
    const auto [lo, hi] = bounds(scene.volume);
    scene.camera = frame_box(lo, hi, scene.camera);
  }
  if (o.azimuth || o.elevation || o.roll || o.zoom)
    scene.camera = move_camera(scene.camera, o.azimuth.value_or(0), o.elevation.value_or(0), o.roll.value_or(0),
                               o.zoom.value_or(1));
}

}  // namespace vri
