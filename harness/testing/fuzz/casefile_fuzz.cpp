// Fuzzes the case-file reader: any bytes either parse or are refused with a CaseFileError (never
// a crash), and whatever parses round-trips through the writer bit for bit.
#include "cases/casefile.hpp"

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<tritri::Case> cases;
  try {
    std::istringstream in(text);
    cases = tritri::read_cases(in, "fuzz");
  } catch (const tritri::CaseFileError&) {
    return 0;
  }
  std::ostringstream out;
  tritri::write_cases(out, cases);
  std::istringstream again(out.str());
  const auto back = tritri::read_cases(again, "fuzz");
  if (back.size() != cases.size()) std::abort();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (back[i].name != cases[i].name || back[i].labels != cases[i].labels) std::abort();
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) {
        if (std::bit_cast<std::uint64_t>(back[i].pair.t1[v][k]) != std::bit_cast<std::uint64_t>(cases[i].pair.t1[v][k])) std::abort();
        if (std::bit_cast<std::uint64_t>(back[i].pair.t2[v][k]) != std::bit_cast<std::uint64_t>(cases[i].pair.t2[v][k])) std::abort();
      }
  }
  return 0;
}
