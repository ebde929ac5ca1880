// The algorithms layer alone, for a cross build (aarch64, scripts/cross-answers): reads case files
// and prints each named algorithm's overlap answer per case, `algorithm<TAB>case<TAB>0|1|2`. It
// links nothing but the layer and Eigen, so it reads the case files itself (only the name and the
// 18 coordinates of each line; labels are ignored) rather than through cases/casefile.hpp.
//   answers ALGORITHM[,ALGORITHM...] FILE...
#include "tritri/algorithm.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace tritri {
void register_exact(Registry&);
void register_guigue03(Registry&);
void register_moller97(Registry&);
}  // namespace tritri

namespace {

struct Input {
  std::vector<std::string> names;
  std::vector<tritri::TrianglePair> pairs;
};

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
  std::cerr << "answers: " << where << ": " << problem << "\n";
  std::exit(2);
}

void read_cases(const std::string& file, Input& in) {
  std::ifstream stream(file);
  if (!stream) fail(file, "cannot be read");
  std::string line;
  for (int number = 1; std::getline(stream, line); ++number) {
    std::istringstream tokens(line);
    std::string name;
    if (!(tokens >> name) || name[0] == '#') continue;
    tritri::TrianglePair pair;
    double* x = pair.t1[0].data();  // 18 packed doubles (algorithms/lanes/isa.hpp)
    for (int s = 0; s < 18; ++s) {
      std::string word;
      char* end = nullptr;
      if (!(tokens >> word) || (x[s] = std::strtod(word.c_str(), &end), *end != '\0'))
        fail(file + ":" + std::to_string(number), "coordinate " + std::to_string(s + 1) + " of 18 is missing or not a number");
    }
    in.names.push_back(name);
    in.pairs.push_back(pair);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) fail("usage", "answers ALGORITHM[,ALGORITHM...] FILE...");
  tritri::Registry registry;
  tritri::register_exact(registry);
  tritri::register_guigue03(registry);
  tritri::register_moller97(registry);
  Input in;
  for (int i = 2; i < argc; ++i) read_cases(argv[i], in);
  std::stringstream algorithms(argv[1]);
  for (std::string name; std::getline(algorithms, name, ',');) {
    const tritri::Algorithm* a = registry.find(name);
    if (!a || !a->has_batch(tritri::Level::overlap)) fail(name, "no such algorithm here (exact, guigue03, moller97 and their variants)");
    std::vector<tritri::Overlap> out(in.pairs.size());
    a->batch<tritri::Level::overlap>()(in.pairs.data(), in.pairs.size(), out.data());
    for (std::size_t k = 0; k < out.size(); ++k)
      std::printf("%s\t%s\t%d\n", name.c_str(), in.names[k].c_str(), static_cast<int>(out[k]));
  }
  return 0;
}
