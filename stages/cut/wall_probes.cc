#include "stages/cut/wall_probes.h"

#include "stages/cut/door_sites.h"
#include "stages/geometry/corridor_shape.h"

namespace areagraph {

// The nearest non-free cell centre to `p` within `radius` px, optionally only
// on the far side of `p` from `away` (angle above 120 degrees); false if none.
bool NearestObstacle(const WallStructure& walls, const Eigen::Vector2d& p, double radius,
                     const Eigen::Vector2d* away, Eigen::Vector2d* found) {
  double best = radius * radius;
  bool any = false;
  const int r = static_cast<int>(std::ceil(radius));
  const int pc = static_cast<int>(std::floor(p.x())), pr = static_cast<int>(std::floor(p.y()));
  for (int row = pr - r; row <= pr + r; ++row) {
    for (int col = pc - r; col <= pc + r; ++col) {
      if (walls.LabelAt(col, row) == 0) continue;
      const Eigen::Vector2d c(col + 0.5, row + 0.5);
      const Eigen::Vector2d d = c - p;
      const double d2 = d.squaredNorm();
      if (d2 > best) continue;
      if (away != nullptr) {
        const Eigen::Vector2d a = *away - p;
        if (d.dot(a) > -0.5 * d.norm() * a.norm()) continue;
      }
      best = d2, *found = c, any = true;
    }
  }
  return any;
}

// Whether non-free cells run on from `jamb` in `direction` for `run_px`.
// Free cells that the door's free space `space` cannot reach count as
// non-free (space 0: none do): they lie behind a wall drawn as a thin line,
// the outside of a map whose outside is drawn free, or the inside of a block
// drawn as a hollow outline.
bool WallRunsOn(const WallStructure& walls, const Eigen::Vector2d& jamb,
                const Eigen::Vector2d& direction, double run_px, int space) {
  int samples = 0, non_free = 0;
  for (double t = 1; t <= run_px; t += 1, ++samples) {
    non_free += walls.Beyond(jamb + t * direction, space);
  }
  return samples == 0 || non_free >= kJambRunShare * samples;
}

// How far non-free cells run from `from` in `direction` (px, whole steps),
// or -1 when they still run at `limit_px` (no free cell within reach).
double NonFreeRun(const WallStructure& walls, const Eigen::Vector2d& from,
                  const Eigen::Vector2d& direction, double limit_px) {
  for (double t = 0; t <= limit_px; t += 0.5) {
    if (walls.LabelAt(from + t * direction) == 0) return t;
  }
  return -1;
}

// Whether the wall at `probe` is at most `max_thickness_px` thick across
// `outward` with free cells on both sides.
bool IsThinAt(const WallStructure& walls, const Eigen::Vector2d& probe,
              const Eigen::Vector2d& outward, double max_thickness_px) {
  if (walls.LabelAt(probe) == 0) return false;
  const Eigen::Vector2d across(-outward.y(), outward.x());
  const double one = NonFreeRun(walls, probe, across, max_thickness_px);
  const double other = NonFreeRun(walls, probe, -across, max_thickness_px);
  return one > 0 && other > 0 && one + other <= max_thickness_px;
}

bool IsThinWallEnd(const WallStructure& walls, const Eigen::Vector2d& jamb,
                   const Eigen::Vector2d& outward, double run_px, double max_thickness_px) {
  for (double t = 1; t <= run_px; t += 1) {
    if (!IsThinAt(walls, jamb + t * outward, outward, max_thickness_px)) return false;
  }
  return true;
}

// Which side of the line through a jamb (along `outward`, away from the
// opening) a wall leaves it on for `depth_px` (+1 along the line's left
// normal, -1 along its right one, 0 neither or both), where the wall on the
// other side is at most `max_thickness_px` thick: the end of a side wall of
// the space behind a mouth, with the wall line's thickness on the far side.
int SideWallAt(const WallStructure& walls, const Eigen::Vector2d& jamb,
               const Eigen::Vector2d& outward, double depth_px, double max_thickness_px,
               int space) {
  const Eigen::Vector2d normal(-outward.y(), outward.x());
  // A cell beside the probed line counts too: a jamb on a bump of a rough
  // wall is a cell off the wall's face.
  auto runs_on = [&](const Eigen::Vector2d& direction) {
    int samples = 0, non_free = 0;
    for (double t = 1; t <= depth_px; t += 1, ++samples) {
      const Eigen::Vector2d at = jamb + t * direction;
      non_free += walls.Beyond(at, space) || walls.Beyond(at + outward, space) ||
                  walls.Beyond(at - outward, space);
    }
    return samples == 0 || non_free >= kJambRunShare * samples;
  };
  const bool left = runs_on(normal);
  const bool right = runs_on(-normal);
  if (left == right) return 0;
  const Eigen::Vector2d far_side = left ? -normal : normal;
  if (NonFreeRun(walls, jamb, far_side, max_thickness_px) < 0) return 0;
  return left ? 1 : -1;
}

// How far free cells run from `from` along `direction` (px, whole steps),
// up to `limit_px`, as seen from free space `space`.
double FreeRun(const WallStructure& walls, const Eigen::Vector2d& from,
               const Eigen::Vector2d& direction, double limit_px, int space) {
  double t = 1;
  while (t <= limit_px && !walls.Beyond(from + t * direction, space)) t += 1;
  return t - 1;
}

bool CorridorBehind(const WallStructure& walls, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                    const Eigen::Vector2d& behind, int space) {
  const double limit = kCorridorElongation * (b - a).norm();
  double deepest = 0;
  for (const double share : {0.25, 0.5, 0.75}) {
    deepest = std::max(deepest, FreeRun(walls, a + share * (b - a), behind, limit, space));
  }
  return deepest >= limit;
}

}  // namespace areagraph
