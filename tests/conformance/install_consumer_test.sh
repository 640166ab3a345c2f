#!/bin/sh
# Installs swarmcheck into a temporary prefix, then configures, builds and runs examples/ (a
# consumer that only does find_package(swarmcheck) + target_link_libraries) against it.
set -eu
src=$1 build=$2 link_flags=${3:-}   # a sanitizer build passes its -fsanitize flags for the link
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" --component Unspecified > "$work/install.log"
cmake -S "$src/examples" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_EXE_LINKER_FLAGS="$link_flags" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
"$work/build/explore"
