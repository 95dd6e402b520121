#pragma once

#include <string>
#include <vector>

namespace areagraph {

// Step (a) of the paper's preprocessing: CGAL's remove_outliers over the
// centres of all occupied cells (at most `percent` % of them, k neighbours),
// computed on the grid: FindOutlierCandidates gives exactly the cells whose
// remove_outliers score reaches the threshold, with that score (tests compare
// it with CGAL's FindOutlierPoints); when more than `percent` % reach it,
// the highest scores win, ties going to the earlier cell.
// What it finds only becomes free where that cannot change the map's
// structure, checked cell by cell in row-major order on the updated grid:
// - the cell is occupied and has free 8-neighbours;
// - none of its 8 neighbours is unknown or outside the image, so the outline
//   of unexplored space stays closed;
// - its free neighbours form one run around it (or all 8 are free), so freeing
//   it cannot join two free regions, i.e. punch a hole through a wall.
// Points at least as dense as a straight one-pixel wall never count as
// outliers, so clean maps lose no wall cells to the percentage.
// Returns the freed flat cell indices in increasing order.
std::vector<int> RemoveOutlierCells(std::string& cells, int width, int height, int neighbors,
                                    double percent);

// The mean squared distance from a point inside an endless straight one-pixel
// line to its `neighbors` nearest points of the line, itself included. (The
// remove_outliers score with k neighbours averages over k + 1 points.)
double StraightWallScore(int neighbors);

}  // namespace areagraph
