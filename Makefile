# The two commands of the README, and a few more.
#   make render   install missing packages, build (Release), render the classic scene
#   make test     the same set-up, then every test through CTest
MAKEFLAGS += --no-print-directory
BUILD_DIR ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
SCENE ?= scenes/whitted_1980.p3f
OUT ?= whitted_1980.png
SIZE ?= 512

.PHONY: all deps configure build render test clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@test -f $(BUILD_DIR)/CMakeCache.txt || cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: configure
	@cmake --build $(BUILD_DIR) -j$(JOBS)

render: build
	@./$(BUILD_DIR)/whitted render $(SCENE) -o $(OUT) --width $(SIZE) --height $(SIZE)

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS)

clean:
	rm -rf $(BUILD_DIR)
