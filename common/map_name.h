#pragma once

#include <string>

namespace areagraph {

// The one rule for map names, wherever a name enters (ag-import, ag-run's
// folders and manifests, ag-live's and ag-listen's LCM messages): 1 to 256
// bytes of UTF-8, without blanks or control characters; '/' separates
// folders (ag-run names the maps of a folder by their path in it, and
// reports write a page per map under that path), so no part may be empty,
// '.' or '..', and the name may not start or end with '/'. Throws InputError
// saying what is wrong, e.g. "map name 'a b' holds a blank".
void CheckMapName(const std::string& name);

}  // namespace areagraph
