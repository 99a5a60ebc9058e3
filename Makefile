# Two commands set up everything on a fresh Debian 12 machine:
#   make play   install what is missing, build Release, start the game
#   make test   install what is missing, build, run the whole suite (CTest)
# Both are idempotent: nothing is installed or rebuilt when nothing changed.

BUILD ?= build
JOBS  ?= $(shell nproc)
# Debian packages the project builds and tests with (see DESIGN.md).
PACKAGES := cmake g++ make pkg-config libbox2d-dev libsdl2-dev libimgui-dev \
            libosmesa6-dev libegl-dev libegl-mesa0 libgl-dev libstb-dev fonts-dejavu-core \
            nlohmann-json3-dev libgtest-dev libbenchmark-dev libeigen3-dev xvfb xauth
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build play test bench clean

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

clean:
	rm -rf $(BUILD)
