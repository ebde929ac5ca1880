#include "harness/run/plugin.hpp"

#include "tritri/plugin.h"
#include "cases/util/input_error.hpp"

#include <array>
#include <cstddef>
#include <dlfcn.h>
#include <stdexcept>
#include <utility>

namespace tritri {
namespace {

// The ABI's answer structs are laid out exactly as tritri's own, so a plug-in's batch function
// is called with tritri's arrays directly: no conversion and no copy per pair.
static_assert(sizeof(TrianglePair) == 18 * sizeof(double));
static_assert(sizeof(Overlap) == sizeof(unsigned char));
static_assert(sizeof(RelationAnswer) == sizeof(tritri_relation));
static_assert(offsetof(RelationAnswer, relation) == offsetof(tritri_relation, relation));
static_assert(offsetof(RelationAnswer, dimension) == offsetof(tritri_relation, dimension));
static_assert(sizeof(SegmentAnswer) == sizeof(tritri_segment));
static_assert(offsetof(SegmentAnswer, p) == offsetof(tritri_segment, p));
static_assert(offsetof(SegmentAnswer, q) == offsetof(tritri_segment, q));
static_assert(static_cast<int>(SegmentKind::unsupported) == TRITRI_SEGMENT_UNSUPPORTED);
static_assert(static_cast<int>(Relation::unknown) == TRITRI_RELATION_DIMENSION_ONLY);
static_assert(static_cast<int>(Relation::unsupported) == TRITRI_RELATION_UNSUPPORTED);

// Batch entry points carry no context, so each loaded plug-in gets a slot and a set of
// trampolines bound to it at compile time.
constexpr std::size_t kSlots = 16;
std::array<const tritri_plugin*, kSlots> g_plugins{};
std::size_t g_used = 0;

const double* as_doubles(const TrianglePair* pairs) { return reinterpret_cast<const double*>(pairs); }

template <std::size_t S>
void overlap_trampoline(const TrianglePair* pairs, std::size_t n, Overlap* out) {
  g_plugins[S]->overlap(as_doubles(pairs), n, reinterpret_cast<unsigned char*>(out));
}
template <std::size_t S>
void relation_trampoline(const TrianglePair* pairs, std::size_t n, RelationAnswer* out) {
  g_plugins[S]->relation(as_doubles(pairs), n, reinterpret_cast<tritri_relation*>(out));
  // The plug-in may give the relation alone; the dimension follows from it.
  for (std::size_t i = 0; i < n; ++i)
    if (dimension_of(out[i].relation) != Dimension::unknown) out[i].dimension = dimension_of(out[i].relation);
}
template <std::size_t S>
void segment_trampoline(const TrianglePair* pairs, std::size_t n, SegmentAnswer* out) {
  g_plugins[S]->segment(as_doubles(pairs), n, reinterpret_cast<tritri_segment*>(out));
}

template <std::size_t... S>
constexpr auto make_table(std::index_sequence<S...>) {
  struct Entry {
    OverlapBatch overlap;
    RelationBatch relation;
    SegmentBatch segment;
  };
  return std::array<Entry, sizeof...(S)>{
      Entry{&overlap_trampoline<S>, &relation_trampoline<S>, &segment_trampoline<S>}...};
}
constexpr auto kTrampolines = make_table(std::make_index_sequence<kSlots>{});

std::string text(const char* s) { return s ? s : ""; }

}  // namespace

const Algorithm& load_plugin(const std::string& path) {
  auto fail = [&](const std::string& problem) -> InputError {
    return InputError("plug-in '" + path + "': " + problem);
  };
  // dlopen searches the library path for a bare name; a plug-in is a file the user names.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw fail(text(dlerror()));
  auto entry = reinterpret_cast<tritri_plugin_entry_fn>(dlsym(handle, TRITRI_PLUGIN_ENTRY));
  if (!entry) throw fail("does not export " TRITRI_PLUGIN_ENTRY "()");
  const tritri_plugin* p = entry();
  if (!p) throw fail(TRITRI_PLUGIN_ENTRY "() returned NULL");
  if (p->abi != TRITRI_PLUGIN_ABI)
    throw fail("built for plug-in ABI " + std::to_string(p->abi) + ", this tritri speaks " +
               std::to_string(TRITRI_PLUGIN_ABI));
  if (text(p->name).empty()) throw fail("declares no name");
  if (!p->overlap && !p->relation && !p->segment) throw fail("answers no level (all functions NULL)");
  if (registry().find(p->name)) throw fail("its name '" + text(p->name) + "' is already taken");
  if (g_used == kSlots) throw fail("too many plug-ins (at most " + std::to_string(kSlots) + ")");

  const std::size_t slot = g_used++;
  g_plugins[slot] = p;
  Algorithm a;
  a.name = p->name;
  a.citation = text(p->citation);
  a.summary = text(p->summary).empty() ? "plug-in " + path : text(p->summary);
  a.boundary = p->closed ? Boundary::closed : Boundary::open;
  if (p->tolerance_quantity) a.tolerance = {p->tolerance, p->tolerance_quantity, p->tolerance_relative != 0};
  a.accepts_degenerate = p->accepts_degenerate != 0;
  if (p->overlap) a.set_batch<Level::overlap>(Scalar::double_, kTrampolines[slot].overlap);
  if (p->relation) a.set_batch<Level::relation>(Scalar::double_, kTrampolines[slot].relation);
  if (p->segment) a.set_batch<Level::segment>(Scalar::double_, kTrampolines[slot].segment);
  a.folder = "plugin:" + path;
  return add_external_algorithm(std::move(a));
}

}  // namespace tritri
