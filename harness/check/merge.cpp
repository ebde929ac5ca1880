#include "harness/check/merge.hpp"

#include "cases/util/input_error.hpp"
#include "harness/check/check_output.hpp"

#include <algorithm>
#include <map>

namespace tritri {
namespace {

using Json = nlohmann::json;

bool is_check(const Json& doc) { return schema_starts_with(doc, "tritri-check/"); }

// The value at a dotted path ("judge.kind"), or null.
Json at_path(const Json& doc, const std::string& path) {
  const Json* j = &doc;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string key = path.substr(start, dot - start);
    if (!j->is_object() || !j->contains(key)) return nullptr;
    j = &(*j)[key];
    start = dot + 1;
  }
  return *j;
}

std::size_t shard_field(const MergePart& p, const char* key) {
  const Json v = at_path(p.doc, std::string("shard.") + key);
  if (!v.is_number_unsigned()) throw InputError(p.path + ": shard." + key + " is missing or not a count");
  return v.get<std::size_t>();
}

std::string shard_name(const MergePart& p) {
  return std::to_string(shard_field(p, "index")) + "/" + std::to_string(shard_field(p, "count"));
}

}  // namespace

const std::vector<MergeKind>& merge_kinds() {
  static const std::vector<MergeKind> kinds = {
      {"check", &is_check, &merge_check, &dump_check_json},
      {"hunt", &is_hunt, &merge_hunt, &dump_hunt_json},
  };
  return kinds;
}

const MergeKind& kind_of_parts(const std::vector<MergePart>& parts) {
  if (parts.size() < 2) throw InputError("tritri merge needs the parts of one campaign: at least two files");
  for (const MergeKind& kind : merge_kinds())
    if (kind.recognises(parts[0].doc)) {
      for (const MergePart& p : parts)
        if (!kind.recognises(p.doc))
          throw InputError(p.path + ": not a " + kind.name + " result, as " + parts[0].path + " is");
      return kind;
    }
  throw InputError(parts[0].path + ": not a result tritri merge knows (check or hunt JSON)");
}

bool schema_starts_with(const Json& doc, const std::string& prefix) {
  return doc.is_object() && doc.contains("schema") && doc["schema"].is_string() &&
         doc["schema"].get<std::string>().rfind(prefix, 0) == 0;
}

std::vector<const MergePart*> shards_in_order(const std::vector<MergePart>& parts, const std::string& schema,
                                              const std::vector<std::string>& same) {
  for (const MergePart& p : parts)
    if (p.doc.at("schema") != schema)
      throw InputError(p.path + ": schema " + p.doc.at("schema").dump() + "; tritri merge reads " + schema);
  for (const MergePart& p : parts) {
    if (!p.doc.contains("shard"))
      throw InputError(p.path + ": not a shard (no \"shard\" field): a whole run, written without --shard");
    for (const std::string& key : same)
      if (at_path(p.doc, key) != at_path(parts[0].doc, key))
        throw InputError(p.path + ": another " + key + " than " + parts[0].path + " (" + at_path(p.doc, key).dump() +
                         " against " + at_path(parts[0].doc, key).dump() + "): a shard of another campaign");
  }
  const std::size_t count = shard_field(parts[0], "count");
  std::vector<const MergePart*> by_index(count, nullptr);
  for (const MergePart& p : parts) {
    const std::size_t k = shard_field(p, "index");
    if (k >= count) throw InputError(p.path + ": shard " + shard_name(p) + " is out of range");
    if (by_index[k]) throw InputError("shard " + shard_name(p) + " is given twice: " + by_index[k]->path + " and " + p.path);
    by_index[k] = &p;
  }
  for (std::size_t k = 0; k < count; ++k)
    if (!by_index[k])
      throw InputError("shard " + std::to_string(k) + "/" + std::to_string(count) + " is missing (" +
                       std::to_string(parts.size()) + " of " + std::to_string(count) + " shards given)");
  std::size_t expected = 0;
  for (const MergePart* p : by_index) {
    const std::size_t first = shard_field(*p, "first_case"), end = shard_field(*p, "end_case");
    if (first != expected || end < first)
      throw InputError(p->path + ": shard " + shard_name(*p) + " covers cases [" + std::to_string(first) + ", " +
                       std::to_string(end) + "), but the shards before it end at case " + std::to_string(expected) +
                       ": the shards overlap or leave a gap");
    expected = end;
  }
  if (expected != shard_field(parts[0], "total_cases"))
    throw InputError("the shards cover " + std::to_string(expected) + " cases of " +
                     std::to_string(shard_field(parts[0], "total_cases")));
  return by_index;
}

}  // namespace tritri
