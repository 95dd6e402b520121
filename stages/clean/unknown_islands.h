#pragma once

#include <string>
#include <vector>

namespace areagraph {

// Unknown cells that form a small island inside the mapped space are
// furniture or a pocket the sensor could not see into, not unexplored
// space: Bormann's maps draw furniture in light grey, which imports as
// unknown. Every 8-connected region of unknown cells with at most
// `max_cells` cells that touches neither the image border nor a bigger
// unknown region becomes free. Returns the freed cells' flat indices,
// increasing.
std::vector<int> FreeUnknownIslands(std::string& cells, int width, int height, double max_cells);

}  // namespace areagraph
