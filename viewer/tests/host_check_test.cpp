// The Host header a request may carry (host_check.hpp): against DNS rebinding.
#include "host_check.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

namespace vri::viewer {
namespace {

TEST(HostCheck, ReadsTheNameOfEveryForm) {
  EXPECT_EQ(host_name_of("127.0.0.1:8765"), "127.0.0.1");
  EXPECT_EQ(host_name_of("localhost"), "localhost");
  EXPECT_EQ(host_name_of("[::1]:8765"), "::1");
  EXPECT_EQ(host_name_of("[::1]"), "::1");
  EXPECT_EQ(host_name_of("[::1"), "");
  EXPECT_EQ(host_name_of("[::1]x"), "");
  EXPECT_EQ(host_name_of("a:b:c"), "");
  EXPECT_EQ(host_name_of(""), "");
}

TEST(HostCheck, AllowsAddressesAndThisMachinesNamesOnly) {
  EXPECT_TRUE(allowed_host("127.0.0.1:8765", "127.0.0.1"));
  EXPECT_TRUE(allowed_host("10.1.2.3:80", "0.0.0.0"));
  EXPECT_TRUE(allowed_host("[::1]:8765", "::1"));
  EXPECT_TRUE(allowed_host("LocalHost:1", "127.0.0.1"));
  EXPECT_TRUE(allowed_host("viewer.lab.example:8765", "viewer.lab.example"));  // the --host given
  char name[256] = {};
  ASSERT_EQ(gethostname(name, sizeof name - 1), 0);
  EXPECT_TRUE(allowed_host(std::string(name) + ":8765", "127.0.0.1"));
  EXPECT_FALSE(allowed_host("attacker.example:8765", "127.0.0.1"));
  EXPECT_FALSE(allowed_host("localhost.attacker.example", "127.0.0.1"));
  EXPECT_FALSE(allowed_host("", "127.0.0.1"));
  EXPECT_FALSE(allowed_host("127.0.0.1.attacker.example:80", "127.0.0.1"));
}

}  // namespace
}  // namespace vri::viewer
