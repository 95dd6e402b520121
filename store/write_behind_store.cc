#include "store/write_behind_store.h"

#include <pthread.h>

#include <condition_variable>
#include <exception>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <utility>

#include "common/error.h"
#include "store/sqlite_connection.h"

namespace areagraph {
namespace {

// What the caller's reads need to know of the artifact being written.
struct PendingArtifact {
  std::string map_name;
  std::string stage;
  std::string cache_key;
  bool versioned = false;
};

// A write handed to the thread: the row, and the serialized payload that
// the thread hashes and compresses.
struct WriteJob {
  NewArtifact artifact;
  SerializedMessage raw;
  // Or, for a big shared message, the message itself and its byte size,
  // serialized by the thread.
  std::shared_ptr<const google::protobuf::MessageLite> message;
  size_t message_bytes = 0;
};

class WriteBehindStore : public ArtifactStore {
 public:
  WriteBehindStore(const std::string& path, size_t serialized_max_bytes)
      : path_(path), serialized_max_bytes_(serialized_max_bytes), store_(OpenArtifactStore(path)) {}

  ~WriteBehindStore() override {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
    writer_.reset();  // before store_, whose close may fold the log
  }

  std::vector<MapRecord> ReadAllMaps() override { return Finished().ReadAllMaps(); }
  std::optional<MapRecord> ReadMap(const std::string& map_name) override {
    return AfterWritesOf(map_name).ReadMap(map_name);
  }
  std::optional<ArtifactRecord> ReadArtifact(const std::string& map_name,
                                             const std::string& cache_key) override {
    return AfterWriteOf(map_name, cache_key).ReadArtifact(map_name, cache_key);
  }
  std::optional<ArtifactRecord> ReadHead(const std::string& map_name,
                                         const std::string& stage) override {
    return AfterWritesOf(map_name).ReadHead(map_name, stage);
  }
  std::vector<ArtifactRecord> ReadArtifactSummaries(const std::string& map_name) override {
    return AfterWritesOf(map_name).ReadArtifactSummaries(map_name);
  }
  std::optional<ArtifactRecord> ReadArtifactSummary(const std::string& map_name,
                                                    const std::string& cache_key) override {
    return AfterWriteOf(map_name, cache_key).ReadArtifactSummary(map_name, cache_key);
  }
  void WriteArtifact(const NewArtifact& artifact) override { Finished().WriteArtifact(artifact); }
  void WriteMessageArtifact(NewArtifact artifact,
                            const google::protobuf::MessageLite& message) override;
  void WriteSharedMessageArtifact(
      NewArtifact artifact, std::shared_ptr<const google::protobuf::MessageLite> message) override;
  void FinishWrites() override { Finished(); }
  void UpdateHead(const std::string& map_name, const std::string& cache_key) override {
    Finished().UpdateHead(map_name, cache_key);
  }

  bool HasArtifact(const std::string& map_name, const std::string& cache_key) override {
    const std::optional<PendingArtifact> pending = Pending();
    if (pending && pending->map_name == map_name && pending->cache_key == cache_key) return true;
    return store_->HasArtifact(map_name, cache_key);  // the pending write adds no other
  }
  std::optional<std::string> ReadHeadKey(const std::string& map_name,
                                         const std::string& stage) override {
    const std::optional<PendingArtifact> pending = Pending();
    if (pending && pending->map_name == map_name && pending->stage == stage) {
      return pending->cache_key;
    }
    return store_->ReadHeadKey(map_name, stage);  // the pending write moves no other head
  }

  std::vector<VersionRecord> ReadVersions(const std::string& map_name) override {
    return (PendingMatches(
                [&](const PendingArtifact& p) { return p.versioned && p.map_name == map_name; })
                ? Finished()
                : *store_)
        .ReadVersions(map_name);
  }
  std::optional<VersionRecord> ReadVersion(const std::string& map_name,
                                           const std::string& cache_key) override {
    return AfterWriteOf(map_name, cache_key).ReadVersion(map_name, cache_key);
  }

  void RecordFailure(const FailureRecord& failure) override { Finished().RecordFailure(failure); }
  void ClearFailure(const std::string& map_name) override { Finished().ClearFailure(map_name); }
  std::vector<FailureRecord> ReadFailures() override { return Finished().ReadFailures(); }

  std::vector<VerifyProblem> Verify(const std::vector<std::string>& file_input_stages,
                                    const std::function<void(int64_t, int64_t)>& progress,
                                    StructureCheck structure) override {
    return Finished().Verify(file_input_stages, progress, structure);
  }
  MaintenanceCounts CollectGarbage() override { return Finished().CollectGarbage(); }
  MaintenanceCounts MergeFrom(const std::string& path) override {
    return Finished().MergeFrom(path);
  }
  bool FoldWriteAheadLog() override { return Finished().FoldWriteAheadLog(); }
  // The thread's connection never folds the log: the caller's closes last.
  void LeaveWriteAheadLogOnClose() override { store_->LeaveWriteAheadLogOnClose(); }
  void BackupTo(const std::string& path) override { Finished().BackupTo(path); }

