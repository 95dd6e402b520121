// Processes that die mid-write, and processes that write at the same time.

#include <google/protobuf/wrappers.pb.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>
#include <thread>

#include "store/artifact_store.h"
#include "store/write_behind_store.h"
#include "tests/support/test_support.h"

namespace areagraph {
namespace {

constexpr char kMap[] = "crash";
constexpr int kSlots = 4;

// The payload of generation g, as a message for WriteMessageArtifact.
google::protobuf::BytesValue GenerationMessage(int64_t generation) {
  // Large enough that a write spans many pages and takes a while.
  const size_t size = 512 * 1024 + (generation % 7) * 65536;
  std::string bytes(size, '\0');
  for (size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((generation * 131 + i * 7) & 0xff);
  google::protobuf::BytesValue message;
  message.set_value(bytes);
  return message;
}

// Generation g goes to slot g % 4 and stage "even"/"odd"; every field is a
// function of g, so a row mixing two writes can be recognized.
NewArtifact GenerationArtifact(int64_t generation) {
  NewArtifact artifact;
  artifact.map_name = kMap;
  artifact.stage = generation % 2 == 0 ? "even" : "odd";
  artifact.cache_key = "slot-" + std::to_string(generation % kSlots);
  artifact.input_keys = {"generation-" + std::to_string(generation), "fixed"};
  artifact.options_text = std::to_string(generation);
  artifact.stage_version = static_cast<int>(generation % 1000);
  artifact.proto_type = "test.Generation";
  artifact.payload = GenerationMessage(generation).SerializeAsString();
  artifact.elapsed_ms = static_cast<double>(generation);
  return artifact;
}

// Runs in a forked child: writes generations [first, first + count) and
// exits 0, or prints the error and exits 1. Never returns. `behind`: through
// a write-behind store, which writes each on its thread while the next is
// made.
[[noreturn]] void WriteGenerations(const std::string& path, int64_t first, int64_t count,
                                   bool behind = false) {
  int exit_code = 0;
  try {
    std::unique_ptr<ArtifactStore> store =
        behind ? OpenWriteBehindStore(path) : OpenArtifactStore(path);
    for (int64_t g = first; g < first + count; ++g) {
      if (behind) {
        store->WriteMessageArtifact(GenerationArtifact(g), GenerationMessage(g));
      } else {
        store->WriteArtifact(GenerationArtifact(g));
      }
    }
    store->FinishWrites();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "writer: %s\n", error.what());
    exit_code = 1;
  }
  _exit(exit_code);
}

// Checks that the store holds exactly the state after some whole number of
// generations: the last min(4, n) generations, each row intact, and each
// stage's head on its newest generation. Sets `latest` to that generation
// (-1 for none).
void ExpectWholeGenerations(const std::string& path, int64_t* latest) {
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  std::set<int64_t> generations;
  std::map<std::string, int64_t> newest_of_stage;
  for (const ArtifactRecord& summary : store->ReadArtifactSummaries(kMap)) {
    const std::optional<ArtifactRecord> artifact = store->ReadArtifact(kMap, summary.cache_key);
    ASSERT_TRUE(artifact);
    const int64_t g = std::stoll(artifact->options_text);
    const NewArtifact expected = GenerationArtifact(g);
    EXPECT_EQ(artifact->cache_key, expected.cache_key);
    EXPECT_EQ(artifact->stage, expected.stage);
    EXPECT_EQ(artifact->input_keys, expected.input_keys);
    EXPECT_EQ(artifact->stage_version, expected.stage_version);
    EXPECT_EQ(artifact->elapsed_ms, expected.elapsed_ms);
    EXPECT_TRUE(artifact->payload == expected.payload) << "payload of generation " << g;
    EXPECT_EQ(summary.payload_bytes, static_cast<int64_t>(expected.payload.size()));
    generations.insert(g);
    newest_of_stage[expected.stage] = std::max(newest_of_stage[expected.stage], g);
  }
  *latest = generations.empty() ? -1 : *generations.rbegin();
  std::set<int64_t> expected_generations;
  for (int64_t g = std::max<int64_t>(0, *latest - kSlots + 1); g <= *latest; ++g) {
    expected_generations.insert(g);
  }
  EXPECT_EQ(generations, expected_generations);
  for (const auto& [stage, newest] : newest_of_stage) {
    const std::optional<ArtifactRecord> head = store->ReadHead(kMap, stage);
    ASSERT_TRUE(head) << stage;
    EXPECT_EQ(std::stoll(head->options_text), newest) << stage;
    EXPECT_TRUE(head->is_head);
  }
}

// SIGKILL at varied moments, including while the store file is first being
// created; after each kill the store must open and hold whole writes only.
void KillWritersAtVariedMoments(bool behind) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  std::mt19937 random(20240601);  // fixed: the same delays on every run
  std::uniform_int_distribution<int> delay_ms(0, 60);
  int64_t latest = -1;
  for (int round = 0; round < 20; ++round) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) WriteGenerations(path, latest + 1, 1000000, behind);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
    kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "writer failed before the kill, round " << round;

