#pragma once

namespace areagraph {

// What `--version` prints: the project version and the `git describe` of the
// checkout it was built from ("areagraph 0.1.0 (a658929-dirty)").
const char* VersionText();

}  // namespace areagraph
