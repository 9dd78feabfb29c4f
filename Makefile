# The README's quick start. Every target first installs what is missing (scripts/setup.sh).
BUILD ?= build
SAN_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?=
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all setup setup-mediapipe build demo test test-sanitize fuzz bench format clean

all: build

setup:
	@bash scripts/setup.sh

# scripts/detect_mediapipe's chromium and npm packages; the tests run the detector end to end.
setup-mediapipe:
	@bash scripts/setup_mediapipe.sh

$(BUILD)/build.ninja: | setup
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: setup $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/apps/simcap/simcap demo

test: build setup-mediapipe
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-sanitize: setup setup-mediapipe
	cmake -S . -B $(SAN_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSIMCAP_SANITIZE=ON -DSIMCAP_BUILD_BENCH=OFF
	cmake --build $(SAN_BUILD) -j $(JOBS)
	cd $(SAN_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ctest --output-on-failure -j $(JOBS)

# Every libFuzzer harness of tests/fuzz for FUZZ_SECONDS each (clang; findings in tests/fuzz/findings/).
fuzz:
	@bash scripts/setup.sh --fuzz
	cmake -S . -B $(FUZZ_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 -DSIMCAP_FUZZ=ON -DSIMCAP_BUILD_TESTS=OFF -DSIMCAP_BUILD_BENCH=OFF
	cmake --build $(FUZZ_BUILD) --target fuzz_harnesses -j $(JOBS)
	bash scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

bench: build
	$(BUILD)/apps/simcap/simcap bench render

format:
	git ls-files '*.cpp' '*.h' | xargs clang-format -i

clean:
	rm -rf $(BUILD) $(SAN_BUILD) $(FUZZ_BUILD)
