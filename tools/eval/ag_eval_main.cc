// ag-eval: scores segmentations against ground-truth images (MCC, precision,
// recall), for one map or for a folder of maps.
#include <CLI/CLI.hpp>
#include <iostream>
#include <regex>
#include <string>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "stages/common/output_file.h"
#include "tools/eval/dataset_evaluation.h"
#include "tools/eval/evaluation_report.h"
#include "tools/eval/gt_picture.h"
#include "tools/eval/map_evaluation.h"

namespace {

// "X,Y" -> point; throws OptionsError otherwise.
cv::Point ParseOffset(const std::string& text) {
  // At most 9 digits each, so that no number overflows an int.
  static const std::regex kOffset(R"(\s*(-?[0-9]{1,9})\s*,\s*(-?[0-9]{1,9})\s*)");
  std::smatch match;
  if (!std::regex_match(text, match, kOffset)) {
    throw areagraph::OptionsError("--gt-offset needs X,Y in pixels, e.g. 192,0; got '" + text +
                                  "'");
  }
  return {std::stoi(match[1]), std::stoi(match[2])};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Scores room segmentations against ground truth: MAORIS' per-zone MCC (with the standard\n"
      "TN = N - TP - FP - FN) and Bormann's per-room precision and recall.\n"
      "  ag-eval --result R.png --gt GT.png\n"
      "  ag-eval --dataset --results DIR --gt DIR [--suffix S] [--gt-suffix S]\n"
      "Segmentations: 8/16-bit label PNGs (0 = none) or colour images (one segment per\n"
      "chromatic colour; white, black and grey = none).\n"
      "Kinds: when both images have a <stem>.kinds.tsv beside them (label<TAB>room|corridor|\n"
      "dead_end; ag-export --format kinds, ag-make-benchmark), the share of the result's area\n"
      "whose kind is that of the GT zone it overlaps most is reported too."};
  std::string result_path, results_dir, gt_path, suffix, gt_suffix, style_name = "auto";
  std::string variant_name = "standard", offset_text;
  bool dataset = false, json = false, maoris_grey = false, scale_result = false;
  int drop_result_px = 0;
  std::string gt_picture;
  int picture_width = 0;
  app.add_option("--result", result_path, "segmentation image to score");
  app.add_flag("--dataset", dataset, "score every file in --results that has a GT in --gt");
  app.add_option("--results", results_dir, "folder of segmentations (with --dataset)");
  app.add_option("--gt", gt_path, "ground-truth image, or folder with --dataset")->required();
  app.add_option("--suffix", suffix,
                 "with --dataset: only results named <map><suffix>.<ext>; the suffix is removed "
                 "to find the GT");
  app.add_option("--gt-suffix", gt_suffix,
                 "with --dataset: GT files are named <map><gt-suffix>.png "
                 "(e.g. _gt_segmentation)");
  app.add_option("--gt-style", style_name,
                 "auto, colour (one segment per chromatic colour), lines (Bormann: free > 250, "
                 "8-connected rooms), maoris-lines (MAORIS' segment_Ground_Truth), labels")
      ->capture_default_str();
  app.add_option("--gt-offset", offset_text,
                 "X,Y of the segmentation's top-left pixel in a bigger GT (default: search "
                 "for the best match)");
  app.add_option("--mcc-variant", variant_name,
                 "standard, or maoris to reproduce MAORIS' published code (its TN = N - (FP - "
                 "|GT zone|) and matching quirks)")
      ->capture_default_str();
  app.add_flag("--maoris-grey", maoris_grey,
               "read segmentations as MAORIS does: grey value = label, so colours may merge");
  app.add_option("--drop-result-px", drop_result_px,
                 "drop result segments of at most this many pixels before scoring")
      ->capture_default_str();
  app.add_flag("--scale-result", scale_result,
               "scale a segmentation of another size but the same shape as its GT (aspect "
               "ratios within 1 %) to the GT's size instead of looking for it inside the GT");
  app.add_flag("--json", json, "print JSON instead of text or Markdown");
  app.add_option("--gt-picture", gt_picture,
                 "instead of scoring: draw the --gt file's segments as ag-eval reads them into "
                 "this PNG (- for standard output)");
  app.add_option("--picture-width", picture_width,
                 "with --gt-picture: at most this many pixels wide");

  return areagraph::RunCommand("ag-eval", app, argc, argv, [&] {
    areagraph::EvaluationOptions options;
    options.gt_style = areagraph::ParseGroundTruthStyle(style_name);
    options.mcc_variant = areagraph::ParseMccVariant(variant_name);
    if (maoris_grey) options.reading = areagraph::SegmentationReading::kGreyLikeMaoris;
    if (!offset_text.empty()) options.gt_offset = ParseOffset(offset_text);
    if (drop_result_px < 0) throw areagraph::OptionsError("--drop-result-px must be >= 0");
    options.drop_result_segments_px = drop_result_px;
    options.scale_result_to_gt = scale_result;

    if (!gt_picture.empty()) {
      if (picture_width < 0) throw areagraph::OptionsError("--picture-width must be positive");
      areagraph::WriteGroundTruthPicture(gt_path, options.gt_style, gt_picture, picture_width);
      if (!areagraph::IsStandardOutput(gt_picture)) std::cout << "wrote " << gt_picture << "\n";
      return 0;
    }
    if (!dataset) {
      if (result_path.empty()) throw areagraph::OptionsError("--result is required");
      if (!results_dir.empty()) throw areagraph::OptionsError("--results needs --dataset");
      const areagraph::MapEvaluation map = areagraph::EvaluateMap(result_path, gt_path, options);
      std::cout << (json ? areagraph::FormatMapJson(map) : areagraph::FormatMapText(map));
      return 0;
    }
    if (results_dir.empty()) throw areagraph::OptionsError("--dataset needs --results DIR");
    if (!result_path.empty()) throw areagraph::OptionsError("--result cannot go with --dataset");
    const areagraph::DatasetEvaluation scored =
        areagraph::EvaluateDataset({results_dir, gt_path, suffix, gt_suffix}, options);
    std::cout << (json ? areagraph::FormatDatasetJson(scored)
                       : areagraph::FormatDatasetMarkdown(scored));
    for (const std::string& failure : scored.failures) {
      std::cerr << "ag-eval: " << failure << "\n";
    }
    return scored.failures.empty() ? 0 : 1;
  });
}
