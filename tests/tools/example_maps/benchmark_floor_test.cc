// The generated quality benchmark: office floors stay as they were, public
// buildings have what the domain promises, and every zone has a kind.
#include "tools/example_maps/benchmark_floor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>

#include "tools/example_maps/public_building_layout.h"

namespace areagraph {
namespace {

using namespace floorplan;

// FNV-1a over an image's bytes, row by row.
uint64_t Digest(const cv::Mat& image) {
  uint64_t hash = 1469598103934665603ull;
  for (int r = 0; r < image.rows; ++r) {
    const uint8_t* row = image.ptr<uint8_t>(r);
    for (size_t c = 0; c < image.cols * image.elemSize(); ++c) {
      hash = (hash ^ row[c]) * 1099511628211ull;
    }
  }
  return hash;
}

constexpr uint64_t kTuningPlanDigest = 13723326020849014218ull;
constexpr uint64_t kTuningTruthDigest = 19221600298199084ull;
constexpr uint64_t kHeldOutPlanDigest = 4342020246780818383ull;
constexpr uint64_t kHeldOutTruthDigest = 2197034409214366815ull;

// The office floors that every figure so far was measured on are drawn as
// before the public-building domain was added (the digests of main's
// generator, 2026-12-04).
TEST(BenchmarkFloorTest, OfficeFloorsAreUnchanged) {
  const BenchmarkFloor tuning = RandomBenchmarkFloor(kTuningPart.first_seed);
  const BenchmarkFloor held_out = RandomBenchmarkFloor(kHeldOutPart.first_seed);
  EXPECT_EQ(Digest(tuning.plan.image()), kTuningPlanDigest);
  EXPECT_EQ(Digest(tuning.truth), kTuningTruthDigest);
  EXPECT_EQ(Digest(held_out.plan.image()), kHeldOutPlanDigest);
  EXPECT_EQ(Digest(held_out.truth), kHeldOutTruthDigest);
}

TEST(BenchmarkFloorTest, KindsNameEveryZoneOfTheTruth) {
  const BenchmarkFloor floor = RandomBenchmarkFloor(kTuningPart.first_seed + 2);
  std::istringstream tsv(GroundTruthKindsTsv(floor.layout));
  std::string line;
  ASSERT_TRUE(std::getline(tsv, line));
  EXPECT_EQ(line, "label\tkind");
  int label = 0, corridors = 0;
  while (std::getline(tsv, line)) {
    ++label;
    const std::string kind = line.substr(line.find('\t') + 1);
    EXPECT_EQ(line.substr(0, line.find('\t')), std::to_string(label));
    EXPECT_EQ(kind, GroundTruthKindName(floor.layout.zones[label - 1].kind));
    corridors += kind == "corridor";
  }
  EXPECT_EQ(label, static_cast<int>(floor.layout.zones.size()));
  double max_label = 0;
  cv::minMaxLoc(floor.truth, nullptr, &max_label);
  EXPECT_LE(max_label, label);
  EXPECT_EQ(corridors, floor.layout.name == "hall" ? 0 : 1);
}

// Two floors of the public tuning part hold, between them, every feature of
// the domain: 100-200 m across, wings with corridors of different widths,
// a lobby with pillars, lecture halls with rows of seats, double doors of
// 1.5-2 m, rooms open along a whole side, stairs, lifts and a corridor that
// ends blind.
TEST(BenchmarkFloorTest, PublicBuildingsHaveEveryFeature) {
  std::set<ZoneKind> kinds;
  int double_doors = 0, open_sides = 0, shafts = 0;
  for (uint32_t seed = kPublicTuningPart.first_seed; seed < kPublicTuningPart.first_seed + 2;
       ++seed) {
    SCOPED_TRACE(seed);
    const BenchmarkFloor floor = MakeBenchmarkFloor(kPublicTuningPart, seed);
    EXPECT_EQ(BenchmarkFloorName(kPublicTuningPart, seed), "public_" + std::to_string(seed));
    const double across = std::max(floor.layout.width_m, floor.layout.height_m);
    EXPECT_GE(across, 100);
    EXPECT_LE(across, 215);
    std::set<double> corridor_widths;
    for (const Zone& zone : floor.layout.zones) {
      kinds.insert(zone.kind);
      if (zone.kind == ZoneKind::kCorridor && zone.parts.size() == 1) {
        const RectM& c = zone.parts[0];
        corridor_widths.insert(std::min(c.width, c.height));
      }
    }
    ASSERT_GE(corridor_widths.size(), 2u);
    EXPECT_GE(*corridor_widths.rbegin() - *corridor_widths.begin(), 0.4);
    for (const DoorM& door : floor.layout.doors) {
      if (door.whole_side) {
        ++open_sides;
      } else {
        EXPECT_LE(door.width, kMaxDoubleDoorM + 1e-9);
        double_doors += door.width >= kMinDoubleDoorM;
      }
    }
    shafts += static_cast<int>(floor.layout.shafts.size());
    EXPECT_FALSE(floor.layout.fixtures.empty());
    // Lift shafts are closed and unknown inside; the truth covers zones only.
    double max_label = 0;
    cv::minMaxLoc(floor.truth, nullptr, &max_label);
    EXPECT_LE(max_label, floor.layout.zones.size());
  }
  for (const ZoneKind kind : {ZoneKind::kLobby, ZoneKind::kLectureHall, ZoneKind::kStairs,
                              ZoneKind::kBay, ZoneKind::kDeadEnd, ZoneKind::kRoom}) {
    EXPECT_EQ(kinds.count(kind), 1u) << static_cast<int>(kind);
  }
  EXPECT_GT(double_doors, 0);
  EXPECT_GT(open_sides, 0);
  EXPECT_GT(shafts, 0);
}

TEST(BenchmarkFloorTest, PublicFloorsDependOnlyOnTheSeed) {
  const BenchmarkFloor a = MakeBenchmarkFloor(kPublicHeldOutPart, kPublicHeldOutPart.first_seed);
  const BenchmarkFloor b = MakeBenchmarkFloor(kPublicHeldOutPart, kPublicHeldOutPart.first_seed);
  EXPECT_EQ(Digest(a.plan.image()), Digest(b.plan.image()));
  EXPECT_EQ(Digest(a.truth), Digest(b.truth));
  EXPECT_EQ(GroundTruthKindsTsv(a.layout), GroundTruthKindsTsv(b.layout));
}

}  // namespace
}  // namespace areagraph
