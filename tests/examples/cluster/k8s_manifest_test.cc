// examples/cluster's Kubernetes manifests. No cluster can run here (no image
// can be pulled), so they are checked the way far as can be without one: the
// fields against the Kubernetes API objects, the values the scripts depend on,
// and each container's command run as the pod would run it, with the volume
// replaced by a temporary folder.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <regex>

#include "tests/examples/cluster/kubernetes_schema.h"
#include "tests/support/raw_sqlite.h"
#include "tests/support/test_support.h"
#include "tools/example_maps/random_floor_plan.h"

namespace areagraph::testing {
namespace {

// Heads per map after a whole run: import, clean, voronoi, prune, cut, merge, match.
constexpr int kStagesPerMap = 7;

YAML::Node Manifest(const std::string& name) {
  return YAML::LoadFile(SourcePath("examples/cluster/" + name));
}

YAML::Node Container(const YAML::Node& job) {
  return job["spec"]["template"]["spec"]["containers"][0];
}

// The value of environment variable `name` in the container, "" if unset.
std::string EnvValue(const YAML::Node& container, const std::string& name) {
  for (const auto& variable : container["env"]) {
    if (variable["name"].as<std::string>() == name) return variable["value"].as<std::string>();
  }
  return "";
}

// Runs the container's command as the pod would, with `mount` (the volume's
// mount path) standing for `folder` and `env` added to the environment.
CommandResult RunContainer(const YAML::Node& container, const std::string& folder,
                           std::vector<std::string> env) {
  const std::string mount = container["volumeMounts"][0]["mountPath"].as<std::string>();
  std::vector<std::string> argv = {"env", "-i",
                                   "PATH=" + std::string(AG_BIN_DIR) + ":/usr/bin:/bin"};
  argv.insert(argv.end(), env.begin(), env.end());
  for (const auto& word : container["command"]) argv.push_back(word.as<std::string>());
  for (const auto& word : container["args"]) {
    std::string arg = word.as<std::string>();
    for (size_t at = arg.find(mount + "/"); at != std::string::npos;
         at = arg.find(mount + "/", at + folder.size())) {
      arg.replace(at, mount.size(), folder);
    }
    argv.push_back(arg);
  }
  return RunProgram(argv);
}

TEST(KubernetesManifestTest, FieldsAreThoseOfTheKubernetesObjects) {
  for (const char* name : {"k8s-indexed-job.yaml", "k8s-index-job.yaml", "k8s-merge-job.yaml"}) {
    const std::vector<std::string> problems = CheckKubernetesJob(Manifest(name));
    EXPECT_TRUE(problems.empty()) << name << ": " << ::testing::PrintToString(problems);
  }
}

TEST(KubernetesManifestTest, SchemaCheckFindsTheUsualMistakes) {
  const auto problems_after = [](const std::function<void(YAML::Node&)>& edit) {
    YAML::Node job = Manifest("k8s-indexed-job.yaml");
    edit(job);
    return ::testing::PrintToString(CheckKubernetesJob(job));
  };
  EXPECT_NE(problems_after([](YAML::Node& job) {
              job["spec"]["completionmode"] = "Indexed";
            }).find(".spec.completionmode is not a field of JobSpec"),
            std::string::npos);
  EXPECT_NE(problems_after([](YAML::Node& job) {
              Container(job)["env"][0]["value"] = YAML::Load("8");
            }).find(".env[0].value must be a string"),
            std::string::npos);
  EXPECT_NE(problems_after([](YAML::Node& job) {
              job["spec"]["template"]["spec"]["restartPolicy"] = "Always";
            }).find("must be Never or OnFailure"),
            std::string::npos);
  EXPECT_NE(problems_after([](YAML::Node& job) {
              job["spec"]["completions"] = "eight";
            }).find(".spec.completions must be a non-negative integer"),
            std::string::npos);
  EXPECT_NE(problems_after([](YAML::Node& job) {
              Container(job).remove("image");
            }).find(".image is required in Container"),
            std::string::npos);
  EXPECT_NE(problems_after([](YAML::Node& job) {
              Container(job)["volumeMounts"][0]["name"] = "scratch";
            }).find("volume mount scratch names no volume"),
            std::string::npos);
}

TEST(KubernetesManifestTest, ShardCountAndVolumeAgreeBetweenTheJobs) {
  const YAML::Node shards = Manifest("k8s-indexed-job.yaml");
  EXPECT_EQ(shards["spec"]["completionMode"].as<std::string>(), "Indexed");
  // Each completion index is one shard, so SHARDS must equal completions.
  EXPECT_EQ(EnvValue(Container(shards), "SHARDS"), shards["spec"]["completions"].as<std::string>());
  const auto claim = [](const YAML::Node& job) {
    return job["spec"]["template"]["spec"]["volumes"][0]["persistentVolumeClaim"]["claimName"]
        .as<std::string>();
  };
  for (const char* name : {"k8s-index-job.yaml", "k8s-merge-job.yaml"}) {
    const YAML::Node step = Manifest(name);
    EXPECT_EQ(claim(shards), claim(step)) << name;
    EXPECT_EQ(Container(shards)["volumeMounts"][0]["mountPath"].as<std::string>(),
              Container(step)["volumeMounts"][0]["mountPath"].as<std::string>())
        << name;
  }
}

TEST(KubernetesManifestTest, ContainerCommandsShardAndIndexOrMergeLikeOneRun) {
  TempDir dir;
  const std::string data = dir.File("data");
  std::filesystem::create_directories(data + "/maps");
  for (unsigned seed = 21; seed < 25; ++seed) {
    floorplan::WritePlanPng(floorplan::RandomOfficePlan(seed),
                            data + "/maps/map_" + std::to_string(seed) + ".png");
  }
  const YAML::Node shards = Container(Manifest("k8s-indexed-job.yaml"));
  const int count = Manifest("k8s-indexed-job.yaml")["spec"]["completions"].as<int>();
  for (int index = 0; index < count; ++index) {
    const CommandResult pod = RunContainer(
        shards, data,
        {"JOB_COMPLETION_INDEX=" + std::to_string(index), "SHARDS=" + EnvValue(shards, "SHARDS")});
    ASSERT_EQ(pod.exit_code, 0) << "index " << index << ": " << pod.err;
    const std::string shard = data + "/stores/shard-" + std::to_string(index) + ".db";
    EXPECT_NE(pod.out.find("checked " + std::to_string(HeadDigests(shard).size()) +
                           " artifacts: no problems"),
              std::string::npos)
        << "each pod verifies its shard: " << pod.out;
  }
  ASSERT_EQ(RunTool("ag-run", {"--store", dir.File("whole.db"), data + "/maps"}).exit_code, 0);
  EXPECT_EQ(HeadDigests(dir.File("whole.db")).size(), static_cast<size_t>(4 * kStagesPerMap));
  const std::string checked =
      "checked " + std::to_string(4 * kStagesPerMap) + " artifacts: no problems";

  // The merge, on a copy of the volume: both write stores/collection.db.
  const std::string copy = dir.File("copy");
  std::filesystem::copy(data, copy, std::filesystem::copy_options::recursive);
  const CommandResult merge = RunContainer(Container(Manifest("k8s-merge-job.yaml")), copy, {});
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  EXPECT_NE(merge.out.find(checked), std::string::npos) << merge.out;
  const std::regex timed(R"(\ncollection: \d+\.\d\d s\n)");
  EXPECT_TRUE(std::regex_search(merge.out, timed)) << merge.out;
  EXPECT_EQ(HeadDigests(copy + "/stores/collection.db"), HeadDigests(dir.File("whole.db")));

  const CommandResult index = RunContainer(Container(Manifest("k8s-index-job.yaml")), data, {});
  ASSERT_EQ(index.exit_code, 0) << index.err;
  EXPECT_TRUE(std::regex_search(index.out, std::regex(R"(indexed \d+ shard stores \(4 maps, )")))
      << index.out;
  EXPECT_EQ(RunTool("ag-store", {"verify", "--store", data + "/stores/collection.db"}).out,
            checked + "\n");
  EXPECT_TRUE(std::regex_search(index.out, timed)) << index.out;
  EXPECT_EQ(StoreHeadDigests(data + "/stores/collection.db"), HeadDigests(dir.File("whole.db")));
}

}  // namespace
}  // namespace areagraph::testing
