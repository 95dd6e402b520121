#pragma once

#include <google/protobuf/message.h>

#include <string>
#include <vector>

#include "proto/pipeline_options.pb.h"

namespace areagraph {

// The step of ag-cut that a pass changes. Cut's passes are rules inside the
// paper's steps (which sites stop the room disk, how W is chosen, where an
// edge is cut), not steps of their own, so each names the function it
// changes and the builder asks RunsCutPass there.
enum class CutStep {
  kRoomWidth,  // W (stages/cut/room_width.h)
  kSites,      // the obstacle sites that stop the room disk
  kClosing,    // the openings closed for the room disk by sites on their line
  kRoomDisk,   // the rooms the disk finds (stages/cut/room_disks.h)
  kEdgeCuts,   // where each Topology Graph edge is cut (stages/cut/cut_planning.h)
};

// One row of cut's pass table: a rule beyond the paper.
struct CutPass {
  proto::CutOptions::Pass pass;
  CutStep step;
  // The function that applies it.
  const char* where;
  // Why it acts where it does.
  const char* order;
  // Its options within CutOptions, or null for a pass without any.
  const google::protobuf::Message* (*options_of)(const proto::CutOptions& options);
};

// Every pass, in the order they act. Nothing else lists them: the option
// cut.skip_passes names them, tools/bench-ablation.sh turns each off in turn,
// and examples/options/paper.pbtxt skips them all.
const std::vector<CutPass>& CutPassTable();

// A pass's name as cut.skip_passes spells it, e.g. "CLOSE_WALL_DOORS".
std::string CutPassName(proto::CutOptions::Pass pass);

// Whether `options` run `pass` (it is not in cut.skip_passes).
bool RunsCutPass(const proto::CutOptions& options, proto::CutOptions::Pass pass);

// The numbers the builder reads, 0 where the pass that uses them is skipped
// (0 turns each off): the longest island, the widest wall gap and the
// widest mouth that are closed, in metres.
double IslandMaxLengthM(const proto::CutOptions& options);
double WallGapMaxWidthM(const proto::CutOptions& options);
double MouthMaxWidthM(const proto::CutOptions& options);

}  // namespace areagraph
