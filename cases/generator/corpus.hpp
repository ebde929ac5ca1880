// The singular-configuration corpus: every family of singular configuration, built
// exactly on small-integer and dyadic grids, then transformed (symmetry, scaling, translation,
// rotation, perturbation). Deterministic: the same options give the same cases, byte for byte,
// whatever the number of threads.
#pragma once

#include "cases/casefile.hpp"
#include "cases/generator/construction.hpp"
#include "cases/oracle/oracle.hpp"
#include "cases/generator/variants.hpp"

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace tritri::corpus {

struct CorpusOptions {
  std::vector<std::string> families;  // empty: all 16
  std::size_t per_family = 144;       // base constructions per family, cycling through its configs
  std::uint64_t seed = 1;
  VariantPlan plan;
};

// The default corpus: 144 base cases per family with all 72 symmetry variants, about 214,000
// cases.
CorpusOptions default_options(std::uint64_t seed = 1);
// For CI: 10 base cases per family (every config of every family at least once), 6 of the 72
// symmetry variants each, one scaling, translation and rotation, all perturbations; about
// 4,000 cases.
CorpusOptions quick_options(std::uint64_t seed = 1);

// One base construction of `config`, moved into a random exact frame of its kind (or left in its
// canonical frame when none is exact), redrawn until both triangles are proper. The corpus and
// the hunt (harness/hunt) build from it.
Construction build_construction(const Family& family, const Config& config, Rng& rng);

// Throws std::invalid_argument naming an unknown family.
std::vector<Case> generate_corpus(const CorpusOptions& options);

// Base constructions per family times the variants each gets, before generation.
std::size_t planned_size(const CorpusOptions& options);

// Adds oracle=<relation> to each case.
void attach_oracle_labels(std::vector<Case>& cases, const std::vector<OracleRecord>& records);

// Counts per family × relation, families in corpus order, with a total row and column.
void print_counts(std::ostream& out, const std::vector<Case>& cases, const std::vector<OracleRecord>& records);

// One file per family, <dir>/<family>.cases, each written atomically; returns their paths.
std::vector<std::string> write_corpus(const std::string& dir, const std::vector<Case>& cases,
                                      const std::string& provenance);

}  // namespace tritri::corpus
