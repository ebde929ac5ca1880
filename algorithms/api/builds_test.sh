#!/usr/bin/env bash
# What the second build (builds.hpp) promises about the machine code:
#   - the baseline build of the algorithms has no fused multiply-add instruction: its
#     -ffp-contract=off (top-level CMakeLists.txt) holds in every library it links;
#   - the v3fma module has some where contraction is possible, in Möller's overlap test on
#     double among others (its plane distances and interval ends are sums of products);
#   - the module exports its entry point alone and asks the program for no tritri symbol, so
#     neither build's templates can be bound to the other's copy at load time.
# Usage: builds_test.sh MODULE BASELINE_LIBRARY...
set -euo pipefail
module=$1
shift
fma=$'\tvfn?m(add|sub)(sub|add)?[0-9]*[ps][sd][ \t]'  # FMA3 mnemonics: vfmadd231pd, vfnmsub132ss, ...
status=0

for lib in "$@"; do
  n=$(objdump -d --no-show-raw-insn "$lib" | grep -cE "$fma" || true)
  if [ "$n" -ne 0 ]; then
    echo "FAIL: $lib (baseline build) has $n FMA instructions:" >&2
    objdump -d --no-show-raw-insn -C "$lib" | grep -E "$fma" | head -n 5 >&2
    status=1
  fi
done
echo "baseline: no FMA instruction in $# libraries"

# Per function of the module, its count of FMA instructions.
per_function=$(objdump -d --no-show-raw-insn -C "$module" |
  awk -v re="$fma" '/^[0-9a-f]+ <.*>:$/ { fn = $0 } $0 ~ re { n[fn]++ } END { for (f in n) print n[f] "\t" f }')
total=$(awk -F'\t' '{ s += $1 } END { print s + 0 }' <<<"$per_function")
moller=$(grep -F 'tritri::moller97::overlap<double' <<<"$per_function" | awk -F'\t' '{ s += $1 } END { print s + 0 }')
echo "v3fma module: $total FMA instructions, $moller in moller97::overlap<double, ...>"
[ "$total" -gt 0 ] || { echo "FAIL: the v3fma module has no FMA instruction" >&2; status=1; }
[ "$moller" -gt 0 ] || { echo "FAIL: moller97::overlap<double> in the v3fma module has no FMA instruction" >&2; status=1; }

# (A sanitizer build adds its runtime's hooks: not tritri's.)
exported=$(nm -D --defined-only "$module" | awk '{ print $NF }' | grep -vE '^_+(odr_)?(asan|ubsan|sancov|sanitizer)' || true)
if [ "$exported" != tritri_build_registry ]; then
  echo "FAIL: the module exports more than its entry point:" >&2
  head -n 10 <<<"$exported" >&2
  status=1
fi
if nm -D --undefined-only -C "$module" | grep -q 'tritri::'; then
  echo "FAIL: the module takes tritri symbols from the program:" >&2
  nm -D --undefined-only -C "$module" | grep 'tritri::' | head -n 5 >&2
  status=1
fi
exit "$status"
