#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// The depth of every non-free cell (occupied or unknown): its distance (px)
// to the nearest free cell, as CV_32F the map's size; 0 on free cells.
cv::Mat ObstacleDepth(const std::string& cells, int width, int height);

// The typical thickness of a map's walls (px): the median, over the ridge
// cells of `depth` (those at least as deep as all 8 neighbours), of twice
// their depth, leaving out ridges thicker than `max_wall_px` (the unknown
// space around the map). 0 when there is none.
double TypicalWallThickness(const cv::Mat& depth, double max_wall_px);

// Walls are thinner than this (metres): thicker ridges of non-free cells are
// unknown space, not walls, when the typical wall thickness is measured.
inline constexpr double kMaxWallThicknessM = 1.0;

}  // namespace areagraph
