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
#   merge_huge    a sparse 2 GB shard, /dev/zero, a sparse terabyte after a
#                 summary's head, a case of 5 MiB and a head of 100 KiB are
#                 refused at once, at their place, naming the limit (a shard
#                 was read whole, up to 1 GiB)
#   merge_memory  merge of 100 000 rows (made from one real row) peaks under
#                 32 MB and no higher than 1 000 rows plus 2 MB, and writes the
#                 summary back byte for byte (read whole, 100 000 rows took
#                 490 MB)
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
    # a shard is read a case at a time: a sparse 2 GB file is no JSON at
    # its first byte, and a case or a head over its limit is refused
    # there, the limit named, whatever the file's size
    truncate -s 2G "$D/s.json" || exit 77
    run 20 merge "$D/s.json"
    [ "$rc" -eq 2 ] || fail "exit code $rc, want 2"
    grep -q "s.json:1:1: error: summary: not JSON" "$D/err" || fail "no diagnostic at 1:1"
    run 5 merge /dev/zero
    [ "$rc" -eq 2 ] || fail "/dev/zero: exit code $rc, want 2"
    grep -q "/dev/zero: error: cannot read the summary: not a regular file" "$D/err" \
        || fail "/dev/zero: no diagnostic naming why"
    cheap_case "$D/a.yaml"
    "$R" batch "$D/a.yaml" -q --json "$D/one.json" || fail "no summary to start from"
    # a head, then a sparse terabyte after "cases": [
    python3 -c 'import sys
t = open(sys.argv[1]).read()
open(sys.argv[2], "w").write(t[:t.index("\"cases\":\t[") + 10])' "$D/one.json" "$D/t.json" \
        && truncate -s 1T "$D/t.json" || exit 77
    run 20 merge "$D/t.json"
    [ "$rc" -eq 2 ] || fail "1 TB: exit code $rc, want 2"
    grep -q "t.json:[0-9]*:[0-9]*: error: cases: case 1 of the list is longer than the limit of 4096 KiB" \
        "$D/err" || fail "1 TB: no diagnostic naming the limit of a case"
    # a case of 5 MiB, and a head of 100 KiB
    python3 -c 'import sys
t = open(sys.argv[1]).read()
i = t.index("\"index\":")
open(sys.argv[2], "w").write(t[:i] + "\"tag\": \"" + "x" * (5 << 20) + "\", " + t[i:])
i = t.index("\"counts\":")
open(sys.argv[3], "w").write(t[:i] + "\"note\": \"" + "x" * (100 << 10) + "\", " + t[i:])' \
        "$D/one.json" "$D/c.json" "$D/h.json" || exit 77
    run 20 merge "$D/c.json"
    [ "$rc" -eq 2 ] || fail "long case: exit code $rc, want 2"
    grep -q "c.json:15:12: error: cases: case 1 of the list is longer than the limit of 4096 KiB: rockbolt batch writes none so long" \
        "$D/err" || fail "long case: no diagnostic naming the limit"
    run 20 merge "$D/h.json"
    [ "$rc" -eq 2 ] || fail "long head: exit code $rc, want 2"
    grep -q "h.json:7:.*: error: note: the summary's head (what comes before \"cases\") is longer than the limit of 64 KiB" \
        "$D/err" || fail "long head: no diagnostic naming the limit"
    ;;
merge_memory)
    # merge streams its shards: peak memory of a merge of 100 000 rows is
    # that of 1 000 rows, under 32 MB. The rows are made from one real row
    # (index and digest changed), not run; the merged JSON must be the
    # summary itself, byte for byte.
    if grep -q __asan_init "$R" 2>/dev/null; then
        echo "AddressSanitizer build: peak memory not comparable, skipped"
        exit 77
    fi
    if [ -x /usr/bin/time ]; then
        peak() { /usr/bin/time -v "$@" 2>&1 >/dev/null | sed -n 's/.*Maximum resident set size (kbytes): //p'; }
    else
        peak() {
            python3 -c 'import resource, subprocess, sys
subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' "$@"
        }
    fi
    cheap_case "$D/a.yaml"
    "$R" batch "$D/a.yaml" -q --json "$D/one.json" || fail "no summary to start from"
    for n in 1000 100000; do
        python3 - "$D/one.json" "$D/s$n.json" "$n" <<'PY' || fail "cannot make the summary"
import hashlib, re, sys
t = open(sys.argv[1]).read()
n = int(sys.argv[3])
head, rest = t.split('"cases":\t[', 1)
row = rest[:rest.rindex("]")]
assert row.startswith("{") and row.endswith("}"), row[:40]
# the digest is over the row as cJSON prints it unformatted, without the
# digest: the formatted row without its blanks outside strings
bare = re.sub(r',\s*"digest":\t"sha256:[0-9a-f]{64}"', "", row)
flat = "".join(p if i % 2 else re.sub(r"[ \t\n]", "", p)
               for i, p in enumerate(re.split(r'("(?:[^"\\]|\\.)*")', bare)))
assert '"index":0,' in flat and '"index":\t0,' in row
for k in ("total", "cases", "passed", "failed", "unreadable", "errors", "runs"):
    head = re.sub(r'("%s":\t)(\d+)' % k, lambda m: m.group(1) + str(int(m.group(2)) * n), head)
with open(sys.argv[2], "w") as f:
    f.write(head + '"cases":\t[')
    for i in range(n):
        one = flat.replace('"index":0,', '"index":%d,' % i, 1)
        d = "sha256:" + hashlib.sha256(one.encode()).hexdigest()
        r = row.replace('"index":\t0,', '"index":\t%d,' % i, 1)
        r = re.sub(r'"digest":\t"sha256:[0-9a-f]{64}"', '"digest":\t"%s"' % d, r)
        f.write((", " if i else "") + r)
    f.write("]\n}\n")
PY
    done
    small=$(peak "$R" merge "$D/s1000.json" -q --json "$D/m1000.json")
    large=$(peak "$R" merge "$D/s100000.json" -q --json "$D/m100000.json")
    cmp -s "$D/s1000.json" "$D/m1000.json" || fail "1000 rows: the merge is not the summary"
    cmp -s "$D/s100000.json" "$D/m100000.json" || fail "100000 rows: the merge is not the summary"
    [ -n "$small" ] && [ -n "$large" ] || fail "no peak memory measured"
    echo "peak RSS of merge: $small KB for 1000 rows, $large KB for 100000 rows"
    [ "$large" -lt 32768 ] || fail "merge of 100000 rows took $large KB (want < 32 MB)"
    [ $((large - small)) -lt 2048 ] || fail "memory grew by $((large - small)) KB from 1000 to 100000 rows"
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
