#pragma once

namespace areagraph {

// The shape that tells a piece of wall standing between two doors from
// furniture standing free. ag-clean keeps such pieces (clean pass
// KEEP_WALL_PIECES); ag-cut keeps them as structure for the room disk
// (cut pass FREE_STANDING_ISLANDS) and takes them as door jambs (cut pass
// CLOSE_WALL_GAPS). How thick each is: stages/geometry/wall_thickness.h.

// A wall runs on: a piece of wall is at least this many times as long as
// wide, a desk or a cabinet is squarer.
inline constexpr double kWallPieceElongation = 3.0;
// A piece of wall is at least this long (metres, bounding box): shorter
// specks are noise, not the wall between two doors. 0.5 and 1 m gave the same
// means on bormann/ and the generated offices, 2 m lost (as ag-cut's short
// wall tips beside a wall gap).
inline constexpr double kMinWallPieceM = 0.5;
// The gap past each end of a piece of wall is at most a door's (metres).
inline constexpr double kWallPieceGapM = 1.6;
// Furniture fills at least this share of its smallest enclosing rectangle
// (a desk or a cabinet all of it, an L of two about half to three
// quarters); a piece of wall with a T or an L and a cabinet against it does
// not. ag-merge's furniture islands use the same share.
inline constexpr double kMinFurnitureSolidity = 0.75;

}  // namespace areagraph
