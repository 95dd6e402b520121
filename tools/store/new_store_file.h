#pragma once

#include <functional>
#include <string>

namespace areagraph {

// Creates the store file `path`, which must not exist yet: `fill` writes a
// store at a temporary path beside it (and closes it), which is then linked
// into place. So `path` appears only complete, a failure leaves nothing (the
// temporary and its -wal and -shm are removed), and a file that appears at
// `path` meanwhile is not replaced. The temporary is the hidden
// ".NAME.HOST.PID.tmp"; those of earlier runs for `path` on this host whose
// process is gone (killed) are removed first. Throws StoreError when `path` exists or
// cannot be created, and whatever `fill` throws.
void CreateStoreFile(const std::string& path,
                     const std::function<void(const std::string& temporary)>& fill);

// True when nothing (not even a link to nothing) exists at `path`.
bool NothingAt(const std::string& path);

}  // namespace areagraph
