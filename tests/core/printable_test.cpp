// Messages that leave vri (issue 47, defect 10): one short line whatever a
// reader quoted from a file.
#include "vri/error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace vri {
namespace {

TEST(MessageLine, EscapesControlBytesAndCapsTheLength) {
  const std::string hostile = "bad header '" + std::string("\x1b]0;owned\x07\r\n") + std::string(50'000'000, 'A') + "'";
  const std::string line = message_line(hostile);
  EXPECT_LE(line.size(), kMaxMessageBytes + 3);
  EXPECT_TRUE(std::none_of(line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }));
  EXPECT_EQ(line.rfind("bad header '\\x1B]0;owned\\x07\\x0D\\x0A", 0), 0u) << line.substr(0, 60);
  EXPECT_EQ(line.substr(line.size() - 3), "...");
  // UTF-8 file names are kept as they are.
  EXPECT_EQ(message_line("cannot open 'Gehirn-\xC3\xBC.nrrd'"), "cannot open 'Gehirn-\xC3\xBC.nrrd'");
}

}  // namespace
}  // namespace vri
