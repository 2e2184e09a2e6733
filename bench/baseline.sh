#!/bin/sh
# The build that a speed is measured against: a given commit (default
# 4c29ff4, the solver before issue 41) built as a release is built, LTO on,
# into a directory of its own, from a temporary git worktree that is
# removed afterwards. A speed then holds on any machine as a ratio: both
# builds timed in the same run, their runs alternated.
#
# Usage: bench/baseline.sh [COMMIT [DIR [BENCH_SOURCE...]]]   (from the source root)
#   DIR defaults to build-base-COMMIT (beside build/). Each BENCH_SOURCE
#   (a file of bench/ of this tree, such as bench/solve_figures.c) is copied
#   into the commit's bench/ before it is built, so that both builds run
#   the same benchmark program over the same work; the commit's own
#   benchmarks are built too. Prints the directory, whose rockbolt and
#   bench_* programs are the commit's.
# A directory already built for the same commit is brought up to date
# (the copied sources rebuilt), not rebuilt from scratch.
set -eu
commit=${1:-4c29ff4}
full=$(git rev-parse --verify "$commit^{commit}") || {
    echo "baseline.sh: $commit is not a commit of this repository" >&2; exit 2; }
short=$(git rev-parse --short "$full")
dir=${2:-}
[ -n "$dir" ] || dir=build-base-$short
[ $# -gt 2 ] && shift 2 || set --
for f in "$@"; do
    [ -f "$f" ] || { echo "baseline.sh: no file $f" >&2; exit 2; }
done
case $dir in /*) ;; *) dir=$(pwd)/$dir ;; esac
mkdir -p "$dir"
stamp="$dir/.baseline-commit"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" != "$full" ]; then
    echo "baseline.sh: $dir holds a build of $(cat "$stamp"), not $full" >&2
    exit 2
fi

if [ -f "$stamp" ] && [ $# -eq 0 ] && [ -x "$dir/rockbolt" ]; then
    echo "$dir"
    exit 0
fi

tree=$(mktemp -d)
cleanup() {
    git worktree remove --force "$tree/src" >/dev/null 2>&1 || true
    rm -rf "$tree"
}
trap cleanup EXIT INT TERM
git worktree add --detach --quiet "$tree/src" "$full"
for f in "$@"; do
    cp "$f" "$tree/src/bench/"
done
# bench sources name the header they share
[ -f bench/bench_common.h ] && [ $# -gt 0 ] && cp bench/bench_common.h "$tree/src/bench/"

# a worktree at a new temporary path each time: ccache sees paths
# relative to it, so a rebuild hits the cache
export CCACHE_BASEDIR="$tree/src"
launcher=
command -v ccache >/dev/null 2>&1 && launcher=-DCMAKE_C_COMPILER_LAUNCHER=ccache
# the sources move with the worktree: the build directory keeps its cache
# but must point at this checkout
rm -f "$dir/CMakeCache.txt"
cmake -S "$tree/src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DRB_LTO=ON \
      -DRB_BUILD_TESTS=OFF $launcher >"$dir/configure.log" 2>&1 || {
    cat "$dir/configure.log" >&2; exit 1; }
# the first build: rockbolt and every benchmark; later ones the copied
# sources' programs alone (an LTO link is what takes the time)
targets=
if [ -f "$stamp" ] && [ -x "$dir/rockbolt" ]; then
    for f in "$@"; do
        targets="$targets $(basename "$f" .c)"
    done
else
    targets="rockbolt"
    for f in "$tree/src"/bench/*.c; do
        targets="$targets $(basename "$f" .c)"
    done
fi
# shellcheck disable=SC2086
nice cmake --build "$dir" -j2 --target $targets >"$dir/build.log" 2>&1 || {
    tail -40 "$dir/build.log" >&2; exit 1; }
echo "$full" >"$stamp"
echo "$dir"
