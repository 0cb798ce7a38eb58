#include "projected_tetrahedra.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "vri/memory.hpp"
#include "vri/error.hpp"
#include "classify.hpp"
#include "shading/chord_lighting.hpp"
#include "tables/cylindrical_table.hpp"

namespace vri {

namespace {

struct Screen {
  Point2 xy;
  double depth;  // view depth: distance along the viewing direction
  bool ok;
};

// A vertex of a rasterised triangle: its image position, and the 3D point,
// scalar and view depth of the front and the back of the tetrahedron there.
struct Vertex {
  Point2 xy;
  Vec3 front, back;
  double s_front, s_back, d_front, d_back;
};

struct Fragment {
  std::int32_t pixel, tet;
  double depth;
  float rgba[4];
};

// floor(v) as an int within [lo, hi]; projections near the eye plane can be
// far outside the image, beyond what an int holds.
int floor_within(double v, int lo, int hi) { return static_cast<int>(std::clamp(std::floor(v), double(lo), double(hi))); }

double orient(Point2 a, Point2 b, Point2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// The edge function of (a, b) evaluated in a canonical vertex order, so that
// two triangles sharing the edge get exactly opposite values.
double edge(Point2 a, Point2 b, Point2 p) {
  const bool ordered = a.x < b.x || (a.x == b.x && a.y < b.y);
  return ordered ? orient(a, b, p) : -orient(b, a, p);
}

// Top-left rule: a pixel centre exactly on an edge belongs to the triangle
// on the side the edge's inward normal (sign * gradient) picks.
bool owns(Point2 a, Point2 b, double sign) {
  const double gx = -(b.y - a.y) * sign, gy = (b.x - a.x) * sign;
  return gx > 0 || (gx == 0 && gy > 0);
}

class TileRaster {
 public:
  // The plain table and, lit in mode interpolated, the weighted ones
  // (indexed by ChordTable): slab tables, or cylinder planes (pt-cylindrical).
  using SlabTables = std::array<const SlabTable*, 3>;
  using CylinderTables = std::array<const CylindricalTable*, 3>;
  // Exactly one of slab[0] and cylinder[0] is given. lighting: null when unlit.
  TileRaster(const Camera& cam, const TetMesh& mesh, SlabTables slab, CylinderTables cylinder,
             const ChargedVector<Screen>& screen, Vec3 view, bool perspective, const ChordLighting* lighting,
             PtReconstruction reconstruction)
      : cam_(cam), mesh_(mesh), slab_(slab), cylinder_(cylinder), screen_(screen), view_(view),
        perspective_(perspective), lighting_(lighting), per_vertex_(reconstruction == PtReconstruction::PerVertex) {}

  void draw(std::int32_t tet, int x0, int y0, int x1, int y1, ChargedVector<Fragment>& out) const {
    const auto& v = mesh_.tets()[tet];
    const auto& P = mesh_.points();
    const auto& S = mesh_.scalars();
    std::array<Point2, 4> xy;
    for (int k = 0; k < 4; ++k) xy[k] = screen_[v[k]].xy;
    auto silhouette = [&](int k) {
      const Screen& s = screen_[v[k]];
      return Vertex{s.xy, P[v[k]], P[v[k]], S[v[k]], S[v[k]], s.depth, s.depth};
    };
    const TetProjection pr = classify(xy);
    // The thick vertex: the 3D points where its ray meets the tetrahedron.
    Vec3 pa, pb;
    double sa, sb;
    Point2 txy;
    if (pr.kind == 1) {
      const int i = pr.inner;
      double w[3], sum = 0;
      for (int k = 0; k < 3; ++k) sum += w[k] = pr.bary[k] / weight_depth(v[pr.others[k]]);
      pb = Vec3{};
      sb = 0;
      for (int k = 0; k < 3; ++k) {
        pb = pb + (w[k] / sum) * P[v[pr.others[k]]];
        sb += (w[k] / sum) * S[v[pr.others[k]]];
      }
      pa = P[v[i]];
      sa = S[v[i]];
      txy = xy[i];
    } else {
      auto on_edge = [&](std::array<int, 2> e, double u, double& s) {
        // The screen parameter u maps to the 3D parameter of the edge through the depths.
        const double w0 = (1 - u) / weight_depth(v[e[0]]), w1 = u / weight_depth(v[e[1]]);
        const double t = w1 / (w0 + w1);
        s = S[v[e[0]]] + t * (S[v[e[1]]] - S[v[e[0]]]);
        return P[v[e[0]]] + t * (P[v[e[1]]] - P[v[e[0]]]);
      };
      pa = on_edge(pr.edge_a, pr.u, sa);
      pb = on_edge(pr.edge_b, pr.v, sb);
      txy = {xy[pr.edge_a[0]].x + pr.u * (xy[pr.edge_a[1]].x - xy[pr.edge_a[0]].x),
             xy[pr.edge_a[0]].y + pr.u * (xy[pr.edge_a[1]].y - xy[pr.edge_a[0]].y)};
    }
    double da = depth(pa), db = depth(pb);
    if (da > db) {
      std::swap(pa, pb);
      std::swap(sa, sb);
      std::swap(da, db);
    }
    const Vertex thick{txy, pa, pb, sa, sb, da, db};
    // PerVertex: one depth for all the tetrahedron's fragments, its centre's.
    const double centre = 0.25 * (screen_[v[0]].depth + screen_[v[1]].depth + screen_[v[2]].depth + screen_[v[3]].depth);
    // pt-cylindrical: the tetrahedron's cylinder plane, from its thick vertex (equation 10).
    const double alpha = cylinder_[0] ? cylinder_[0]->alpha(length(pb - pa), sa, sb) : 0;
    if (pr.kind == 1) {
      const auto& o = pr.others;
      for (int k = 0; k < 3; ++k) triangle(tet, alpha, centre, thick, silhouette(o[k]), silhouette(o[(k + 1) % 3]), x0, y0, x1, y1, out);
    } else {
      // The quadrilateral's corners in order around it alternate between the two diagonals.
      const int ring[4] = {pr.edge_a[0], pr.edge_b[0], pr.edge_a[1], pr.edge_b[1]};
      for (int k = 0; k < 4; ++k)
        triangle(tet, alpha, centre, thick, silhouette(ring[k]), silhouette(ring[(k + 1) % 4]), x0, y0, x1, y1, out);
    }
  }

 private:
  double depth(Vec3 p) const { return dot(p - cam_.spec().eye, view_); }
  // The divisor of perspective-correct interpolation (1 under orthographic
  // projection). The thick vertex's own points are exact either way.
  double weight_depth(std::int32_t point) const { return perspective_ ? screen_[point].depth : 1.0; }
  // Across a triangle: 1 (linear in screen space) for PerVertex; there the
  // silhouette vertices' front = back, so l = |back - front| is the thick
  // vertex's l times its screen barycentric, the papers' interpolated l.
  double weight_of(double d) const { return perspective_ && !per_vertex_ ? d : 1.0; }

  void triangle(std::int32_t tet, double alpha, double centre, const Vertex& a, const Vertex& b, const Vertex& c, int x0, int y0, int x1, int y1,
                ChargedVector<Fragment>& out) const {
    const double area = edge(a.xy, b.xy, c.xy);
    if (area == 0) return;
    const double sign = area > 0 ? 1 : -1;
    const bool own_bc = owns(b.xy, c.xy, sign), own_ca = owns(c.xy, a.xy, sign), own_ab = owns(a.xy, b.xy, sign);
    // Pixels whose centres x + 0.5 can lie in the triangle's bounding box.
    const int bx0 = floor_within(std::min({a.xy.x, b.xy.x, c.xy.x}) - 0.5, x0, x1);
    const int bx1 = floor_within(std::max({a.xy.x, b.xy.x, c.xy.x}) - 0.5, x0 - 1, x1 - 1) + 1;
    const int by0 = floor_within(std::min({a.xy.y, b.xy.y, c.xy.y}) - 0.5, y0, y1);
    const int by1 = floor_within(std::max({a.xy.y, b.xy.y, c.xy.y}) - 0.5, y0 - 1, y1 - 1) + 1;
    const int W = cam_.width();
    for (int y = by0; y < by1; ++y)
      for (int x = bx0; x < bx1; ++x) {
        const Point2 p{x + 0.5, y + 0.5};
        const double ea = edge(b.xy, c.xy, p) * sign, eb = edge(c.xy, a.xy, p) * sign, ec = edge(a.xy, b.xy, p) * sign;
        if (ea < 0 || eb < 0 || ec < 0) continue;
        if ((ea == 0 && !own_bc) || (eb == 0 && !own_ca) || (ec == 0 && !own_ab)) continue;
        const double la = ea / (ea + eb + ec), lb = eb / (ea + eb + ec), lc = 1 - la - lb;
        // Front and back surfaces are each one plane over this triangle.
        auto interpolate = [&](double wa, double wb, double wc, Vec3 pa, Vec3 pb, Vec3 pc, double sa, double sb,
                               double sc, double& s) {
          const double sum = wa + wb + wc;
          s = (wa * sa + wb * sb + wc * sc) / sum;
          return (wa * pa + wb * pb + wc * pc) * (1 / sum);
        };
        double sf, sbk;
        const Vec3 f = interpolate(la / weight_of(a.d_front), lb / weight_of(b.d_front), lc / weight_of(c.d_front),
                                   a.front, b.front, c.front, a.s_front, b.s_front, c.s_front, sf);
        const Vec3 k = interpolate(la / weight_of(a.d_back), lb / weight_of(b.d_back), lc / weight_of(c.d_back),
                                   a.back, b.back, c.back, a.s_back, b.s_back, c.s_back, sbk);
        const double l = length(k - f);
        const auto look = [&](ChordTable t) {
          const auto i = static_cast<std::size_t>(t);
          return cylinder_[0] ? cylinder_[i]->lookup(alpha, l, sf, sbk) : slab_[i]->lookup(l, sf, sbk);
        };
        // A silhouette pixel (l = 0) has no chord to light: the empty slab.
        const Rgba v = lighting_ && l > 0 ? lighting_->chord(look, tet, f, k, (k - f) * (1 / l)) : look(ChordTable::plain);
        if (v[3] == 0 && v[0] == 0 && v[1] == 0 && v[2] == 0) continue;
        out.push_back({y * W + x, tet, per_vertex_ ? centre : depth(f), {float(v[0]), float(v[1]), float(v[2]), float(v[3])}});
      }
  }

  const Camera& cam_;
  const TetMesh& mesh_;
  SlabTables slab_;
  CylinderTables cylinder_;
  const ChargedVector<Screen>& screen_;
  Vec3 view_;
  bool perspective_;
  const ChordLighting* lighting_;
  bool per_vertex_;
};

Image render_tetrahedra(const Camera& camera, const TetMesh& mesh, TileRaster::SlabTables slab,
                        TileRaster::CylinderTables cylinder, const RenderOptions& options, const Lighting& lighting,
                        PtReconstruction reconstruction) {
  if (options.threads < 0) throw Error("thread count must be >= 0");
  if (options.tile_size <= 0) throw Error("tile size must be positive");
  std::optional<ChordLighting> lit;
  if (lighting.enabled) lit.emplace(mesh, lighting);
  const bool weighted = lit && lit->interpolated();
  const char* method = slab[0] ? "pt" : "pt-cylindrical";
  for (std::size_t t = 0; t < (weighted ? 3 : 1); ++t) {
    if (!slab[t] && !cylinder[t])
      throw Error(std::string(method) + ": lighting mode 'interpolated' needs the weighted tables");
    if ((slab[t] ? slab[t]->max_length() : cylinder[t]->max_length()) < mesh.max_edge_length())
      throw Error(std::string(method) + ": the table must cover segments up to the longest edge of the mesh");
  }
  const CameraSpec& cs = camera.spec();
  const Vec3 view = normalize(cs.target - cs.eye);
  const bool perspective = cs.projection == Projection::Perspective;
  const int W = camera.width(), H = camera.height(), ts = options.tile_size;
  const int tiles_x = (W + ts - 1) / ts, tiles_y = (H + ts - 1) / ts;
  Image image(W, H);
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    // Every point projected once. This and the tile lists below grow with
    // the mesh and the image, so they are charged to --max-memory as they
    // are allocated (issue 47): a million tetrahedra each over thousands of
    // tiles is refused, not tried.
    ChargedVector<Screen> screen(mesh.points().size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, screen.size()), [&](const auto& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const Vec3 p = mesh.points()[i];
        const double d = dot(p - cs.eye, view);
        const auto xy = camera.project(p);
        screen[i] = {xy ? Point2{xy->first, xy->second} : Point2{0, 0}, d, xy.has_value() && d > 0};
      }
    });
    // The tiles a tetrahedron's projected bounding box touches; false when it is not drawn.
    const auto tiles_of = [&](std::size_t t, int& tx0, int& tx1, int& ty0, int& ty1) {
      double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
      for (int k = 0; k < 4; ++k) {
        const Screen& s = screen[mesh.tets()[t][k]];
        if (!s.ok) return false;
        lo[0] = std::min(lo[0], s.xy.x);
        hi[0] = std::max(hi[0], s.xy.x);
        lo[1] = std::min(lo[1], s.xy.y);
        hi[1] = std::max(hi[1], s.xy.y);
      }
      if (hi[0] < 0 || hi[1] < 0 || lo[0] > W || lo[1] > H) return false;
      tx0 = floor_within(lo[0] - 0.5, 0, W - 1) / ts, tx1 = floor_within(hi[0] + 0.5, 0, W - 1) / ts;
      ty0 = floor_within(lo[1] - 0.5, 0, H - 1) / ts, ty1 = floor_within(hi[1] + 0.5, 0, H - 1) / ts;
      return true;
    };
    // Tetrahedra binned to their tiles, in index order: counted, then filled
    // (tile k's are bin_items[bin_start[k] .. bin_start[k + 1])).
    ChargedVector<std::size_t> bin_start(std::size_t(tiles_x) * tiles_y + 1, 0);
    int tx0, tx1, ty0, ty1;
    for (std::size_t t = 0; t < mesh.size(); ++t)
      if (tiles_of(t, tx0, tx1, ty0, ty1))
        for (int ty = ty0; ty <= ty1; ++ty)
          for (int tx = tx0; tx <= tx1; ++tx) ++bin_start[std::size_t(ty) * tiles_x + tx + 1];
    for (std::size_t k = 1; k < bin_start.size(); ++k) bin_start[k] += bin_start[k - 1];
    ChargedVector<std::int32_t> bin_items(bin_start.back());
    {
      ChargedVector<std::size_t> fill(bin_start.begin(), bin_start.end() - 1);
      for (std::size_t t = 0; t < mesh.size(); ++t)
        if (tiles_of(t, tx0, tx1, ty0, ty1))
          for (int ty = ty0; ty <= ty1; ++ty)
            for (int tx = tx0; tx <= tx1; ++tx) bin_items[fill[std::size_t(ty) * tiles_x + tx]++] = std::int32_t(t);
    }
    const TileRaster raster(camera, mesh, slab, cylinder, screen, view, perspective, lit ? &*lit : nullptr,
                            reconstruction);
    tbb::parallel_for(tbb::blocked_range<int>(0, tiles_x * tiles_y, 1), [&](const tbb::blocked_range<int>& r) {
      // A tile's fragments: as many as its depth complexity, charged too.
      ChargedVector<Fragment> frags, by_pixel;
      ChargedVector<std::size_t> start;
      for (int tile = r.begin(); tile != r.end(); ++tile) {
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
        const int x0 = (tile % tiles_x) * ts, y0 = (tile / tiles_x) * ts;
        const int x1 = std::min(W, x0 + ts), y1 = std::min(H, y0 + ts), tw = x1 - x0;
        frags.clear();
        for (std::size_t i = bin_start[tile]; i < bin_start[tile + 1]; ++i)
          raster.draw(bin_items[i], x0, y0, x1, y1, frags);
        // Bucket by pixel (counting sort), then order each pixel's few fragments by depth.
        auto local = [&](const Fragment& f) { return std::size_t((f.pixel / W - y0) * tw + f.pixel % W - x0); };
        start.assign(std::size_t(tw) * (y1 - y0) + 1, 0);
        for (const Fragment& f : frags) ++start[local(f) + 1];
        for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
        by_pixel.resize(frags.size());
        {
          ChargedVector<std::size_t> next(start.begin(), start.end() - 1);
          for (const Fragment& f : frags) by_pixel[next[local(f)]++] = f;
        }
        for (std::size_t p = 0; p + 1 < start.size(); ++p) {
          if (start[p] == start[p + 1]) continue;
          const auto first = by_pixel.begin() + start[p], last = by_pixel.begin() + start[p + 1];
          std::sort(first, last, [](const Fragment& a, const Fragment& b) {
            return a.depth != b.depth ? a.depth < b.depth : a.tet < b.tet;
          });
          double T = 1, C[3] = {0, 0, 0};
          for (auto f = first; f != last; ++f) {
            for (int c = 0; c < 3; ++c) C[c] += T * f->rgba[c];
            T *= 1 - f->rgba[3];
          }
          image.set(x0 + int(p) % tw, y0 + int(p) / tw, {C[0], C[1], C[2], 1 - T});
        }
      }
    });
  });
  throw_if_cancelled(options);
  return image;
}

}  // namespace

Image render_projected(const Camera& camera, const TetMesh& mesh, const SlabTable& table,
                       const RenderOptions& options, const Lighting& lighting, const WeightedLengthTables* weighted,
                       PtReconstruction reconstruction) {
  return render_tetrahedra(camera, mesh,
                           {&table, weighted ? &weighted->front : nullptr, weighted ? &weighted->back : nullptr}, {},
                           options, lighting, reconstruction);
}

Image render_projected(const Camera& camera, const TetMesh& mesh, const CylindricalTable& table,
                       const RenderOptions& options, const Lighting& lighting,
                       const WeightedCylindricalTables* weighted) {
  return render_tetrahedra(camera, mesh, {},
                           {&table, weighted ? &weighted->front : nullptr, weighted ? &weighted->back : nullptr},
                           options, lighting, PtReconstruction::PerPixel);
}

}  // namespace vri
