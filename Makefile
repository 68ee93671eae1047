# Quick start: `make run` renders the default scene headlessly; `make test` runs the whole suite.
BUILD ?= build
JOBS ?= $(shell nproc)
BUILD_TYPE ?= Release

.PHONY: deps configure build run test sanitize clean bench fuzz

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Only the pbr binary: the test binaries are built by `make test`.
run: configure
	@cmake --build $(BUILD) -j $(JOBS) --target pbr
	./$(BUILD)/pbr render --scene default --out out/default.png

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (warnings are checked by the main build:
# GCC 12 reports false positives inside <regex> under -fsanitize). Leak checking is off: Mesa's
# driver keeps a few allocations alive until process exit, which LeakSanitizer would report on every GL test.
sanitize: deps
	@cmake -S . -B $(BUILD)-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPBR_SANITIZE=ON -DPBR_WERROR=OFF >/dev/null
	@cmake --build $(BUILD)-sanitize -j $(JOBS)
	cd $(BUILD)-sanitize && ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

# The stress-scene sweep of docs/performance.md: table on stdout; CSV, JSON, Chrome trace and charts in bench/out/.
# Brute force at 16,384 lights would take the better part of an hour on llvmpipe: --max-seconds skips it, noted.
# The second sweep shrinks light radii as lights are added (--constant-density) for the 16,384 vs 1,024 comparison;
# the next two sweep many-lights from 65,536 to 1,048,576 lights, radii shrinking with the count and fixed; the
# last measures the cost per light-pixel pair of each shading model.
BENCH_OUT ?= bench/out
BENCH_FRAMES ?= --warmup 2 --frames 10 --max-seconds 600

bench: build
	@mkdir -p $(BENCH_OUT)
	./$(BUILD)/pbr bench --scene stress --lights 64,256,1024,4096,16384 --culling none,clustered \
	  --model pbr,blinn-phong --size 1280x720 $(BENCH_FRAMES) \
	  --csv $(BENCH_OUT)/bench.csv --json $(BENCH_OUT)/bench.json --trace $(BENCH_OUT)/trace.json
	./$(BUILD)/pbr bench --scene stress --lights 1024,16384 --culling clustered --model pbr,blinn-phong \
	  --size 1280x720 --constant-density $(BENCH_FRAMES) \
	  --csv $(BENCH_OUT)/density.csv --json $(BENCH_OUT)/density.json --trace $(BENCH_OUT)/density-trace.json
	./$(BUILD)/pbr bench --scene many-lights --lights 65536,262144,1048576 --culling clustered --model pbr \
	  --size 1280x720 --constant-density --warmup 1 --frames 3 --max-seconds 1800 \
	  --csv $(BENCH_OUT)/million-density.csv --json $(BENCH_OUT)/million-density.json
	./$(BUILD)/pbr bench --scene many-lights --lights 65536,262144,1048576 --culling clustered --model pbr \
	  --size 1280x720 --warmup 1 --frames 3 --max-seconds 1800 \
	  --csv $(BENCH_OUT)/million.csv --json $(BENCH_OUT)/million.json
	./$(BUILD)/pbr bench --pair-cost default,blinn-phong,blinn-phong-sg --rounds 9 \
	  --csv $(BENCH_OUT)/pair-cost.csv --json $(BENCH_OUT)/pair-cost.json
	scripts/plot_bench.py $(BENCH_OUT)/bench.csv --out $(BENCH_OUT)
	scripts/plot_light_count.py "$(BENCH_OUT)/million-density.csv=radii shrinking with the count" \
	  "$(BENCH_OUT)/million.csv=fixed radii" --out $(BENCH_OUT)/perf-light-count.png

# The libFuzzer targets of fuzz/ (clang, ASan + UBSan, in build-fuzz/): each fuzzed for FUZZ_SECONDS, then every
# regression input; fails on any crash. `make fuzz FUZZ_SECONDS=3600` for a long run.
FUZZ_SECONDS ?= 60

fuzz:
	FUZZ_SECONDS=$(FUZZ_SECONDS) fuzz/run.sh

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize build-fuzz out
