// ag-merge: the Area Graph from a map's cut graph.
#include "stages/common/stage_main.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::kMergeStage, argc, argv);
}
