// ag-store: maintenance of areagraph stores (merge, gc, verify, backup, failures).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "stages/common/command_line.h"
#include "tools/store/collection_commands.h"
#include "tools/store/store_commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Maintains areagraph stores.\n"
      "  ag-store merge OUT IN...              copy stores (e.g. shards) into OUT\n"
      "  ag-store index --out C SHARD...       index shard stores as one collection C,\n"
      "                                        without copying payloads\n"
      "  ag-store gc [--store S] [--keep final] [--vacuum]   drop artifacts that no head\n"
      "                                        reaches (--keep final: all but Area Graphs)\n"
      "  ag-store verify [--store S] [--quick]   check SQLite's structure and every payload\n"
      "                                        digest (exit 1 on problems)\n"
      "  ag-store backup [--store S] OUT       copy the store, even while it is in use, into\n"
      "                                        the new file OUT\n"
      "  ag-store failures [--store S] [--json]   maps that failed in a runner\n"
      "A store is its file plus, while a tool writes, the -wal file beside it: copy stores\n"
      "with ag-store backup (or after every writer has finished).\n"
      "Run ag-store COMMAND --help for details."};
  // At most one; none is reported below, so that an unknown word gets
  // CLI11's "not expected: WORD" rather than "a subcommand is required".
  app.require_subcommand(0, 1);
  std::string store_path = "areagraph.db", output;
  std::vector<std::string> inputs;
  bool vacuum = false, json = false, quick = false, shallow = false;
  std::string only = "all", keep = "reachable";

  CLI::App* merge = app.add_subcommand(
      "merge",
      "Copies the maps, artifacts, heads, failures and version histories of each IN into OUT\n"
      "(created if needed),\n"
      "one transaction per IN. Artifacts match by map name and key; a head both stores have\n"
      "goes to the artifact created later, a failure to the later one (dropped if the map\n"
      "has a newer head). All INs are checked before OUT is opened.");
  merge->add_option("OUT", output, "store to merge into")->required();
  merge->add_option("IN", inputs, "stores to copy from (a collection index: its shard stores)")
      ->required();

  CLI::App* index = app.add_subcommand(
      "index",
      "Writes a collection index: one small store file that every reading tool (ag-inspect,\n"
      "ag-export, ag-render, ag-run --report) opens as one store holding the maps of all\n"
      "SHARDs (e.g. the shard stores of a cluster run), without copying their payloads. It\n"
      "holds each map's rows (artifacts without payloads, heads, history) and failures, and\n"
      "the shard that holds its payloads, by a path relative to OUT's folder: move the folder\n"
      "as a whole. Shards are only read; each map must be in one shard. OUT is a new file,\n"
      "or an index written before, replaced whole (index again after a shard ran again).\n"
      "Nothing writes through an index: run ag-run and the stages on a shard store.");
  index->add_option("--out", output, "collection index to write")->required();
  index->add_option("SHARD", inputs, "shard stores")->required();
  index
      ->add_option("--only", only,
                   "all: every artifact; final: only the heads of the Area Graph stages (merge "
                   "and match), what exports read; the rest stays in the shards, unindexed")
      ->check(CLI::IsMember({"all", "final"}))
      ->capture_default_str();

  CLI::App* gc = app.add_subcommand(
      "gc",
      "Deletes the artifacts that no head reaches (directly or through the input keys of\n"
      "kept artifacts) and maps left empty, in one transaction. Superseded Area Graph\n"
      "versions go too; their rows in the map's history stay (ag-inspect --history).\n"
      "On a collection index: each shard store it names, then the index is written again.");
  gc->add_option("--store", store_path, "SQLite artifact store or collection index")
      ->capture_default_str();
  gc->add_option("--keep", keep,
                 "reachable: what a head reaches; final: only the heads of the Area Graph stages "
                 "(merge and match), every other artifact dropped, e.g. from shard stores once "
                 "indexed with --only final. The cache then no longer holds those stages: a "
                 "later ag-run of these maps computes import to cut again (merge and match are "
                 "hits), and ag-render and ag-export --format html, which read them, fail")
      ->check(CLI::IsMember({"reachable", "final"}))
      ->capture_default_str();
  gc->add_flag("--vacuum", vacuum, "then shrink the file (needs free space about its size)");

  CLI::App* verify = app.add_subcommand(
      "verify",
      "Runs SQLite's integrity_check (pages, b-trees, indexes), then reads every artifact and\n"
      "checks its payload digest and encoding, that heads point at artifacts of their map and\n"
      "stage, and that input keys name artifacts of the map. Prints one line per problem and\n"
      "exits 1 if there is any. A collection index: the index file, then each shard store\n"
      "as above, and whether it still holds what the index says (a missing shard, or one\n"
      "that ran again after indexing, is a problem naming the shard).");
  verify->add_option("--store", store_path, "SQLite artifact store or collection index")
      ->capture_default_str();
  verify->add_flag("--quick", quick,
                   "SQLite's quick_check instead of integrity_check (skips the index contents)");
  verify->add_flag("--shallow", shallow,
                   "collection index: check only that each shard is there and holds the indexed "
                   "artifacts and heads, without reading payloads (for shards verified where "
                   "they were written)");

  CLI::App* backup = app.add_subcommand(
      "backup",
      "Copies the store into the new file OUT with SQLite's online backup: one consistent\n"
      "moment even while runners write, with the write-ahead log folded in. OUT must not\n"
      "exist; it appears only when complete.");
  backup->add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  backup->add_option("OUT", output, "new store file to write")->required();

  CLI::App* failures = app.add_subcommand(
      "failures", "Lists the maps that failed in a runner: map, stage, time, message.");
  failures->add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  failures->add_flag("--json", json, "print a JSON array instead of a table");

  return areagraph::RunCommand("ag-store", app, argc, argv, [&] {
    if (app.get_subcommands().empty()) {
      std::cerr << "ag-store: name a command: merge, index, gc, verify, backup or failures (see "
                   "--help)\n";
      return 2;
    }
    if (*merge) return areagraph::MergeStores(output, inputs, std::cout);
    if (*index) {
      return areagraph::IndexCollection(
          output, inputs,
          only == "final" ? areagraph::CollectionScope::kFinal : areagraph::CollectionScope::kAll,
          std::cout);
    }
    if (*gc) {
      return areagraph::CollectStoreGarbage(store_path, keep == "final", vacuum, std::cout);
    }
    if (*verify) {
      return areagraph::VerifyStore(store_path, isatty(STDERR_FILENO) == 1, quick, shallow,
                                    std::cout);
    }
    if (*backup) return areagraph::BackupStore(store_path, output, std::cout);
    return areagraph::ListStoreFailures(store_path, json, std::cout);
  });
}
