#!/bin/sh
# rockbolt installed into a temporary prefix, then moved: the tree must
# work from its new place with the source tree out of its reach (no
# RB_DATA_DIR, no cases/ in the working directory, a starter template and
# records proved to come from the moved tree), RB_DATA_DIR must override,
# and programs must build against the installed library through
# pkg-config and find_package(rockbolt).
#
#   sh tests/install/install_test.sh BUILD_DIR SCRATCH [CC]
#
# Exit 0 pass, 1 fail, 77 skipped (no cmake to install with).
set -u
B=$1 S=$2 CC=${3:-cc}
command -v cmake >/dev/null 2>&1 || { echo "SKIP: no cmake"; exit 77; }
rm -rf "$S" && mkdir -p "$S" || exit 1
S=$(cd "$S" && pwd)

fail() {
    echo "FAIL [install]: $*"
    for f in "$S/out" "$S/err"; do
        [ -s "$f" ] && { echo "--- $f"; head -30 "$f"; }
    done
    exit 1
}
run() {
    "$@" >"$S/out" 2>"$S/err"
    rc=$?
}

unset RB_DATA_DIR RB_TEMPLATE_DIR
cmake --install "$B" --prefix "$S/prefix" >"$S/out" 2>"$S/err" || fail "cmake --install"
P=$S/prefix
# the library directory as the build's layout has it (lib, lib64,
# lib/x86_64-linux-gnu): where the pkg-config file went
PC=$(cd "$P" && find . -name rockbolt.pc | head -1)
[ -n "$PC" ] || fail "not installed: rockbolt.pc"
LIBDIR=$(dirname "$(dirname "$PC")" | sed 's|^\./||')
for f in bin/rockbolt "$LIBDIR/librockbolt.a" "$LIBDIR/librockbolt.so" \
         include/rockbolt/rockbolt.h include/rockbolt/version.h include/rockbolt/datadir.h \
         "$LIBDIR/pkgconfig/rockbolt.pc" "$LIBDIR/cmake/rockbolt/rockbolt-config.cmake" \
         "$LIBDIR/cmake/rockbolt/rockbolt-config-version.cmake" \
         share/rockbolt/records/elcentro_1940_ns.at2 share/rockbolt/records/taft_1952_s69e.txt \
         share/rockbolt/records/PROVENANCE.md \
         share/rockbolt/templates/starter.yaml share/rockbolt/templates/report.txt \
         share/man/man1/rockbolt.1 share/bash-completion/completions/rockbolt \
         share/zsh/site-functions/_rockbolt share/doc/rockbolt/LICENSE \
         share/man/man5/rockbolt-case.5 share/doc/rockbolt/docs/case-format.md \
         share/doc/rockbolt/docs/fragility.md; do
    [ -e "$P/$f" ] || fail "not installed: $f"
done
echo "installed: binary, library, headers, pkg-config, CMake config, data, man page, completions"

# Move the tree: the prefix it was installed to is gone.
M=$S/moved/opt/rockbolt
mkdir -p "$S/moved/opt" && mv "$P" "$M" || fail "cannot move the installed tree"
# a mark in the moved tree's starter shows where init took it from
echo "# installed copy" >>"$M/share/rockbolt/templates/starter.yaml"
W=$S/work
mkdir -p "$W" && cd "$W" || exit 1
[ -e cases ] && fail "the working directory has a cases/"

run "$M/bin/rockbolt" --version
[ "$rc" -eq 0 ] || fail "--version from the moved tree"
run "$M/bin/rockbolt" init pump.yaml
[ "$rc" -eq 0 ] || fail "init: exit code $rc"
grep -q "^# installed copy" pump.yaml || fail "init did not take the moved tree's starter"
run "$M/bin/rockbolt" check pump.yaml --quiet
[ "$rc" -le 1 ] || fail "check of the starter case: exit code $rc"
# the starter's record example: a shipped record
sed -e 's/^  type: harmonic.*//' -e 's/^  amplitude: .*//' -e 's/^  frequency: 4 Hz.*//' \
    -e 's/^  duration: .*//' -e 's/^  # type: record/  type: record/' \
    -e 's/^  # file: shipped:elcentro.*/  file: shipped:elcentro/' \
    -e 's/^  # building: /  building: /' -e 's/^  # peak: /  peak: /' pump.yaml >pump-ec.yaml
