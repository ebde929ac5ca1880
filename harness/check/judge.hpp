// The one judge of tritri: whether an algorithm's answer agrees with the oracle. `tritri check`
// and `tritri bench` both score through it, so they can never disagree about the same answer.
#pragma once

#include "cases/label.hpp"
#include "tritri/answers.hpp"

#include <string>

namespace tritri {

enum class Verdict : std::uint8_t { right, wrong, unsupported };

// What a relation answer says about overlap: its dimension decides it (none: no; a point, a
// segment or an area: yes); unsupported when it says nothing.
Overlap implied_overlap(const RelationAnswer& answer);
// What a segment answer says about overlap: empty is no, anything else found is yes.
Overlap implied_overlap(const SegmentAnswer& answer);

Verdict judge_overlap(Overlap answer, const Truth& truth);

// A relation answer is judged by the relation, or by the dimension alone when the algorithm
// states only the dimension (Relation::unknown) or when the pair is degenerate (a zero-area
// triangle has no relation of two proper triangles). `said` and `expected` are the words the
// judgement was made on: relation names, or "dim:<dimension>".
struct RelationVerdict {
  Verdict verdict = Verdict::right;
  std::string said;
  std::string expected;
};
RelationVerdict judge_relation(const RelationAnswer& answer, const Truth& truth);

// "1"/"0": the vocabulary of overlap answers in failures and baselines.
inline std::string overlap_word(bool b) { return b ? "1" : "0"; }
// The relation's name, or "dim:<dimension>" for a dimension-only answer.
std::string relation_word(const RelationAnswer& answer);

}  // namespace tritri
