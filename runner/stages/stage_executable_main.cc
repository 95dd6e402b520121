// ag-clean, ag-voronoi, ag-prune, ag-cut, ag-merge and ag-match: one stage of
// the stage table, the one whose name the build gives (AG_STAGE).
#include "runner/stages/stage_main.h"
#include "stages/pipeline/stage_table.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::FindStage(AG_STAGE).info, argc, argv);
}
