#!/bin/sh
# Outputs of the rockbolt executable: what it writes, where, and what it
# leaves when it fails or is stopped (docs/robustness.md, "Outputs").
#
#   sh tests/robustness/outputs.sh TEST ROCKBOLT SCRATCH_DIR
#
# Run from the source root (ctest does). Each TEST is one function below;
# it exits 0 (pass), 1 (fail) or 77 (skipped).
#   fanout     numbered --svg and --sweep-csv files that would replace the
#              case or its records are refused before solving
#   clashes    batch, merge and check outputs onto inputs (lists, bases,
#              shards, case files under --reports) or onto each other
#   special    '-', a link to standard output, a character device, a FIFO
#              and symbolic links are written through, never replaced; an
#              overwritten report keeps its mode (and owner, as root)
#   names      255-byte names work; a numbered name over the limit is
#              refused before solving, with nothing written
#   signals    TERM while outputs are staged, and TERM during a batch
#              with --reports, leave no temporary file and no output
#   reasons    a full device and a file size limit say why ("No space
#              left on device", "File too large"); a directory as the case
#              says it is one
set -u
T=$1
RB=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
D=$3
rm -rf "$D"
mkdir -p "$D" || exit 1
ROOT=$(pwd)

fail() {
    echo "FAIL [$T]: $*"
    for f in "$D/out" "$D/err"; do
        [ -f "$f" ] && { echo "--- $f"; head -c 2000 "$f" | head -20; }
    done
    exit 1
}

# run ARGS...: exit code in $rc, stdout in $D/out, stderr in $D/err
run() {
    "$RB" "$@" >"$D/out" 2>"$D/err" </dev/null
    rc=$?
}

# A case of two short harmonic motions, under the given file name.
two_motions() {
    cat >"$1" <<EOF
extends: $ROOT/cases/base/reference-cabinet.yaml
name: two
motions:
  - { name: a, type: harmonic, amplitude: 0.3 A*, frequency: 4 Hz, duration: 0.5 s }
  - { name: b, type: harmonic, amplitude: 0.2 A*, frequency: 3 Hz, duration: 0.5 s }
EOF
}

# A case that takes seconds to solve: ten motions of an hour each.
long_case() {
    {
        echo "extends: $ROOT/cases/base/reference-cabinet.yaml"
        echo "name: long"
        echo "motions:"
        for i in 1 2 3 4 5 6 7 8 9 10; do
            echo "  - { name: m$i, type: harmonic, amplitude: 0.3 A*, frequency: 4 Hz, duration: 3600 s }"
        done
    } >"$1"
}

# No temporary file of any naming scheme in the directory.
no_temps() {
    left=$(ls -A "$1" | grep -E '^\.rb-|\.tmp\.' || true)
    [ -z "$left" ] || fail "temporary files left in $1: $left"
}

