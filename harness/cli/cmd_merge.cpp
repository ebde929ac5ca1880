#include "harness/cli/args.hpp"
#include "harness/cli/commands.hpp"
#include "harness/check/merge.hpp"

#include "cases/util/atomic_file.hpp"
#include "cases/util/input_error.hpp"

#include <fstream>
#include <iostream>

namespace tritri::cli {
namespace {

MergePart read_part(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open for reading");
  MergePart part{path, nullptr};
  try {
    part.doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
  return part;
}

}  // namespace

int cmd_merge(int argc, char** argv) {
  Args args(argc, argv, {.valued = {"--out"}});
  if (args.help()) {
    std::cout << "usage: tritri merge [--out FILE] PART.json...\n\n"
                 "Joins the results of the shards of one campaign into the result one run on one machine\n"
                 "writes. Check (tritri check --shard K/N --json): byte for byte; counts added, per-family\n"
                 "tables, confusion cells and segment errors joined, failures in the run's order (and\n"
                 "capped as --json-max-failures capped them), the scorecards of shard 0. Hunt (tritri\n"
                 "hunt --pairs N --shard K/N, each shard's hunt.json): the same groups, counts and\n"
                 "witnesses as the one run; the clock's fields are the shards' seconds added up.\n"
                 "A wrong set of parts is refused, naming the problem: a shard missing or given twice,\n"
                 "shards whose case ranges overlap or leave a gap, or a part of another campaign (another\n"
                 "corpus, judge, schema, choice of algorithms or groupings, or number of shards).\n\n"
                 "  --out FILE   write the result to FILE (atomically) instead of standard output\n\n"
                 "Exit status: 0; 2 on bad arguments or a wrong set of parts.\n";
    return kOk;
  }
  std::vector<MergePart> parts;
  for (const std::string& path : args.positional()) parts.push_back(read_part(path));
  const MergeKind& kind = kind_of_parts(parts);
  const nlohmann::json merged = kind.merge(parts);
  if (auto out = args.value("--out"))
    write_file_atomically(*out, [&](std::ostream& o) { kind.dump(o, merged); });
  else
    kind.dump(std::cout, merged);
  return kOk;
}

}  // namespace tritri::cli
