#!/usr/bin/env bash
# Install test: `cmake --install` into a temporary prefix, then, from that prefix only, `abalike --version`,
# `abalike check` on the installed campaign and `abalike play --frames 30 --screenshot` under Xvfb (an installed
# level, and the no-argument form). Where a mount namespace can be made (root, or user namespaces), the source
# and build trees are hidden behind empty folders while the installed game runs, so it cannot be reading them.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
build="$(cd "$1" && pwd)"
src="$(cd "$2" && pwd)"
version="$3"
work="$(mktemp -d "${TMPDIR:-/tmp}/abalike-install-XXXXXX")"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
exe="$prefix/games/abalike"
data="$prefix/share/games/abalike"

# Debian's layout for games, and everything a desktop and `man` look for.
for file in games/abalike share/games/abalike/levels/campaign.json share/games/abalike/levels/schema/level.schema.json \
    share/games/abalike/assets/catalog.json share/applications/example.abalike.Abalike.desktop \
    share/icons/hicolor/scalable/apps/abalike.svg share/metainfo/example.abalike.Abalike.metainfo.xml \
    share/man/man6/abalike.6.gz share/doc/abalike/copyright share/doc/abalike/changelog.Debian.gz; do
    [[ -s "$prefix/$file" ]] || fail "not installed: $file"
done
# A manual page for every subcommand --help lists, so a new subcommand cannot be left without one.
subcommands=$("$exe" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF { print $1 }')
[[ -n "$subcommands" ]] || fail "abalike --help lists no subcommands"
for name in $subcommands; do
    [[ -s "$prefix/share/man/man6/abalike-$name.6.gz" ]] || fail "no manual page for abalike $name"
    zcat "$prefix/share/man/man6/abalike-$name.6.gz" | grep -q "^\.TH ABALIKE-${name^^} \"6\"" ||
        fail "abalike-$name.6 is not a section 6 page"
done
# Nothing installed points at the source tree's data.
if grep -rlF -e "$src/levels" -e "$src/assets" "$prefix"; then
    fail "the files above name $src/levels or $src/assets"
fi
if command -v appstreamcli >/dev/null; then
    appstreamcli validate --no-net "$prefix/share/metainfo/example.abalike.Abalike.metainfo.xml" >/dev/null ||
        fail "appstreamcli rejects the metainfo: $(appstreamcli validate --no-net "$prefix"/share/metainfo/*.xml)"
fi

# What runs from the prefix only: the source tree's files are not there (the smoke script is copied out first).
cp "$src/tests/window/play_smoke.sh" "$src/tests/window/xvfb.sh" "$work/"
cat >"$work/from-prefix.sh" <<SCRIPT
set -euo pipefail
fail() { echo "FAIL: \$*" >&2; exit 1; }
cd "$work"
unset ABALIKE_SHARE_DIR ABALIKE_LEVELS_DIR
export ABALIKE_DATA_DIR="$work/save" HOME="$work/home"
[[ "\$("$exe" --version)" == "abalike $version" ]] || fail "abalike --version printed: \$("$exe" --version)"
"$exe" check "$data/levels/campaign.json" >"$work/check.out" || { cat "$work/check.out"; fail "abalike check"; }
levels=\$(grep -o '"[^"/]*\.json"' "$data/levels/campaign.json" | wc -l)
passed=\$(grep -c "^PASS $data/levels/" "$work/check.out" || true)
[[ \$passed -ge 1 && \$passed -eq \$levels ]] || { cat "$work/check.out"; fail "\$passed of \$levels levels pass"; }
echo "check: \$passed installed levels pass"
ABALIKE_SMOKE_FRAMES=30 "$work/play_smoke.sh" "$exe" "$work/shots" "$data/levels/1-1-first-flight.json"
ABALIKE_SMOKE_FRAMES=30 "$work/play_smoke.sh" "$exe" "$work/shots"
SCRIPT

hide=()
if [[ $(id -u) -eq 0 ]]; then hide=(unshare --mount --propagation private); else hide=(unshare --map-root-user --mount); fi
if "${hide[@]}" true 2>/dev/null; then
    # An empty tmpfs over each tree, inside a private mount namespace that ends with the command.
    mounts="mount -t tmpfs none '$src'"
    [[ "$build" == "$src"/* ]] || mounts+=" && mount -t tmpfs none '$build'"
    "${hide[@]}" bash -c "$mounts && [[ ! -e '$src/CMakeLists.txt' ]] && bash '$work/from-prefix.sh'"
    echo "ok: installed game ran with $src and $build hidden"
else
    echo "note: no mount namespace here; the installed game ran with the source tree visible"
    bash "$work/from-prefix.sh"
    echo "ok: installed game ran from $prefix"
fi
