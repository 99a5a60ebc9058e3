# Two commands set up everything on a fresh Debian 12 machine:
#   make play   install what is missing, build Release, start the game
#   make test   install what is missing, build, run the whole suite (CTest)
# Both are idempotent: nothing is installed or rebuilt when nothing changed.

BUILD ?= build
JOBS  ?= $(shell nproc)
# Debian packages the project builds, tests and packages with.
PACKAGES := cmake g++ make pkg-config libbox2d-dev libsdl2-dev libimgui-dev \
            libosmesa6-dev libegl-dev libegl-mesa0 libgl-dev libstb-dev fonts-dejavu-core \
            nlohmann-json3-dev libgtest-dev libbenchmark-dev libeigen3-dev xvfb xauth \
            libenet-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev \
            libswresample-dev xdotool help2man dpkg-dev
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build play test bench charts clean sanitize fuzz cli-docs screenshots \
        clang-deps san-configure fuzz-seconds package install

all: build

# Install only the packages that dpkg does not already report as installed.
deps:
	@missing=$$(for p in $(PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; \
	  done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

play: build
	./$(BUILD)/artillery

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The Debian package (CPack): $(BUILD)/package/artillery_VERSION_ARCH.deb, installed with
# `sudo apt install ./$(BUILD)/package/artillery_*.deb`. `make install` installs into
# /usr/local instead (PREFIX=... elsewhere); either way the game finds its levels
# beside the executable (../share/artillery).
PREFIX ?= /usr/local
package: build
	cmake --build $(BUILD) --target package
install: build
	$(SUDO) cmake --install $(BUILD) --prefix $(PREFIX)

# The README's speed-and-accuracy charts: docs/*.png from the bench verbs (about a
# minute on 2 cores; the CSVs go to $(BUILD)/charts/). Add BENCH=--full for the long sweeps.
# The scaling chart is refused while the load average is above 1; SCALING=--under-load
# draws it anyway, marked as taken under load.
charts: build
	@mkdir -p $(BUILD)/charts docs
	./$(BUILD)/artillery bench work-precision $(BENCH) --csv $(BUILD)/charts/work_precision.csv --png docs/work_precision.png
	./$(BUILD)/artillery bench stability $(BENCH) --csv $(BUILD)/charts/stability.csv --png docs/stability.png
	./$(BUILD)/artillery bench scaling $(BENCH) $(SCALING) --csv $(BUILD)/charts/scaling.csv --png docs/scaling.png

# docs/cli.md's reference part: every verb's --help as the program prints it (the docs
# check in `make test` fails when it is out of date).
cli-docs: build
	cmake -DEXE=$(BUILD)/artillery -DSRC=. -DUPDATE=ON -P tests/docs/docs_check.cmake

# The README's and the docs' pictures, drawn by the game's own headless renderer.
screenshots: build
	./$(BUILD)/artillery play levels/05_castle.json --headless --frames 4 --no-panel --screenshot docs/game.png
	./$(BUILD)/artillery play --replay tests/replays/05_castle.replay.json --headless --no-panel \
	  --warmup 1.5 --frames 4 --ghosts --forces --contacts --models --screenshot docs/debug_view.png
	docs/screenshots.sh $(BUILD)

clean:
	rm -rf $(BUILD)

# --- Robustness -----------------------------------------------------------
# make sanitize: the whole suite built with AddressSanitizer + UndefinedBehaviorSanitizer,
# floating-point exceptions trapped in the physics tests (ARTILLERY_TRAP_FP). Built with
# clang at -O1 with line tables only (-g1): an instrumented file compiles in half the time
# of -O2 -g (game/match.cpp 12.9 s against 25.7 s with g++), clang takes a fifth less
# than g++ (10.6 s), and line tables are all the sanitizers' stack traces need. The same
# build holds the fuzzers (ARTILLERY_FUZZ), so `make fuzz` after it compiles nothing
# again; and the suite runs under both compilers (the Release build is g++'s).
SAN_BUILD ?= build-asan
SAN_FLAGS := -O1 -g1 -DNDEBUG
CLANG_PACKAGES := clang libclang-rt-14-dev
clang-deps: deps
	@missing=$$(for p in $(CLANG_PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q 'install ok installed' || echo $$p; \
	  done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:" $$missing; \
	  $(SUDO) apt-get update -qq && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	fi
san-configure: clang-deps
	@if [ -f $(SAN_BUILD)/CMakeCache.txt ] && \
	    ! grep -q '^CMAKE_CXX_COMPILER:.*clang++' $(SAN_BUILD)/CMakeCache.txt; then \
	  echo "$(SAN_BUILD) was configured with another compiler: building it again with clang"; \
	  rm -rf $(SAN_BUILD); \
	fi
	CC=clang CXX=clang++ cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DARTILLERY_SANITIZE=ON -DARTILLERY_FUZZ=ON \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(SAN_FLAGS)" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(SAN_FLAGS)"
sanitize: san-configure
	cmake --build $(SAN_BUILD) -j $(JOBS)
	cd $(SAN_BUILD) && ARTILLERY_TRAP_FP=1 ASAN_OPTIONS=detect_leaks=0 \
	  UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

# make fuzz: libFuzzer on the level, replay, commands and player settings loaders, the
# network message decoder, and levels and command scripts simulated (sim_*), FUZZ_SECONDS
# each, from the sanitizer build (only the fuzzers are built, if they are not there yet).
# What a fuzzer finds (crash-*, leak-*, timeout-*, oom-*) is saved in
# $(SAN_BUILD)/fuzz/artifacts/LOADER/ and its corpus grows in $(SAN_BUILD)/fuzz/corpus/LOADER/,
# never in the source tree (the seed folders are only read); the target fails if any
# fuzzer did.
FUZZ_SECONDS ?= 60
FUZZERS := level replay commands settings message sim_level sim_commands
# libFuzzer reads -max_total_time with atol: text would be 0, which is no limit at all.
fuzz-seconds:
	@case "$(FUZZ_SECONDS)" in ''|*[!0-9]*) false;; *) [ "$(FUZZ_SECONDS)" -gt 0 ];; esac || { \
	  echo "make fuzz: FUZZ_SECONDS must be a whole number of seconds above 0, not '$(FUZZ_SECONDS)'"; \
	  exit 2; }
fuzz: fuzz-seconds san-configure
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZERS))
	@failed=""; \
	for t in $(FUZZERS); do \
	  case $$t in \
	    level) seeds="levels tests/data/bad_levels" ;; \
	    replay) seeds="tests/replays tests/data/bad_replays" ;; \
	    commands) seeds="tests/data/bad_commands" ;; \
	    settings) seeds="tests/data/bad_settings" ;; \
	    message) seeds="tests/data/net_messages" ;; \
	    sim_*) seeds="" ;; \
	  esac; \
	  corpus=$(SAN_BUILD)/fuzz/corpus/$$t; artifacts=$(SAN_BUILD)/fuzz/artifacts/$$t; \
	  log=$(SAN_BUILD)/fuzz/$$t.log; mkdir -p $$corpus $$artifacts; \
	  echo "fuzzing the $$t loader for $(FUZZ_SECONDS) s"; \
	  if $(SAN_BUILD)/tests/fuzz/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -max_len=65536 \
	      -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=$$artifacts/ \
	      $$corpus $$seeds > $$log 2>&1; then \
	    tail -4 $$log; \
	  else \
	    tail -40 $$log; failed="$$failed $$t"; \
	  fi; \
	done; \
	if [ -n "$$failed" ]; then \
	  echo "fuzz: the$$failed loader(s) failed; the inputs are in $(SAN_BUILD)/fuzz/artifacts/"; exit 1; \
	fi
