#!/bin/sh
# Installs swarmcheck into a temporary prefix, then configures, builds and runs examples/ (three
# consumers that only do find_package(swarmcheck) + target_link_libraries) against it. The
# system-B consumers read the thesis files from the source tree's scenarios/thesis.
set -eu
src=$1 build=$2 link_flags=${3:-}   # a sanitizer build passes its -fsanitize flags for the link
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" --component Unspecified > "$work/install.log"
cmake -S "$src/examples" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_EXE_LINKER_FLAGS="$link_flags" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
"$work/build/explore"
"$work/build/supervise" "$src/scenarios/thesis/control2.fsm" "$src/scenarios/thesis/components"
"$work/build/mission" "$src/scenarios/thesis/thesis-mission.json"
# The installed libraries carry no reference-model code (the model is the harness's oracle).
if find "$work/prefix" -name 'libswarmcheck*.a' -exec nm -C {} + | grep -q 'model::'; then
  echo "install_consumer: the installed libraries contain model:: symbols" >&2
  exit 1
fi