test_fanout() {
    mkdir -p "$D/f"
    two_motions "$D/f/c-1.yaml"
    cksum "$D/f/c-1.yaml" >"$D/before"
    # --svg c.yaml fans out to c-1.yaml (the case) and c-2.yaml
    run check "$D/f/c-1.yaml" --svg "$D/f/c.yaml"
    [ "$rc" -eq 2 ] || fail "--svg onto the case: exit $rc, expected 2"
    grep -q -- "--svg" "$D/err" && grep -q "c-1.yaml" "$D/err" ||
        fail "the message names neither the option nor the file"
    cksum "$D/f/c-1.yaml" | cmp -s - "$D/before" || fail "the case file changed"
    [ ! -e "$D/f/c-2.yaml" ] || fail "c-2.yaml was written"
    # records rec-1.txt and rec-2.txt, replaced by --svg rec.txt
    awk 'NR > 4 && NF { print $1 }' cases/records/elcentro_1940_ns.at2 | head -400 \
        >"$D/f/rec-1.txt"
    cp "$D/f/rec-1.txt" "$D/f/rec-2.txt"
    cat >"$D/f/recs.yaml" <<EOF
extends: $ROOT/cases/base/reference-cabinet.yaml
name: recs
motions:
  - { name: one, type: record, file: rec-1.txt, format: one-column, dt: 0.01 s, units: g, peak: 0.2 A* }
  - { name: two, type: record, file: rec-2.txt, format: one-column, dt: 0.01 s, units: g, peak: 0.2 A* }
EOF
    cat "$D/f/rec-1.txt" "$D/f/rec-2.txt" | cksum >"$D/before"
    run check "$D/f/recs.yaml" --svg "$D/f/rec.txt"
    [ "$rc" -eq 2 ] || fail "--svg onto the records: exit $rc, expected 2"
    cat "$D/f/rec-1.txt" "$D/f/rec-2.txt" | cksum | cmp -s - "$D/before" ||
        fail "a record changed"
    # design's numbered sweep files are planned from the case too
    cp cases/reference-design.yaml "$D/f/d.yaml"
    sed -i "s|extends: base/|extends: $ROOT/cases/base/|; s|file: records/|file: $ROOT/cases/records/|" \
        "$D/f/d.yaml"
    n=$(grep -c "type: frequency\|type: amplitude" "$D/f/d.yaml")
    if [ "$n" -ge 2 ]; then
        cp "$D/f/d.yaml" "$D/f/s-1.yaml"
        cksum "$D/f/s-1.yaml" >"$D/before"
        run design "$D/f/s-1.yaml" --sweep-csv "$D/f/s.yaml"
        [ "$rc" -eq 2 ] || fail "--sweep-csv onto the case: exit $rc, expected 2"
        cksum "$D/f/s-1.yaml" | cmp -s - "$D/before" || fail "the design case changed"
    fi
    no_temps "$D/f"
    echo "numbered outputs onto the case and its records refused"
}

test_clashes() {
    B=$D/b
    cp -r tests/batch "$B"
    sed -i "s|extends: \(\.\./\)*cases/base/|extends: $ROOT/cases/base/|" "$B/base/harmonic.yaml"
    sum() { cat "$B/list.csv" "$B/base/harmonic.yaml" | cksum; }
    sum >"$D/before"
    cd "$B" || fail "cd"
    run batch list.csv --csv list.csv
    [ "$rc" -eq 2 ] || fail "batch --csv onto the list: exit $rc"
    grep -q -- "--csv" "$D/err" || fail "no option named"
    run batch list.csv --json base/harmonic.yaml
    [ "$rc" -eq 2 ] || fail "batch --json onto a row's base: exit $rc"
    run batch list.csv --json ./base/../base/harmonic.yaml
    [ "$rc" -eq 2 ] || fail "batch --json onto a row's base, spelt differently: exit $rc"
    run batch list.csv --json x --csv ./x
    [ "$rc" -eq 2 ] || fail "batch --json x --csv ./x: exit $rc"
    [ ! -e x ] || fail "x was written"
    run batch cases --json cases/a-pass.yaml
    [ "$rc" -eq 2 ] || fail "batch --json onto a case file of a directory: exit $rc"
    cd "$ROOT" || fail "cd"
    sum | cmp -s - "$D/before" || fail "the list or the base changed"
    # a report named like the case file it reports on
    mkdir -p "$D/r"
    two_motions "$D/r/0-two.txt"
    cksum "$D/r/0-two.txt" >"$D/before"
    run batch "$D/r/0-two.txt" --reports "$D/r"
    [ "$rc" -eq 2 ] || fail "--reports onto the case: exit $rc, expected 2"
    grep -q -- "--reports" "$D/err" || fail "no --reports in the message"
    cksum "$D/r/0-two.txt" | cmp -s - "$D/before" || fail "the case under --reports changed"
    [ "$(ls -A "$D/r")" = "0-two.txt" ] || fail "files written: $(ls -A "$D/r")"
    # a clash found once the cases are read leaves no reports directory
    mkdir -p "$D/rec"
    cp cases/records/elcentro_1940_ns.at2 "$D/rec/"
    sed -e "s|extends: base/|extends: $ROOT/cases/base/|" \
        -e "s|file: records/|file: $D/rec/|" cases/reference-elcentro.yaml >"$D/rec/c.yaml"
    cksum "$D/rec/elcentro_1940_ns.at2" >"$D/before"
    run batch "$D/rec/c.yaml" --reports "$D/rec/new" --json "$D/rec/elcentro_1940_ns.at2"
    [ "$rc" -eq 2 ] || fail "batch --json onto a case's record: exit $rc"
    cksum "$D/rec/elcentro_1940_ns.at2" | cmp -s - "$D/before" || fail "the record changed"
    [ ! -e "$D/rec/new" ] || fail "the reports directory was left"
    # check --json o --html ./o would keep only one
    mkdir -p "$D/c"
    run check cases/reference-harmonic.yaml --json "$D/c/o" --html "$D/c/./o"
    [ "$rc" -eq 2 ] || fail "check --json o --html ./o: exit $rc"
    [ -z "$(ls -A "$D/c")" ] || fail "check wrote $(ls -A "$D/c")"
    # merge onto a shard
    run batch tests/batch/cases --shard 1/2 --json "$D/c/s1.json" -q
    run batch tests/batch/cases --shard 2/2 --json "$D/c/s2.json" -q
    [ -s "$D/c/s1.json" ] && [ -s "$D/c/s2.json" ] || fail "no shards"
    cksum "$D/c/s1.json" >"$D/before"
    run merge "$D/c/s1.json" "$D/c/s2.json" --csv "$D/c/s1.json"
    [ "$rc" -eq 2 ] || fail "merge --csv onto a shard: exit $rc"
    cksum "$D/c/s1.json" | cmp -s - "$D/before" || fail "the shard changed"
    run merge "$D/c/s1.json" "$D/c/s2.json" --csv "$D/c/m" --junit "$D/c/m"
    [ "$rc" -eq 2 ] || fail "merge --csv m --junit m: exit $rc"
    no_temps "$D/c"
    echo "outputs onto inputs and onto each other refused in batch, merge and check"
}