grep -q "^  file: shipped:elcentro" pump-ec.yaml || fail "the starter has no shipped record example"
run "$M/bin/rockbolt" check pump-ec.yaml --json pump-ec.json --quiet
[ "$rc" -le 1 ] || fail "check with file: shipped:elcentro: exit code $rc"
grep -q "\"$M/share/rockbolt/records/elcentro_1940_ns.at2\"" pump-ec.json ||
    fail "the record did not come from the moved tree: $(grep -o '"[^"]*elcentro[^"]*"' pump-ec.json | head -2)"
echo "moved tree: init, check, shipped:elcentro from $M/share/rockbolt"

# batch on an equipment list naming the shipped records
printf 'tag,motion\nP-1,elcentro\nP-2,taft\n' >list.csv
run "$M/bin/rockbolt" batch list.csv --base pump.yaml --reports reports --json summary.json --quiet
[ "$rc" -le 1 ] || fail "batch with elcentro and taft: exit code $rc"
grep -q "$M/share/rockbolt/records/elcentro_1940_ns.at2" reports/*P-1*.json ||
    fail "batch's elcentro did not come from the moved tree"
grep -q "$M/share/rockbolt/records/taft_1952_s69e.txt" reports/*P-2*.json ||
    fail "batch's taft did not come from the moved tree"
echo "moved tree: batch on a list with elcentro and taft"

# RB_DATA_DIR wins over the tree next to the binary
cp -R "$M/share/rockbolt" "$S/data"
echo "# overridden copy" >>"$S/data/templates/starter.yaml"
rm -f pump2.yaml
RB_DATA_DIR=$S/data "$M/bin/rockbolt" init pump2.yaml >/dev/null || fail "init with RB_DATA_DIR"
grep -q "^# overridden copy" pump2.yaml || fail "RB_DATA_DIR not used by init"
RB_DATA_DIR=$S/data "$M/bin/rockbolt" check pump-ec.yaml --json ec2.json --quiet
[ $? -le 1 ] || fail "check with RB_DATA_DIR"
grep -q "\"$S/data/records/elcentro_1940_ns.at2\"" ec2.json || fail "RB_DATA_DIR not used for records"
RB_DATA_DIR=$S/nowhere "$M/bin/rockbolt" check pump-ec.yaml --quiet 2>"$S/err"
[ $? -eq 2 ] || fail "a wrong RB_DATA_DIR is not a usage error"
grep -q "$S/nowhere/records/elcentro_1940_ns.at2" "$S/err" || fail "a wrong RB_DATA_DIR is not named"
echo "RB_DATA_DIR: overrides, and a wrong one names the file"

# the man page of the installed tree
if command -v man >/dev/null 2>&1; then
    man -l "$M/share/man/man1/rockbolt.1" >man.txt 2>/dev/null || fail "man -l"
    grep -q "ROCKBOLT CHECK" man.txt || fail "man -l: no check section"
    grep -q "rockbolt-case.5" man.txt || fail "man rockbolt does not name rockbolt-case(5)"
    # the case file's page, found by man in the moved tree, holds every
    # section and every table key of the document it is made from
    MANPATH=$M/share/man MANWIDTH=100 man 5 rockbolt-case >case.txt 2>"$S/err" \
        || fail "man 5 rockbolt-case"
    grep -q "^ROCKBOLT-CASE(5)" case.txt || fail "man 5 rockbolt-case: no title"
    DOC=$M/share/doc/rockbolt/docs/case-format.md
    sed -n 's/^#\{2,3\} //p' "$DOC" | sed 's/`//g' >heads.txt
    while IFS= read -r h; do
        grep -qiF -- "$h" case.txt || fail "man 5 rockbolt-case: no section '$h'"
    done <heads.txt
    sed -n 's/^| `\([a-z_0-9]*\)`.*/\1/p' "$DOC" | sort -u >keys.txt
    [ "$(wc -l <keys.txt)" -gt 60 ] || fail "case-format.md: only $(wc -l <keys.txt) keys read"
    while IFS= read -r k; do
        grep -qE "^ {7}$k([ ,]|\$)" case.txt || fail "man 5 rockbolt-case: no entry '$k'"
    done <keys.txt
    grep -q "man 5 rockbolt-case" "$M/share/rockbolt/templates/starter.yaml" \
        || fail "the starter does not point at man 5 rockbolt-case"
    echo "man 5 rockbolt-case: $(wc -l <heads.txt) sections, $(wc -l <keys.txt) keys"
