#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "store/artifact_store.h"

namespace areagraph {

// The largest serialized artifact handed to the thread. The hand-over holds
// the serialized bytes besides the message (the stream of a direct write
// holds neither), and for big maps that is the peak: lab_a tiled 8 x 8 went
// from 576 to 614-635 MB with its 101-MB Voronoi diagram written behind.
// Every artifact of areagraph/input's 16 maps is under 6 MB.
inline constexpr size_t kWriteBehindMaxBytes = size_t{32} << 20;

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
// A payload over `serialized_max_bytes` is written in the caller's thread,
// streamed as OpenArtifactStore's store does, unless it comes through
// WriteSharedMessageArtifact: then the thread holds the message itself and
// streams it (no serialized copy), so the caller must not change the message
// until FinishWrites or its shared_ptr shows no other holder.
//
// A failed write is thrown, as a MapStepError naming the artifact's map and
// stage, by the next call that waits for it (FinishWrites, the next write,
// or such a read), once; the artifacts handed over after it are dropped
// unwritten. ":memory:" stores, which a second connection cannot share, are
// opened as OpenArtifactStore does (every write in the caller's thread).
// (Tests pass a smaller `serialized_max_bytes` to take that way with small maps.)
std::unique_ptr<ArtifactStore> OpenWriteBehindStore(
    const std::string& path, size_t serialized_max_bytes = kWriteBehindMaxBytes);

}  // namespace areagraph
