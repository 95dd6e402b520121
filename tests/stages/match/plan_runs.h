#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "proto/artifacts.pb.h"
#include "proto/pipeline_options.pb.h"
#include "runner/common/map_run.h"
#include "store/artifact_store.h"

namespace areagraph::testing {

// Runs a drawn map (an 8-bit grey image, as floorplan draws them) through
// the whole pipeline as ag-run would run the PNG file: import through match
// with the store's cache. Fails the test when the run fails.
MapOutcome RunPlan(ArtifactStore& store, const std::string& map_name, const cv::Mat& grey,
                   const proto::PipelineOptions& options = {});

// The map's Area Graph with stable ids (the match head), and its key.
proto::AreaGraph MatchedGraph(ArtifactStore& store, const std::string& map_name,
                              std::string* key = nullptr);

// The stable id of the area whose polygon holds the point given in plan
// metres (x right, y down from the top-left corner), or -1.
int StableIdAt(const proto::AreaGraph& graph, double x_m, double y_m);

// Options with a fixed room width W (metres), so that drawn maps segment
// the same way whatever the automatic estimate would make of them.
proto::PipelineOptions FixedWidthOptions(double room_width_m = 1.25);

}  // namespace areagraph::testing
