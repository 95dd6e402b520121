#include "tools/export/html_viewer.h"

#include <memory>

#include "common/error.h"
#include "stages/common/output_file.h"
#include "stages/pipeline/stage.h"
#include "stages/pipeline/stage_table.h"
#include "tools/export/area_graph_export.h"
#include "tools/export/html_page_text.h"
#include "tools/export/markup_escape.h"
#include "tools/export/viewer_assets.h"
#include "tools/export/viewer_run.h"

namespace areagraph {
namespace {

// Which stage versions wrote the page, for whoever finds it later.
std::string GeneratorText() {
  std::string text = "areagraph viewer; stage versions";
  for (const StageDefinition& stage : StageTable()) {
    text += std::string(" ") + stage.info.name + " " + std::to_string(stage.info.version);
  }
  return text;
}

// Every artifact message carries the map frame in its field `frame`.
proto::MapFrame FrameOf(const ArtifactRecord& artifact) {
  const std::unique_ptr<google::protobuf::Message> message =
      NewArtifactMessage(artifact.proto_type);
  if (!message || !message->ParseFromString(artifact.payload)) return proto::MapFrame();
  const auto* field = message->GetDescriptor()->FindFieldByName("frame");
  if (field == nullptr || field->message_type() != proto::MapFrame::descriptor()) {
    return proto::MapFrame();
  }
  proto::MapFrame frame;
  frame.CopyFrom(message->GetReflection()->GetMessage(*message, field));
  return frame;
}

}  // namespace

viewer::Page ViewerPageOf(const std::string& map_name, const std::vector<ArtifactRecord>& first,
                          const std::vector<ArtifactRecord>* second) {
  viewer::Page page;
  page.set_map_name(map_name);
  page.set_generator(GeneratorText());
  *page.add_runs() = ViewerRunOf(first, "A");
  if (second != nullptr) *page.add_runs() = ViewerRunOf(*second, "B", &page.runs(0));
  if (!first.empty()) *page.mutable_frame() = FrameOf(first.front());
  if (page.frame().resolution_m() <= 0 || page.frame().width_px() <= 0) {
    throw StoreError("the artifacts of map '" + map_name + "' hold no valid map frame");
  }
  return page;
}

viewer::Page BuildViewerPage(ArtifactStore& store, const std::string& map_name,
                             const std::string& key, const std::string& compare_key) {
  const std::vector<ArtifactRecord> first = RunArtifacts(store, map_name, key);
  if (compare_key.empty()) return ViewerPageOf(map_name, first);
  const std::vector<ArtifactRecord> second = RunArtifacts(store, map_name, compare_key);
  return ViewerPageOf(map_name, first, &second);
}

std::string ViewerPageHtml(const viewer::Page& page) {
  return FillTemplate(
      embedded::kViewerHtml,
      {{"{{TITLE}}", MarkupEscaped(page.map_name())},
       {"/*{{STYLE}}*/", embedded::kViewerCss},
       {"/*{{SCRIPT}}*/", std::string(embedded::kViewerRouteJs) + embedded::kViewerJs},
       {"{{DATA}}", ScriptJson(page)}});
}

int ExportViewerPage(const std::string& store_path, const std::string& map_name,
                     const std::string& key, const std::string& compare_key,
                     const std::string& out_path) {
  const std::unique_ptr<ArtifactStore> store = OpenArtifactStore(store_path, StoreMode::kReadOnly);
  const viewer::Page page = BuildViewerPage(*store, map_name, key, compare_key);
  WriteOutputFile(out_path, ViewerPageHtml(page));
  return 0;
}

}  // namespace areagraph
