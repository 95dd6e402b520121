#pragma once

#include <string>

#include "tools/eval/ground_truth.h"

namespace areagraph {

// Draws the segments of a ground-truth file as ag-eval reads them (one
// distinct colour per segment over the image in grey) and writes a PNG, at
// most `max_width` pixels wide (0: full size). Shows what is being scored
// without copying the dataset's image. Throws InputError when the GT cannot
// be read or the PNG cannot be written.
void WriteGroundTruthPicture(const std::string& gt_path, GroundTruthStyle style,
                             const std::string& out_path, int max_width);

}  // namespace areagraph
