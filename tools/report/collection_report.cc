#include "tools/report/collection_report.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>

#include "common/error.h"
#include "proto/artifacts.pb.h"
#include "stages/common/output_file.h"
#include "stages/pipeline/stage.h"
#include "store/artifact_store.h"
#include "tools/export/area_graph_export.h"
#include "tools/export/html_page_text.h"
#include "tools/export/html_viewer.h"
#include "tools/export/markup_escape.h"
#include "tools/export/svg_path.h"
#include "tools/export/viewer_run.h"
#include "tools/report/collection_index.pb.h"
#include "tools/report/index_assets.h"
#include "tools/report/map_thumbnail.h"

namespace areagraph {
namespace {

constexpr int kThumbnailSide = 120;

// File names compared without case, for file systems that ignore it.
std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The map's viewer page, with the row's numbers filled from it.
std::string MapPage(const std::string& map_name, const std::vector<ArtifactRecord>& run,
                    report::MapRow* row) {
  const viewer::Page page = ViewerPageOf(map_name, run);
  const viewer::Run& first = page.runs(0);
  double compute_ms = 0;
  for (const viewer::StageRecord& stage : first.stages()) compute_ms += stage.elapsed_ms();
  row->set_compute_s(Rounded(compute_ms / 1000, 3));
  if (first.has_area_graph()) {
    row->set_has_area_graph(true);
    row->set_areas(first.area_graph().areas_size());
    row->set_passages(first.area_graph().passages_size());
  }
  if (first.has_room_width()) {
    row->set_room_width_m(first.room_width().room_width_m());
    row->set_room_width_automatic(first.room_width().automatic());
  }
  row->set_thumbnail_png(MapThumbnailPng(run, kThumbnailSide));
  return ViewerPageHtml(page);
}

}  // namespace

std::string MapPageFileName(const std::string& map_name, std::vector<std::string>* taken) {
  std::string stem;
  for (const char c : map_name) {
    stem +=
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ? c : '_';
  }
  if (stem.empty() || stem[0] == '.') stem = "_" + stem;
  std::string name = "maps/" + stem + ".html";
  for (int suffix = 2; std::find(taken->begin(), taken->end(), Lower(name)) != taken->end();
       ++suffix) {
    name = "maps/" + stem + "-" + std::to_string(suffix) + ".html";
  }
  taken->push_back(Lower(name));
  return name;
}

CollectionReport WriteCollectionReport(const std::string& store_path,
                                       const std::vector<std::string>& map_names,
                                       const std::string& dir, std::ostream& progress) {
  std::error_code error;
  std::filesystem::create_directories(dir + "/maps", error);
  if (error) throw InputError("cannot make the report folder '" + dir + "': " + error.message());
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  std::map<std::string, FailureRecord> failures;
  for (FailureRecord& failure : store->ReadFailures()) {
    failures[failure.map_name] = std::move(failure);
  }

  CollectionReport report;
  report::CollectionIndex index;
  index.set_title("areagraph report: " + std::to_string(map_names.size()) + " maps");
  std::vector<std::string> taken;
  const size_t step = std::max<size_t>(1, map_names.size() / 10);
  for (size_t i = 0; i < map_names.size(); ++i) {
    const std::string& name = map_names[i];
    report::MapRow* row = index.add_rows();
    row->set_map_name(name);
    if (auto failure = failures.find(name); failure != failures.end()) {
      row->set_failed_stage(failure->second.stage);
      row->set_failure(failure->second.message);
    }
    std::string page;
    if (store->ReadMap(name)) {
      try {
        page = MapPage(name, RunArtifacts(*store, name, ""), row);
      } catch (const Error& page_error) {  // a damaged artifact: the other maps go on
        if (row->failure().empty()) row->set_failure(std::string("no page: ") + page_error.what());
      }
    }
    if (!page.empty()) {
      row->set_page(MapPageFileName(name, &taken));
      WriteOutputFile(dir + "/" + row->page(), page);  // an unwritable folder ends the report
      ++report.pages;
    }
    if (!row->failure().empty()) ++report.failed;
    if ((i + 1) % step == 0 || i + 1 == map_names.size()) {
      progress << "ag-run: report: " << i + 1 << "/" << map_names.size() << " maps\n";
    }
  }
  report.index_path = dir + "/index.html";
  WriteOutputFile(report.index_path,
                  FillTemplate(embedded::kIndexHtml, {{"{{TITLE}}", MarkupEscaped(index.title())},
                                                      {"/*{{SCRIPT}}*/", embedded::kIndexJs},
                                                      {"{{DATA}}", ScriptJson(index)}}));
  return report;
}

}  // namespace areagraph
