// ag-bench-geometry: geometry statistics of the Area Graphs in a store, one
// tab-separated line per map, for tools/bench-geometry.sh.
#include <google/protobuf/text_format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "common/error.h"
#include "stages/common/command_line.h"
#include "stages/geometry/ring_area.h"
#include "stages/merge/area_graph_builder.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tools/bench/area_graph_checks.h"
#include "tools/bench/outline_distance.h"
#include "tools/export/area_label_image.h"
#include "tools/export/area_polygons.h"

using namespace areagraph;

namespace {

// The columns, in the order they are printed.
constexpr const char* kHeader =
    "map\tareas\tvertices_median\tvertices_max\tholes\tholes_under_min\tpassages\t"
    "passages_on_both\toverlapping_pairs\tmax_distance_px\tmax_distance_m\t"
    "vertices_with_holes_max";

int VertexCount(const proto::Polygon& polygon) {
  int count = polygon.outer().points_size();
  for (const proto::Ring& hole : polygon.holes()) count += hole.points_size();
  return count;
}

// The merge options the head Area Graph was made with.
proto::MergeOptions StoredMergeOptions(ArtifactStore& store, const std::string& map) {
  const auto record = store.ReadHead(map, kMergeStage.name);
  if (!record) throw InputError("map '" + map + "' has no merge artifact; run ag-pipeline first");
  proto::MergeOptions options;
  if (!google::protobuf::TextFormat::ParseFromString(record->options_text, &options)) {
    throw InputError("map '" + map + "': the merge artifact's options do not parse");
  }
  return options;
}

// The same areas with the raster's outlines: every cell edge and every hole.
proto::AreaGraph RasterOutlines(ArtifactStore& store, const std::string& map,
                                proto::MergeOptions options) {
  options.set_outline_tolerance_m(0);
  options.set_min_hole_m2(0);
  const auto cut = ReadHeadArtifact<proto::CutGraph>(store, map, kCutStage);
  const auto cleaned = ReadHeadArtifact<proto::CleanedMap>(store, map, kCleanStage);
  return BuildAreaGraph(cut, cleaned, options);
}

void WriteLabels(const proto::AreaGraph& graph, const std::string& path) {
  if (!cv::imwrite(path, AreaLabelImage(graph))) throw InputError("cannot write " + path);
}

void PrintMap(ArtifactStore& store, const std::string& map, const std::string& labels_dir,
              std::FILE* vertex_list) {
  const auto graph = ReadHeadArtifact<proto::AreaGraph>(store, map, kMergeStage);
  const proto::MergeOptions options = StoredMergeOptions(store, map);
  const double resolution_m = graph.frame().resolution_m();
  const double min_hole_px2 = options.min_hole_m2() / (resolution_m * resolution_m);

  std::vector<int> vertices;
  int holes = 0, small_holes = 0, with_holes = 0;
  for (const proto::Area& area : graph.areas()) {
    vertices.push_back(area.polygon_px().outer().points_size());
    with_holes = std::max(with_holes, VertexCount(area.polygon_px()));
    for (const proto::Ring& hole : area.polygon_px().holes()) {
      ++holes;
      small_holes += std::abs(TwiceSignedArea(hole)) / 2 < min_hole_px2;
    }
  }
  if (vertex_list != nullptr) {
    for (const int count : vertices) std::fprintf(vertex_list, "%s\t%d\n", map.c_str(), count);
  }
  std::sort(vertices.begin(), vertices.end());
  const double median =
      vertices.empty() ? 0
      : vertices.size() % 2 == 1
          ? vertices[vertices.size() / 2]
          : 0.5 * (vertices[vertices.size() / 2 - 1] + vertices[vertices.size() / 2]);
  int on_both = 0;
  for (const proto::Passage& passage : graph.passages()) {
    on_both += PassageEndsOnBothOutlines(graph, passage);
  }
  const size_t overlaps = OverlappingAreaPairs(graph).size();

  const proto::AreaGraph raster = RasterOutlines(store, map, options);
  std::string distance_px = "-", distance_m = "-";
  if (raster.areas_size() == graph.areas_size()) {
    double farthest = 0;
    for (int k = 0; k < graph.areas_size(); ++k) {
      farthest = std::max(farthest, BoundaryDistancePx(graph.areas(k).polygon_px(),
                                                       raster.areas(k).polygon_px(), min_hole_px2));
    }
    char text[64];
    std::snprintf(text, sizeof(text), "%.2f", farthest);
    distance_px = text;
    std::snprintf(text, sizeof(text), "%.3f", farthest * resolution_m);
    distance_m = text;
  }
  if (!labels_dir.empty()) {
    WriteLabels(raster, labels_dir + "/raster/" + map + ".png");
    WriteLabels(graph, labels_dir + "/polygons/" + map + ".png");
  }
  std::printf("%s\t%d\t%.1f\t%d\t%d\t%d\t%d\t%d\t%zu\t%s\t%s\t%d\n", map.c_str(),
              graph.areas_size(), median, vertices.empty() ? 0 : vertices.back(), holes,
              small_holes, graph.passages_size(), on_both, overlaps, distance_px.c_str(),
              distance_m.c_str(), with_holes);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Prints geometry statistics of the head Area Graph of each map, one tab-separated line "
      "per map: areas; vertices per area (outer ring; median, max); holes, and holes "
      "smaller than merge.min_hole_m2; passages, and those whose two end points are vertices "
      "of both areas' outlines; pairs of areas whose interiors overlap (exact); the largest "
      "distance between an area's outline and the same area's outline along the raster's cell "
      "edges (recomputed from the stored CutGraph with merge.outline_tolerance_m = 0, holes "
      "under the minimum left out); the most vertices of an area with its holes. --labels DIR "
      "writes DIR/raster/MAP.png and "
      "DIR/polygons/MAP.png, label images of both, for ag-eval. A benchmark: it checks "
      "nothing."};
  std::string store_path = "areagraph.db", labels_dir, vertex_list_path;
  std::vector<std::string> maps;
  bool header = false;
  app.add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  app.add_option("--labels", labels_dir, "folder for the label images (needs raster/, polygons/)");
  app.add_option("--vertex-list", vertex_list_path,
                 "file to write every area's vertex count to (map<TAB>count lines)");
  app.add_flag("--header", header, "print the column names first");
  app.add_option("MAP", maps, "maps in the store")->required();
  return RunCommand("ag-bench-geometry", app, argc, argv, [&] {
    auto store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> vertex_list(nullptr, std::fclose);
    if (!vertex_list_path.empty()) {
      vertex_list.reset(std::fopen(vertex_list_path.c_str(), "w"));
      if (!vertex_list) throw InputError("cannot write " + vertex_list_path);
    }
    if (header) std::printf("%s\n", kHeader);
    for (const std::string& map : maps) PrintMap(*store, map, labels_dir, vertex_list.get());
    return 0;
  });
}
