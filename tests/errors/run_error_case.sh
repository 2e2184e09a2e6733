#!/bin/sh
# One entry of the bad-input catalogue: `rockbolt check` on CASE must exit 2,
# print EXPECT's line as the first line on stderr, and write no output file.
# Usage: run_error_case.sh ROCKBOLT CASE EXPECT   (from the repository root)
set -u
rockbolt=$1
case_file=$2
expect_file=$3
out=$(mktemp -d) || exit 1
trap 'rm -rf "$out"' EXIT

"$rockbolt" check "$case_file" --json "$out/out.json" --text "$out/out.txt" \
    >"$out/stdout" 2>"$out/stderr"
code=$?
fail=0
if [ "$code" -ne 2 ]; then
    echo "exit code $code, want 2"
    fail=1
fi
want=$(head -n 1 "$expect_file")
got=$(head -n 1 "$out/stderr")
if [ "$got" != "$want" ]; then
    echo "first line of stderr differs"
    echo "  want: $want"
    echo "  got:  $got"
    fail=1
fi
for f in out.json out.txt; do
    if [ -e "$out/$f" ]; then
        echo "$f was written despite the bad input"
        fail=1
    fi
done
if [ "$fail" -ne 0 ]; then
    echo "--- stderr:"
    cat "$out/stderr"
fi
exit $fail