test_special() {
    S=$D/s
    mkdir -p "$S"
    # '-': the JSON report alone on stdout
    run check cases/reference-harmonic.yaml --json - -q
    [ "$rc" -eq 1 ] || fail "--json -: exit $rc"
    [ "$(head -c 1 "$D/out")" = "{" ] || fail "--json -: stdout is not the JSON report"
    tail -n +2 "$D/out" | grep -q "^FAIL" && fail "--json -: the text report is mixed in"
    [ ! -e ./- ] || fail "a file named '-' was written"
    # a link to the process's standard output is written through
    ln -s /proc/self/fd/1 "$S/so"
    "$RB" check cases/reference-harmonic.yaml --json "$S/so" -q >"$S/stdout.json" 2>"$D/err"
    rc=$?
    [ "$rc" -eq 1 ] || fail "--json link-to-stdout: exit $rc"
    [ -L "$S/so" ] || fail "the link to standard output was replaced"
    [ "$(head -c 1 "$S/stdout.json")" = "{" ] || fail "no JSON on standard output"
    # a character device: our own null device as root, else /dev/null
    if [ "$(id -u)" -eq 0 ] && mknod "$S/null" c 1 3 2>/dev/null; then
        NUL=$S/null
    else
        NUL=/dev/null
    fi
    run check cases/reference-harmonic.yaml --json "$NUL" --text "$S/t.txt"
    [ "$rc" -eq 1 ] || fail "--json $NUL: exit $rc"
    [ -c "$NUL" ] || fail "$NUL is no longer a character device"
    [ -s "$S/t.txt" ] || fail "the text report is missing"
    # a FIFO with a reader (timeouts so that nothing can hang)
    mkfifo "$S/fifo" || fail "mkfifo"
    timeout 20 cat "$S/fifo" >"$S/fifo.out" &
    reader=$!
    timeout 20 "$RB" check cases/reference-harmonic.yaml --json "$S/fifo" -q >"$D/out" 2>"$D/err"
    rc=$?
    wait $reader
    [ "$rc" -eq 1 ] || fail "--json FIFO: exit $rc"
    [ -p "$S/fifo" ] || fail "the FIFO was replaced"
    [ "$(head -c 1 "$S/fifo.out")" = "{" ] || fail "the reader got no JSON"
    # a FIFO without a reader is an error, not a wait
    timeout 20 "$RB" check cases/reference-harmonic.yaml --json "$S/fifo" -q >"$D/out" 2>"$D/err"
    rc=$?
    [ "$rc" -eq 3 ] || fail "--json FIFO without a reader: exit $rc, expected 3"
    grep -q "reader" "$D/err" || fail "the message does not say the FIFO has no reader"
    # symbolic links: the target is written, the link stays
    echo old >"$S/real.json"
    ln -s real.json "$S/link.json"
    ln -s new.json "$S/dangling.json"
    run check cases/reference-harmonic.yaml --json "$S/link.json" --text "$S/dangling.json"
    [ "$rc" -eq 1 ] || fail "links: exit $rc"
    [ -L "$S/link.json" ] && [ -L "$S/dangling.json" ] || fail "a link was replaced"
    [ "$(head -c 1 "$S/real.json")" = "{" ] || fail "the link's target was not written"
    [ -s "$S/new.json" ] || fail "the dangling link's target was not made"
    # mode (and, as root, owner) of an overwritten report
    echo old >"$S/kept.json"
    chmod 0640 "$S/kept.json"
    [ "$(id -u)" -eq 0 ] && chown 4321:4322 "$S/kept.json"
    before=$(stat -c '%a %u %g' "$S/kept.json")
    run check cases/reference-harmonic.yaml --json "$S/kept.json" -q
    [ "$rc" -eq 1 ] || fail "overwrite: exit $rc"
    after=$(stat -c '%a %u %g' "$S/kept.json")
    [ "$before" = "$after" ] || fail "mode and owner '$before' became '$after'"
    [ "$(head -c 1 "$S/kept.json")" = "{" ] || fail "not overwritten"
    no_temps "$S"
    echo "'-', standard output, devices, FIFOs and links written through; mode $after kept"
}

