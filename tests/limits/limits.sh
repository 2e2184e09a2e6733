#!/bin/sh
# Bounds on work and memory that a single bad case file cannot show.
# Usage: limits.sh TEST ROCKBOLT SCRATCH   (from the repository root)
#   fifo_batch    a FIFO and a directory named *.yaml in a batch directory
#                 are refused by name, and the batch ends (it used to wait
#                 for ever on the FIFO)
#   fifo_check    `check` on a FIFO nobody writes to ends at once (exit 2)
#   fifo_list     an equipment list that is a FIFO is refused, not opened
#   fifo_base     a --base that is a FIFO is refused, not waited on
#   record_bytes  a record file over 256 MiB (blank lines) is refused
#                 before it is read (1 GiB used to be read for 45 s)
#   batch_tmpdir  a batch whose TMPDIR cannot take the streamed summary
#                 stops before any work (exit 2, naming it and why) and
#                 writes no output; with a writable TMPDIR nothing is left
#                 in it
#   batch_tmpdir_full  a TMPDIR that fills while the summary is spooled
#                 (a file size limit stands in for a full disk) names the
#                 temporary file and the system's reason, exit 2, and
#                 writes no output (it said "input/output error", exit 3)
#   digest_huge   a batch of a sparse 1 TB case file, and of /proc/self/pagemap
#                 (which says 0 bytes and reads on for ever), ends at once
#                 with the file unreadable, as check does: the inputs'
#                 digest read every input to its end
#   merge_fifo    merge of a FIFO nobody writes to, or a device, ends at
#                 once naming the file (it waited for ever on the FIFO)
#   record_once   20 motions naming one 100 MB record read it once (within
#                 the 256 MiB of records a case may read), and three that read
#                 it in other units are refused at the third, naming the limit
#                 (each motion read its file again: 20 motions of a 260 MB
#                 record took 160 s)
#   merge_huge    a shard's summary over 1 GiB (sparse) is refused at once,
#                 naming the limit (it was read to 1 GiB, then "cannot read
#                 the summary")
#   batch_memory  peak memory of a batch with every summary output grows by
#                 under 512 bytes per list row, which is the list itself
#                 (2 000 against 20 000 rows; it grew by 2.8 KB before the
#                 rows' errors were kept only for the rows that have one, and
#                 by about 1.4 KB before the summary was streamed)
set -u
T=$1
R=$2
D=$3
rm -rf "$D"
mkdir -p "$D" || exit 1
BASE="$(pwd)/cases/base/reference-cabinet.yaml"

fail() {
    echo "FAIL [$T]: $*"
    for f in "$D/out" "$D/err"; do
        [ -f "$f" ] && { echo "--- $f"; head -n 20 "$f"; }
    done
    exit 1
}

# run SECONDS ARGS...: rockbolt with a time limit; sets rc (124: timed out)
run() {
    secs=$1
    shift
    timeout "$secs" "$R" "$@" >"$D/out" 2>"$D/err"
    rc=$?
}

cheap_case() {
    printf 'extends: %s\nmotion:\n  type: harmonic\n  amplitude: 0.1 A*\n  frequency: 4 Hz\n  duration: 0.01 s\n' \
        "$BASE" >"$1"
}

case "$T" in
fifo_batch)
    mkdir "$D/dir" && cheap_case "$D/dir/a-good.yaml" && mkfifo "$D/dir/b-fifo.yaml" \
        && mkdir "$D/dir/c-dir.yaml" || exit 77
    run 30 batch "$D/dir" -j 2
    [ "$rc" -ne 124 ] || fail "the batch waited on the FIFO"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2 (two entries cannot be read)"
    grep -q "b-fifo.yaml: error: case: not a regular file (a FIFO" "$D/err" \
        || fail "no diagnostic naming the FIFO"
    grep -q "c-dir.yaml: error: case: not a regular file but a directory" "$D/err" \
        || fail "no diagnostic naming the directory"
    grep -q "^a-good .* pass" "$D/out" || fail "the regular case did not run"
    # the same through a glob
    run 30 batch "$D/dir/*.yaml" -j 2
    [ "$rc" -eq 2 ] || fail "glob: exit code $rc, want 2"
    ;;
fifo_check)
    mkfifo "$D/lone.yaml" || exit 77
    run 30 check "$D/lone.yaml"
    [ "$rc" -ne 124 ] || fail "check waited for a writer on the FIFO"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    # a pipe that has a writer is still read (`check <(gen-case)`)
    cheap_case "$D/c.yaml"
    cat "$D/c.yaml" | timeout 30 "$R" check /dev/stdin --quiet >"$D/out" 2>"$D/err"
    rc=$?
    [ "$rc" -eq 0 ] || fail "a pipe with a writer: exit code $rc, want 0"
    ;;
