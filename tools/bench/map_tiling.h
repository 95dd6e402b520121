#pragma once

#include <opencv2/core.hpp>

namespace areagraph {

// `map` (8-bit grey, free >= 250 as ag-import reads it without a YAML)
// repeated `tiles` x `tiles` times side by side. Each copy is joined to its
// right neighbour by a walled corridor 21 px wide along the row of the map's
// longest horizontal run of free cells, from the copy's last free cell in
// that row to the neighbour's first one, and to its lower neighbour likewise
// along the column of the longest vertical run: the free space of all copies
// is one piece, as in a campus of identical buildings joined by corridors.
cv::Mat TileMap(const cv::Mat& map, int tiles);

}  // namespace areagraph
