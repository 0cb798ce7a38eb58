#pragma once
// Shared by the mesh reader tests: parsing from text and error checks.
#include <gtest/gtest.h>

#include <cstddef>
#include <span>
#include <string>

#include "vri/error.hpp"
#include "io/vtk_legacy.hpp"
#include "io/vtu.hpp"

namespace vri::test {

inline std::span<const std::byte> bytes_of(const std::string& text) {
  return {reinterpret_cast<const std::byte*>(text.data()), text.size()};
}

// Expects `parse` to throw one line of vri::Error containing `fragment`.
template <class F>
void expect_mesh_error(F&& parse, const std::string& fragment) {
  try {
    parse();
    ADD_FAILURE() << "expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

}  // namespace vri::test
