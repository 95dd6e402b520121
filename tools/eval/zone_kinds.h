#pragma once

#include <map>
#include <optional>
#include <string>

#include "tools/eval/zone_overlaps.h"

namespace areagraph {

// The kind of each zone of a label image ("room", "corridor" or
// "dead_end"), by label.
using ZoneKinds = std::map<int, std::string>;

// The kinds file that goes with a label image: "<stem>.kinds.tsv" beside
// it (ag-export --format kinds writes one for a result, ag-make-benchmark
// one for each ground truth).
std::string KindsPathFor(const std::string& image_path);

// Reads a kinds file: a header line "label<TAB>kind", then one line per
// zone. Throws InputError for a malformed line or an unknown kind.
ZoneKinds ReadZoneKinds(const std::string& path);

// The share of the result's scored area whose kind is the kind of the GT
// zone it overlaps most (each result zone counted with its scored pixels),
// over the result zones that have a kind and overlap a GT zone that has
// one. A dead end in a GT corridor counts as right: the GT draws a corridor
// with its blind branches as one zone. Unset when no zone counts.
std::optional<double> KindAccuracy(const ZoneOverlaps& counts, const ZoneKinds& result,
                                   const ZoneKinds& gt);

}  // namespace areagraph
