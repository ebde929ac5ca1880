// What an algorithm is and the registry's bookkeeping: compiled into tritri_algorithms and,
// again, into every build variant's module (algorithms/api/build_variant_module.cpp), which
// fills a registry of its own.
#include "tritri/algorithm.hpp"

#include <stdexcept>

namespace tritri {

std::string_view to_string(Scalar s) {
  constexpr std::string_view kNames[] = {"double", "float", "counted"};  // in Scalar's order
  return kNames[static_cast<std::size_t>(s)];
}

Algorithm variant(Declaration paper, std::string name, std::string summary) {
  paper.name = std::move(name);
  paper.summary = std::move(summary);
  return Algorithm(std::move(paper));
}

std::optional<Algorithm> Algorithm::on_scalar(Scalar s) const {
  if (s == Scalar::double_) return *this;
  if (kind != Kind::batch || !has_scalar(s)) return std::nullopt;
  Algorithm copy = *this;
  copy.name = name + "@" + std::string(to_string(s));
  copy.summary = summary + " [" + std::string(to_string(s)) + " instantiation: each pair rounded to " +
                 std::string(to_string(s)) + "]";
  copy.table_ = {};
  for (Level l : kLevels) copy.table_[index(l)][index(Scalar::double_)] = table_[index(l)][index(s)];
  copy.stages.clear();
  copy.counters = {};
  return copy;
}

std::string Algorithm::levels() const {
  std::string out;
  for (Level level : kLevels) {
    if (!answers(level)) continue;
    if (!out.empty()) out += ',';
    out += to_string(level);
  }
  return out;
}

void Registry::add(Algorithm algorithm) {
  if (algorithm.name.empty()) throw std::logic_error("an algorithm was registered without a name");
  if (find(algorithm.name))
    throw std::logic_error("algorithm '" + algorithm.name + "' is registered twice");
  if (!algorithm.answers(Level::overlap) && !algorithm.answers(Level::relation) && !algorithm.answers(Level::segment))
    throw std::logic_error("algorithm '" + algorithm.name + "' answers no level");
  algorithm.folder = current_folder_;
  algorithms_.push_back(std::move(algorithm));
}

const Algorithm* Registry::find(std::string_view name) const {
  for (const auto& a : algorithms_)
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace tritri
