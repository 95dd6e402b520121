#include "tools/eval/evaluation_report.h"

#include <google/protobuf/util/json_util.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "common/error.h"
#include "tools/eval/evaluation_report.pb.h"

namespace areagraph {

namespace {

std::string Fixed3(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f", value);
  return text;
}

std::string OffsetText(const MapEvaluation& map) {
  return std::to_string(map.gt_offset.x) + "," + std::to_string(map.gt_offset.y);
}

struct Summary {
  double mcc, precision, recall;
  std::optional<double> kind_accuracy;
};

// Mean (or median) of each score over the maps (the kind accuracy over the
// maps that have one).
Summary Summarize(const DatasetEvaluation& dataset, bool median) {
  std::vector<double> mcc, precision, recall, kinds;
  for (const MapEvaluation& map : dataset.maps) {
    mcc.push_back(map.mcc);
    precision.push_back(map.precision);
    recall.push_back(map.recall);
    if (map.kind_accuracy) kinds.push_back(*map.kind_accuracy);
  }
  auto of = [&](const std::vector<double>& values) {
    return median ? Median(values) : Mean(values);
  };
  Summary summary{of(mcc), of(precision), of(recall), std::nullopt};
  if (!kinds.empty()) summary.kind_accuracy = of(kinds);
  return summary;
}

// " 0.953 |" or " - |": a kind accuracy column.
std::string KindCell(const std::optional<double>& accuracy) {
  return " " + (accuracy ? Fixed3(*accuracy) : std::string("-")) + " |";
}

eval::MapScores MapMessage(const MapEvaluation& map) {
  eval::MapScores scores;
  scores.set_map(map.name);
  scores.set_result(map.result_path);
  scores.set_gt(map.gt_path);
  scores.set_gt_style(GroundTruthStyleName(map.gt_style));
  scores.set_mcc(map.mcc);
  scores.set_precision(map.precision);
  scores.set_recall(map.recall);
  scores.set_segments_found(map.result_segments);
  scores.set_segments_gt(map.gt_segments);
  scores.set_scored_pixels(static_cast<uint32_t>(map.scored_pixels));
  if (map.gt_cropped) {
    scores.set_gt_offset_x(map.gt_offset.x);
    scores.set_gt_offset_y(map.gt_offset.y);
  }
  if (map.result_scaled) scores.set_result_scaled(true);
  if (map.kind_accuracy) scores.set_kind_accuracy(*map.kind_accuracy);
  return scores;
}

void SetSummary(const Summary& summary, eval::SummaryScores* scores) {
  scores->set_mcc(summary.mcc);
  scores->set_precision(summary.precision);
  scores->set_recall(summary.recall);
  if (summary.kind_accuracy) scores->set_kind_accuracy(*summary.kind_accuracy);
}

std::string ToJson(const google::protobuf::Message& message) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = true;
  options.preserve_proto_field_names = true;
  std::string json;
  if (!google::protobuf::util::MessageToJsonString(message, &json, options).ok()) {
    throw Error("cannot print the scores as JSON");
  }
  return json;
}

}  // namespace

std::string FormatMapText(const MapEvaluation& map) {
  std::string text = "MCC " + Fixed3(map.mcc) + "\nprecision " + Fixed3(map.precision) +
                     "\nrecall " + Fixed3(map.recall) + "\nsegments " +
                     std::to_string(map.result_segments) + "/" + std::to_string(map.gt_segments) +
                     "\ngt style " + GroundTruthStyleName(map.gt_style) + "\n";
  if (map.gt_cropped) text += "gt offset " + OffsetText(map) + "\n";
  if (map.result_scaled) text += "result scaled to the gt's size\n";
  if (map.kind_accuracy) text += "kind accuracy " + Fixed3(*map.kind_accuracy) + "\n";
  return text;
}

std::string FormatDatasetMarkdown(const DatasetEvaluation& dataset) {
  const Summary mean = Summarize(dataset, false), median = Summarize(dataset, true);
  // The kind column only where some map has kinds on both sides.
  const bool kinds = mean.kind_accuracy.has_value();
  std::string table = kinds ? "| map | MCC | precision | recall | segments found/GT | kind "
                              "accuracy |\n|---|---|---|---|---|---|\n"
                            : "| map | MCC | precision | recall | segments found/GT |\n"
                              "|---|---|---|---|---|\n";
  for (const MapEvaluation& map : dataset.maps) {
    table += "| " + map.name + " | " + Fixed3(map.mcc) + " | " + Fixed3(map.precision) + " | " +
             Fixed3(map.recall) + " | " + std::to_string(map.result_segments) + "/" +
             std::to_string(map.gt_segments) + " |" + (kinds ? KindCell(map.kind_accuracy) : "") +
             "\n";
  }
  const std::string count = std::to_string(dataset.maps.size()) + " maps";
  table += "| **mean** | **" + Fixed3(mean.mcc) + "** | " + Fixed3(mean.precision) + " | " +
           Fixed3(mean.recall) + " | " + count + " |" +
           (kinds ? KindCell(mean.kind_accuracy) : "") + "\n";
  table += "| **median** | **" + Fixed3(median.mcc) + "** | " + Fixed3(median.precision) + " | " +
           Fixed3(median.recall) + " | |" + (kinds ? KindCell(median.kind_accuracy) : "") + "\n";
  return table;
}

std::string FormatMapJson(const MapEvaluation& map) { return ToJson(MapMessage(map)); }

std::string FormatDatasetJson(const DatasetEvaluation& dataset) {
  eval::DatasetScores scores;
  for (const MapEvaluation& map : dataset.maps) *scores.add_maps() = MapMessage(map);
  SetSummary(Summarize(dataset, false), scores.mutable_mean());
  SetSummary(Summarize(dataset, true), scores.mutable_median());
  for (const std::string& failure : dataset.failures) scores.add_failures(failure);
  return ToJson(scores);
}

}  // namespace areagraph