 private:
  // The caller's store once the pending write is done; throws its error.
  ArtifactStore& Finished();
  // The artifact being written, if any; throws the error of one that failed
  // (its map must not look as if that stage had never run).
  std::optional<PendingArtifact> Pending() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    return pending_;
  }
  // Whether a read must wait for the pending write: `matches` says that
  // write could change its answer, or a write failed (Finished throws it).
  template <typename Matches>
  bool PendingMatches(Matches matches) {
    const std::lock_guard<std::mutex> lock(mutex_);
    return error_ || (pending_ && matches(*pending_));
  }
  ArtifactStore& AfterWritesOf(const std::string& map_name) {
    return PendingMatches([&](const PendingArtifact& p) { return p.map_name == map_name; })
               ? Finished()
               : *store_;
  }
  ArtifactStore& AfterWriteOf(const std::string& map_name, const std::string& cache_key) {
    return PendingMatches([&](const PendingArtifact& p) {
      return p.map_name == map_name && p.cache_key == cache_key;
    })
               ? Finished()
               : *store_;
  }
  // WriteMessageArtifact of a message whose ByteSizeLong is `byte_size`.
  void WriteMessageOfSize(NewArtifact artifact, const google::protobuf::MessageLite& message,
                          size_t byte_size);
  // Waits for the pending write, then makes `job` the pending one.
  void HandOver(WriteJob job);
  void RunWriter();
  void Write(WriteJob& job);

  const std::string path_;
  const size_t serialized_max_bytes_;
  const std::unique_ptr<ArtifactStore> store_;  // the caller's connection
  std::unique_ptr<ArtifactStore> writer_;       // the thread's, opened on its first write

  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<PendingArtifact> pending_;  // from hand-over to commit
  std::optional<WriteJob> job_;             // handed over, not yet taken by the thread
  std::exception_ptr error_;
  bool stopping_ = false;
  std::thread thread_;  // started by the first write
};

ArtifactStore& WriteBehindStore::Finished() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !pending_; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  return *store_;
}

void WriteBehindStore::WriteMessageArtifact(NewArtifact artifact,
                                            const google::protobuf::MessageLite& message) {
  WriteMessageOfSize(std::move(artifact), message, message.ByteSizeLong());
}

void WriteBehindStore::WriteMessageOfSize(NewArtifact artifact,
                                          const google::protobuf::MessageLite& message,
                                          size_t byte_size) {
  if (byte_size > serialized_max_bytes_) {
    Finished();  // the previous artifact is in the store before this one
    artifact.encoded_payload = EncodeMessagePayload(message, byte_size);
    store_->WriteArtifact(artifact);
    return;
  }
  // Serialized here, the one step that reads `message`: the caller may
  // change or free it as soon as this returns.
  HandOver(WriteJob{std::move(artifact), SerializeMessage(message, byte_size)});
}

void WriteBehindStore::WriteSharedMessageArtifact(
    NewArtifact artifact, std::shared_ptr<const google::protobuf::MessageLite> message) {
  const size_t byte_size = message->ByteSizeLong();
  if (byte_size <= serialized_max_bytes_) {
    WriteMessageOfSize(std::move(artifact), *message, byte_size);
    return;
  }
  // The thread streams it as a direct write would, holding no serialized
  // copy beside the message (whose sizes are cached above, before the
  // hand-over): the next stage computes meanwhile.
  WriteJob job{std::move(artifact), SerializedMessage(), std::move(message), byte_size};
  HandOver(std::move(job));
}

void WriteBehindStore::HandOver(WriteJob job) {
  Finished();  // the previous artifact is in the store before this one starts
  PendingArtifact pending{job.artifact.map_name, job.artifact.stage, job.artifact.cache_key,
                          job.artifact.version.has_value()};
  // Before anything is pending: a thread that cannot start throws here.
  if (!thread_.joinable()) thread_ = std::thread([this] { RunWriter(); });
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    pending_ = std::move(pending);
    job_ = std::move(job);
  }
  changed_.notify_all();
}

void WriteBehindStore::RunWriter() {
  pthread_setname_np(pthread_self(), "ag-store-writer");  // for top and perf; 15 characters
  while (true) {
    std::optional<WriteJob> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return job_ || stopping_; });
      if (!job_) return;
      job = std::exchange(job_, std::nullopt);
    }
    std::exception_ptr error;
    try {
      Write(*job);
    } catch (const std::bad_alloc&) {
      error = std::make_exception_ptr(
          MapStepError(job->artifact.map_name, job->artifact.stage, "out of memory"));
    } catch (const std::exception& failure) {
      error = std::make_exception_ptr(
          MapStepError(job->artifact.map_name, job->artifact.stage, failure.what()));
    }
    job.reset();  // its memory goes before the caller hears
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      pending_.reset();
      if (error && !error_) error_ = error;
    }
    changed_.notify_all();
  }
}

void WriteBehindStore::Write(WriteJob& job) {
  if (job.message) {
    job.artifact.encoded_payload = EncodeMessagePayload(*job.message, job.message_bytes);
    job.message.reset();  // its last holder may free it before the insert
  } else {
    job.artifact.encoded_payload = EncodeRawPayload(job.raw.view());
    job.raw = SerializedMessage();  // not held through the insert
  }
  if (!writer_) {
    writer_ = OpenArtifactStore(path_);
    // The caller's connection closes last and folds the log, or leaves it.
    writer_->LeaveWriteAheadLogOnClose();
  }
  writer_->WriteArtifact(job.artifact);
}

}  // namespace

std::unique_ptr<ArtifactStore> OpenWriteBehindStore(const std::string& path,
                                                    size_t serialized_max_bytes) {
  if (path == kMemoryStorePath) return OpenArtifactStore(path);
  return std::make_unique<WriteBehindStore>(path, serialized_max_bytes);
}

}  // namespace areagraph
