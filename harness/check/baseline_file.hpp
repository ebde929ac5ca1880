// Baseline files on disk: plain TSV (algorithms/*/expected-failures.tsv), or the same TSV
// compressed with gzip when the name ends in ".gz" (algorithms/*/expected-failures-corpus.tsv.gz,
// the disagreements on the default corpus: hundreds of thousands of rows, a few hundred
// kilobytes compressed).
#pragma once

#include "harness/check/check_output.hpp"

#include <string>

namespace tritri {

// The whole file, decompressed if it starts with the gzip magic bytes (whatever its name), so
// a reader never guesses from the name. Throws InputError naming the path when it is unreadable or malformed.
std::string read_possibly_gzipped(const std::string& path);

// Writes the baseline atomically: gzip-compressed (deterministically: no time stamp, so
// re-recording an unchanged baseline leaves the file byte for byte the same) when `path` ends
// in ".gz", else plain.
void write_baseline_file(const std::string& path, const Baseline& baseline);

}  // namespace tritri