fi

# a program against the installed library
cat >prog.c <<'PROG'
#include <stdio.h>
#include <string.h>
#include <rockbolt/rockbolt.h>
#include <rockbolt/datadir.h>

int main(int argc, char **argv)
{
    rb_case c;
    rb_diag_list dl;
    rb_derived d;
    rb_diag dg;
    memset(&c, 0, sizeof c);
    memset(&dl, 0, sizeof dl);
    if (argc < 2 || rb_case_load(argv[1], &c, &dl) != RB_OK) {
        fprintf(stderr, "cannot load the case\n");
        return 1;
    }
    rb_diag_clear(&dg);
    if (rb_model_derive(&c.model, &d, &dg) != RB_OK)
        return 1;
    printf("rockbolt %s: %zu motion, records in %s\n", RB_VERSION_STRING,
           c.n_motions, rb_data_records_dir());
    rb_case_free(&c);
    rb_diag_list_free(&dl);
    return 0;
}
PROG
VERSION=$("$M/bin/rockbolt" --version | cut -d' ' -f2)
check_prog() {   # check_prog PROGRAM HOW
    RB_DATA_DIR=$M/share/rockbolt "$1" pump-ec.yaml >"$S/out" 2>"$S/err" ||
        fail "$2: the program failed"
    grep -q "^rockbolt $VERSION: 1 motion, records in $M/share/rockbolt/records" "$S/out" ||
        fail "$2: unexpected output"
    echo "library: $2"
}
if command -v "$CC" >/dev/null 2>&1 && command -v pkg-config >/dev/null 2>&1; then
    export PKG_CONFIG_PATH="$M/$LIBDIR/pkgconfig"
    [ "$(pkg-config --modversion rockbolt)" = "$VERSION" ] || fail "pkg-config --modversion"
    # shellcheck disable=SC2046
    "$CC" -o prog-pc prog.c $(pkg-config --cflags --libs rockbolt) \
        -Wl,-rpath,"$M/$LIBDIR" 2>"$S/err" || fail "cannot build against pkg-config's flags"
    check_prog ./prog-pc "pkg-config, shared"
    "$CC" -o prog-pc-static prog.c $(pkg-config --cflags rockbolt) "$M/$LIBDIR/librockbolt.a" \
        $(pkg-config --static --libs rockbolt | sed 's/-lrockbolt//') 2>"$S/err" ||
        fail "cannot build against the archive with pkg-config --static"
    check_prog ./prog-pc-static "pkg-config --static"
    unset PKG_CONFIG_PATH
else
    echo "no $CC or pkg-config: the pkg-config build skipped"
fi
if command -v "$CC" >/dev/null 2>&1; then
    mkdir -p consumer && cp prog.c consumer/ && cat >consumer/CMakeLists.txt <<'CML'
cmake_minimum_required(VERSION 3.16)
project(consumer C)
find_package(rockbolt 0.1 REQUIRED)
add_executable(prog prog.c)
target_link_libraries(prog PRIVATE rockbolt::rockbolt)
add_executable(prog_static prog.c)
target_link_libraries(prog_static PRIVATE rockbolt::rockbolt_static)
CML
    run cmake -S consumer -B consumer/build -DCMAKE_C_COMPILER="$CC" \
        -DCMAKE_PREFIX_PATH="$M" -DCMAKE_BUILD_TYPE=Release
    [ "$rc" -eq 0 ] || fail "find_package(rockbolt)"
    run cmake --build consumer/build
    [ "$rc" -eq 0 ] || fail "cannot build against find_package(rockbolt)"
    check_prog consumer/build/prog "find_package, rockbolt::rockbolt"
    check_prog consumer/build/prog_static "find_package, rockbolt::rockbolt_static"
fi

echo "install: ok"
cd / && rm -rf "$S"
exit 0
