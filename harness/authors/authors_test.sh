#!/usr/bin/env bash
# The authors'-code mechanism, end to end, on the stand-in sources (CI has no copy of the
# authors' code): scripts/authors-code refuses a tree without the files and names them; builds
# the seven plug-ins from the stand-in; `tritri diff` sets each port beside its "original" and
# finds the differences (the stand-in is a bounding-box test, so there are some); `tritri bench`
# times them in one run relative to an original.
# Usage: authors_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1
build=$2
tritri="$build/bin/tritri"
out="$build/authors-standin"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. A tree without the files: status 2, each missing file named.
set +e
"$src/scripts/authors-code" "$tmp" --out "$tmp/out" >"$tmp/log" 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] || fail "authors-code on an empty tree: status $rc, expected 2"
for f in Moller1997b/tritri_isectline.c Moller1997b/opttritri.c Guigue2003/tri_tri_intersect.c Shen2003/tri_tri.c; do
  grep -q "$f" "$tmp/log" || fail "the error does not name $f: $(cat "$tmp/log")"
done

# 2. The stand-in builds into seven plug-ins; the copies are the float->double ones.
TRITRI_BUILD_DIR=$build "$src/scripts/authors-code" "$src/harness/authors/standin" \
  --tropp "$src/harness/authors/standin/tr_tri_intersect3D.c" --out "$out" >"$tmp/log"
libs=(moller-tri_tri_intersect moller-NoDivTriTriIsect moller-isectline guigue-overlap guigue-intersection tropp shen)
plugins=()
for l in "${libs[@]}"; do
  [ -f "$out/lib$l.so" ] || fail "lib$l.so was not built"
  plugins+=(--plugin "$out/lib$l.so")
done
! grep -qw float "$out/src/tritri_isectline.c" || fail "the copy still has float"
# The originals written in float are also built as published: unchanged copies, named @float.
for l in moller-tri_tri_intersect-float moller-NoDivTriTriIsect-float moller-isectline-float shen-float; do
  [ -f "$out/lib$l.so" ] || fail "lib$l.so (the float build) was not built"
done
cmp -s "$out/src-float/tri_tri.c" "$src/harness/authors/standin/Volume_08/Number_1/Shen2003/tri_tri.c" ||
  fail "the float build's copy of tri_tri.c is not the file as published"
float_plugins=()
for l in moller-tri_tri_intersect-float shen-float; do float_plugins+=(--plugin "$out/lib$l.so"); done
"$tritri" list --tsv "${float_plugins[@]}" | cut -f1 | grep -qx 'orig-shen03@float' ||
  fail "the float build of Shen's routine is not named orig-shen03@float"
grep -qw float "$src/harness/authors/standin/Volume_02/Number_2/Moller1997b/tritri_isectline.c" ||
  fail "the stand-in should declare float (so that the change is exercised)"

# 3. tritri diff: every port against its original, with the JSON.
pairs=()
for p in moller97 moller97-nodiv moller97-segment guigue03 guigue03-segment tropp06 shen03; do
  pairs+=(--pair "$p=orig-$p")
done
set +e
"$tritri" diff "${plugins[@]}" "${pairs[@]}" --json "$tmp/diff.json" "$src/cases/builtin.cases" >"$tmp/diff.txt"
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "tritri diff: status $rc, expected 1 (the stand-in differs): $(head -20 "$tmp/diff.txt")"
grep -q '^moller97 vs orig-moller97: ' "$tmp/diff.txt" || fail "no moller97 line: $(head "$tmp/diff.txt")"
grep -q '^# .*: overlap guigue03=0 orig-guigue03=1' "$tmp/diff.txt" || fail "no paste-ready guigue03 example"
python3 - "$tmp/diff.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["schema"] == "tritri-diff/1", d["schema"]
assert len(d["pairs"]) == 7, len(d["pairs"])
for p in d["pairs"]:
    assert p["b"] == "orig-" + p["a"], p
    assert p["differ"] > 0, p          # boxes meet far more often than triangles
    assert sum(f["differ"] for f in p["families"]) == p["differ"], p
    assert p["examples"] and p["examples"][0]["case"], p
seg = {p["a"]: p["segment_compared"] for p in d["pairs"]}
assert seg["moller97-segment"] and seg["guigue03-segment"] and not seg["moller97"], seg
PY

# 4. A port and its original timed in one run, relative to the original.
"$tritri" bench "${plugins[@]}" --algo moller97,orig-moller97,guigue03,orig-guigue03 --reference orig-moller97 \
  --workload ratio:0.5 --pool 1024 --repetitions 1 --min-time 0.001 --json "$tmp/bench.json" >"$tmp/bench.txt" 2>&1 ||
  fail "tritri bench with the plug-ins: $(tail -20 "$tmp/bench.txt")"
grep -q 'orig-guigue03' "$tmp/bench.txt" || fail "bench did not time orig-guigue03"

# 5. The float builds beside the ports' float instantiations, in one run: both are timed.
"$tritri" bench "${float_plugins[@]}" --algo shen03@float,orig-shen03@float,moller97@float,orig-moller97@float \
  --mode batch --workload ratio:0.5 --pool 1024 --repetitions 1 --min-time 0.001 --json "$tmp/float.json" \
  >"$tmp/float.txt" 2>&1 || fail "tritri bench with the float builds: $(tail -20 "$tmp/float.txt")"
for a in shen03@float orig-shen03@float moller97@float orig-moller97@float; do
  grep -q "^$a/overlap/ratio:0.50/batch" "$tmp/float.txt" || fail "bench did not time $a: $(tail -20 "$tmp/float.txt")"
done
echo "ok"
