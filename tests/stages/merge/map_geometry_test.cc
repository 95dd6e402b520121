// The Area Graph as a map on drawn floor plans: neighbours share one border
// polyline, passages are pieces of it, walls are straight, junctions are
// shared vertices.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "tests/support/area_test_support.h"
#include "tools/example_maps/floor_plan.h"

namespace areagraph::testing {
namespace {

using Vertex = std::pair<double, double>;

std::vector<Vertex> Outer(const proto::Area& area) {
  std::vector<Vertex> points;
  for (const proto::Point2& p : area.polygon_m().outer().points())
    points.emplace_back(p.x(), p.y());
  return points;
}

bool HasVertex(const std::vector<Vertex>& ring, const proto::Point2& p) {
  return std::find(ring.begin(), ring.end(), Vertex(p.x(), p.y())) != ring.end();
}

// Where each outer-ring vertex of the graph occurs: the areas it belongs to.
std::map<Vertex, std::set<int>> VertexOwners(const proto::AreaGraph& graph) {
  std::map<Vertex, std::set<int>> owners;
  for (const proto::Area& area : graph.areas()) {
    for (const Vertex& v : Outer(area)) owners[v].insert(area.id());
  }
  return owners;
}

// The ring's vertices where it turns by more than 20 degrees: its corners.
int Corners(const std::vector<Vertex>& ring) {
  int corners = 0;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Vertex& a = ring[(i + n - 1) % n];
    const Vertex& b = ring[i];
    const Vertex& c = ring[(i + 1) % n];
    const double ux = b.first - a.first, uy = b.second - a.second;
    const double vx = c.first - b.first, vy = c.second - b.second;
    const double turn = std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
    corners += turn > 20 * M_PI / 180;
  }
  return corners;
}

TEST(MapGeometryTest, TwoRoomsShareOneBorderWithTheDoorOnItAndAreRectangles) {
  const proto::CleanedMap map = CleanedMapFromImage(TwoRoomsWithADoor().image());
  const AreaStages stages = RunAreaStages(map);
  ExpectAreaGraphInvariants(stages, map);
  const proto::AreaGraph& graph = stages.areas;
  ASSERT_EQ(graph.areas_size(), 2);
  ASSERT_EQ(graph.passages_size(), 1);
  const proto::Passage& door = graph.passages(0);

  // The two outlines share exactly the door's border: its points, in order.
  std::vector<Vertex> shared;
  const std::vector<Vertex> left = Outer(graph.areas(0)), right = Outer(graph.areas(1));
  for (const Vertex& v : left) {
    if (std::find(right.begin(), right.end(), v) != right.end()) shared.push_back(v);
  }
  ASSERT_GE(door.border_m_size(), 2);
  EXPECT_EQ(shared.size(), static_cast<size_t>(door.border_m_size()));
  for (const proto::Point2& p : door.border_m()) {
    EXPECT_TRUE(HasVertex(left, p) && HasVertex(right, p)) << p.x() << ", " << p.y();
  }
  // The door's end points are its jambs: 0.9 m apart, in the wall at x = 4.5 m.
  const proto::Segment& segment = door.segment_m();
  EXPECT_NEAR(std::hypot(segment.a().x() - segment.b().x(), segment.a().y() - segment.b().y()), 0.9,
              0.1);
  for (const proto::Point2* end : {&segment.a(), &segment.b()}) {
    EXPECT_NEAR(end->x(), 4.5, 0.1);
  }
  // Each room is a rectangle: four corners (the door's end points lie on a
  // straight side), and nothing else but the door's two end points.
  for (const std::vector<Vertex>* ring : {&left, &right}) {
    EXPECT_EQ(Corners(*ring), 4);
    EXPECT_LE(ring->size(), 6u);
  }
}

TEST(MapGeometryTest, NoisyLCorridorOutlineHasItsSixCorners) {
  floorplan::FloorPlan plan = LCorridor();
  // Scan noise: one-cell bumps on the walls every 7 cells, which the
  // outline should not follow.
  cv::Mat& image = plan.image();
  const cv::Mat drawn = image.clone();
  for (int r = 1; r + 1 < image.rows; ++r) {
    for (int c = 1; c + 1 < image.cols; ++c) {
      if (drawn.at<uint8_t>(r, c) != floorplan::kFreeGrey || (r + c) % 7 != 0) continue;
      const bool by_wall = drawn.at<uint8_t>(r - 1, c) == floorplan::kWallGrey ||
                           drawn.at<uint8_t>(r + 1, c) == floorplan::kWallGrey ||
                           drawn.at<uint8_t>(r, c - 1) == floorplan::kWallGrey ||
                           drawn.at<uint8_t>(r, c + 1) == floorplan::kWallGrey;
      if (by_wall) image.at<uint8_t>(r, c) = floorplan::kWallGrey;
    }
  }
  const proto::CleanedMap map = CleanedMapFromImage(plan.image());
  proto::PipelineOptions options;
  options.mutable_cut()->set_room_width_m(1.25);  // a fixed W (0, the default, estimates it)
  const AreaStages stages = RunAreaStages(map, options);
  ExpectAreaGraphInvariants(stages, map);
  ASSERT_EQ(stages.areas.areas_size(), 1);
  const std::vector<Vertex> ring = Outer(stages.areas.areas(0));
  EXPECT_EQ(ring.size(), 6u);
  EXPECT_EQ(stages.areas.areas(0).polygon_m().holes_size(), 0);
}

TEST(MapGeometryTest, EveryMazeJunctionIsAVertexOfThreeOrMoreOutlines) {
  const proto::CleanedMap map = CleanedMapFromImage(FiveByFiveMaze().image());
  const AreaStages stages = RunAreaStages(map, PaperMazeOptions());
  ExpectAreaGraphInvariants(stages, map);
  const proto::AreaGraph& graph = stages.areas;
  const std::map<Vertex, std::set<int>> owners = VertexOwners(graph);
  // At every Topology Graph junction three or more areas meet, and they all
  // meet at one vertex of their outlines, near the junction.
  const double reach_m = 1.0;
  int junctions = 0;
  for (int v = 0; v < stages.cut.vertices_size(); ++v) {
    const proto::GraphVertex& vertex = stages.cut.vertices(v);
    if (vertex.kind() != proto::VERTEX_JUNCTION) continue;
    ++junctions;
    const double x = vertex.position().x() * 0.05;
    const double y = (map.frame().height_px() - vertex.position().y()) * 0.05;
    std::set<int> meeting;
    for (const proto::GraphEdge& edge : stages.cut.edges()) {
      if (edge.source() != v && edge.target() != v) continue;
      for (const proto::Area& area : graph.areas()) {
        for (int id : area.topology_edge_ids()) {
          if (id == edge.id()) meeting.insert(area.id());
        }
      }
    }
    ASSERT_GE(meeting.size(), 3u);
    bool shared_vertex = false;
    for (const auto& [point, areas] : owners) {
      if (std::hypot(point.first - x, point.second - y) > reach_m) continue;
      shared_vertex = shared_vertex || (areas.size() >= 3 && areas == meeting);
    }
    EXPECT_TRUE(shared_vertex) << "junction at " << x << ", " << y;
  }
  EXPECT_GE(junctions, 2);
}

}  // namespace
}  // namespace areagraph::testing
