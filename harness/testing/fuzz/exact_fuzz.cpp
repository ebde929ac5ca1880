// libFuzzer entry point: the exact algorithm (algorithms/exact) against the oracle on pairs built from the
// fuzzer's bytes. Aborts on the first disagreement, at either level, on any path (one-pair API,
// and the batch on every ISA this machine runs, the pair placed at every lane position).
//
// The first byte picks how the remaining bytes become a pair:
//   0  18 raw doubles (non-finite ones replaced by 0)
//   1  18 small integers in -3..3 (shared vertices, coplanar, touching, degenerate)
//   2  small integers scaled by a power of two taken from the bytes (2^-1074 .. 2^1000)
//   3  small integers, each coordinate moved by a few ulps (near-singular)
//   4  small integers plus a common offset 2^-k (exact translation off the grid)
// Built with -DTRITRI_FUZZ=ON; scripts/test runs it. An oracle that throws (contradicts itself)
// is a finding too, as in differential_fuzz.cpp.
#include "algorithms/exact/exact.hpp"
#include "cases/oracle/oracle.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace tritri;
namespace ex = tritri::exact;

namespace {

struct Bytes {
  const std::uint8_t* p;
  std::size_t n;
  std::uint8_t next() {
    if (n == 0) return 0;
    --n;
    return *p++;
  }
  double raw() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(next()) << (8 * i);
    double d;
    std::memcpy(&d, &bits, sizeof d);
    return std::isfinite(d) ? d : 0.0;
  }
  double small() { return static_cast<double>(static_cast<int>(next() % 7) - 3); }
};

[[noreturn]] void fail(const TrianglePair& p, const char* what, int got_rel, int got_dim, const OracleRecord& o) {
  std::fprintf(stderr, "exact disagrees with the oracle (%s): got %d/%d, oracle %d/%d (overlap %d)\n", what, got_rel,
               got_dim, static_cast<int>(o.relation), static_cast<int>(o.dimension), o.overlap);
  for (const Triangle* t : {&p.t1, &p.t2})
    for (const auto& v : t->v) std::fprintf(stderr, " %a %a %a |", v.x(), v.y(), v.z());
  std::fprintf(stderr, "\n");
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Bytes b{data + 1, size - 1};
  const int mode = data[0] % 5;
  TrianglePair p;
  double c[18];
  for (double& x : c) x = mode == 0 ? b.raw() : b.small();
  if (mode == 2) {
    const int e = static_cast<int>((static_cast<unsigned>(b.next()) | (static_cast<unsigned>(b.next()) << 8)) % 2075) - 1074;
    for (double& x : c) x = std::ldexp(x, e);
  } else if (mode == 3) {
    for (double& x : c) {
      const int steps = static_cast<int>(b.next() % 7) - 3;
      for (int s = 0; s < std::abs(steps); ++s) x = std::nextafter(x, steps > 0 ? INFINITY : -INFINITY);
    }
  } else if (mode == 4) {
    const double offset = std::ldexp(1.0, -static_cast<int>(b.next() % 64));
    for (double& x : c) x += offset;
  }
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      p.t1[i][k] = c[3 * i + k];
      p.t2[i][k] = c[9 + 3 * i + k];
    }
  const OracleRecord o = oracle_label(p);
  const RelationAnswer r = ex::relation(p);
  if (r.relation != o.relation || r.dimension != o.dimension) fail(p, "relation", int(r.relation), int(r.dimension), o);
  if ((ex::overlap(p) == Overlap::yes) != o.overlap) fail(p, "overlap", int(ex::overlap(p)), 0, o);
  // the batch: the pair at every position of a batch of 9 general-position fillers
  static const TrianglePair filler{{{Vec3<double>(0, 0, 0), Vec3<double>(4, 0, 0), Vec3<double>(0, 4, 0)}},
                                   {{Vec3<double>(1, 1, -1), Vec3<double>(1, 1, 1), Vec3<double>(2, -3, 0)}}};
  std::vector<TrianglePair> batch(9, filler);
  std::vector<Overlap> ov(batch.size());
  std::vector<RelationAnswer> rel(batch.size());
  for (ex::Isa isa : {ex::Isa::scalar, ex::Isa::sse2, ex::Isa::avx2, ex::Isa::avx512}) {
    if (!ex::supported(isa)) continue;
    for (std::size_t at = 0; at < batch.size(); ++at) {
      batch.assign(batch.size(), filler);
      batch[at] = p;
      ex::overlap_batch_with(isa, batch.data(), batch.size(), ov.data());
      ex::relation_batch_with(isa, batch.data(), batch.size(), rel.data());
      if ((ov[at] == Overlap::yes) != o.overlap) fail(p, ex::to_string(isa), int(ov[at]), 0, o);
      if (rel[at].relation != o.relation || rel[at].dimension != o.dimension)
        fail(p, ex::to_string(isa), int(rel[at].relation), int(rel[at].dimension), o);
    }
  }
  return 0;
}
