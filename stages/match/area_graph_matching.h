#pragma once

#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "store/artifact_store.h"

namespace areagraph {

// ag-match: `current` (a merge artifact) with stable ids and its place in the
// map's history. Without a `previous` version (a map's first graph), areas
// and passages are numbered in order. Otherwise both graphs' areas are
// rasterized on `current`'s grid (RasterizeAreas) and paired by shared
// cells: a pair counts when it shares at least options.min_overlap() of the
// smaller area's cells, pairs are taken largest overlap first, and each
// previous id goes to at most one area and each area takes at most one id.
// So a grown area keeps its id, a split keeps it on its largest part and a
// merge keeps the id of its largest parent. Before that, a new area smaller
// than options.fold_fragments_below_m2() that lies inside one previous area,
// beside the area that took its id, is folded into that area (scan noise
// split it off; see FindNoiseFragments): the published graph then has fewer
// areas than `current`. A passage keeps its id when it
// joins the same two stable areas within options.passage_max_shift_m() of
// where it was, nearest first. Everything else gets ids never used before in
// the map's history (previous->version() counts them).
// `segmentation_options_digest` names the options of the stages before match
// (SegmentationOptionsDigest); pieces fold back only when the previous
// version was made with the same, so that a re-run with other options
// publishes their areas. It is stored in the version.
proto::AreaGraph MatchAreaGraph(const proto::AreaGraph& current, const proto::AreaGraph* previous,
                                const VersionLink& version, const proto::MatchOptions& options,
                                const std::string& segmentation_options_digest = "");

// SHA-256 of the canonical text of `options` without its match options.
std::string SegmentationOptionsDigest(const proto::PipelineOptions& options);

}  // namespace areagraph
