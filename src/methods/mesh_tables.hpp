#pragma once
// The tables the mesh methods (pt, pt-cylindrical, tet-raycast) look up,
// built from a scene's MethodSpec (src/methods/make_integrator.cpp).
#include <memory>

#include "vri/methods.hpp"
#include "vri/volume.hpp"
#include "vri/lighting.hpp"
#include "tables/slab_table.hpp"
#include "tables/weighted_tables.hpp"
#include "vri/transfer_function.hpp"

namespace vri {

// The (l, s_f, s_b) table the mesh methods use: table_size scalars a side,
// length_samples lengths up to the mesh's longest edge.
std::unique_ptr<SlabTable> make_slab_table(const MethodSpec& spec, const TetMesh& mesh, const TransferFunction& tf);

// The weighted tables of lighting mode interpolated over the same
// (l, s_f, s_b) grid (build_weighted_length_tables); null unless lighting is
// enabled in mode interpolated.
std::unique_ptr<WeightedLengthTables> make_weighted_length_tables(const MethodSpec& spec, const TetMesh& mesh,
                                                                  const TransferFunction& tf,
                                                                  const Lighting& lighting);

}  // namespace vri