    const int64_t before = latest;
    ExpectWholeGenerations(path, &latest);
    if (::testing::Test::HasFailure()) FAIL() << "after the kill of round " << round;
    EXPECT_GE(latest, before) << "a committed write was lost";
  }
  // A writer that is not killed finishes, and the store moves on from there.
  const int64_t before = latest;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) WriteGenerations(path, latest + 1, 5, behind);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  ExpectWholeGenerations(path, &latest);
  EXPECT_EQ(latest, before + 5);
}

TEST(StoreCrashTest, KilledWriterLeavesOldOrNewStateOnly) { KillWritersAtVariedMoments(false); }

// The same with the write pending on the store's thread (ag-run's workers):
// whole generations only, in order, none after a missing one.
TEST(StoreCrashTest, KilledWriteBehindStoreLeavesWholeWritesInOrder) {
  KillWritersAtVariedMoments(true);
}

// Runs in a forked child: writes `count` artifacts of its own stage.
[[noreturn]] void WriteOwnStage(const std::string& path, int writer, int count) {
  int exit_code = 0;
  try {
    std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
    for (int i = 0; i < count; ++i) {
      NewArtifact artifact;
      artifact.map_name = "shared";
      artifact.stage = "writer" + std::to_string(writer);
      artifact.cache_key = "w" + std::to_string(writer) + "-" + std::to_string(i);
      artifact.payload = std::string(64 * 1024, static_cast<char>('a' + i % 26));
      artifact.source_path = "/from/writer" + std::to_string(writer);
      store->WriteArtifact(artifact);
      if (i % 5 == 2) store->UpdateHead("shared", "w" + std::to_string(writer) + "-0");
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "writer %d: %s\n", writer, error.what());
    exit_code = 1;
  }
  _exit(exit_code);
}

// Both processes also race to create the file; busy_timeout and BEGIN
// IMMEDIATE must queue them rather than fail.
TEST(StoreCrashTest, ConcurrentWritersBothSucceed) {
  testing::TempDir dir;
  const std::string path = dir.File("store.db");
  constexpr int kWriters = 2, kCount = 30;
  std::vector<pid_t> children;
  for (int writer = 0; writer < kWriters; ++writer) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) WriteOwnStage(path, writer, kCount);
    children.push_back(child);
  }
  for (pid_t child : children) {
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a writer failed";
  }
  std::unique_ptr<ArtifactStore> store = OpenArtifactStore(path);
  const std::vector<ArtifactRecord> summaries = store->ReadArtifactSummaries("shared");
  EXPECT_EQ(summaries.size(), static_cast<size_t>(kWriters * kCount));
  for (const ArtifactRecord& summary : summaries) {
    const std::optional<ArtifactRecord> artifact = store->ReadArtifact("shared", summary.cache_key);
    ASSERT_TRUE(artifact);
    EXPECT_EQ(artifact->payload_bytes, 64 * 1024);
  }
  for (int writer = 0; writer < kWriters; ++writer) {
    const std::string w = "w" + std::to_string(writer);
    EXPECT_EQ(store->ReadHead("shared", "writer" + std::to_string(writer))->cache_key,
              w + "-" + std::to_string(kCount - 1));
  }
  EXPECT_EQ(store->ReadAllMaps().size(), 1u);
}

}  // namespace
}  // namespace areagraph
