#!/usr/bin/env bash
# Prints the sizes of an ocean installation and checks them against the limits the README
# states; exits non-zero when one is exceeded or a packaging property is lost:
#
#   scripts/sizes.sh PREFIX        (after scripts/install.sh PREFIX, both variants)
#
# Checks, each of which fails on a regression:
#   - the stripped shared libraries: libocean-cpu <= 3 MB, libocean <= 20 MB; each has its
#     SONAME and exports only ocean_* symbols;
#   - the CPU-only archive contains no wgpu or naga code (not even local symbols; the full
#     archive's are counted to show that the check sees them);
#   - each static archive's only global symbols are the ocean_* entry points;
#   - C programs linked fully statically (-static) with `pkg-config --static` flags: one that
#     calls a single function, and one that takes the address of every function the header
#     declares for the variant, so that the linker can drop nothing: CPU-only <= 5 MB.
set -euo pipefail

[ $# -eq 1 ] && [ -d "$1" ] || {
    echo "usage: $0 PREFIX" >&2
    exit 2
}
prefix=$(cd "$1" && pwd)
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
work=$(mktemp -d "${TMPDIR:-/tmp}/ocean-sizes.XXXXXX")
trap 'rm -rf "$work"' EXIT

failures=0
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}
mib() { awk -v b="$1" 'BEGIN { printf "%.2f MB", b / 1e6 }'; }
size_of() { stat -L -c %s "$1"; }

# check_size WHAT FILE LIMIT_BYTES
check_size() {
    local size
    size=$(size_of "$2")
    printf '  %-58s %10s (limit %s)\n' "$1" "$(mib "$size")" "$(mib "$3")"
    [ "$size" -le "$3" ] || fail "$1 is $(mib "$size"), above $(mib "$3")"
}

# An every-entry-point program for the header as VARIANT_FLAGS declares it.
entry_points_program() {
    local out=$1
    shift
    # shellcheck disable=SC2068 # the flags are words
    cc -E -P $@ -I "$prefix/include" "$prefix/include/ocean.h" |
        grep -o '\bocean_[a-z0-9_]*(' | tr -d '(' | sort -u >"$out.names"
    {
        echo '#include <ocean.h>'
        echo '#include <stdio.h>'
        echo 'typedef void (*ocean_entry)(void);'
        echo 'static ocean_entry const entries[] = {'
        sed 's/.*/    (ocean_entry)\&&,/' "$out.names"
        echo '};'
        echo 'int main(void)'
        echo '{'
        echo '    size_t i, n = sizeof entries / sizeof entries[0];'
        echo '    for (i = 0; i < n; i++)'
        echo '        if (entries[i] == NULL)'
        echo '            return 1;'
        echo '    printf("ocean %s: %u entry points\n", ocean_version(), (unsigned)n);'
        echo '    return 0;'
        echo '}'
    } >"$out"
}

cat >"$work/minimal.c" <<'EOF'
#include <ocean.h>
#include <stdio.h>

int main(void)
{
    printf("ocean %s\n", ocean_version());
    return 0;
}
EOF

echo "ocean installation in $prefix"
for name in ocean-cpu ocean; do
    case $name in
        ocean-cpu) so_limit=3000000 ;;
        ocean) so_limit=20000000 ;;
    esac
    so=$prefix/lib/lib$name.so
    archive=$prefix/lib/lib$name.a
    if [ ! -e "$so" ] || [ ! -e "$archive" ]; then
        fail "lib$name is not installed in $prefix"
        continue
    fi
    echo "lib$name"
    check_size "lib$name.so (stripped)" "$so" "$so_limit"
    if nm "$so" >/dev/null 2>&1 && [ "$(nm "$so" 2>/dev/null | wc -l)" -gt 0 ]; then
        fail "lib$name.so is not stripped"
    fi
    soname=$(readelf -d "$so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
    echo "  SONAME $soname"
    case $soname in
        "lib$name.so."[0-9]*) [ -e "$prefix/lib/$soname" ] || fail "no $soname in $prefix/lib" ;;
        *) fail "lib$name.so has SONAME '$soname'" ;;
    esac
    exports=$(nm -D --defined-only "$so" | awk '{ print $3 }')
    stray=$(grep -vc '^ocean_' <<<"$exports" || true)
    echo "  exports $(wc -l <<<"$exports") dynamic symbols, $stray not ocean_*"
    [ "$stray" = 0 ] || fail "lib$name.so exports $stray symbols that are not ocean_*"

    printf '  %-58s %10s\n' "lib$name.a" "$(mib "$(size_of "$archive")")"
    globals=$(nm -g --defined-only "$archive" | awk 'NF == 3 { print $3 }')
    stray=$(grep -vc '^ocean_' <<<"$globals" || true)
    echo "  archive: $(wc -l <<<"$globals") global symbols, $stray not ocean_*"
    [ "$stray" = 0 ] || fail "lib$name.a has $stray global symbols that are not ocean_*: $(grep -v '^ocean_' <<<"$globals" | head -5 | tr '\n' ' ')"
    gpu_symbols=$(nm "$archive" | grep -c -E '(wgpu|naga)' || true)
    echo "  archive: $gpu_symbols symbols of wgpu or naga"
    if [ "$name" = ocean-cpu ]; then
        [ "$gpu_symbols" = 0 ] || fail "the CPU-only archive holds $gpu_symbols wgpu or naga symbols"
    else
        [ "$gpu_symbols" -gt 0 ] || fail "no wgpu or naga symbol found in the full archive: the check is blind"
    fi

    cflags=$(pkg-config --cflags "$name")
    libs=$(pkg-config --static --libs "$name")
    entry_points_program "$work/all_$name.c" "$cflags"
    for program in minimal "all_$name"; do
        # shellcheck disable=SC2086 # the flags are words
        cc -std=c11 -Wall -Wextra -Werror -pedantic $cflags "$work/$program.c" -static \
            $libs -o "$work/$program" 2>"$work/$program.log" || {
            cat "$work/$program.log" >&2
            fail "could not link $program.c statically against lib$name"
            continue
        }
        "$work/$program" >/dev/null || fail "$program (lib$name) did not run"
        strip -o "$work/$program.stripped" "$work/$program"
        what="$program.c, static, $(wc -l <"$work/all_$name.c.names") entry points"
        [ "$program" = minimal ] && what="minimal.c (ocean_version), static"
        if [ "$name" = ocean-cpu ]; then
            check_size "$what" "$work/$program" 5000000
        else
            printf '  %-58s %10s\n' "$what" "$(mib "$(size_of "$work/$program")")"
        fi
        printf '  %-58s %10s\n' "  stripped" "$(mib "$(size_of "$work/$program.stripped")")"
    done
done

if [ "$failures" -gt 0 ]; then
    echo "$failures size or packaging checks failed" >&2
    exit 1
fi
echo "all size and packaging checks passed"
