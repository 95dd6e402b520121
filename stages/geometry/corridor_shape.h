#pragma once

namespace areagraph {

// What a corridor is, for every stage that asks (ag-cut's narrow tails,
// ag-merge's passes and the areas' kinds). A space's width profile is the
// free width along its middle (twice the distance to the nearest obstacle);
// it is shaped like a corridor when
// - its typical width (the profile's median) is at most kMaxCorridorWidthM,
//   and
// - it covers at least kCorridorElongation squares of its widest width: it
//   is long even against its widest spot, where a room, however cluttered
//   or oddly cut, is about as long as wide.
// A corridor of even width w and length l covers l / w squares of it.

// "An indoor corridor is hardly wider than 4 m" (the paper, on the range of
// W): a wider space is a hall.
inline constexpr double kMaxCorridorWidthM = 4.0;
// Rooms and halls are squarer: a room 2.5 m wide and 8 m long is one of the
// narrowest offices; a corridor runs past several of them.
inline constexpr double kCorridorElongation = 4.0;
// One corridor is about as wide everywhere: the median free widths of two
// pieces of it differ by at most this factor, and no width along it or where
// its pieces meet is narrower than its median over this factor (a cabinet
// or a pillar narrows it by a fifth or so; a side branch, a room off it or a
// door is clearly narrower or wider).
inline constexpr double kCorridorWidthRatio = 1.3;

// Whether a free width `width` narrows a corridor whose median free width is
// `median`: it is narrower than one corridor's width varies
// (kCorridorWidthRatio). Nothing narrows along a piece of corridor, and two
// pieces of one corridor, or a branch and its corridor, do not narrow where
// they meet; a door is narrower than the corridor or room it opens from.
inline bool NarrowsCorridor(double width, double median) {
  return width * kCorridorWidthRatio < median;
}

// How many squares of `width` a space of `area` covers (0 without a width).
inline double Elongation(double width, double area) {
  return width > 0 ? area / (width * width) : 0;
}

// Whether a space whose width profile has median `typical_px` and maximum
// `widest_px`, covering `area_px` (pixels of `resolution_m` metres), is
// shaped like a corridor.
inline bool IsCorridorShaped(double typical_px, double widest_px, double area_px,
                             double resolution_m) {
  return typical_px > 0 && typical_px * resolution_m <= kMaxCorridorWidthM &&
         Elongation(widest_px, area_px) >= kCorridorElongation;
}

}  // namespace areagraph
