# The two commands of the README, and a few more.
#   make render   install missing packages, build (Release), render the classic scene
#   make test     the same set-up, then every test through CTest
#   make handout OUT=dir, make proofs, make references: for instructors
#   make test-grader  end-to-end check of `whitted grade` (CI, after make test)
MAKEFLAGS += --no-print-directory
BUILD_DIR ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
SCENE ?= scenes/whitted_1980.p3f
OUT ?= whitted_1980.png
SIZE ?= 512

.PHONY: all deps configure build render test test-grader references handout proofs clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@test -f $(BUILD_DIR)/CMakeCache.txt || cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: configure
	@cmake --build $(BUILD_DIR) -j$(JOBS)

render: build
	@./$(BUILD_DIR)/whitted render $(SCENE) -o $(OUT) --width $(SIZE) --height $(SIZE)

# With the reference solution (the instructor's tree): every test, plainly.
# Without it (the student handout): every test, then each lab's progress.
test: build
ifneq ($(wildcard solution/01_ray_casting.cpp),)
	@cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS)
else
	@bash scripts/lab-progress.sh $(BUILD_DIR)
endif

ifneq ($(wildcard solution/01_ray_casting.cpp),)
test-grader: build
	@JOBS=$(JOBS) BUILD_DIR=$(BUILD_DIR) bash scripts/test-grader.sh

# Instructors: rewrite every reference picture from the reference solution.
references: build
	@cd $(BUILD_DIR) && WHITTED_UPDATE_REFERENCES=1 ctest -R '^(lab[0-9]\.(Hidden)?Lab[0-9]Image|integration\.)' -j$(JOBS) --output-on-failure
	@git status --short -- tests

# Instructors: write the student handout (no solution, hidden tests or mistakes) to OUT.
handout:
	@test -n "$(OUT)" || { echo "usage: make handout OUT=folder"; exit 2; }
	@bash scripts/export-handout.sh "$(OUT)"

# Instructors: prove the tests catch every stub and every catalogued mistake.
proofs:
	@bash scripts/prove-tests.sh
else
# The student handout has no reference solution: these are the instructor's.
test-grader references handout proofs:
	@echo "make $@ is for instructors: it needs the instructor's tree (solution/, tests/hidden/)"; exit 2
endif

clean:
	rm -rf $(BUILD_DIR)
