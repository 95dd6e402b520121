// ag-cut: rooms from alpha shapes, and the Topology Graph's edges cut at them.
#include "stages/common/stage_main.h"

int main(int argc, char** argv) {
  return areagraph::RunStageMain(areagraph::kCutStage, argc, argv);
}
