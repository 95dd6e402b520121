#include "store/cache_key.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace areagraph {
namespace {

const std::string kOptions("alpha: 0.5\n\0x", 13);  // embedded NUL: options are bytes
const std::vector<std::string> kInputs = {"aaaa", "bbbb"};

TEST(CacheKeyTest, SameInputsGiveSameKey) {
  EXPECT_EQ(ComputeCacheKey("voronoi", 3, kOptions, kInputs),
            ComputeCacheKey("voronoi", 3, kOptions, kInputs));
}

// These values were computed once with this code and, independently, with
// Python's hashlib over the documented encoding (length-prefixed fields after
// "areagraph-cache-key-v1"). A key that changes between runs, builds or
// machines would silently invalidate every store, so they are fixed here.
TEST(CacheKeyTest, KeyIsStableAcrossRuns) {
  EXPECT_EQ(ComputeCacheKey("voronoi", 3, kOptions, kInputs),
            "8459a241a12830b98ba447c45fe2a3ed4c6346d9db3d362ec008aedd38706bbf");
  EXPECT_EQ(ComputeCacheKey("import", 1, "", {}),
            "057c74cef6758e437ccd936936e7e1e6b47394be156502b7b8f8e273ca0336c0");
}

TEST(CacheKeyTest, EveryPartChangesTheKey) {
  const std::string base = ComputeCacheKey("voronoi", 3, kOptions, kInputs);
  std::string other_options = kOptions;
  other_options.back() = 'y';
  const std::vector<std::string> variants = {
      ComputeCacheKey("prune", 3, kOptions, kInputs),
      ComputeCacheKey("voronoi", 4, kOptions, kInputs),
      ComputeCacheKey("voronoi", 3, other_options, kInputs),
      ComputeCacheKey("voronoi", 3, kOptions.substr(0, 12), kInputs),  // bytes after the NUL
      ComputeCacheKey("voronoi", 3, kOptions, {"aaab", "bbbb"}),
      ComputeCacheKey("voronoi", 3, kOptions, {"aaaa", "bbbc"}),
      ComputeCacheKey("voronoi", 3, kOptions, {"bbbb", "aaaa"}),  // order matters
      ComputeCacheKey("voronoi", 3, kOptions, {"aaaa"}),
      ComputeCacheKey("voronoi", 3, kOptions, {"aaaa", "bbbb", ""}),
  };
  std::set<std::string> distinct(variants.begin(), variants.end());
  distinct.insert(base);
  EXPECT_EQ(distinct.size(), variants.size() + 1);
}

TEST(CacheKeyTest, FieldBoundariesDoNotCollide) {
  // Plain concatenation would make these equal.
  EXPECT_NE(ComputeCacheKey("ab", 1, "c", {}), ComputeCacheKey("a", 1, "bc", {}));
  EXPECT_NE(ComputeCacheKey("s", 1, "", {"ab", "c"}), ComputeCacheKey("s", 1, "", {"a", "bc"}));
  EXPECT_NE(ComputeCacheKey("s", 1, "x", {}), ComputeCacheKey("s", 1, "", {"x"}));
}

TEST(CacheKeyTest, KeyIsLowerCaseSha256Hex) {
  const std::string key = ComputeCacheKey("voronoi", 3, kOptions, kInputs);
  ASSERT_EQ(key.size(), 64u);
  EXPECT_EQ(key.find_first_not_of("0123456789abcdef"), std::string::npos);
}

}  // namespace
}  // namespace areagraph
