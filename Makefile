# The two set-up commands of the README:
#   make demo   install dependencies, build (Release), install the Python module
#               for /usr/bin/python3, run the showcase job
#   make test   install dependencies, build, run every test
MAKEFLAGS += --no-print-directory
SHELL = /bin/bash
BUILD ?= build
JOBS ?= $(shell nproc)
PDS = $(BUILD)/apps/pds/pds
DEMO_DIR ?= out/demo

.PHONY: all deps build demo test bench san-build sanitize fuzz clean

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

# Every test in the main (g++) build, then the clang lane: the tests again
# under ASan and UBSan, and each fuzz target for FUZZ_SECONDS.
test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) sanitize
	@$(MAKE) fuzz

bench: build
	@$(BUILD)/bench/pds_bench

# The clang lane: the whole project built with clang under ASan and UBSan
# (any report fails; line tables only: the reports' file:line, a quarter less
# compile time than -g), every test run in it, then each libFuzzer target for
# FUZZ_SECONDS from the seeds in fuzz/corpus, JOBS targets side by side
# (scripts/fuzz.sh: the corpus it grows stays in the build folder; a crash
# leaves its input there as crash-* and fails the run).
# Leaks inside Cairo's font stack are suppressed by tests/lsan.supp, nothing else.
# The Python module is left out: an ASan-built module cannot load into Debian's
# uninstrumented python3 (its tests run in the main build); so is pds-mpi
# (Open MPI's own allocations read as leaks; its test runs in the main build,
# and the chunk writer it shares with pds chunks runs here).
SAN_BUILD ?= build-san
FUZZ_SECONDS ?= 60
SAN_SWEEP_SHARDS ?= 2
FUZZ_TARGETS = read_csv read_npy read_png read_geojson read_manifest read_mesh generate
SAN_FLAGS = -fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link -fno-omit-frame-pointer
SAN_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0

san-build: deps
	@CC=clang CXX=clang++ cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(LAUNCHER) \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
	  -DCMAKE_CXX_FLAGS="$(SAN_FLAGS)" -DPDS_BUILD_FUZZ=ON -DPDS_BUILD_BENCH=OFF -DPDS_BUILD_PYTHON=OFF -DPDS_BUILD_MPI=OFF >/dev/null
	@cmake --build $(SAN_BUILD) -j $(JOBS)

