// ag-clean: outlier and furniture removal on an imported grid map.
#include "stages/common/stage_main.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::kCleanStage, argc, argv);
}
