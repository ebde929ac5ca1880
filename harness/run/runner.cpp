#include "harness/run/runner.hpp"

#include "harness/run/process_plugin.hpp"

#include <type_traits>

namespace tritri {
namespace {

RunAnswers run_process(ProcessPluginOptions process, const Algorithm& algorithm,
                       const std::vector<std::string>& names, const std::vector<TrianglePair>& pairs,
                       LevelSet levels, std::size_t max_faults) {
  process.max_faults = max_faults;
  ProcessAnswers got = run_process_plugin(process, names, pairs);
  RunAnswers out;
  out.stopped_at = got.stopped_at;
  if (levels.contains(Level::overlap)) out.overlap = std::move(got.overlap);
  if (levels.contains(Level::relation) && algorithm.answers(Level::relation)) out.relation = std::move(got.relation);
  out.faults = std::move(got.faults);
  return out;
}

// The answers are written to memory shared with the child that computes them, one array per
// level asked for that the algorithm answers.
RunAnswers run_batches(const Algorithm& algorithm, const std::vector<TrianglePair>& pairs, LevelSet levels,
                       const IsolationOptions& isolation) {
  auto wanted = [&](Level l) { return levels.contains(l) && algorithm.has_batch(l); };
  struct Shared {
    SharedArray<Overlap> overlap;
    SharedArray<RelationAnswer> relation;
    SharedArray<SegmentAnswer> segment;
  } shared{SharedArray<Overlap>(wanted(Level::overlap) ? pairs.size() : 0),
           SharedArray<RelationAnswer>(wanted(Level::relation) ? pairs.size() : 0),
           SharedArray<SegmentAnswer>(wanted(Level::segment) ? pairs.size() : 0)};
  RunAnswers out;
  auto arrays_of = [&]<Level L>(std::integral_constant<Level, L>) {
    if constexpr (L == Level::overlap) return std::pair{&shared.overlap, &out.overlap};
    else if constexpr (L == Level::relation) return std::pair{&shared.relation, &out.relation};
    else return std::pair{&shared.segment, &out.segment};
  };
  out.faults = run_isolated(pairs.size(), [&](std::size_t begin, std::size_t end) {
    for_each_level([&](auto level) {
      if (wanted(level())) algorithm.batch<level()>()(pairs.data() + begin, end - begin, arrays_of(level).first->data() + begin);
    });
  }, isolation, &out.stopped_at);
  for_each_level([&](auto level) {
    auto [from, to] = arrays_of(level);
    if (wanted(level())) to->assign(from->data(), from->data() + pairs.size());
  });
  return out;
}

}  // namespace

RunAnswers run_algorithm(const Algorithm& algorithm, const std::vector<std::string>& names,
                         const std::vector<TrianglePair>& pairs, LevelSet levels, const IsolationOptions& isolation) {
  if (const ProcessPluginOptions* process = find_process_plugin(algorithm.name))
    return run_process(*process, algorithm, names, pairs, levels, isolation.max_faults);
  return run_batches(algorithm, pairs, levels, isolation);
}

}  // namespace tritri
