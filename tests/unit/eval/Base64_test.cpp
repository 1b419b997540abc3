#include "eval/Base64.hpp"

#include <gtest/gtest.h>

namespace unimap::eval {
namespace {

TEST(Base64Test, MatchesRfc4648TestVectors) {
  EXPECT_EQ(EncodeBase64(""), "");
  EXPECT_EQ(EncodeBase64("f"), "Zg==");
  EXPECT_EQ(EncodeBase64("fo"), "Zm8=");
  EXPECT_EQ(EncodeBase64("foo"), "Zm9v");
  EXPECT_EQ(EncodeBase64("foob"), "Zm9vYg==");
  EXPECT_EQ(EncodeBase64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(EncodeBase64("foobar"), "Zm9vYmFy");
}

TEST(Base64Test, EncodesHighBytes) {
  EXPECT_EQ(EncodeBase64(std::string("\x89PNG", 4)), "iVBORw==");
  EXPECT_EQ(EncodeBase64(std::string("\xff\xff\xff", 3)), "////");
}

}  // namespace
}  // namespace unimap::eval
