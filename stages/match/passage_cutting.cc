#include "stages/match/passage_cutting.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace areagraph {
namespace {

BorderPoint ToPoint(const proto::Point2& p) { return {p.x(), p.y()}; }

double Distance(const BorderPoint& a, const BorderPoint& b) {
  return std::hypot(a.first - b.first, a.second - b.second);
}

double Length(const std::vector<BorderPoint>& line) {
  double length = 0;
  for (size_t i = 0; i + 1 < line.size(); ++i) length += Distance(line[i], line[i + 1]);
  return length;
}

// `passage` along `border` only.
proto::Passage PassageAlong(const proto::Passage& passage, const std::vector<BorderPoint>& border,
                            bool keeps_point) {
  proto::Passage piece = passage;
  piece.clear_border_m();
  for (const BorderPoint& p : border) {
    proto::Point2* point = piece.add_border_m();
    point->set_x(p.first);
    point->set_y(p.second);
  }
  *piece.mutable_segment_m()->mutable_a() = piece.border_m(0);
  *piece.mutable_segment_m()->mutable_b() = piece.border_m(piece.border_m_size() - 1);
  piece.set_width_m(Distance(border.front(), border.back()));
  if (!keeps_point) {
    const BorderPoint& a = border[(border.size() - 1) / 2];
    const BorderPoint& b = border[border.size() / 2];
    piece.mutable_point_m()->set_x((a.first + b.first) / 2);
    piece.mutable_point_m()->set_y((a.second + b.second) / 2);
    piece.clear_stable_id();
  }
  return piece;
}

}  // namespace

bool OnSegment(const BorderPoint& p, const BorderPoint& u, const BorderPoint& v) {
  const double dx = v.first - u.first, dy = v.second - u.second;
  const double length2 = dx * dx + dy * dy;
  if (length2 == 0 || p == u || p == v) return false;
  const double cross = dx * (p.second - u.second) - dy * (p.first - u.first);
  if (std::abs(cross) > 1e-9 * std::sqrt(length2)) return false;
  const double along = dx * (p.first - u.first) + dy * (p.second - u.second);
  return along > 0 && along < length2;
}

std::vector<proto::Passage> CutPassage(const proto::Passage& passage,
                                       const std::vector<BorderPoint>& cuts, double min_piece_m) {
  std::set<BorderPoint> placed;
  std::vector<std::vector<BorderPoint>> pieces(1);
  for (int i = 0; i < passage.border_m_size(); ++i) {
    const BorderPoint from = ToPoint(passage.border_m(i));
    pieces.back().push_back(from);
    if (i + 1 == passage.border_m_size()) break;
    const BorderPoint to = ToPoint(passage.border_m(i + 1));
    std::vector<BorderPoint> on_edge;
    for (const BorderPoint& cut : cuts) {
      if (OnSegment(cut, from, to)) on_edge.push_back(cut);
    }
    std::sort(on_edge.begin(), on_edge.end(), [&](const BorderPoint& a, const BorderPoint& b) {
      return Distance(a, from) < Distance(b, from);
    });
    for (const BorderPoint& cut : on_edge) {
      placed.insert(cut);
      pieces.back().push_back(cut);
      pieces.push_back({cut});
    }
  }
  for (const BorderPoint& cut : cuts) {
    if (placed.count(cut) == 0) return {};
  }
  size_t longest = 0;
  for (size_t i = 1; i < pieces.size(); ++i) {
    if (Length(pieces[i]) > Length(pieces[longest])) longest = i;
  }
  std::vector<proto::Passage> out;
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (i != longest && Length(pieces[i]) < min_piece_m) continue;
    out.push_back(PassageAlong(passage, pieces[i], i == longest));
  }
  return out;
}

}  // namespace areagraph
