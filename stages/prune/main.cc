// ag-prune: the Topology Graph with polygons from a map's Voronoi diagram.
#include "stages/common/stage_main.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::kPruneStage, argc, argv);
}
