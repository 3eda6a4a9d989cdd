# The two set-up commands of the README:
#   make demo   install dependencies, build (Release), install the Python module
#               for /usr/bin/python3, run the showcase job
#   make test   install dependencies, build, run every test
MAKEFLAGS += --no-print-directory
BUILD ?= build
JOBS ?= $(shell nproc)
PDS = $(BUILD)/apps/pds/pds
DEMO_DIR ?= out/demo

.PHONY: all deps build demo test bench clean

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

clean:
	rm -rf $(BUILD) out
