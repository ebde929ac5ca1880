// A process plug-in in C++ that runs any of tritri's registered algorithms through the process
// protocol (harness/run/process_plugin.hpp), protocol 2 with timing:
//     tritri bench --exec 'build/plugins/process-peer moller97' --exec-name moller97-process ...
// Beside the same algorithm timed by Google Benchmark in call mode, and `null` run the same way,
// it shows what timing a test in its own process costs and whether the two clocks agree: the
// protocol's own overhead. Its loop calls the algorithm's one-pair entry through a pointer, one
// call per pair, as call mode does.
#include "tritri/algorithm.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using tritri::Level;
using tritri::Overlap;
using tritri::TrianglePair;
using OverlapFn = tritri::PairFn<Level::overlap>;

bool read_case(const std::string& line, std::string& name, TrianglePair& pair) {
  std::istringstream in(line);
  in >> name;
  for (auto* t : {&pair.t1, &pair.t2})
    for (auto& v : t->v) in >> v.x() >> v.y() >> v.z();
  return static_cast<bool>(in);
}

// Whole passes over the pool until `min_ns` have passed on the steady clock: ns per pair. The
// answers are summed into `live`, so that no pass can be left out.
double passes(OverlapFn test, const std::vector<TrianglePair>& pool, double min_ns, long& live) {
  const auto start = std::chrono::steady_clock::now();
  long count = 0;
  for (;;) {
    for (const auto& p : pool) live += test(p) == Overlap::yes;
    ++count;
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
    if (ns >= min_ns) return ns / (static_cast<double>(count) * static_cast<double>(pool.size()));
  }
}

const char* word(Overlap o) { return o == Overlap::yes ? "1" : o == Overlap::no ? "0" : "unsupported"; }

// '#time N REPETITIONS MIN_SECONDS' and the N cases that follow: answers, then '#timed ...'.
void time_pool(OverlapFn test, const std::string& request) {
  std::istringstream in(request.substr(6));
  std::size_t n = 0;
  int repetitions = 0;
  double min_seconds = 0;
  in >> n >> repetitions >> min_seconds;
  std::vector<std::string> names(n);
  std::vector<TrianglePair> pool(n);
  std::string line;
  for (std::size_t i = 0; i < n && std::getline(std::cin, line); ++i) read_case(line, names[i], pool[i]);
  for (std::size_t i = 0; i < n; ++i) std::cout << names[i] << ' ' << word(test(pool[i])) << '\n';
  long live = 0;
  passes(test, pool, min_seconds * 1e9, live);
  std::cout << "#timed";
  for (int r = 0; r < repetitions; ++r) std::cout << ' ' << passes(test, pool, min_seconds * 1e9, live);
  std::cout << std::endl;
  if (live < 0) std::cerr << "impossible\n";
}

}  // namespace

int main(int argc, char** argv) {
  const tritri::Algorithm* a = argc == 2 ? tritri::registry().find(argv[1]) : nullptr;
  const OverlapFn test = a ? a->one_pair<Level::overlap>() : nullptr;
  if (!test) {
    std::cerr << "usage: process-peer NAME (an algorithm of 'tritri list' with a one-pair overlap entry)\n";
    return 2;
  }
  std::ios::sync_with_stdio(false);  // buffered input, so in_avail() below sees what is waiting
  const char* protocol = std::getenv("TRITRI_PROTOCOL");
  if (protocol && std::atoi(protocol) >= 2) std::cout << "#tritri 2 timing" << std::endl;
  std::string line, name;
  TrianglePair pair;
  while (std::getline(std::cin, line)) {
    if (line.rfind("#time ", 0) == 0) {
      time_pool(test, line);
    } else if (read_case(line, name, pair)) {
      std::cout << name << ' ' << word(test(pair)) << '\n';
      if (std::cin.rdbuf()->in_avail() == 0) std::cout.flush();  // all the input there is is answered
    }
  }
}
