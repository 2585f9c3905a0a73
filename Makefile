# The two commands of the README, and a few more.
#   make render   install missing packages, build (Release), render the classic scene
#   make test     the same set-up, then every test through CTest
#   make handout OUT=dir, make proofs, make references: for instructors
#   make test-grader  end-to-end check of `whitted grade` (CI, after make test)
#   make test-report  the grader's report.html opened in headless Chromium (CI)
#   make test-explore `whitted explore` in headless Chromium: a click, a pass, a broken and a mended lab (CI)
#   make bench    time whitted against POV-Ray and Embree (instructor/docs/instructors.md, "Benchmark")
#   make sanitize every test built with AddressSanitizer + UBSan (instructor/docs/robustness.md)
#   make fuzz     fuzz the loaders and the image reader, MINUTES each (instructor/docs/robustness.md)
#   make test-hostile  the grader against hostile submissions (CI)
#   make gradescope    the Gradescope autograder zip (instructor/docs/instructors.md, "Deploy")
#   make test-gradescope  that zip in a root shaped like Gradescope's (CI)
MAKEFLAGS += --no-print-directory
BUILD_DIR ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
SCENE ?= scenes/whitted_1980.p3f
OUT ?= whitted_1980.png
SIZE ?= 512
# make bench: generated sphereflake levels, scene files, extra whitted-bench flags.
SPD_DIR ?= ../shared/scenes/spd
BENCH_FLAKES ?= 4,5,6
# A held-out scene kind the renderer is not tuned to: a random triangle soup of 64,000 triangles.
BENCH_SOUPS ?= 4
BENCH_SCENES ?= $(wildcard $(SPD_DIR)/teapot6.nff $(SPD_DIR)/mount6.nff $(SPD_DIR)/tetra6.nff)
BENCH_ARGS ?=
# The last committed figures: make bench flags whitted's load or render times that got worse.
BENCH_BASELINE ?= instructor/bench/baseline.json

MINUTES ?= 10
# make gradescope: the zip and the choices it carries (instructor/scripts/make-autograder.sh).
ZIP ?= autograder.zip
HIDDEN_VISIBILITY ?= hidden
TEST_TIMEOUT ?= 20
BUDGET ?= 600

# The tree's build mode (cmake/WhittedMode.cmake): instructor (solution/ and
# instructor/ are here) or handout (the student's tree).
MODE := $(shell sed -n 's/^set(WHITTED_DEFAULT_MODE \([a-z]*\))$$/\1/p' cmake/WhittedMode.cmake)
INSTRUCTOR := $(filter instructor,$(MODE))

.PHONY: all deps configure build render test bench sanitize fuzz test-grader test-report test-explore test-hostile references handout proofs gradescope test-gradescope clean

all: build

deps:
	@bash scripts/install-deps.sh $(DEPS_ARGS)

configure: deps
	@test -f $(BUILD_DIR)/CMakeCache.txt || cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: configure
	@cmake --build $(BUILD_DIR) -j$(JOBS)

# Only what rendering needs (the whitted command), not the tests: the first picture comes sooner.
render: configure
	@cmake --build $(BUILD_DIR) -j$(JOBS) --target whitted
	@./$(BUILD_DIR)/whitted render $(SCENE) -o $(OUT) --width $(SIZE) --height $(SIZE)

# With the reference solution (the instructor's tree): every test, plainly.
# Without it (the student handout): every test, then each lab's progress.
# make test LAB=3: only lab 3's tests (built and run), for a student working on one lab.
ifneq ($(LAB),)
# LAB=07 is lab 7.
LAB_NUMBER = $(shell echo "$(LAB)" | sed 's/^0*//')
test: configure
	@echo "$(LAB)" | grep -qE '^0*([1-9]|10)$$' || { echo "make test LAB=$(LAB): the labs are numbered 1 to 10 (make test LAB=7; ./$(BUILD_DIR)/whitted labs lists them)"; exit 2; }
	@cmake --build $(BUILD_DIR) -j$(JOBS) --target lab$(LAB_NUMBER)
	@cd $(BUILD_DIR) && ctest -L '^lab$(LAB_NUMBER)$$' --output-on-failure -j$(JOBS)
	@echo "lab $(LAB_NUMBER)'s picture: $(BUILD_DIR)/pictures/lab$(LAB_NUMBER).png"
