#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace areagraph {

// Decodes the plainest PNGs (8-bit grey, grey + alpha, RGB or RGBA, not
// interlaced, no chunk besides IHDR, IDAT, IEND, pHYs, tIME, bKGD, sBIT and
// text: nothing that bears on colour) to 8-bit grey itself, with zlib and
// its own unfiltering, to the pixels libpng's rgb_to_gray gives there
// (DecodeCommonPngToGrey): libpng unfilters the Paeth rows of RGB images a
// byte at a time, for 40 % of ag-import. Returns false, leaving `grey`
// empty, for anything else or anything wrong (a chunk's CRC, the data's
// length): the caller then asks libpng, which also words the errors.
bool DecodePlainPngToGrey(const std::string& bytes, cv::Mat* grey);

}  // namespace areagraph
