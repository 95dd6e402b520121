#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "stages/merge/passage_borders.h"
#include "stages/merge/planar_partition.h"

namespace areagraph {

// Whether a body fits across each chain of `partition` (traced from
// `labels`): some point of the chain (a cell edge's middle or a corner) is
// at least `clearance_px` from every cell that no area covers (label 0, or
// outside the image), so that a disk of that radius centred there lies in
// the areas. Only chains between two areas can be true; none is when
// `clearance_px` is 0.
std::vector<bool> PassableChains(const PlanarPartition& partition, const cv::Mat& labels,
                                 double clearance_px);

// A passage on every chain between two areas that a body fits across
// (`passable`) and that no passage of `placed` lies on: areas meeting in
// open free space are joined, not walled off, wherever the graph vertices
// that FindPassages reads put no passage (areas grown from graph edges
// that share no vertex). Its point is the middle point of the chain's
// `chain_points` (the simplified chain) and its width the distance between
// the chain's ends; area_a is the chain's right region. Areas are labelled
// `label_of_area[id]`; a chain with a label of no area gets none. In chain
// order.
std::vector<PassageOnBorder> OpenBorderPassages(const PlanarPartition& partition,
                                                const std::vector<bool>& passable,
                                                const std::vector<PointList>& chain_points,
                                                const std::vector<int>& label_of_area,
                                                const std::vector<PassageOnBorder>& placed);

}  // namespace areagraph