# Left out of the clang lane: the consumers (they link the instrumented
# libraries into uninstrumented programs), the generated-docs checks (not
# code), the long statistical comparisons, whose code paths the other
# tests already run under the sanitizers, and the 8D lattice's maximality
# proof (103 s instrumented, a third of the lane's test time; the 4D
# lattice runs the same code), gbn's spectrum test (18 s instrumented; the other
# gbn tests run its code), ebeida's largest 5D cases and wei's 5D and 6D
# tests (below); the property
# sweep runs 2 of its 20 shards; the registry's 6D, 7D and 8D cases (about
# 200 s of the lane: the same templates run instrumented at 4D and 5D, and
# uninstrumented in every dimension in the main build; best-candidate from
# 4D is the literal method, the same code in every dimension); the 5D
# lattice's maximality proof (the 4D one runs its code); the comparison of
# elimination's sweeps with its heap on many sets (19 s; the other
# elimination tests run both); Sobol's net quality of scrambled pairs (31 s
# instrumented: 1,024 points in all 21,201 dimensions five times; the other
# Sobol tests and the registry's 21,201D cases run the scrambles); fpo's
# relative radius in a box (14 s; the registry's box cases run its code);
# the registry's 5D cases of best-candidate, gbn and dart-throwing (31, 11
# and 10 s: from 4D each is one code for every dimension, run at 4D);
# tests whose time is their oracle or their size, with their code run by
# smaller tests (SAN_SLOW, 7-18 s each, below).
# What it runs: docs/reliability.md.
# ctest's tests (-E, a regular expression) and GoogleTest's inside pds_tests
# (GTEST_FILTER, patterns joined by ':'; the line breaks' spaces are removed).
SAN_EXCLUDE = consumer_|core_needs|_in_sync
empty :=
space := $(empty) $(empty)
SAN_GTEST_EXCLUDE = *SameDistributionAsTheLiteralMethod*:*MatchesMaximalDartThrowing*:*ComparedWithMaximalDartThrowing*:\
*OneWindowPerPassLeavesThePhaseLattice*:*CountsStayWithinTheStatedBound*:*DefaultSpectrumMatches*:*PrefixHasTheLaw*:\
*PrefixSpectrumMatches*:*Maximality.LatticeE8*:*SpreadsPointsIntoBlueNoise*:*Ebeida.FiveDimensions*:*Ebeida.SevenDimensions*:*Ebeida.EightDimensions*:\
*Registry/*_6d_*:*Registry/*_7d_*:*Registry/*_8d_*:*Maximality.LatticeD5*:\
*Elimination.SweepsRemoveWhatTheHeapRemovesInItsOrder*:*Sobol.ScrambledPairsKeepTheirNetQuality*:\
*Fpo.ReachesTheOptimizedRelativeRadiusInABox*:*Registry/*best_candidate_5d_*:*Registry/*gbn_5d_*:\
*Registry/*dart_throwing_5d_*:$(SAN_EBEIDA_5D):$(SAN_WEI):$(SAN_SLOW)
# ebeida's 5D registry cases with the most points (96, 41, 24, 23, 22 and 21 s
# instrumented, then 10-20 s each for the short periods from 150 r); its 5D
# code runs instrumented in the others (the smaller short periods, the sweep).
SAN_EBEIDA_5D = *SameSeedSameBytesOtherSeedOtherPoints/ebeida_5d*:*RadiusHoldsBetweenEveryPairAndMaximalityWhereClaimed/ebeida_5d*:\
*PointsAreInsideTheDomainAndCountsAreRight/ebeida_5d*:*ShortPeriod.ValidSetOrClearRefusal/ebeida_5d_*_150r:\
*ShortPeriod.ValidSetOrClearRefusal/ebeida_5d_*_220r:*ShortPeriod.ValidSetOrClearRefusal/ebeida_5d_*_233r:\
*ShortPeriod.ValidSetOrClearRefusal/ebeida_5d_*_300r:*ShortPeriod.ValidSetOrClearRefusal/ebeida_5d_*_400r
# wei from 4D (0.6 to 2.5 s each in Release): its 5D, 6D and 8D sets, its 5D
# thread and saturation tests and its 5D registry cases (11-23 s each
# instrumented); the 5D prefix test and the registry cases in 4D run the same
# code instrumented.
SAN_WEI = *Wei.MinimumDistanceInsideAndReproducible5D*:*Wei.MinimumDistanceInsideAndReproducible6D*:*Wei.MinimumDistanceInsideAndReproducible7D*:\
*Wei.MinimumDistanceInsideAndReproducible8D*:*Wei.SameBytesForOneTwoAndFourThreads5D*:\
*Wei.FiveDimensionsNearlySaturated*:*Registry/*/wei_5d_*
# Halton's 1,000 axes at 7,919 points, three times a scramble (the registry's
# 1,000D cases run the same code); jones far from the origin (its registry
# cases run its code); the scalloped region's area against a ray quadrature
# (the quadrature is the time; every dunbar-humphreys test runs the area);
# gbn on 1 to 4 threads (the other gbn tests run its code); and five more
# statistical checks (7-8 s each): wei against maximal dart throwing, SciPy's
# loop against SciPy's law, fpo's relative radius on the torus, jitter's torus
# discrepancy against its bound (SweepMatchesBruteForce runs the sweep), the
# stratified render against the uniform one.
SAN_SLOW = *Halton.LargeBasesStratifyTheirAxesScrambledOrNot*:*Jones.MaximalFarFromTheOrigin*:\
*ScallopedRegion.ExactAreaMatchesRayQuadrature*:*Gbn.SameSeedSamePointsForAnyThreads*:\
*Wei.DefaultsMatchMaximalDartThrowing*:*Bridson.ScipyLoopFollowsScipysLaw*:*Fpo.ReachesTheOptimizedRelativeRadius*:\
*TorusDiscrepancy.WithinTheStrataBoundForJitter*:*Render.StratifiedBeatsUniformRandomOnTheZonePlate*
sanitize: san-build
	@cd $(SAN_BUILD) && $(SAN_ENV) PDS_SWEEP_SHARDS=$(SAN_SWEEP_SHARDS) GTEST_FILTER='-$(subst $(space),,$(SAN_GTEST_EXCLUDE))' \
	  ctest --output-on-failure -j $(JOBS) -E "$(SAN_EXCLUDE)"

fuzz: san-build
	@$(SAN_ENV) bash scripts/fuzz.sh $(SAN_BUILD) $(FUZZ_SECONDS) $(JOBS) $(FUZZ_TARGETS)

clean:
	rm -rf $(BUILD) $(SAN_BUILD) out
