#include "harness/bench/workload.hpp"

#include <algorithm>
#include <stdexcept>

namespace tritri::bench {

// Generated from the list in harness/bench/CMakeLists.txt (register_workloads.cpp).
std::vector<std::unique_ptr<Workload>> make_workloads();

namespace {

void add_distinct(std::vector<std::string>& to, const std::vector<std::string>& values) {
  for (const auto& v : values)
    if (std::find(to.begin(), to.end(), v) == to.end()) to.push_back(v);
}

// "*" is the value of every family (a workload whose values are known only once it builds).
bool asked_for(const std::vector<std::string>& values, const std::string& value) {
  return std::find(values.begin(), values.end(), value) != values.end() ||
         std::find(values.begin(), values.end(), "*") != values.end();
}

Selected& selected_entry(std::vector<Selected>& selected, const Workload* w) {
  auto it = std::find_if(selected.begin(), selected.end(), [&](const Selected& s) { return s.workload == w; });
  if (it == selected.end()) it = selected.insert(selected.end(), Selected{w, {}});
  return *it;
}

}  // namespace

const std::vector<std::unique_ptr<Workload>>& workloads() {
  static const std::vector<std::unique_ptr<Workload>> all = make_workloads();
  return all;
}

const Workload* find_workload(const std::string& kind) {
  for (const auto& w : workloads())
    if (w->kind() == kind) return w.get();
  return nullptr;
}

std::string known_workloads() {
  std::string out;
  for (const auto& w : workloads()) out += (out.empty() ? "" : ", ") + w->usage();
  return out;
}

std::vector<Selected> select_workloads(const std::vector<std::string>& specs,
                                       const std::vector<const Algorithm*>& algorithms) {
  std::vector<Selected> selected;
  if (specs.empty()) {
    for (const auto& w : workloads())
      if (w->in_default_set(algorithms)) selected.push_back({w.get(), w->default_values()});
    return selected;
  }
  for (const auto& spec : specs) {
    const auto colon = spec.find(':');
    const Workload* w = find_workload(spec.substr(0, colon));
    if (!w) throw std::invalid_argument("unknown workload '" + spec + "' (known: " + known_workloads() + ")");
    add_distinct(selected_entry(selected, w).values, colon == std::string::npos
                                                         ? w->default_values()
                                                         : std::vector{w->parse_value(spec.substr(colon + 1))});
  }
  return selected;
}

Planned build_pools(const std::vector<Selected>& selected, const WorkloadInput& input) {
  // Per workload that builds pools: the values asked for its levels, and for stages.
  struct Asked {
    const Workload* builder;
    std::vector<std::string> values, for_levels, for_stages;
  };
  std::vector<Asked> asked;
  for (const Selected& s : selected) {
    const Workload* builder = find_workload(s.workload->pools_from());
    if (!builder) throw std::logic_error(s.workload->kind() + ": no workload '" + s.workload->pools_from() + "'");
    auto it = std::find_if(asked.begin(), asked.end(), [&](const Asked& a) { return a.builder == builder; });
    if (it == asked.end()) it = asked.insert(asked.end(), Asked{builder, {}, {}, {}});
    add_distinct(it->values, s.values);
    if (s.workload->times_levels_and_stages()) {
      add_distinct(it->for_levels, s.values);
      add_distinct(it->for_stages, s.values);
    } else {
      add_distinct(s.workload->times_stages() ? it->for_stages : it->for_levels, s.values);
    }
  }
  Planned planned;
  for (const Asked& a : asked) {
    WorkloadPools built = a.builder->build(a.values, input);
    for (auto& p : built.pools) {
      const bool levels = asked_for(a.for_levels, p.value), stages = asked_for(a.for_stages, p.value);
      planned.pools.push_back({std::move(p), levels, stages});
    }
    planned.context.insert(planned.context.end(), built.context.begin(), built.context.end());
  }
  return planned;
}

}  // namespace tritri::bench