fifo_list)
    mkfifo "$D/list.csv" || exit 77
    run 30 batch "$D/list.csv" --base "$BASE"
    [ "$rc" -ne 124 ] || fail "batch waited on the FIFO list"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "list.csv: error: case: not a regular file" "$D/err" \
        || fail "no diagnostic naming the list"
    ;;
fifo_base)
    mkfifo "$D/base.yaml" || exit 77
    printf 'tag,mass\nA,454 kg\n' >"$D/list.csv"
    run 30 batch "$D/list.csv" --base "$D/base.yaml"
    [ "$rc" -ne 124 ] || fail "batch waited on the FIFO base"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "base.yaml: error: --base: the base case is not a regular file" "$D/err" \
        || fail "no diagnostic naming the base"
    ;;
record_bytes)
    # 270 000 000 bytes, just over 256 MiB: two samples, then blank lines
    { printf '0.1\n-0.1\n'; head -c 270000000 /dev/zero | tr '\0' '\n'; } >"$D/blank.txt" \
        || exit 77
    printf 'extends: %s\nmotion:\n  type: record\n  file: blank.txt\n  format: one-column\n  units: g\n  dt: 0.01 s\n' \
        "$BASE" >"$D/c.yaml"
    start=$(date +%s)
    run 60 check "$D/c.yaml"
    took=$(( $(date +%s) - start ))
    rm -f "$D/blank.txt"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "c.yaml:4:9: error: motion.file: cannot read record .*over the 256 MiB a record may hold" \
        "$D/err" || fail "diagnostic does not name the limit at the key"
    [ "$took" -le 5 ] || fail "took $took s: the file was read before it was refused"
    ;;
batch_tmpdir)
    cheap_case "$D/base.yaml"
    printf 'tag,base,mass\nA,base.yaml,400 kg\nB,base.yaml,500 kg\n' >"$D/list.csv"
    TMPDIR="$D/missing" run 30 batch "$D/list.csv" --json "$D/s.json"
    [ "$rc" -eq 2 ] || fail "unwritable TMPDIR: exit code $rc, want 2"
    grep -q "missing: error: cannot make a temporary file for the summary here: No such file or directory" "$D/err" \
        || fail "no diagnostic naming TMPDIR and why"
    [ ! -e "$D/s.json" ] || fail "a summary was written without its cases"
    mkdir "$D/tmp"
    TMPDIR="$D/tmp" run 30 batch "$D/list.csv" --json "$D/s.json" --csv "$D/s.csv"
    [ "$rc" -eq 0 ] || fail "writable TMPDIR: exit code $rc, want 0"
    grep -q '"cases":[[:space:]]*2' "$D/s.json" || grep -q '"passed":[[:space:]]*2' "$D/s.json" \
        || fail "the summary lacks its counts"
    [ -z "$(ls -A "$D/tmp")" ] || fail "temporary files were left in TMPDIR"
    ;;
batch_tmpdir_full)
    cheap_case "$D/base.yaml"
    { echo tag,base,mass; i=1; while [ $i -le 300 ]; do echo "T$i,base.yaml,$((400 + i)) kg"; i=$((i + 1)); done; } >"$D/list.csv"
    mkdir "$D/tmp"
    # SIGXFSZ ignored: the write fails with EFBIG instead of ending the process
    (trap '' XFSZ; ulimit -f 40 && TMPDIR="$D/tmp" exec "$R" batch "$D/list.csv" --json "$D/s.json" --quiet) \
        >"$D/out" 2>"$D/err"
    rc=$?
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "/tmp/rockbolt-summary-.*: error: cannot write the summary's temporary file: File too large" "$D/err" \
        || fail "no diagnostic naming the temporary file and the reason"
    [ ! -e "$D/s.json" ] || fail "a summary was written"
    [ -z "$(ls -A "$D/tmp")" ] || fail "temporary files were left in TMPDIR"
    ;;
record_once)
    # lines of 16 000 blanks: 100 MB that read fast and hold few samples
    python3 -c "
