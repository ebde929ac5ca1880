#!/usr/bin/env bash
# A process peer's findings, held: each case of its witnesses.cases carries `answer=0|1`, the
# answer the pinned package gives (right or wrong: the comment above it says which and why), and
# this fails when the peer answers otherwise, so a finding in its README cannot go stale.
#   witnesses_test.sh TRITRI ALGORITHM CASES
set -euo pipefail
tritri=$1 algorithm=$2 cases=$3
answers=$("$tritri" answer --algo "$algorithm" "$cases")
status=0
while read -r name expected; do
  got=$(awk -v n="$name" '$1 == n { print $2 }' <<<"$answers")
  if [ "$got" != "$expected" ]; then
    echo "$algorithm: $name: answered '${got:-nothing}', its witness records $expected ($cases)" >&2
    status=1
  fi
done < <(grep -v '^#' "$cases" | grep -o '^[^ ]* .* answer=[01]' | awk '{ for (i = 1; i <= NF; i++) if ($i ~ /^answer=/) print $1, substr($i, 8) }')
[ "$status" -eq 0 ] && echo "$algorithm: every witness answered as recorded"
exit "$status"
