#!/usr/bin/env bash
# Make a local Unity source tree for the tests, offline from Debian:
# the bookworm source package of cjson carries Unity 2.4.3 in tests/unity/src/.
# apt downloads it without touching the system: a temporary deb-src list made
# from the system's own apt sources, and private Dir::State::Lists.
# Prints the directory holding src/unity.c. Usage: tools/fetch-unity.sh [DEST]
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
dest=${1:-$root/.deps/unity}
if [ -f "$dest/src/unity.c" ]; then echo "$dest"; exit 0; fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/lists/partial" "$work/dl"

# deb822 sources: flip "Types: deb" to deb-src; one-line sources: "deb " -> "deb-src ".
n=0
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  sed -E 's/^Types:[[:space:]]*deb[[:space:]]*$/Types: deb-src/' "$f" > "$work/src$n.sources"; n=$((n+1))
done
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] || continue
  sed -nE 's/^[[:space:]]*deb[[:space:]]+/deb-src /p' "$f" > "$work/src$n.list"; n=$((n+1))
done

opts=(-o "Dir::Etc::SourceList=/dev/null" -o "Dir::Etc::SourceParts=$work"
      -o "Dir::State::Lists=$work/lists" -o "Debug::NoLocking=1"
      -o "APT::Sandbox::User=$(id -un)")
apt-get "${opts[@]}" update -qq >/dev/null 2>"$work/err" || { cat "$work/err" >&2; exit 1; }
(cd "$work/dl" && apt-get "${opts[@]}" source --download-only -qq cjson >/dev/null 2>"$work/err") \
  || { cat "$work/err" >&2; echo "fetch-unity: could not download cjson sources" >&2; exit 1; }
orig=$(ls "$work"/dl/cjson_*.orig.tar.* | head -n1)
# cjson's copy includes ../examples/unity_config.h from unity_internals.h.
tar -xf "$orig" -C "$work/dl" --wildcards '*/tests/unity/src/*' '*/tests/unity/examples/unity_config.h'
src=$(ls -d "$work"/dl/*/tests/unity)
mkdir -p "$dest"
rm -rf "$dest/src" "$dest/examples"
cp -r "$src/src" "$src/examples" "$dest/"
echo "$dest"
