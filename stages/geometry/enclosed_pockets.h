#pragma once

#include <opencv2/core.hpp>

namespace areagraph {

// Marks as obstacle (255) every pocket of free cells in `obstacle` (an
// ObstacleMask) that touches no image border and whose bounding box is at
// most `max_pocket_px` long on its longer side: the inside of a desk or
// cabinet drawn, or scanned, as a closed outline. Nobody can reach it, and
// the outline around it is then one solid block like any other piece of
// furniture instead of a thin ring. Pockets are 4-connected, as the free
// space is.
void FillEnclosedPockets(double max_pocket_px, cv::Mat* obstacle);

}  // namespace areagraph
