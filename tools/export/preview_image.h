#pragma once

#include <opencv2/core.hpp>

#include "proto/artifacts.pb.h"

namespace areagraph {

// A colour picture of the Area Graph for people (the 16-bit label image looks
// black in viewers): the map scaled up by a whole factor (at most 8) until
// its longer side has at least 800 px; white where no area is; each area
// filled with its own hue (consecutive ids far apart on the colour wheel),
// strong for rooms, pale for corridors, dark for dead ends, outlined in grey;
// each passage a red line along the border it opens. BGR, 8 bits per
// channel. Throws InputError as AreaLabelImage does.
cv::Mat AreaGraphPreview(const proto::AreaGraph& graph);

}  // namespace areagraph
