#include "runner/run/shard.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace areagraph {
namespace {

TEST(ShardTest, ParsesValidShards) {
  const Shard shard = ParseShard("1/4");
  EXPECT_EQ(shard.index, 1);
  EXPECT_EQ(shard.count, 4);
}

TEST(ShardTest, RefusesIndexBeyondCount) {
  try {
    ParseShard("3/2");
    FAIL() << "3/2 accepted";
  } catch (const OptionsError& error) {
    EXPECT_NE(std::string(error.what()).find("0..1"), std::string::npos) << error.what();
  }
  EXPECT_THROW(ParseShard("0/0"), OptionsError);
  EXPECT_THROW(ParseShard("-1/2"), OptionsError);
  EXPECT_THROW(ParseShard("1"), OptionsError);
  EXPECT_THROW(ParseShard("a/b"), OptionsError);
}

TEST(ShardTest, ShardsPartitionTheCollection) {
  constexpr int kShards = 3;
  std::vector<int> sizes(kShards, 0);
  for (int i = 0; i < 300; ++i) {
    const std::string name = "map_" + std::to_string(i);
    int owners = 0;
    for (int k = 0; k < kShards; ++k) {
      if (InShard(name, {k, kShards})) {
        ++owners;
        ++sizes[k];
      }
    }
    EXPECT_EQ(owners, 1) << name;
  }
  // A hash spreads 300 names roughly evenly.
  for (int size : sizes) EXPECT_GT(size, 60);
}

TEST(ShardTest, MembershipDependsOnTheNameOnly) {
  // SHA-256("two_rooms") starts with a fixed value, so its shard never moves.
  const bool first = InShard("two_rooms", {0, 2});
  for (int i = 0; i < 3; ++i) EXPECT_EQ(InShard("two_rooms", {0, 2}), first);
  EXPECT_NE(InShard("two_rooms", {0, 2}), InShard("two_rooms", {1, 2}));
  EXPECT_TRUE(InShard("anything", {0, 1}));
}

}  // namespace
}  // namespace areagraph
