#!/bin/sh
# The help of every command, the options it documents against the parser,
# "did you mean", and the man page and completions made from the same
# source (src/cli/help.txt).
#
#   sh tests/install/help_test.sh ROCKBOLT MANPAGE BASH_COMPLETION ZSH_COMPLETION SCRATCH
#
# Run from the source root. Exit 0 pass, 1 fail.
set -u
RB=$1 MAN=$2 BASHC=$3 ZSHC=$4 D=$5
rm -rf "$D" && mkdir -p "$D" || exit 1
CASE=cases/reference-harmonic.yaml

fail() {
    echo "FAIL [help]: $*"
    for f in "$D/out" "$D/err"; do
        [ -f "$f" ] && { echo "--- $f"; head -20 "$f"; }
    done
    exit 1
}
run() {
    "$RB" "$@" >"$D/out" 2>"$D/err"
    rc=$?
}

COMMANDS="check design batch merge init help"
for c in $COMMANDS; do
    run help "$c"
    [ "$rc" -eq 0 ] || fail "help $c: exit code $rc"
    [ -s "$D/err" ] && fail "help $c wrote to stderr"
    head -1 "$D/out" | grep -q "^usage: rockbolt $c" || fail "help $c: no usage line"
    cp "$D/out" "$D/help-$c"
    if [ "$c" != help ]; then
        run "$c" --help
        [ "$rc" -eq 0 ] || fail "$c --help: exit code $rc"
        cmp -s "$D/out" "$D/help-$c" || fail "'$c --help' differs from 'help $c'"
    fi
    # every documented option is one the parser takes: given with a value
    # where it needs one, then --help, it must reach the help
    sed -n '/^options:/,$p' "$D/help-$c" | grep -E '^  -' | while read -r spec; do
        names=$(echo "$spec" | sed 's/  .*//' | tr ',' ' ')
        value=
        case "$spec" in
            *" DIR"*) value=. ;;
            *" I/N"*) value=1/2 ;;
            *" N "*|*" N") value=2 ;;
            *" FILE"*|*" CASE"*) value=x ;;
            *" NAME"*) value=cp1252 ;;
            *" pfa|sa"*) value=sa ;;
        esac
        for n in $names; do
            case "$n" in -*) ;; *) continue ;; esac
            if [ -n "$value" ]; then run "$c" "$n" "$value" --help
            else run "$c" "$n" --help; fi
            [ "$rc" -eq 0 ] || { echo "FAIL [help]: '$c $n' is documented but not taken (exit $rc)"; cat "$D/err"; exit 1; }
        done
    done || exit 1
done

# the overview names every command and the exit codes
run --help
[ "$rc" -eq 0 ] || fail "--help exit code $rc"
for c in $COMMANDS "exit codes" "RB_DATA_DIR" "0  the design passes" "3  internal"; do
    grep -q -- "$c" "$D/out" || fail "--help does not mention '$c'"
done

# batch's options, all described
for o in --base --csv --junit --reports --shard --sandbox --design --threads --json; do
    grep -q -- "^  .*$o" "$D/help-batch" || fail "help batch does not describe $o"
done

# unknown options and commands: a hint, exit 2, one line
run check "$CASE" --jsn x.json
[ "$rc" -eq 2 ] || fail "--jsn: exit code $rc"
grep -q "^rockbolt: error: unknown option '--jsn' for 'check'; did you mean '--json'?" "$D/err" ||
    fail "no hint for --jsn"
[ "$(wc -l <"$D/err")" -eq 1 ] || fail "more than one line for --jsn"
run batch "$CASE" --shrad 1/2
[ "$rc" -eq 2 ] || fail "--shrad: exit code $rc"
grep -q "did you mean '--shard'?" "$D/err" || fail "no hint for --shrad"
run check "$CASE" --design
[ "$rc" -eq 2 ] || fail "check --design: exit code $rc"
grep -q "'--design' is an option of 'batch'" "$D/err" || fail "no owner named for --design"
run chekc "$CASE"
[ "$rc" -eq 2 ] || fail "chekc: exit code $rc"
grep -q "did you mean 'check'?" "$D/err" || fail "no hint for chekc"
run help frobnicate
[ "$rc" -eq 2 ] || fail "help frobnicate: exit code $rc"
# a long option must be spelled out (getopt_long would take "--jso")
run check "$CASE" --jso "$D/a.json"
[ "$rc" -eq 2 ] || fail "--jso taken as --json (exit $rc)"
[ -e "$D/a.json" ] && fail "--jso wrote a report"
# the forms getopt_long gives, as before: =VALUE, -jN, options after operands, --
run design "$CASE" -j2 --quiet --json="$D/b.json"
[ "$rc" -le 1 ] || fail "-j2 --json=FILE: exit code $rc"
[ -s "$D/b.json" ] || fail "--json=FILE not written"
run check -- "$CASE" --quiet
[ "$rc" -eq 2 ] || fail "'--' does not end the options (exit $rc)"

# the man page: one section per command, every option of the help
[ -s "$MAN" ] || fail "no man page at $MAN"
for c in $COMMANDS; do
    C=$(echo "$c" | tr a-z A-Z)
    grep -q "^\.SH \"ROCKBOLT $C\"" "$MAN" || fail "man page has no section for $c"
done
for o in --base --csv --junit --reports --shard --sandbox --sweep-csv --history; do
    grep -q -- "$(echo "$o" | sed 's/-/\\\\-/g')" "$MAN" || fail "man page lacks $o"
done
if command -v man >/dev/null 2>&1 && man -l "$MAN" >"$D/man.txt" 2>"$D/man.err"; then
    grep -q "ROCKBOLT BATCH" "$D/man.txt" || fail "man -l: no batch section"
    grep -q -- "--shard I/N" "$D/man.txt" || fail "man -l: --shard not rendered"
    echo "man page rendered with man -l"
elif command -v groff >/dev/null 2>&1; then
    groff -man -Tutf8 -ww -z "$MAN" 2>"$D/groff.err" || fail "groff rejects the man page"
    [ -s "$D/groff.err" ] && fail "groff warnings: $(head -3 "$D/groff.err")"
    echo "man page checked with groff"
else
    head -1 "$MAN" | grep -q '^\.' || fail "man page is not roff"
    echo "man page structure checked (no man or groff here)"
fi

# the completions parse, and offer the commands and an option
bash -n "$BASHC" || fail "bash completion does not parse"
out=$(bash -c ". '$BASHC'; COMP_WORDS=(rockbolt ba); COMP_CWORD=1; _rockbolt; echo \"\${COMPREPLY[*]}\"")
[ "$out" = batch ] || fail "bash completion of 'ba': '$out'"
out=$(bash -c ". '$BASHC'; COMP_WORDS=(rockbolt batch --sh); COMP_CWORD=2; _rockbolt; echo \"\${COMPREPLY[*]}\"")
[ "$out" = --shard ] || fail "bash completion of 'batch --sh': '$out'"
if command -v zsh >/dev/null 2>&1; then
    zsh -n "$ZSHC" || fail "zsh completion does not parse"
fi
head -1 "$ZSHC" | grep -q '^#compdef rockbolt' || fail "zsh completion lacks #compdef"
echo "help, man page and completions: ok"
rm -rf "$D"
exit 0
