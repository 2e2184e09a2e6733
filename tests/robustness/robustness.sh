#!/bin/sh
# Robustness of the rockbolt executable towards its files.
#
#   sh tests/robustness/robustness.sh TEST ROCKBOLT SCRATCH_DIR
#
# Run from the source root (ctest does). Each TEST is one function below;
# it exits 0 (pass), 1 (fail) or 77 (skipped).
#   unwritable   an output that cannot be written is exit 2 before any
#                solving, and no other output is written either
#   inputs       a run leaves its case, base and record byte-for-byte as
#                they were, and adds no file next to them
#   over_inputs  an output path that names the base or the record of the
#                case is refused (exit 2) and both stay as they were
set -u
T=$1
RB=$2
D=$3
rm -rf "$D"
mkdir -p "$D" || exit 1

fail() {
    echo "FAIL [$T]: $*"
    for f in "$D/out" "$D/err"; do
        [ -f "$f" ] && { echo "--- $f"; head -20 "$f"; }
    done
    exit 1
}

# run ARGS...: exit code in $rc, stdout in $D/out, stderr in $D/err, and
# the wall time in milliseconds in $ms
run() {
    t0=$(date +%s%N)
    "$RB" "$@" >"$D/out" 2>"$D/err" </dev/null
    rc=$?
    ms=$(( ($(date +%s%N) - t0) / 1000000 ))
}

# A private copy of the El Centro case with its base and record, so that
# the tests can check and even target them without touching the sources.
copy_case() {
    mkdir -p "$D/case/base" "$D/case/records" || fail "cannot make $D/case"
    cp cases/reference-elcentro.yaml "$D/case/" &&
    cp cases/base/reference-cabinet.yaml "$D/case/base/" &&
    cp cases/records/elcentro_1940_ns.at2 "$D/case/records/" ||
        fail "cannot copy the El Centro case"
    CASE=$D/case/reference-elcentro.yaml
    BASE=$D/case/base/reference-cabinet.yaml
    REC=$D/case/records/elcentro_1940_ns.at2
}

# Checksums and the file list of the case tree, to compare before/after.
snapshot() {
    (cd "$D/case" && find . -type f | sort && find . -type f | sort | xargs cksum)
}

test_unwritable() {
    mkdir -p "$D/outdir"
    # The text report could be written; the JSON one cannot. Neither may be.
    run check cases/reference-elcentro.yaml --text "$D/outdir/r.txt" \
        --json /nonexistent-dir/x.json
    [ "$rc" -eq 2 ] || fail "exit code $rc, expected 2"
    grep -q "/nonexistent-dir/x.json" "$D/err" || fail "stderr does not name the path"
    [ -z "$(ls -A "$D/outdir")" ] || fail "files written: $(ls -A "$D/outdir")"
    [ -e /nonexistent-dir ] && fail "/nonexistent-dir exists"
    # Refused before solving: this case (the reference cabinet rocking
    # under ten harmonic motions of an hour each, the longest run a case
    # may ask for, at a level that breaks nothing so that every run goes to
    # its end) takes about 3 s to solve in an optimised build and far
    # longer under sanitizers; the refusal is a stat() and must come back
    # well within a second, and must be the output's, not the case's.
    {
        echo "extends: $(pwd)/cases/base/reference-cabinet.yaml"
        echo "motions:"
        for i in 1 2 3 4 5 6 7 8 9 10; do
            echo "  - { type: harmonic, amplitude: 0.3 A*, frequency: 4 Hz, duration: 3600 s }"
        done
    } >"$D/long.yaml" || fail "cannot write long.yaml"
    run check "$D/long.yaml" --json /nonexistent-dir/x.json
    [ "$rc" -eq 2 ] || fail "exit code $rc, expected 2"
    grep -q "/nonexistent-dir/x.json" "$D/err" || fail "the long case was refused, not the output"
    [ "$ms" -lt 1000 ] || fail "refusal took $ms ms: did it solve first?"
    # A directory as the output, and an output in a directory that is a file.
    run check cases/reference-harmonic.yaml --json "$D/outdir"
    [ "$rc" -eq 2 ] || fail "--json DIR: exit code $rc, expected 2"
    : >"$D/plain"
    run check cases/reference-harmonic.yaml --history "$D/plain/h.csv"
    [ "$rc" -eq 2 ] || fail "--history FILE/x: exit code $rc, expected 2"
    # A directory without write permission (root may write anyway).
    if [ "$(id -u)" -ne 0 ]; then
        mkdir -p "$D/ro" && chmod 0555 "$D/ro"
        run check cases/reference-harmonic.yaml --json "$D/ro/x.json"
        chmod 0755 "$D/ro"
        [ "$rc" -eq 2 ] || fail "read-only dir: exit code $rc, expected 2"
        [ -z "$(ls -A "$D/ro")" ] || fail "files written in the read-only dir"
    fi
    echo "unwritable outputs refused, the long case in $ms ms"
}

test_inputs() {
    copy_case
    snapshot >"$D/before"
    touch -d '2001-01-01 00:00:00' "$CASE" "$BASE" "$REC"
    run check "$CASE" --json "$D/r.json" --text "$D/r.txt" --history "$D/h.csv"
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "exit code $rc, expected 0 or 1"
    [ -s "$D/r.json" ] && [ -s "$D/r.txt" ] && [ -s "$D/h.csv" ] ||
        fail "a report is missing"
    snapshot >"$D/after"
    cmp -s "$D/before" "$D/after" || fail "the case tree changed: $(diff "$D/before" "$D/after")"
    for f in "$CASE" "$BASE" "$REC"; do
        [ -n "$(find "$f" ! -newermt '2001-01-02')" ] || fail "$f was touched"
    done
    echo "case, base and record unchanged after a run"
}

test_over_inputs() {
    copy_case
    snapshot >"$D/before"
    run check "$CASE" --json "$REC"
    [ "$rc" -eq 2 ] || fail "--json RECORD: exit code $rc, expected 2"
    run check "$CASE" --text "$BASE"
    [ "$rc" -eq 2 ] || fail "--text BASE: exit code $rc, expected 2"
    snapshot >"$D/after"
    cmp -s "$D/before" "$D/after" || fail "an input was overwritten"
    echo "outputs over the base or the record refused"
}

case $T in
unwritable) test_unwritable ;;
inputs) test_inputs ;;
over_inputs) test_over_inputs ;;
*) echo "unknown test $T"; exit 2 ;;
esac
