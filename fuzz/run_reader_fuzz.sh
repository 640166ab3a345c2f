#!/bin/sh
# Builds one reader's libFuzzer target with clang++ (ASan + UBSan) and runs it for a short budget
# on a copy of its seed corpus, taken from the shipped files (the repository is never written to).
#
# usage: run_reader_fuzz.sh NAME SOURCE_DIR BUILD_DIR SECONDS [SWARMCHECK_BIN]
#   NAME: fsm | scenario | mission | trace | dse
#   SWARMCHECK_BIN (trace only, optional): the built CLI, to add fresh `run --trace` seeds.
#
# Objects go to BUILD_DIR/fuzz/obj, shared by the five targets and rebuilt only when a source,
# a header it includes or the flags change (make, with clang's dependency files); a lock lets
# the five ctests run at once. A crashing input is saved as BUILD_DIR/fuzz/artifacts/NAME-*.
# Exit 77 (ctest: skipped) only when clang++ or its libFuzzer runtime is not installed.
set -eu
[ $# -ge 4 ] || { echo "usage: $0 fsm|scenario|mission|trace|dse SOURCE_DIR BUILD_DIR SECONDS [SWARMCHECK_BIN]" >&2; exit 2; }
name=$1
src=$(cd "$2" && pwd)
out=$3/fuzz
seconds=$4
bin=${5:-}

# ---- each target -------------------------------------------------------------------------------
# sources: the reader, compiled with the sanitizers and coverage (one object each, shared).
# support: what the target links but does not fuzz (trace: the engines replay runs), compiled
#   as one file without instrumentation: about 20 s instead of 170 s, and coverage of the
#   reader only, so the fuzzer does not chase simulation branches.
support=""
case $name in
  fsm)
    sources="impl/supervisor/fsm_read.cpp impl/supervisor/fsm.cpp impl/supervisor/fsm_write.cpp spec/supervisor/automaton.cpp
      spec/supervisor/attributes.cpp"
    libs="" max_len=8192 ;;
  scenario)
    sources="spec/exploration/scenario.cpp"
    libs="" max_len=4096 ;;
  mission)
    sources="spec/mission/mission.cpp spec/mission/mission_check.cpp
      spec/supervisor/automaton.cpp spec/supervisor/semantics.cpp spec/supervisor/attributes.cpp
      impl/supervisor/fsm_read.cpp impl/supervisor/fsm.cpp"
    # The rest of spec/mission (plans, worlds, polygons...), which the checks call: listed, not
    # named, so a new file of the layer cannot break the link.
    support="$(cd "$src" && ls spec/mission/*.cpp | grep -v -x -e spec/mission/mission.cpp -e spec/mission/mission_check.cpp)"
    libs="-lfmt" max_len=4096 ;;
  trace)
    sources="conformance/exploration/trace_io.cpp spec/exploration/scenario.cpp"
    support="conformance/exploration/engine.cpp conformance/exploration/lockstep.cpp
      conformance/exploration/transition.cpp
      $(cd "$src" && ls impl/io/*.cpp model/exploration/*.cpp impl/exploration/*.cpp spec/exploration/*.cpp |
        grep -v '^spec/exploration/scenario.cpp$') spec/util/sym.cpp"
    libs="-ltbb" max_len=16384 ;;
  dse)
    sources="impl/dse/config.cpp impl/dse/expression.cpp impl/dse/names.cpp impl/dse/design_space.cpp"
    # The exploration spec the design space builds scenarios with: listed, not named.
    support="$(cd "$src" && ls spec/exploration/*.cpp) spec/util/sym.cpp"
    libs="-lfmt" max_len=8192 ;;
  *) echo "run_reader_fuzz.sh: unknown target \"$name\" (fsm, scenario, mission, trace or dse)" >&2; exit 2 ;;
esac
sources="fuzz/${name}_reader_fuzz.cpp $sources"

if ! command -v clang++ >/dev/null 2>&1; then
  echo "SKIPPED: clang++ not found; the libFuzzer targets need clang (apt-get install clang libclang-rt-dev)"
  exit 77
fi
case $src$out in *' '*) echo "run_reader_fuzz.sh: paths with spaces are not supported (make)" >&2; exit 2 ;; esac
mkdir -p "$out/bin" "$out/obj" "$out/artifacts"

# -O1 is what libFuzzer recommends (-O0 compiles in half the time but runs 20 times slower);
# -gline-tables-only gives a report's stack and compiles faster than -g.
cxx=clang++
if command -v ccache >/dev/null 2>&1; then cxx="ccache clang++"; fi
common="-std=c++20 -O1 -gline-tables-only -fno-omit-frame-pointer -ffp-contract=off -fno-fast-math
  -I$src -I$src/impl/include -isystem /usr/include/eigen3 -DSWARMCHECK_SCENARIOS='\"$src/scenarios\"'"
fuzzflags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all"
ldflags="-fsanitize=fuzzer,address,undefined"

# Writes $2 to file $1 only when it differs, so that make sees a change only when there is one.
put() { printf '%s\n' "$2" > "$1.new"; if cmp -s "$1.new" "$1"; then rm "$1.new"; else mv "$1.new" "$1"; fi; }

build() {
  # The runtime may be absent even with clang++ (Debian: libclang-rt-dev is only recommended).
  if [ ! -f "$out/.runtime-ok" ]; then
    printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' |
      clang++ $ldflags -x c++ - -o "$out/probe" 2>/dev/null || {
        echo "SKIPPED: clang++ cannot link -fsanitize=fuzzer,address,undefined (install libclang-rt-dev)"
        exit 77
      }
    rm -f "$out/probe"
    touch "$out/.runtime-ok"
  fi
  put "$out/obj/flags" "$cxx $(echo $common $fuzzflags)"
  objs=""
  for s in $sources; do objs="$objs \$(OBJ)/${s%.cpp}.o"; done
  if [ -n "$support" ]; then
    put "$out/obj/support-flags" "$cxx $(echo $common)"
    put "$out/obj/${name}_support.cpp" "$(for s in $support; do echo "#include \"$src/$s\""; done)"
    objs="$objs \$(OBJ)/${name}_support.o"   # last: the instrumented copies of inline code win
  fi
  make -s -j"${FUZZ_JOBS:-2}" -f - OBJ="$out/obj" "$out/bin/$name" <<EOF
\$(OBJ)/%.o: $src/%.cpp \$(OBJ)/flags
	@mkdir -p \$(@D)
	@echo "fuzz: compiling \$*.cpp"
	@$cxx $(echo $common $fuzzflags) -MMD -MP -c \$< -o \$@
\$(OBJ)/%_support.o: \$(OBJ)/%_support.cpp \$(OBJ)/support-flags
	@echo "fuzz: compiling the $name support (not instrumented)"
	@$cxx $(echo $common) -MMD -MP -c \$< -o \$@
$out/bin/$name: $objs
	@echo "fuzz: linking $name"
	@clang++ $ldflags \$^ $libs -o \$@
-include $(for o in $objs; do printf '%s ' "${o%.o}.d"; done)
EOF
}

start=$(date +%s)
exec 9>"$out/.lock"
flock 9   # one build at a time: the four ctests share objects
build
flock -u 9
built=$(date +%s)
echo "fuzz: $name built in $((built - start)) s (waiting for the lock included)"

# ---- the seed corpus: the shipped files, copied (flattened names) into a scratch folder --------
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
seed() { for f in "$@"; do [ -f "$f" ] && cp "$f" "$work/$(echo "${f#"$src"/}" | tr / _)"; done; return 0; }
case $name in
  fsm) seed "$src"/fuzz/corpus/fsm/* $(find "$src/scenarios" -name '*.fsm') ;;
  scenario) seed $(find "$src/scenarios" -name '*.json') ;;
  mission) seed $(grep -rl --include='*.json' --exclude-dir=node_modules '"marked_states"' "$src/scenarios" "$src/tests") ;;
  dse) seed $(find "$src/scenarios" "$src/bench" -name '*.dse.json') "$src"/fuzz/corpus/dse/* ;;
  trace)
    seed "$src"/fuzz/corpus/trace/*
    if [ -n "$bin" ] && [ -x "$bin" ]; then   # fresh traces from the built CLI, small enough to replay fast
      { "$bin" run --steps 5 --trace "$work/fresh-cosim.jsonl" &&
        "$bin" run --mode abstract --rule stochastic --steps 5 --trace-field 2 --trace "$work/fresh-abstract.jsonl"
      } >/dev/null || echo "fuzz: $bin wrote no fresh traces; the committed seeds only"
    fi ;;
esac
echo "fuzz: $name: $(ls "$work" | wc -l) seeds, $seconds s"

# libFuzzer's own error exit code is 77, which ctest would read as "skipped": use 1.
status=0
"$out/bin/$name" -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
  -error_exitcode=1 -timeout_exitcode=1 -artifact_prefix="$out/artifacts/$name-" \
  -print_final_stats=1 -print_funcs=0 "$work" || status=$?
echo "fuzz: $name ran $(( $(date +%s) - built )) s"
if [ "$status" -ne 0 ]; then
  echo "fuzz: $name FAILED (status $status): the input is in $out/artifacts/$name-*;" \
    "reproduce with $out/bin/$name <input>" >&2
  exit 1
fi
