#include "stages/cut/cut_passes.h"

#include "stages/common/skipped_passes.h"

namespace areagraph {
namespace {

using Options = proto::CutOptions;
using google::protobuf::Message;

std::vector<CutPass> MakeTable() {
  return {
      {Options::WIDTH_ABOVE_DOORS, CutStep::kRoomWidth, "EstimateRoomWidth (width_estimate.h)",
       "first: W decides every later step, and only an estimated W (cut.room_width_m 0) reads it",
       nullptr},
      {Options::FREE_STANDING_ISLANDS, CutStep::kSites, "StructureSitesFrom (structure_sites.h)",
       "before any opening is closed: the openings' jambs are measured on the obstacles that "
       "stay sites, and a desk in a room is no jamb",
       [](const Options& o) -> const Message* { return &o.islands(); }},
      {Options::WALL_PIECES_NEED_BOTH_ENDS, CutStep::kSites, "WallPiece (structure_sites.cc)",
       "with the islands, which it narrows: only an island candidate can be a piece of wall",
       nullptr},
      {Options::CLOSE_WALL_DOORS, CutStep::kClosing, "NarrowingOpenings (door_sites.h)",
       "after W: the doors are the estimate's, and a door narrower than W needs no closing",
       nullptr},
      {Options::CLOSE_WALL_GAPS, CutStep::kClosing, "WallGapFinder (door_sites.h)",
       "beside the doors: it closes the gaps the width estimate does not see as doors",
       [](const Options& o) -> const Message* { return &o.wall_gaps(); }},
      {Options::CLOSE_MOUTHS, CutStep::kClosing, "MouthOpenings (mouth_sites.h)",
       "beside the doors and gaps: a mouth is a whole open side, which neither finds",
       [](const Options& o) -> const Message* { return &o.mouths(); }},
      {Options::SMALL_ROOM_DISK, CutStep::kRoomDisk, "RoomDisks (room_disks.h)",
       "after every closing: both disks meet the same closed openings, and the rooms it adds "
       "are what the edge cuts read",
       nullptr},
      {Options::KEEP_CLOSED_ROOM_TIPS, CutStep::kEdgeCuts, "PlanEdgeCuts (cut_planning.h)",
       "after the room disk: it reads where the closing sites lie on the edges", nullptr},
      {Options::CUT_NARROW_TAILS, CutStep::kEdgeCuts, "CutNarrowTails (narrow_tails.h)",
       "last: it cuts a room's piece of an edge that the planning made, where the tail begins",
       nullptr},
  };
}

}  // namespace

const std::vector<CutPass>& CutPassTable() {
  static const std::vector<CutPass> table = MakeTable();
  return table;
}

std::string CutPassName(proto::CutOptions::Pass pass) { return proto::CutOptions::Pass_Name(pass); }

bool RunsCutPass(const proto::CutOptions& options, proto::CutOptions::Pass pass) {
  return RunsStagePass(options, pass);
}

double IslandMaxLengthM(const proto::CutOptions& options) {
  return RunsCutPass(options, Options::FREE_STANDING_ISLANDS) ? options.islands().max_length_m()
                                                              : 0;
}

double WallGapMaxWidthM(const proto::CutOptions& options) {
  return RunsCutPass(options, Options::CLOSE_WALL_GAPS) ? options.wall_gaps().max_width_m() : 0;
}

double MouthMaxWidthM(const proto::CutOptions& options) {
  return RunsCutPass(options, Options::CLOSE_MOUTHS) ? options.mouths().max_width_m() : 0;
}

}  // namespace areagraph
