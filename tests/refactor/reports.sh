#!/bin/sh
# The JSON report of every case in cases/ and tests/ against its recorded
# digest, so that a change meant to move no number (a refactor) proves it
# moved none.
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
if [ "${3:-}" = --update ]; then
    cp "$D/now" "$LIST" && echo "recorded $(wc -l <"$LIST") cases in $LIST"
    exit 0
fi
if ! diff -u "$LIST" "$D/now" >"$D/diff"; then
    echo "FAIL: reports differ from $LIST (exit code, digest, case):"
    head -40 "$D/diff"
    exit 1
fi
echo "$(wc -l <"$LIST") passed, 0 failed"
