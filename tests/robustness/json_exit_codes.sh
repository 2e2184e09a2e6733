#!/bin/sh
# json_exit_codes.sh ROCKBOLT SCRATCH: `rockbolt check` on every shipped
# case (cases/*.yaml) and every bad-input case (tests/errors/*.yaml), with
# and without `--json FILE`: the exit codes must agree. A value that only
# the JSON writer could not print (a non-finite number) used to turn a PASS
# (exit 0) into exit 3 with --json. Run from the source tree; the two runs
# of a case go side by side.
set -u
rb=$1
s=$2
rm -rf "$s"
mkdir -p "$s"
fail=0 n=0
for c in cases/*.yaml tests/errors/*.yaml; do
    "$rb" check "$c" -q >/dev/null 2>&1 &
    pid=$!
    "$rb" check "$c" -q --json "$s/r.json" >/dev/null 2>&1
    with=$?
    wait $pid
    without=$?
    rm -f "$s/r.json"
    n=$((n + 1))
    if [ "$with" -ne "$without" ]; then
        echo "$c: exit $without without --json, $with with it"
        fail=1
    fi
done
echo "$n cases, exit codes compared with and without --json"
exit $fail
