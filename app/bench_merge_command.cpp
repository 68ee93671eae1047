#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "app/args.hpp"
#include "app/bench/bench_merge.hpp"
#include "app/bench/trace_writer.hpp"
#include "app/commands.hpp"
#include "app/option_table.hpp"
#include "app/file_clash.hpp"
#include "core/io/output_file.hpp"
#include "app/provenance.hpp"

namespace pbr {

namespace {

void writeOutput(const Args& args, const std::string& option, void (*write)(std::ostream&, const BenchReport&),
                 const BenchReport& report) {
  if (!args.has(option)) return;
  OutputFile out(args.get(option));
  out.write([&](std::ostream& stream) { write(stream, report); });
  std::printf("wrote %s\n", out.path().c_str());
}

}  // namespace

int runBenchMerge(const std::vector<std::string>& argv) {
  const auto& specs = commandOptions(Command::BenchMerge);
  const Args args(specs, argv, true);
  if (args.helpRequested()) {
    std::cout << Args::helpText(
        "pbr bench-merge SHARD.json... [options]",
        "Joins the JSON reports of the shards of one sweep (pbr bench --shard K/N --json F, one per K from 1 to N) "
        "into the report the whole sweep would have written: the table on stdout, and the same CSV and JSON as pbr "
        "bench, configurations in sweep order, and a trace of every shard's frames. Refuses shards of different "
        "sweeps, a shard given twice or missing, and mixed renderers or builds. Provenance values that differ "
        "between shards are listed per shard.",
        specs);
    return 0;
  }
  if (args.operands().empty()) throw UsageError("expects the JSON reports of a sweep's shards");
  if (args.has("--csv")) requireExtension(args.get("--csv"), ".csv");
  if (args.has("--json")) requireExtension(args.get("--json"), ".json");
  if (args.has("--trace")) requireExtension(args.get("--trace"), ".json");
  std::vector<NamedFile> inputs;
  for (const std::string& path : args.operands()) inputs.push_back({"shard", path});
  checkOutputsApart(inputs, {{"--csv", args.get("--csv")},
                             {"--csv's provenance", args.has("--csv") ? provenancePath(args.get("--csv")) : ""},
                             {"--json", args.get("--json")},
                             {"--trace", args.get("--trace")}});
  std::vector<ShardFile> shards;
  for (const std::string& path : args.operands()) {
    shards.push_back(readShardFile(path));
    if (args.has("--trace") && !shards.back().file.traceLayout) {
      throw std::runtime_error(path + ": holds no pass start times (written by an earlier pbr bench), which --trace "
                               "needs: measure the shard again, or merge without --trace");
    }
  }
  BenchReport merged = mergeShards(shards, args.has("--allow-mixed"));
  merged.provenance.set("merge_command", processCommandLine());
  printBenchTable(std::cout, merged);
  writeOutput(args, "--csv", writeBenchCsv, merged);
  if (args.has("--csv")) {
    OutputFile out(provenancePath(args.get("--csv")));
    out.write([&](std::ostream& stream) { writeKeyValues(stream, benchCsvProvenance(merged)); });
    std::printf("wrote %s\n", out.path().c_str());
  }
  writeOutput(args, "--json", writeBenchJson, merged);
  writeOutput(args, "--trace", writeTrace, merged);
  return 0;
}

}  // namespace pbr
