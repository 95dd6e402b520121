#pragma once

#include <string>

namespace areagraph {

// The PNG of a bare map (ag-render's import picture): the canvas's greys of
// `cells` (CellState bytes, row by row; missing cells unknown) at `scale`
// pixels per cell, written from the cells directly. The same pixels as a
// Canvas's greys through WriteGreyPngFileAsColour, and the same palette (the
// greys in the order they first appear, 1 or 2 bits per pixel), without the
// grey picture, its palette indices and libpng's packing of them: those
// were a third of lab_a's import picture. Compressed for runs (zlib's Z_RLE). Throws Error when
// libpng fails.
std::string EncodeMapPng(const std::string& cells, int width, int height, int scale);

}  // namespace areagraph
