// ag-match: stable ids for a map's head AreaGraph, matched to its previous version.
#include "stages/common/stage_main.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::kMatchStage, argc, argv);
}