test_names() {
    N=$D/n
    mkdir -p "$N"
    long255=$(printf 'a%.0s' $(seq 1 250)).json
    run check cases/reference-harmonic.yaml --json "$N/$long255" -q
    [ "$rc" -eq 1 ] || fail "a 255-byte name: exit $rc, expected 1"
    [ -s "$N/$long255" ] || fail "the 255-byte file is missing"
    no_temps "$N"
    rm -f "$N/$long255"
    # 254 bytes fit, their numbered names (256) do not: refused at once,
    # before a case of seconds is solved, and nothing else is written
    long_case "$D/long.yaml"
    svg=$(printf 'b%.0s' $(seq 1 250)).svg
    t0=$(date +%s%N)
    run check "$D/long.yaml" --json "$N/r.json" --svg "$N/$svg"
    ms=$(( ($(date +%s%N) - t0) / 1000000 ))
    [ "$rc" -eq 2 ] || fail "a numbered name over NAME_MAX: exit $rc, expected 2"
    grep -q -- "--svg" "$D/err" || fail "the message does not name --svg"
    [ "$ms" -lt 2000 ] || fail "refused after $ms ms: did it solve first?"
    [ -z "$(ls -A "$N")" ] || fail "files written: $(ls -A "$N")"
    run check cases/reference-harmonic.yaml --json "$N/$(printf 'c%.0s' $(seq 1 256))"
    [ "$rc" -eq 2 ] || fail "a 256-byte name: exit $rc, expected 2"
    echo "255-byte names written; longer ones refused in $ms ms"
}

# Wait (at most 20 s) until a file shows in directory $1.
wait_for_file() {
    i=0
    while [ -z "$(ls -A "$1")" ]; do
        i=$((i + 1))
        [ "$i" -gt 200 ] && return 1
        sleep 0.1
    done
    return 0
}

