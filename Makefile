# Quick start (README): bash scripts/install-deps.sh && make run | make test
#   make run    installs what is missing, builds, runs the paper's experiment
#   make test   installs what is missing, builds, runs every test (also under ASan+UBSan)
#   make        builds (the program, the libraries, the Python module, the man page)
JOBS ?= $(shell nproc)
# Release tests run two per core: many wait on a child process, a terminal
# or an HTTP server for part of their time (ctest took 49 s instead of 92 s).
TEST_JOBS ?= $(shell echo $$(( $(JOBS) * 2 )))
BUILD ?= build
# Release at -O2 (CMake's Release is -O3) keeps `make test` within CI's
# time on 2 cores; for debug info, make BUILD_TYPE=RelWithDebInfo (a build
# directory keeps the type it was configured with until given another).
BUILD_TYPE ?= Release
# Unity builds (CMakeLists.txt, APPRENTICE_UNITY): each module's files
# compile in batches; make UNITY=OFF compiles file by file.
UNITY ?= ON
ASAN_BUILD ?= build-asan

.PHONY: all deps build run test test-release test-asan test-fuzz fuzz-long bench figure clean

# `make` builds the program, the libraries and the Python module
# (build/python/apprentice; PYTHONPATH=build/python /usr/bin/python3).
all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -DAPPRENTICE_UNITY=$(UNITY)
	cmake --build $(BUILD) -j $(JOBS)

# The LLM conditions run too when an LLM is at hand: $$APPRENTICE_LLM, or
# the recorded GPT-3 goal responses of ../shared when this checkout has them.
CORPUS ?= ../shared/data/stars-tidy-kitchen/goal_responses.jsonl
LLM_FLAG = $(if $(APPRENTICE_LLM),,$(if $(wildcard $(CORPUS)),--llm corpus:$(CORPUS)))

run: build
	./$(BUILD)/apprentice experiment --scenario data/scenarios/tidy-kitchen.yaml $(LLM_FLAG) --transcript $(BUILD)/transcripts

test-release: build
	cd $(BUILD) && ctest --output-on-failure -j $(TEST_JOBS)

# -g1: line tables only; ASan and UBSan reports keep file:line, and the
# build is quicker than with full debug info. -O1 for the libraries and the
# program (test files stay at -O0, tests/CMakeLists.txt): a test runs about
# twice as fast as at -O0 (RecordReplay.ACorpusRunReplaysExactly: 10.7 s of
# CPU against 22.4 s), for about half as long again compiling the libraries.
# The ASan ctest took 308 s this way; at -O0 with two tests per core, 453 s.
# The Python module and its tests run in the release build only (pybind11
# at -O0 costs minutes). Of the replay of a recorded experiment through each
# LLM backend (RecordReplayEveryBackend, about 75 s of CPU each under ASan),
# only llama's runs here: the agent's code is the same for all three, and
# the openai shapes' wire format runs under ASan in the HTTP client and LLM
# fault tests and in fuzz_llm_reply, and is replayed in the release build.
# The page's browser test (serve.page) runs in the release build only: its
# chromium, a browser of its own that is not built with the sanitizers,
# would take a core beside the ASan server, and what it drives on the
# server's side (sessions, events, replies, limits) runs under ASan in
# serve.http and serve.load, 20 sessions at once.
ASAN_EXCLUDE = RecordReplayEveryBackend[.].*/openai|serve[.]page
test-asan: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" -DAPPRENTICE_SANITIZE=ON -DAPPRENTICE_BENCH=OFF -DAPPRENTICE_PYTHON=OFF -DAPPRENTICE_UNITY=$(UNITY)
	cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -E '$(ASAN_EXCLUDE)'

# Each libFuzzer target of fuzz/ briefly (5 s, so that make test stays
# within CI's 30 minutes), seeded from data/ and fuzz/seeds
# (docs/fuzzing.md); fuzz-long runs each for 10 minutes.
test-fuzz: deps
	FUZZ_SECONDS=5 bash scripts/fuzz.sh

fuzz-long: deps build
	FUZZ_SECONDS=600 bash scripts/fuzz.sh

test: test-release test-asan test-fuzz

# The README's figure (docs/experiment.svg), drawn by experiment --plot.
figure: build
	bash scripts/make-figure.sh

bench: build
	./$(BUILD)/bench/bench_search

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) build-fuzz
