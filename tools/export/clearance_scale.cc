#include "tools/export/clearance_scale.h"

#include <cstdio>
#include <iterator>

namespace areagraph {
namespace {

// "0.15": a band limit as its label shows it.
std::string LimitText(double metres) {
  char text[16];
  std::snprintf(text, sizeof(text), "%g", metres);
  return text;
}

// Band 0 faint; the others from red to blue by equal steps of hue.
std::vector<ClearanceBand> MakeBands() {
  std::vector<ClearanceBand> bands = {{"#f3d9e6", "hugs an obstacle (< 2 px)"}};
  const int count = static_cast<int>(std::size(kClearanceBandLimitsM)) + 1;
  for (int i = 0; i < count; ++i) {
    // Hue from red (0) to blue (240) through yellow and green.
    const int hue = 240 * i / (count - 1);
    char colour[32];
    std::snprintf(colour, sizeof(colour), "hsl(%d,85%%,%d%%)", hue, i == 0 ? 45 : 42);
    const std::string low = i == 0 ? "0" : LimitText(kClearanceBandLimitsM[i - 1]);
    const std::string label = i + 1 == count
                                  ? "over " + low + " m"
                                  : low + "-" + LimitText(kClearanceBandLimitsM[i]) + " m";
    bands.push_back({colour, label});
  }
  return bands;
}

}  // namespace

const std::vector<ClearanceBand>& ClearanceBands() {
  static const std::vector<ClearanceBand> bands = MakeBands();
  return bands;
}

int ClearanceBandOf(double clearance_px, double resolution_m) {
  if (clearance_px < kHuggingClearancePx) return 0;
  const double metres = clearance_px * resolution_m;
  int band = 1;
  for (const double limit : kClearanceBandLimitsM) {
    if (metres < limit) return band;
    ++band;
  }
  return band;
}

}  // namespace areagraph
