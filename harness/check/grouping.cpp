#include "harness/check/grouping.hpp"

#include "cases/util/text.hpp"

#include <stdexcept>

namespace tritri {
namespace {

constexpr std::string_view kBase = "@base";

std::optional<std::string> value_of(const Case& c, std::string_view key) {
  if (key == kBase) {
    const auto dot = c.name.rfind('.');
    if (dot == std::string::npos) return std::nullopt;
    return c.name.substr(0, dot);
  }
  if (auto v = c.label(key)) return std::string(*v);
  return std::nullopt;
}

}  // namespace

Grouping parse_grouping(std::string_view spec) {
  Grouping g;
  for (std::string_view field : split_fields(spec, ',')) {
    const auto eq = field.find('=');
    Grouping::Key k{std::string(field.substr(0, eq)), std::nullopt};
    if (eq != std::string_view::npos) k.value = std::string(field.substr(eq + 1));
    if (k.key.empty()) throw std::invalid_argument("empty label key in grouping '" + std::string(spec) + "'");
    g.keys.push_back(std::move(k));
  }
  return g;
}

std::vector<std::string> groups_of(const Case& c, const std::vector<Grouping>& groupings) {
  if (groupings.empty()) return {c.family()};
  std::vector<std::string> groups;
  for (const Grouping& g : groupings) {
    std::string name;
    bool in = true;
    for (const auto& [key, fixed] : g.keys) {
      const auto v = value_of(c, key);
      if (!v || (fixed && *v != *fixed)) {
        in = false;
        break;
      }
      name += (name.empty() ? "" : " ") + key + "=" + *v;
    }
    if (in) groups.push_back(std::move(name));
  }
  return groups;
}

}  // namespace tritri
