#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// 255 on every non-free cell (occupied or unknown) and 0 on free cells, as
// CV_8U the map's size: the input of OpenCV's labelling and distance
// transform.
cv::Mat ObstacleMask(const std::string& cells, int width, int height);

// The depth of every non-free cell of an ObstacleMask: its distance (px) to
// the nearest free cell, as CV_32F the map's size; 0 on free cells.
cv::Mat ObstacleDepth(const cv::Mat& obstacle);

// The typical thickness of a map's walls (px): the median, over the ridge
// cells of `depth` (those at least as deep as all 8 neighbours), of twice
// their depth, leaving out ridges thicker than `max_wall_px` (the unknown
// space around the map). 0 when there is none.
double TypicalWallThickness(const cv::Mat& depth, double max_wall_px);

// A wall is at most this thick (metres): inner walls are 0.1-0.3 m, most
// outer walls under half a metre. So a wall end beside a door or a mouth
// (ag-cut) is at most this thick across the opening's line, and thicker
// ridges of non-free cells are unknown space or blocks, not walls, when the
// typical wall thickness is measured.
inline constexpr double kMaxWallThicknessM = 0.6;

// Furniture (desks, cabinets, shelves) is at least this thick (metres) and
// kFurnitureWallRatio times the map's typical wall thickness; a lone piece of
// wall between two doors, and noise, are thinner. ag-clean keeps thinner
// pieces as walls, ag-merge takes only thicker islands for furniture.
inline constexpr double kMinFurnitureThicknessM = 0.3;
// Twice a wall: a drawn or scanned wall varies by a cell or two, furniture
// stands clearly thicker.
inline constexpr double kFurnitureWallRatio = 2.0;

// A scan misses at most this share of a wall's cells (a few cells here and
// there); a frontier of unknown space runs along a whole side instead. So a
// room's walls face unknown cells along at most this share
// (stages/merge/closed_rooms.h), and a flat wall face shows in all but this
// share of the points along it (stages/merge/one_sided_narrowing.h).
inline constexpr double kMissedWallShare = 0.1;

}  // namespace areagraph
