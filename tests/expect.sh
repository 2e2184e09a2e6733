# What the shell end-to-end tests of batch, ci and hostile share; sourced
# from the source root after they set rb (the executable) and s (their
# scratch directory).

fail() { echo "FAIL: $*" >&2; exit 1; }

# run EXPECTED_RC ARGS...: rockbolt with stdout/stderr kept in $s
run() {
    want=$1
    shift
    "$rb" "$@" >"$s/out" 2>"$s/err"
    rc=$?
    [ "$rc" -eq "$want" ] || { cat "$s/err" >&2; fail "rockbolt $* exited $rc, expected $want"; }
}

has() { grep -q -- "$2" "$1" || fail "$1 lacks '$2'"; }
lacks() { ! grep -q -- "$2" "$1" || fail "$1 has '$2'"; }
