#!/usr/bin/env bash
# Runs the README tutorial's commands exactly as written (the '$ ' lines of its fenced blocks,
# from the <!-- tutorial --> marker to the next section), in a scratch copy of the paths they
# use, so the tutorial cannot rot.
set -euo pipefail
source=$1
build=$2
work="$build/tutorial-test"
rm -rf "$work"
mkdir -p "$work"
# The tutorial runs from the top of a built checkout: give it one with this build in place.
for entry in algorithms cases harness; do ln -s "$source/$entry" "$work/$entry"; done
ln -s "$build" "$work/build"
cd "$work"
commands=$(awk '/<!-- tutorial -->/{on=1} on && /^## /{exit} on && /^\$ /{sub(/^\$ /, ""); print}' "$source/README.md")
[ -n "$commands" ] || { echo "tutorial: no commands found in README.md" >&2; exit 1; }
while IFS= read -r command; do
  echo "\$ $command"
  bash -c "$command" > output.txt 2>&1 || { cat output.txt; echo "tutorial: failed: $command" >&2; exit 1; }
  tail -n 3 output.txt
done <<< "$commands"
echo "tutorial: every command ran"
