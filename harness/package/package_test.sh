#!/usr/bin/env bash
# Installs tritri into a scratch prefix, then builds and runs harness/package/consumer against it with
# find_package(tritri): the tutorial's third step, exactly as another project would do it.
set -euo pipefail
build=$1
source=$2
work="$build/package-test"
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$source/harness/package/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" -j 2 >/dev/null
cd "$work/build"
# first run records the consumer's baseline of singular-corpus disagreements; the second holds it
TRITRI_WRITE_BASELINE=1 ./my_triangle_test --gtest_brief=1
./my_triangle_test --gtest_brief=1
grep -q . separating-axes-expected-failures.tsv
# The installed tritri finds the v3fma build's module where the package put it (when one was
# built and this CPU can run it: else tritri says why on stderr and lists none).
if find "$work/prefix" -name 'libtritri_v3fma.so' | grep -q .; then
  "$work/prefix/bin/tritri" list --tsv >"$work/list.tsv" 2>"$work/list.err"
  grep -q 'is not loaded' "$work/list.err" || grep -q '^moller97@v3fma	' "$work/list.tsv" ||
    { echo "the installed tritri does not load its v3fma module:" >&2; cat "$work/list.err" >&2; exit 1; }
fi