import sys
line = '0.01' + ' ' * 16000 + '\\n'
open(sys.argv[1], 'w').write(line * (100 * 1024 * 1024 // len(line)))" "$D/big.txt" || exit 77
    m='{type: record, file: big.txt, format: one-column, units: %s, dt: 0.01 s, window: [0 s, 1 s]}'
    { printf 'extends: %s\nmotions:\n' "$BASE"; i=0
      while [ $i -lt 20 ]; do printf "  - $m\n" g; i=$((i + 1)); done; } >"$D/r20.yaml"
    run 60 check "$D/r20.yaml" --quiet
    [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ] || fail "20 motions of one record: exit code $rc, want 0 or 1"
    { printf 'extends: %s\nmotions:\n' "$BASE"
      for u in g m/s^2 cm/s^2; do printf "  - $m\n" "$u"; done; } >"$D/r3.yaml"
    run 60 check "$D/r3.yaml" --quiet
    [ "$rc" -eq 2 ] || fail "three reads of 100 MB: exit code $rc, want 2"
    grep -q "r3.yaml:5:26: error: motions\[3\].file: cannot read record '.*big.txt' (104848755 bytes): the records of one case may take 256 MiB in all" "$D/err" \
        || fail "no diagnostic at the third motion naming the limit"
    ;;
merge_huge)
    truncate -s 2G "$D/s.json" || exit 77
    run 20 merge "$D/s.json"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "s.json: error: cannot read the summary: it is larger than the limit of 1024 MiB" "$D/err" \
        || fail "no diagnostic naming the limit"
    ;;
digest_huge)
    truncate -s 1T "$D/huge.yaml" || exit 77
    run 20 batch "$D/huge.yaml"
    [ "$rc" -ne 124 ] || fail "the batch read the whole sparse file"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "huge.yaml: error: case: .* larger than the limit of 4 MiB" "$D/err" \
        || fail "no diagnostic naming the limit"
    if [ -r /proc/self/pagemap ]; then
        run 20 batch /proc/self/pagemap
        [ "$rc" -ne 124 ] || fail "the batch read /proc/self/pagemap to its end"
        [ "$rc" -eq 2 ] || fail "pagemap: exit code $rc, want 2"
    fi
    # the same list twice: the digest still agrees between shards
    cheap_case "$D/a.yaml"
    run 30 batch "$D/a.yaml" "$D/huge.yaml" --shard 1/2 --json "$D/s1.json"
    [ "$rc" -eq 0 ] || fail "shard 1: exit code $rc, want 0"
    run 30 batch "$D/a.yaml" "$D/huge.yaml" --shard 2/2 --json "$D/s2.json"
    [ "$rc" -eq 2 ] || fail "shard 2: exit code $rc, want 2"
    run 30 merge "$D/s1.json" "$D/s2.json"
    [ "$rc" -eq 2 ] || fail "merge: exit code $rc, want 2 (one unreadable case)"
    ;;
merge_fifo)
    mkfifo "$D/s.json" || exit 77
    run 20 merge "$D/s.json"
    [ "$rc" -ne 124 ] || fail "merge waited for a writer on the FIFO"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "s.json: error: .*not a regular file" "$D/err" \
        || fail "no diagnostic naming the FIFO"
    run 20 merge /dev/zero
    [ "$rc" -eq 2 ] || fail "/dev/zero: exit code $rc, want 2"
    grep -q "/dev/zero: error: .*not a regular file" "$D/err" \
        || fail "no diagnostic naming the device"
    ;;
batch_memory)
    # Under AddressSanitizer every allocation carries redzones and freed
    # memory is held in quarantine: the RSS would measure the sanitizer.
    if grep -q __asan_init "$R" 2>/dev/null; then
        echo "AddressSanitizer build: peak memory not comparable, skipped"
        exit 77
    fi
    # peak RSS of a child, in KB
    if [ -x /usr/bin/time ]; then
        peak() { /usr/bin/time -v "$@" 2>&1 >/dev/null | sed -n 's/.*Maximum resident set size (kbytes): //p'; }
    elif command -v python3 >/dev/null 2>&1; then
        peak() {
            python3 -c 'import resource, subprocess, sys
subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' "$@"
        }
    else
        echo "no /usr/bin/time and no python3: skipped"
        exit 77
    fi
    cheap_case "$D/base.yaml"
    for n in 2000 20000; do
        awk -v n=$n 'BEGIN { print "tag,base,mass"; for (i = 1; i <= n; i++)
            printf "T-%d,base.yaml,%d kg\n", i, 400 + i % 100 }' >"$D/list$n.csv"
    done
    outs() { echo --json "$D/o$1.json" --csv "$D/o$1.csv" --junit "$D/o$1.xml"; }
    # shellcheck disable=SC2046
    small=$(peak "$R" batch "$D/list2000.csv" -j 2 $(outs 2000))
    # shellcheck disable=SC2046
    large=$(peak "$R" batch "$D/list20000.csv" -j 2 $(outs 20000))
    [ "$(grep -c '<testcase ' "$D/o20000.xml")" -eq 20000 ] \
        || fail "the JUnit summary of 20000 rows lacks cases"
    [ -n "$small" ] && [ -n "$large" ] || fail "no peak memory measured"
    per_row=$(( (large - small) * 1024 / 18000 ))
    echo "peak RSS: $small KB for 2000 rows, $large KB for 20000 rows: $per_row bytes per row"
    [ "$per_row" -lt 512 ] || fail "memory grows by $per_row bytes per row (want < 512)"
    ;;
*)
    echo "unknown test $T"
    exit 1
    ;;
esac
rm -rf "$D"
echo "$T: ok"
exit 0
