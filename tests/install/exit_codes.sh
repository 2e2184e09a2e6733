#!/bin/sh
# Each exit code of docs/exit-codes.md, driven by the case or the command
# line the table names for it.
#
#   sh tests/install/exit_codes.sh ROCKBOLT SCRATCH
#
# Run from the source root. Exit 0 pass, 1 fail.
set -u
RB=$1 D=$2
rm -rf "$D" && mkdir -p "$D" || exit 1

fail() {
    echo "FAIL [exit codes]: $*"
    [ -f "$D/err" ] && { echo "--- stderr"; head -20 "$D/err"; }
    exit 1
}
# expect CODE WHAT ARGS...
expect() {
    want=$1 what=$2
    shift 2
    "$RB" "$@" >"$D/out" 2>"$D/err"
    rc=$?
    [ "$rc" -eq "$want" ] || fail "$what: exit code $rc, expected $want (rockbolt $*)"
    echo "$want  $what"
}

expect 0 "every motion passes" check cases/reference-taft.yaml --quiet
expect 1 "a motion fails" check cases/reference-elcentro.yaml --quiet
expect 0 "batch: every case passes" batch cases/reference-taft.yaml --quiet
expect 1 "batch: a case fails" batch cases/reference-taft.yaml cases/reference-elcentro.yaml --quiet

# 2: usage and input
expect 2 "no command" 
expect 2 "unknown command" frobnicate
expect 2 "unknown option" check cases/reference-taft.yaml --frobnicate
expect 2 "missing case file" check "$D/none.yaml"
printf 'equipment:\n  mass: -3 kg\n' >"$D/bad.yaml"
expect 2 "invalid case" check "$D/bad.yaml"
expect 2 "batch: a case cannot be read" batch cases/reference-taft.yaml "$D/bad.yaml" --quiet
# 2: an output that cannot be written, however it cannot
expect 2 "output in a missing directory" check cases/reference-taft.yaml --json "$D/no/such/dir/r.json"
expect 2 "output is a directory" check cases/reference-taft.yaml --json "$D"
expect 2 "output is the case" check cases/reference-taft.yaml --text cases/reference-taft.yaml
if [ -d /proc ] && [ -e /proc/self ]; then
    expect 2 "output in /proc (takes no new files)" check cases/reference-taft.yaml --json /proc/x.json
    expect 2 "batch: output in /proc" batch cases/reference-taft.yaml --json /proc/x.json --quiet
    expect 2 "design: sweep CSV in /proc" design cases/reference-design.yaml --sweep-csv /proc/s.csv --quiet
    expect 2 "batch: reports in /proc" batch cases/reference-taft.yaml --reports /proc --quiet
    [ -e /proc/x.json ] && fail "wrote /proc/x.json"
fi
if [ "$(id -u)" -ne 0 ]; then
    mkdir "$D/ro" && chmod 555 "$D/ro"
    expect 2 "output in a read-only directory" check cases/reference-taft.yaml --json "$D/ro/r.json"
    chmod 755 "$D/ro"
fi

# 3: the solver cannot finish a valid case (a square wave of +-50 g that
# flips every 10 us makes the cabinet chatter past the work bound)
awk 'BEGIN { for (i = 0; i < 30000; i++) print (i % 2 ? -50 : 50) }' >"$D/square.txt"
printf 'extends: %s/cases/base/reference-cabinet.yaml\nmotion:\n  type: record\n  file: square.txt\n  format: one-column\n  units: g\n  dt: 0.01 ms\n' \
    "$(pwd)" >"$D/chatter.yaml"
expect 3 "solver error" check "$D/chatter.yaml" --quiet
expect 3 "batch: solver error" batch "$D/chatter.yaml" --quiet

echo "exit codes: ok"
rm -rf "$D"
exit 0
