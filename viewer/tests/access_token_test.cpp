// The access token: where a request carries it, and how it is compared.
#include "access_token.hpp"

#include <gtest/gtest.h>

#include <set>

namespace vri::viewer {
namespace {

TEST(AccessToken, Is128RandomBitsInHex) {
  std::set<std::string> seen;
  for (int i = 0; i < 100; ++i) {
    const std::string t = make_token();
    ASSERT_EQ(t.size(), 32u);
    EXPECT_EQ(t.find_first_not_of("0123456789abcdef"), std::string::npos);
    seen.insert(t);
  }
  EXPECT_EQ(seen.size(), 100u);
}

TEST(AccessToken, ComesFromTheQueryOrTheCookie) {
  EXPECT_EQ(token_of("/?token=abc", ""), "abc");
  EXPECT_EQ(token_of("/ws?x=1&token=abc&y=2", ""), "abc");
  EXPECT_EQ(token_of("/viewer.js", "a=b; vri_token=abc; c=d"), "abc");
  EXPECT_EQ(token_of("/viewer.js", "vri_token=abc"), "abc");
  EXPECT_EQ(token_of("/viewer.js", "not_vri_token=abc"), "");
  EXPECT_EQ(token_of("/?tokenx=abc", ""), "");
  EXPECT_EQ(token_of("/", ""), "");
}

TEST(AccessToken, ComparesWholeTokens) {
  EXPECT_TRUE(same_token("abc", "abc"));
  EXPECT_FALSE(same_token("abd", "abc"));
  EXPECT_FALSE(same_token("ab", "abc"));
  EXPECT_FALSE(same_token("", ""));  // no token is never the token
}

TEST(AccessToken, PathDropsTheQuery) {
  EXPECT_EQ(path_of("/ws?token=1"), "/ws");
  EXPECT_EQ(path_of("/"), "/");
}

}  // namespace
}  // namespace vri::viewer
