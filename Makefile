# The two set-up commands of the README:
#   make demo   install dependencies, build (Release), install the Python module
#               for /usr/bin/python3, run the showcase job
#   make test   install dependencies, build, run every test
MAKEFLAGS += --no-print-directory
BUILD ?= build
JOBS ?= $(shell nproc)
PDS = $(BUILD)/apps/pds/pds
DEMO_DIR ?= out/demo

.PHONY: all deps build demo test bench fuzz clean

all: build

deps:
	@bash scripts/install-deps.sh

# ccache when present (the set-up installs it): the consumer tests rebuild the
# core as a subproject, and those objects come from the cache.
LAUNCHER = $(if $(shell command -v ccache),-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(LAUNCHER) >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The Python module goes where Debian's /usr/bin/python3 finds it
# (/usr/local/lib/python3.X/dist-packages; docs/python.md).
demo: build
	@cmake --install $(BUILD) --component python >/dev/null
	@bash scripts/demo.sh $(PDS) $(DEMO_DIR)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	@$(BUILD)/bench/pds_bench

# libFuzzer under ASan and UBSan (clang): each target for FUZZ_SECONDS, from the
# seeds in fuzz/corpus (the corpus it grows stays in the build folder). A
# crash leaves its input in $(FUZZ_BUILD)/crash-* and fails the target.
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS = read_csv read_npy generate
fuzz: deps
	@CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(LAUNCHER) \
	  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link" \
	  -DBUILD_SHARED_LIBS=OFF -DPDS_BUILD_FUZZ=ON -DPDS_BUILD_APPS=OFF -DPDS_BUILD_TESTS=OFF -DPDS_BUILD_BENCH=OFF \
	  -DPDS_WITH_PLOT=OFF -DPDS_WITH_RENDER=OFF >/dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(addsuffix _fuzz,$(FUZZ_TARGETS))
	@for t in $(FUZZ_TARGETS); do \
	  corpus=fuzz/corpus/$$(case $$t in read_csv) echo csv;; read_npy) echo npy;; *) echo request;; esac); \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t; \
	  echo "fuzz: $$t for $(FUZZ_SECONDS) s"; \
	  (cd $(FUZZ_BUILD) && ./fuzz/$${t}_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	    -print_final_stats=1 corpus/$$t ../$$corpus 2>&1 | tail -12) || exit 1; \
	done

clean:
	rm -rf $(BUILD) out
