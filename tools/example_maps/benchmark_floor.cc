#include "tools/example_maps/benchmark_floor.h"

#include <cmath>
#include <vector>

#include "tools/example_maps/benchmark_furniture.h"
#include "tools/example_maps/public_building_layout.h"

namespace areagraph::floorplan {
namespace {

// In front of a door, on both sides of the wall, nothing is put.
RectM DoorKeepOut(const DoorM& door) {
  constexpr double kDepthM = 1.1, kSideM = 0.3;
  if (door.wall == WallDirection::kHorizontal) {
    return {door.x - door.width / 2 - kSideM, door.y - kDepthM, door.width + 2 * kSideM,
            2 * kDepthM};
  }
  return {door.x - kDepthM, door.y - door.width / 2 - kSideM, 2 * kDepthM, door.width + 2 * kSideM};
}

void Furnish(const FloorLayout& layout, double wall_m, PortableRandom& random, FloorPlan& plan) {
  std::vector<RectM> doors;
  for (const DoorM& door : layout.doors) doors.push_back(DoorKeepOut(door));
  // Nothing is put on fixed furniture either.
  doors.insert(doors.end(), layout.fixtures.begin(), layout.fixtures.end());
  for (const Zone& zone : layout.zones) {
    std::vector<RectM> items;
    if (IsCorridorKind(zone.kind)) {
      for (size_t p = 0; p < zone.parts.size(); ++p) {
        if (!random.Chance(0.5)) continue;
        std::vector<RectM> keep_out = doors;
        for (size_t q = 0; q < zone.parts.size(); ++q) {
          if (q != p) keep_out.push_back(zone.parts[q]);  // junctions stay clear
        }
        const std::vector<RectM> found =
            FurnishCorridor(InnerRect(zone.parts[p], wall_m), keep_out, random);
        items.insert(items.end(), found.begin(), found.end());
      }
    } else {
      const Furnishing furnishing = RandomFurnishing(zone.kind, random);
      items = FurnishRoom(InnerRect(zone.parts[0], wall_m), furnishing, doors, random.Chance(0.5),
                          random);
    }
    for (const RectM& item : items) DrawFurniture(plan, item);
  }
}

// Rooms never scanned (their door opens onto unknown space) and big rooms
// whose far part was not scanned.
void LeaveUnknown(const FloorLayout& layout, PortableRandom& random, FloorPlan& plan) {
  for (const Zone& zone : layout.zones) {
    if (IsCorridorKind(zone.kind)) continue;
    const RectM& room = zone.parts[0];
    if (random.Chance(0.05)) {
      plan.image()(InnerCells(plan, room)).setTo(kUnknownGrey);
    } else if (room.width * room.height > 20 && random.Chance(0.12)) {
      const double share = random.Uniform(0.25, 0.45);
      RectM strip = room;
      switch (random.Int(0, 3)) {
        case 0:
          strip.height *= share;
          break;
        case 1:
          strip.y += strip.height * (1 - share), strip.height *= share;
          break;
        case 2:
          strip.width *= share;
          break;
        default:
          strip.x += strip.width * (1 - share), strip.width *= share;
      }
      const cv::Rect cells = InnerCells(plan, room) & InnerCells(plan, strip);
      plan.image()(cells).setTo(kUnknownGrey);
    }
  }
}

// Stretches of wall that the scan missed (unknown), rough wall surfaces
// (free cells beside walls turned into obstacles) and noise dots.
void AddScanNoise(const FloorLayout& layout, PortableRandom& random, FloorPlan& plan) {
  cv::Mat& image = plan.image();
  for (int n = random.Int(0, 4); n > 0; --n) {
    const Zone& zone = layout.zones[random.Int(0, static_cast<int>(layout.zones.size()) - 1)];
    const RectM& part = zone.parts[random.Int(0, static_cast<int>(zone.parts.size()) - 1)];
    const double length = random.Uniform(0.2, 1.0);
    const int t = plan.wall_thickness_px();
    const int side = random.Int(0, 3);
    cv::Rect band;
    if (side < 2) {
      const double x = random.Uniform(part.x, part.x + std::max(0.0, part.width - length));
      band = cv::Rect(plan.ToPixels(x), plan.WallStart(plan.ToPixels(part.y + side * part.height)),
                      plan.ToPixels(length), t);
    } else {
      const double y = random.Uniform(part.y, part.y + std::max(0.0, part.height - length));
      band = cv::Rect(plan.WallStart(plan.ToPixels(part.x + (side - 2) * part.width)),
                      plan.ToPixels(y), t, plan.ToPixels(length));
    }
    band &= cv::Rect(0, 0, image.cols, image.rows);
    cv::Mat stretch = image(band);
    stretch.setTo(kUnknownGrey, stretch == kWallGrey);
  }
  const double roughness = random.Uniform(0, 0.06);
  const cv::Mat before = image.clone();
  for (int r = 1; r + 1 < image.rows; ++r) {
    for (int c = 1; c + 1 < image.cols; ++c) {
      if (before.at<uint8_t>(r, c) != kFreeGrey) continue;
      const bool by_wall =
          before.at<uint8_t>(r - 1, c) == kWallGrey || before.at<uint8_t>(r + 1, c) == kWallGrey ||
          before.at<uint8_t>(r, c - 1) == kWallGrey || before.at<uint8_t>(r, c + 1) == kWallGrey;
      if (by_wall && random.Chance(roughness)) image.at<uint8_t>(r, c) = kWallGrey;
    }
  }
  DrawNoiseDots(plan, random.Int(0, 60), static_cast<uint32_t>(random.Int(0, 1 << 30)));
}

// Draws `layout` (zones, lift shafts left unknown inside, doors, fixtures,
// furniture), its ground truth, unknown rooms and scan noise.
BenchmarkFloor DrawFloor(FloorLayout layout, double resolution, double wall,
                         PortableRandom& random) {
  FloorPlan plan(layout.width_m, layout.height_m, resolution, wall);
  for (const Zone& zone : layout.zones) DrawRegion(plan, zone.parts);
  for (const RectM& shaft : layout.shafts) {
    DrawRoom(plan, shaft);
    plan.image()(InnerCells(plan, shaft)).setTo(kUnknownGrey);
  }
  const double wall_m = plan.wall_thickness_px() * resolution;
  for (const DoorM& door : layout.doors) {
    DrawDoor(plan, door.x, door.y, door.whole_side ? door.width - wall_m : door.width, door.wall);
  }
  for (const RectM& fixture : layout.fixtures) DrawFurniture(plan, fixture);
  Furnish(layout, wall_m, random, plan);

  cv::Mat truth = cv::Mat::zeros(plan.image().size(), CV_16U);
  for (size_t k = 0; k < layout.zones.size(); ++k) {
    for (const RectM& part : layout.zones[k].parts) {
      truth(InnerCells(plan, part)).setTo(static_cast<int>(k) + 1);
    }
  }
  LeaveUnknown(layout, random, plan);
  AddScanNoise(layout, random, plan);
  truth.setTo(0, plan.image() == kUnknownGrey);
  return {std::move(layout), std::move(plan), std::move(truth)};
}

}  // namespace

std::string BenchmarkFloorName(uint32_t seed) { return "floor_" + std::to_string(seed); }

BenchmarkFloor RandomBenchmarkFloor(uint32_t seed) {
  PortableRandom random(seed);
  const double resolution = std::round(random.Uniform(0.025, 0.1) * 1000) / 1000;
  const double wall = random.Uniform(0.1, 0.3);
  return DrawFloor(RandomFloorLayout(random), resolution, wall, random);
}

BenchmarkFloor RandomPublicBuildingFloor(uint32_t seed) {
  PortableRandom random(seed);
  const double resolution = std::round(random.Uniform(0.05, 0.1) * 1000) / 1000;
  const double wall = random.Uniform(0.15, 0.3);
  return DrawFloor(RandomPublicBuildingLayout(random), resolution, wall, random);
}

BenchmarkFloor MakeBenchmarkFloor(const BenchmarkPart& part, uint32_t seed) {
  return part.domain == BenchmarkDomain::kPublic ? RandomPublicBuildingFloor(seed)
                                                 : RandomBenchmarkFloor(seed);
}

std::string BenchmarkFloorName(const BenchmarkPart& part, uint32_t seed) {
  return part.domain == BenchmarkDomain::kPublic ? "public_" + std::to_string(seed)
                                                 : BenchmarkFloorName(seed);
}

std::string GroundTruthKindsTsv(const FloorLayout& layout) {
  std::string tsv = "label\tkind\n";
  for (size_t k = 0; k < layout.zones.size(); ++k) {
    tsv += std::to_string(k + 1) + "\t" + GroundTruthKindName(layout.zones[k].kind) + "\n";
  }
  return tsv;
}

}  // namespace areagraph::floorplan
