// What the conformance suites test, whether a function or a registered algorithm: its answers at
// each level it gives, for a batch of pairs, and the checks both suites share.
#pragma once

#include "harness/testing/tritri/testing.hpp"

#include "cases/casefile.hpp"
#include "cases/label.hpp"

#include <functional>
#include <string>
#include <vector>

namespace tritri::testing {

// One vector per level; an empty one: the level is not answered.
struct LevelAnswers {
  std::vector<Overlap> overlap;
  std::vector<RelationAnswer> relation;
  std::vector<SegmentAnswer> segment;
};

struct Subject {
  std::string name;
  bool tolerant = false;  // it declares a tolerance: general position keeps clear of it
  std::function<LevelAnswers(const std::vector<TrianglePair>&)> answer;
};

Subject subject_of(OverlapFunction overlap, std::string name);
Subject subject_of(const Algorithm& algorithm, Scalar scalar);

// The oracle's full records of `pairs`, on every core.
std::vector<OracleRecord> oracle_records(const std::vector<TrianglePair>& pairs);

// Every case answered as the oracle does, at every level.
void expect_cases(const Subject& subject, const std::vector<Case>& cases);
// Random pairs in general position answered as the oracle does; segment endpoints to 1e-9
// (unless the subject declares a tolerance).
void expect_general_position(const Subject& subject);
// Each case answered alike with the triangles swapped and their vertices in any order.
void expect_same_in_any_order(const Subject& subject, const std::vector<Case>& cases);
// `pairs`, in both argument orders, answered as the oracle does; `singular_at_least` of them
// must be singular (neither disjoint nor crossing), or the sample proves little.
void expect_pairs(const Subject& subject, const std::vector<TrianglePair>& pairs, std::size_t singular_at_least);

// The pair as a case file line in hex: pasted into a .cases file, it is the same pair.
std::string paste_ready(const TrianglePair& pair);

}  // namespace tritri::testing
