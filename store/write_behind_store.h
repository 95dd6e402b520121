#pragma once

#include <memory>
#include <string>

#include "store/artifact_store.h"

namespace areagraph {

// Opens a store whose WriteMessageArtifact returns once the message is
// serialized: hashing, compressing and the insert happen on a thread of the
// store's own, over a second SQLite connection, while the caller computes
// the next stage (ag-run's workers, ag-pipeline). At most one artifact is
// pending: the next write, and every read that the pending one could change,
// waits for it; the head key and HasArtifact of the pending artifact itself
// are answered without waiting. Each artifact is still one transaction of
// its own, in the order they were handed over, so a process killed meanwhile
// leaves the store as a run killed before that write would: consistent,
// without the pending artifact.
//
// A failed write is thrown, as a MapStepError naming the artifact's map and
// stage, by the next call that waits for it (FinishWrites, the next write,
// or such a read), once; the artifacts handed over after it are dropped
// unwritten. ":memory:" stores, which a second connection cannot share, are
// opened as OpenArtifactStore does (every write in the caller's thread).
std::unique_ptr<ArtifactStore> OpenWriteBehindStore(const std::string& path);

}  // namespace areagraph