test_signals() {
    G=$D/g
    mkdir -p "$G/out"
    # check: the JSON report is staged, then the history goes to a FIFO
    # whose reader never reads, so the run stops there with the staged
    # file on disk; TERM must remove it
    mkfifo "$G/fifo" || fail "mkfifo"
    timeout 30 sh -c 'exec 3<"$1"; sleep 25' sh "$G/fifo" &
    reader=$!
    "$RB" check cases/reference-elcentro.yaml --json "$G/out/r.json" \
        --history "$G/fifo" -q >"$D/out" 2>"$D/err" &
    pid=$!
    wait_for_file "$G/out" || { kill -KILL $pid $reader; fail "nothing was staged"; }
    sleep 0.3
    kill -TERM $pid
    wait $pid
    rc=$?
    kill $reader 2>/dev/null
    wait $reader 2>/dev/null
    [ "$rc" -eq 143 ] || fail "check ended with $rc, expected 143 (TERM)"
    [ -z "$(ls -A "$G/out")" ] || fail "left after TERM: $(ls -A "$G/out")"
    # batch --reports: quick cases are done and staged while the long one
    # runs; TERM leaves no report at all, not half of them
    mkdir -p "$G/cases" "$G/rep"
    for c in a b c; do
        sed "s|extends: base/|extends: $ROOT/cases/base/|" cases/reference-harmonic.yaml \
            | sed "s/^name: .*/name: $c/" >"$G/cases/$c.yaml"
    done
    long_case "$G/cases/z.yaml"
    "$RB" batch "$G/cases" -j 1 --reports "$G/rep" --csv "$G/s.csv" -q \
        >"$D/out" 2>"$D/err" &
    pid=$!
    wait_for_file "$G/rep" || { kill -KILL $pid; fail "no report was staged"; }
    kill -TERM $pid
    wait $pid
    rc=$?
    [ "$rc" -eq 143 ] || fail "batch ended with $rc, expected 143 (TERM)"
    [ -z "$(ls -A "$G/rep")" ] || fail "left after TERM: $(ls -A "$G/rep")"
    [ ! -e "$G/s.csv" ] || fail "the summary was written"
    no_temps "$G"
    echo "TERM during staging and during a batch leaves nothing"
}

test_reasons() {
    R=$D/reasons
    mkdir -p "$R"
    if [ "$(id -u)" -eq 0 ] && mknod "$R/full" c 1 7 2>/dev/null; then
        FULL=$R/full
    else
        FULL=/dev/full
    fi
    run check cases/reference-harmonic.yaml --json "$FULL" -q
    [ "$rc" -eq 3 ] || fail "--json $FULL: exit $rc, expected 3"
    grep -q "No space left on device" "$D/err" || fail "no reason for the full device"
    [ -c "$FULL" ] || fail "$FULL is no longer a device"
    # a regular file that hits a size limit (SIGXFSZ ignored: EFBIG)
    (ulimit -f 8 && trap '' XFSZ && exec "$RB" check cases/reference-elcentro.yaml \
        --history "$R/h.csv" --json "$R/r.json" -q) >"$D/out" 2>"$D/err" </dev/null
    rc=$?
    [ "$rc" -eq 3 ] || fail "file size limit: exit $rc, expected 3"
    grep -q "File too large" "$D/err" || fail "no reason for the size limit"
    [ -z "$(ls -A "$R" | grep -v '^full$')" ] || fail "left: $(ls -A "$R")"
    run check cases
    [ "$rc" -eq 2 ] || fail "check DIR: exit $rc"
    grep -q "directory" "$D/err" || fail "check DIR does not say it is a directory"
    echo "full device, size limit and directory say why"
}

case $T in
fanout) test_fanout ;;
clashes) test_clashes ;;
special) test_special ;;
names) test_names ;;
signals) test_signals ;;
reasons) test_reasons ;;
*) echo "unknown test $T"; exit 2 ;;
esac
