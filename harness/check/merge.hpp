// `tritri merge`: the parts of a sharded campaign (`--shard K/N`) joined into the document that
// one run on one machine writes, byte for byte. A wrong set of parts (one missing or given
// twice, overlapping ranges, another corpus, judge, tritri schema or choice of algorithms) is
// refused with an InputError naming the files and the problem, never silently merged.
//
// Each kind of document is one MergeKind: a function that merges parsed parts, and one line in
// merge_kinds() (merge.cpp) that registers it.
#pragma once

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace tritri {

struct MergePart {
  std::string path;
  nlohmann::json doc;
};

struct MergeKind {
  const char* name;                                       // "check"
  bool (*recognises)(const nlohmann::json& doc);          // is the document of this kind?
  nlohmann::json (*merge)(const std::vector<MergePart>& parts);  // throws InputError
  void (*dump)(std::ostream& out, const nlohmann::json& doc);    // as the kind's writer does
};

const std::vector<MergeKind>& merge_kinds();

// The kind of every part (all must be one kind), or an InputError naming the odd one.
const MergeKind& kind_of_parts(const std::vector<MergePart>& parts);

// The shard fields every kind shares ("shard": {index, count, first_case, end_case,
// total_cases}): the parts sorted by index, or an InputError when a part's schema is not `schema`
// (the version the kind's merge reads), one is missing or given twice, the ranges do not tile
// [0, total) in order, or the parts disagree on `same` (dotted key paths whose values must be
// equal in every part).
std::vector<const MergePart*> shards_in_order(const std::vector<MergePart>& parts, const std::string& schema,
                                              const std::vector<std::string>& same);

// Whether `doc` is an object whose "schema" starts with `prefix` ("tritri-check/"): a kind's
// `recognises`.
bool schema_starts_with(const nlohmann::json& doc, const std::string& prefix);

// The check JSON's merge (harness/check/check_output.hpp).
nlohmann::json merge_check(const std::vector<MergePart>& parts);

// The hunt JSON's merge (merge_hunt.cpp; the document: harness/hunt/output.cpp).
bool is_hunt(const nlohmann::json& doc);
nlohmann::json merge_hunt(const std::vector<MergePart>& parts);
void dump_hunt_json(std::ostream& out, const nlohmann::json& doc);

}  // namespace tritri
