// The stage workload: the stages an algorithm registers (Algorithm::stages, e.g. Yu–He's
// transform into the frame and the test in the frame), each timed on its own on the ratio:0.50
// pool: the very pool ratio:0.50 times the whole test on, when both are run.
#include "harness/bench/workload.hpp"
#include "harness/bench/workloads/ratio.hpp"

#include <algorithm>
#include <stdexcept>

namespace tritri::bench {
namespace {

class StageWorkload : public Workload {
 public:
  StageWorkload() : Workload("stage", "stage") {}
  std::vector<std::string> default_values() const override { return {ratio_text(0.5)}; }
  std::string parse_value(const std::string& value) const override {
    throw std::invalid_argument("stage takes no value ('stage:" + value + "'): it times every registered stage");
  }
  bool in_default_set(const std::vector<const Algorithm*>& algorithms) const override {
    return std::any_of(algorithms.begin(), algorithms.end(), [](const Algorithm* a) { return !a->stages.empty(); });
  }
  std::string pools_from() const override { return "ratio"; }
  bool times_stages() const override { return true; }
  WorkloadPools build(const std::vector<std::string>&, const WorkloadInput&) const override {
    throw std::logic_error("stage builds no pools of its own: it borrows ratio's");
  }
};

}  // namespace

std::unique_ptr<Workload> make_stage_workload() { return std::make_unique<StageWorkload>(); }

}  // namespace tritri::bench