else
test: build
ifneq ($(INSTRUCTOR),)
	@cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS)
else
	@cmake -DBUILD_DIR=$(BUILD_DIR) -DJOBS=$(JOBS) -P scripts/lab.cmake
endif
endif

# Every test again, built with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/).
sanitize: deps
	@bash scripts/test-sanitizers.sh

ifneq ($(INSTRUCTOR),)
# The benchmark of issue 4; it also installs POV-Ray and Embree 3 when it can.
# Configuring again finds Embree when it has just been installed.
bench: DEPS_ARGS = --bench
bench: configure
	@cmake -S . -B $(BUILD_DIR) -DWHITTED_BENCH=ON > /dev/null
	@grep -q '^CMAKE_BUILD_TYPE:STRING=Release$$' $(BUILD_DIR)/CMakeCache.txt || echo "warning: $(BUILD_DIR) is not a Release build: the times say little"
	@cmake --build $(BUILD_DIR) -j$(JOBS) --target whitted-bench whitted-as-student
	@test -d "$(SPD_DIR)" || echo "note: no SPD scenes in $(SPD_DIR): benching the generated scenes only (make bench SPD_DIR=folder/with/teapot6.nff...)"
	@./$(BUILD_DIR)/whitted-bench --flake $(BENCH_FLAKES) --soup $(BENCH_SOUPS) $(BENCH_SCENES) \
	  --student-whitted $(BUILD_DIR)/whitted-as-student $(if $(wildcard $(BENCH_BASELINE)),--baseline $(BENCH_BASELINE)) $(BENCH_ARGS)

test-grader: build
	@JOBS=$(JOBS) BUILD_DIR=$(BUILD_DIR) bash instructor/scripts/test-grader.sh

# The grading report in a real browser; it also installs chromium when it can.
test-report: DEPS_ARGS = --browser
test-report: build
	@JOBS=$(JOBS) BUILD_DIR=$(BUILD_DIR) bash instructor/scripts/test-report-browser.sh

test-explore: DEPS_ARGS = --browser
test-explore: deps
	@bash instructor/scripts/test-explore-browser.sh

test-hostile: build
	@JOBS=$(JOBS) BUILD_DIR=$(BUILD_DIR) bash instructor/scripts/test-hostile.sh

# Instructors: the Gradescope autograder (setup.sh, run_autograder, the tree); it needs no build.
gradescope:
	@bash instructor/scripts/make-autograder.sh --out "$(ZIP)" --hidden-visibility "$(HIDDEN_VISIBILITY)" \
	  --timeout "$(TEST_TIMEOUT)" --budget "$(BUDGET)"

# That zip unpacked in a folder shaped like Gradescope's /autograder: setup.sh, then submissions.
test-gradescope: deps
	@bash instructor/scripts/test-gradescope.sh

# libFuzzer on the NFF and P3F loaders and the image reader, MINUTES each (build-fuzz/).
fuzz: DEPS_ARGS = --fuzz
fuzz: deps
	@bash instructor/scripts/fuzz.sh --minutes $(MINUTES)

# Instructors: rewrite every reference picture from the reference solution.
references: build
	@cd $(BUILD_DIR) && WHITTED_UPDATE_REFERENCES=1 ctest -R '^(lab[0-9]\.(Hidden)?Lab[0-9]Image|integration\.)' -j$(JOBS) --output-on-failure
	@git status --short -- tests instructor/tests

# Instructors: write the student handout (no solution, hidden tests or mistakes) to OUT.
handout:
	@test -n "$(OUT)" || { echo "usage: make handout OUT=folder"; exit 2; }
	@bash instructor/scripts/export-handout.sh "$(OUT)"

# Instructors: prove the tests catch every stub and every catalogued mistake.
proofs:
	@bash scripts/install-deps.sh --proofs
	@bash instructor/scripts/prove-tests.sh
else
# The student handout has no reference solution: these are the instructor's.
test-grader test-report test-explore test-hostile fuzz references handout proofs bench gradescope test-gradescope:
	@echo "make $@ is for instructors: it needs the instructor's tree (solution/ and instructor/)"; exit 2
endif

clean:
	rm -rf $(BUILD_DIR)
