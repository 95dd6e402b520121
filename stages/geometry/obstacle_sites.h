#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace areagraph {

// Flat indices (row * width + col), in row-major order, of the cells that the
// Voronoi diagram is built from: every non-free cell (occupied OR unknown;
// unknown space is never free) with a free cell among its 8 neighbours.
// Obstacle cells deeper inside walls cannot be nearest to any free point, so
// leaving them out shrinks the triangulation without changing the diagram in
// free space.
std::vector<int> ObstacleSiteCells(const std::string& cells, int width, int height);

// The centres of ObstacleSiteCells in pixel coordinates: (c + 0.5, r + 0.5).
std::vector<Eigen::Vector2d> ObstacleSites(const std::string& cells, int width, int height);

}  // namespace areagraph
