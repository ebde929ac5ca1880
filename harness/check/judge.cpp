#include "harness/check/judge.hpp"

namespace tritri {
namespace {

std::string dimension_word(Dimension d) { return "dim:" + std::string(to_string(d)); }

}  // namespace

Overlap implied_overlap(const RelationAnswer& a) {
  if (a.relation == Relation::unsupported) return Overlap::unsupported;
  const Dimension d = a.relation == Relation::unknown || a.relation == Relation::degenerate ? a.dimension : dimension_of(a.relation);
  if (d == Dimension::unknown) return Overlap::unsupported;
  return d == Dimension::none ? Overlap::no : Overlap::yes;
}

Overlap implied_overlap(const SegmentAnswer& s) {
  if (s.kind == SegmentKind::unsupported) return Overlap::unsupported;
  return s.kind == SegmentKind::empty ? Overlap::no : Overlap::yes;
}

Verdict judge_overlap(Overlap answer, const Truth& truth) {
  if (answer == Overlap::unsupported) return Verdict::unsupported;
  return (answer == Overlap::yes) == truth.overlap ? Verdict::right : Verdict::wrong;
}

RelationVerdict judge_relation(const RelationAnswer& r, const Truth& truth) {
  if (r.relation == Relation::unsupported) return {Verdict::unsupported, "unsupported", ""};
  const bool by_dimension = r.relation == Relation::unknown || truth.degenerate;
  RelationVerdict v;
  if (by_dimension) {
    const Dimension said = r.relation == Relation::unknown || r.relation == Relation::degenerate ? r.dimension : dimension_of(r.relation);
    v.said = dimension_word(said);
    v.expected = dimension_word(truth.dimension);
    v.verdict = said == truth.dimension ? Verdict::right : Verdict::wrong;
  } else {
    v.said = std::string(to_string(r.relation));
    v.expected = std::string(to_string(truth.relation));
    v.verdict = r.relation == truth.relation ? Verdict::right : Verdict::wrong;
  }
  return v;
}

std::string relation_word(const RelationAnswer& a) {
  if (a.relation == Relation::unknown) return dimension_word(a.dimension);
  return std::string(to_string(a.relation));
}

}  // namespace tritri
