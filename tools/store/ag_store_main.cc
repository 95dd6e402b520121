// ag-store: maintenance of areagraph stores (merge, gc, verify, failures).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "stages/common/command_line.h"
#include "tools/store/store_commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "Maintains areagraph stores.\n"
      "  ag-store merge OUT IN...              copy stores (e.g. shards) into OUT\n"
      "  ag-store gc [--store S] [--vacuum]    drop artifacts that no head reaches\n"
      "  ag-store verify [--store S]           check every payload digest (exit 1 on problems)\n"
      "  ag-store failures [--store S] [--json]   maps that failed in a runner\n"
      "Run ag-store COMMAND --help for details."};
  // At most one; none is reported below, so that an unknown word gets
  // CLI11's "not expected: WORD" rather than "a subcommand is required".
  app.require_subcommand(0, 1);
  std::string store_path = "areagraph.db", output;
  std::vector<std::string> inputs;
  bool vacuum = false, json = false;

  CLI::App* merge = app.add_subcommand(
      "merge",
      "Copies the maps, artifacts, heads, failures and version histories of each IN into OUT\n"
      "(created if needed),\n"
      "one transaction per IN. Artifacts match by map name and key; a head both stores have\n"
      "goes to the artifact created later, a failure to the later one (dropped if the map\n"
      "has a newer head). All INs are checked before OUT is opened.");
  merge->add_option("OUT", output, "store to merge into")->required();
  merge->add_option("IN", inputs, "stores to copy from")->required();

  CLI::App* gc = app.add_subcommand(
      "gc",
      "Deletes the artifacts that no head reaches (directly or through the input keys of\n"
      "kept artifacts) and maps left empty, in one transaction. Superseded Area Graph\n"
      "versions go too; their rows in the map's history stay (ag-inspect --history).");
  gc->add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  gc->add_flag("--vacuum", vacuum, "then shrink the file (needs free space about its size)");

  CLI::App* verify = app.add_subcommand(
      "verify",
      "Reads every artifact and checks its payload digest and encoding, that heads point at\n"
      "artifacts of their map and stage, and that input keys name artifacts of the map.\n"
      "Prints one line per problem and exits 1 if there is any.");
  verify->add_option("--store", store_path, "SQLite artifact store")->capture_default_str();

  CLI::App* failures = app.add_subcommand(
      "failures", "Lists the maps that failed in a runner: map, stage, time, message.");
  failures->add_option("--store", store_path, "SQLite artifact store")->capture_default_str();
  failures->add_flag("--json", json, "print a JSON array instead of a table");

  return areagraph::RunCommand("ag-store", app, argc, argv, [&] {
    if (app.get_subcommands().empty()) {
      std::cerr << "ag-store: name a command: merge, gc, verify or failures (see --help)\n";
      return 2;
    }
    if (*merge) return areagraph::MergeStores(output, inputs, std::cout);
    if (*gc) return areagraph::CollectStoreGarbage(store_path, vacuum, std::cout);
    if (*verify) return areagraph::VerifyStore(store_path, isatty(STDERR_FILENO) == 1, std::cout);
    return areagraph::ListStoreFailures(store_path, json, std::cout);
  });
}
