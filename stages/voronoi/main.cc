// ag-voronoi: the Voronoi diagram of a cleaned map's obstacle cells.
#include "stages/common/stage_main.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::kVoronoiStage, argc, argv);
}
