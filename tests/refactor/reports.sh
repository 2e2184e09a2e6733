#!/bin/sh
# The JSON report of every case in cases/ and tests/, and every other JSON
# output (design, fragility, spectrum, motion, batch: the runs listed in
# tests/refactor/outputs.txt), against its recorded digest, so that a change
# meant to move no number (a refactor) proves it moved none.
#
#   sh tests/refactor/reports.sh ROCKBOLT SCRATCH           check
#   sh tests/refactor/reports.sh ROCKBOLT SCRATCH --update  record anew
#
# Run from the source root. A change that moves results on purpose records
# the digests anew in the same commit and says why. Cases that do not load
# or do not solve (the error cases) are recorded by their exit code alone.
set -u
RB=$1 D=$2
LIST=tests/refactor/reports.sha256
rm -rf "$D" && mkdir -p "$D" || exit 1
# a cap per case, so that a hang fails the test instead of stalling it (60 s:
# a triaxial AC156 suite of seven sets takes 10 s of one core to generate)
find cases tests -name '*.yaml' -not -path '*/fuzz/*' | LC_ALL=C sort >"$D/cases"
: >"$D/now"
while read -r c; do
    out="$D/report.json"
    rm -f "$out"
    timeout 60 "$RB" check "$c" --json "$out" --quiet >/dev/null 2>&1
    rc=$?
    if [ -f "$out" ]; then
        sum=$(sha256sum <"$out" | cut -c1-64)
    else
        sum=-
    fi
    printf '%s %s %s\n' "$rc" "$sum" "$c" >>"$D/now"
done <"$D/cases"
# the other commands' JSON: "COMMAND ARG..." a line, "@" the scratch directory
grep -v '^#' tests/refactor/outputs.txt | grep . >"$D/runs"
while read -r run; do
    out="$D/out.json"
    rm -rf "$out" "$D/floors"
    # shellcheck disable=SC2086 # the line is split into its words on purpose
    timeout 120 "$RB" $(printf '%s\n' "$run" | sed "s|@|$D|g") --json "$out" --quiet </dev/null \
        >/dev/null 2>&1
    rc=$?
    if [ -f "$out" ]; then
        sum=$(sed "s|$D|@|g" "$out" | sha256sum | cut -c1-64)
    else
        sum=-
    fi
    printf '%s %s %s\n' "$rc" "$sum" "$run" >>"$D/now"
done <"$D/runs"
if [ "${3:-}" = --update ]; then
    cp "$D/now" "$LIST" && echo "recorded $(wc -l <"$LIST") outputs in $LIST"
    exit 0
fi
if ! diff -u "$LIST" "$D/now" >"$D/diff"; then
    echo "FAIL: reports differ from $LIST (exit code, digest, case):"
    head -40 "$D/diff"
    exit 1
fi
echo "$(wc -l <"$LIST") passed, 0 failed"
