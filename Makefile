# swarmcheck: the two commands of the README are `make run` and `make test`.
JOBS ?= $(shell nproc)

.PHONY: deps build run test test-debug fuzz bench pictures clean

deps:
	@scripts/install-deps

build: deps
	@cmake --preset release >/dev/null
	@cmake --build --preset release -j $(JOBS)

run: build
	build/bin/swarmcheck run

# ctest starts the longest tests first when it knows their cost; a fresh build directory does
# not, so it is seeded with the measured costs (tests/ctest-cost-seed.txt), which keeps the slow
# fault-catalogue campaigns from starting last on 2 cores. ctest updates the file after a run.
test: build
	@mkdir -p build/Testing/Temporary
	@[ -f build/Testing/Temporary/CTestCostData.txt ] || cp tests/ctest-cost-seed.txt build/Testing/Temporary/CTestCostData.txt
	ctest --preset release -j $(JOBS)

# ASan + UBSan build of everything, with the same tests except the fault catalogue (label
# "faults", excluded by the debug test preset), plus the libFuzzer targets (tests/fuzz).
test-debug:
	@scripts/install-deps --fuzz
	@cmake --preset debug >/dev/null
	@cmake --build --preset debug -j $(JOBS)
	ctest --preset debug -j $(JOBS)

# The fuzz run of issue 38 over every verb of the binary: 10^4 mutated inputs, flags and HTTP
# requests (tests/hardening/cli_fuzz.cpp); fails on any crash, exit status 3 or hang.
# FUZZ_CASES and FUZZ_SEED change the run.
FUZZ_CASES ?= 10000
FUZZ_SEED ?= 1
fuzz: build
	@cmake --build --preset release -j $(JOBS) --target swarmcheck_cli_fuzz
	build/bin/swarmcheck_cli_fuzz --cases $(FUZZ_CASES) --seed $(FUZZ_SEED) --jobs $(JOBS)

# Google Benchmark, impl against model as a ratio. bench/results.json is system A's
# (bench_exploration); the other systems write bench/results-<name>.json.
bench: deps
	@cmake --preset bench >/dev/null
	@cmake --build --preset bench -j $(JOBS)
	build-bench/bin/bench_exploration --benchmark_out=bench/results.json --benchmark_out_format=json
	@for b in build-bench/bin/bench_*; do \
	  name=$${b##*/bench_}; [ "$$name" = exploration ] && continue; \
	  $$b --benchmark_out=bench/results-$$name.json --benchmark_out_format=json; \
	done

# The README's pictures (docs/img/): swarmcheck's own SVGs and the browser tests' screenshots.
pictures: build
	@scripts/pictures build

clean:
	rm -rf build build-debug build-bench
