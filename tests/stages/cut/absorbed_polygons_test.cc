#include "stages/cut/absorbed_polygons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace areagraph {
namespace {

// The search as it was: std::hypot of every pair, the first least wins.
size_t NearestByEveryHypot(const std::vector<proto::GraphEdge>& pieces, const proto::Ring& ring) {
  size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < pieces.size(); ++k) {
    for (const proto::Point2& p : pieces[k].path()) {
      for (const proto::Point2& q : ring.points()) {
        const double d = std::hypot(p.x() - q.x(), p.y() - q.y());
        if (d < best) best = d, nearest = k;
      }
    }
  }
  return nearest;
}

void AddPoint(google::protobuf::RepeatedPtrField<proto::Point2>* points, double x, double y) {
  proto::Point2* p = points->Add();
  p->set_x(x);
  p->set_y(y);
}

TEST(NearestPieceTest, EqualsTheHypotOfEveryPairOnRandomPieces) {
  std::mt19937 random(14);
  // Coarse grids (many exact ties between pieces), fine and huge coordinates.
  for (const double step : {1.0, 0.5, 1e-7, 1e6}) {
    std::uniform_int_distribution<int> cell(0, 40);
    for (int round = 0; round < 300; ++round) {
      std::vector<proto::GraphEdge> pieces(1 + random() % 4);
      for (proto::GraphEdge& piece : pieces) {
        const int points = 1 + static_cast<int>(random() % 12);
        for (int i = 0; i < points; ++i) {
          AddPoint(piece.mutable_path(), cell(random) * step, cell(random) * step);
        }
      }
      proto::Ring ring;
      const int points = 1 + static_cast<int>(random() % 10);
      for (int i = 0; i < points; ++i) {
        AddPoint(ring.mutable_points(), cell(random) * step + step / 3, cell(random) * step);
      }
      EXPECT_EQ(NearestPiece(pieces, ring), NearestByEveryHypot(pieces, ring))
          << "step " << step << ", round " << round;
    }
  }
}

TEST(NearestPieceTest, TheFirstOfEquallyNearPiecesWins) {
  std::vector<proto::GraphEdge> pieces(3);
  AddPoint(pieces[0].mutable_path(), 10, 0);
  AddPoint(pieces[1].mutable_path(), 3, 4);  // distance 5
  AddPoint(pieces[2].mutable_path(), 0, 5);  // distance 5 too
  proto::Ring ring;
  AddPoint(ring.mutable_points(), 0, 0);
  EXPECT_EQ(NearestPiece(pieces, ring), 1u);
}

TEST(NearestPieceTest, NoPointsGivesTheFirstPiece) {
  std::vector<proto::GraphEdge> pieces(2);
  AddPoint(pieces[1].mutable_path(), 1, 1);
  EXPECT_EQ(NearestPiece(pieces, proto::Ring()), 0u);
  EXPECT_EQ(NearestPiece({}, proto::Ring()), 0u);
}

}  // namespace
}  // namespace areagraph
