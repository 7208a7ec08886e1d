# retro: voxel-space render kernels. `make help` lists the targets.
# Objects go to $(BUILD); ISA flags are set per file; every object gets -ffp-contract=off.

CC       ?= cc
CXX      ?= c++
BUILD    ?= build
BIN      := $(BUILD)/bin
OPT      ?= -O2
SAN      ?=
V        ?= 0
Q        := $(if $(filter 1,$(V)),,@)
SHARED   ?= ../shared
VERSION  := 0.1.0
SOVERSION := 0
# Where runs write (bench, accuracy, demo): an ignored folder. `make publish` copies a full
# run from here into the committed results/ that the README quotes.
RESULTS  ?= $(BUILD)/results

WARN     := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wvla -Wconversion -Wno-sign-conversion
FPFLAGS  := -ffp-contract=off -fno-math-errno
CFLAGS   ?= $(OPT) -g
# Every folder that holds headers is on the include path, so a file moved between folders
# keeps its #include lines.
INCS     := -Isrc $(addprefix -I,$(patsubst %/,%,$(sort $(dir $(shell find include src tools -name '*.h')))))
ALLCFLAGS = -std=c11 -D_POSIX_C_SOURCE=200809L $(CFLAGS) $(WARN) $(FPFLAGS) $(SAN) $(INCS) -MMD -MP
CXXFLAGS ?= $(OPT) -g
ALLCXXFLAGS = -std=c++17 $(CXXFLAGS) -Wall -Wextra $(FPFLAGS) $(SAN) $(INCS) -MMD -MP

PKGS_LIB  := spng hwloc inih
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS_LIB) 2>/dev/null)
PKG_LIBS   = $(shell pkg-config --libs $(PKGS_LIB) 2>/dev/null)
TEST_LIBS  = $(shell pkg-config --libs criterion 2>/dev/null)
LDLIBS     = $(PKG_LIBS) -fopenmp -lm
# SDL2 is the retro CLI's alone (retro view's window): the library never sees it. Its headers
# are system headers, so the warning flags stay on for our code only.
SDL_CFLAGS = $(patsubst -I%,-isystem %,$(shell pkg-config --cflags sdl2 2>/dev/null))
SDL_LIBS   = $(shell pkg-config --libs sdl2 2>/dev/null)

# The course API (render, draw_line, update_player, bonus_implemented) is kept out of libretro,
# whose every exported name starts with retro_, so a program can define its own render().
COURSE_SRC := src/core/course.c
# Peer algorithms (src/peer/): others' traversals timed and measured beside the kernels, in the
# CLI and the benchmark only, never in the library or its kernel table.
PEER_SRC := $(wildcard src/peer/*.c)
# The library: every .c under src/ and tools/ but the CLI, the submission's own parts, the peers
# and the course API.
LIB_SRC  := $(sort $(filter-out src/cli/% src/submission/% src/peer/% $(COURSE_SRC),\
              $(shell find src tools -name '*.c')))
CLI_SRC  := $(wildcard src/cli/*.c) $(PEER_SRC)
TEST_SRC := $(wildcard tests/test_*.c) tests/ref_exact.c tests/hard_rig.c tests/skipping_rig.c $(PEER_SRC)
# The CLI's parts the unit tests call: retro view's SDL-free parts (tests/test_view_keys.c) and
# the accuracy run's steadiness (tests/test_accuracy_steady.c).
TEST_CLI := $(addprefix src/cli/,view_keys.c view_font.c view_overlay.c view_render.c \
              scene_job.c scene_args.c cli_args.c work_estimate.c chart_labels.c accuracy_steady.c timing.c)
COUNT_TEST_SRC := tests/count_writes.c tests/test_util.c
# Kernels rebuilt with RETRO_COUNT_WRITES for the write-once test.
COUNTED  := $(sort $(shell find src -name 'kernel_*.c'))

# The ybuffer kernel once more, counting the samples it evaluates (retro render --stats).
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o) $(BUILD)/src/voxel/ybuffer_counted.o $(BUILD)/src/voxel/simd_avx512_counted.o
CLI_OBJ  := $(CLI_SRC:%.c=$(BUILD)/%.o)
TEST_OBJ := $(TEST_SRC:%.c=$(BUILD)/%.o) $(TEST_CLI:%.c=$(BUILD)/%.o)
COUNT_OBJ := $(COUNTED:%.c=$(BUILD)/count/%.o) $(COUNT_TEST_SRC:%.c=$(BUILD)/%.o)
COUNT_LIB_OBJ := $(filter-out $(COUNTED:%.c=$(BUILD)/%.o),$(LIB_OBJ))

LIB      := $(BUILD)/libretro.a
COURSE_LIB := $(BUILD)/libretro-course.a
RETRO    := $(BIN)/retro
TESTS    := $(BIN)/retro-tests
COUNT_TESTS := $(BIN)/retro-count-tests
# The benchmark's own logic that needs no timing (tests/test_retime.cc: bench/retime.h's judgement).
BENCH_TESTS := $(BIN)/retro-bench-tests
# The course's update_player over a list of velocities: tests/view.sh checks retro view's poses.
VIEW_POSE := $(BIN)/retro-view-pose

.PHONY: all help deps check verify demo maps asan clean install submission accuracy view
all: $(RETRO) ## build the library and the retro CLI

help: ## list the targets and the variables they take
	@grep -hE '^[a-z-]+:.*## ' Makefile | sed 's/:.*## /\t/' | expand -t 16
	@echo
	@echo "Variables (make TARGET NAME=VALUE):"
	@echo "  SHARED=DIR      the course data folder, DIR/course (default ../shared); tests skip without it"
	@echo "  BUILD=DIR       where objects, binaries and runs go (default build)"
	@echo "  V=1             show the full compiler commands"
	@echo "  PREFIX=DIR      make install's destination (default /usr/local; DESTDIR is honoured)"
	@echo "  QUICK=1         make bench: 3 short repetitions, fewer sweep points (not publishable)"
	@echo "  RESULTS=DIR     where bench, accuracy and demo write (default BUILD/results)"
	@echo "  BENCH_ARGS=...  more retro-bench flags, e.g. --benchmark_filter=omp (build/bin/retro-bench --help)"
	@echo "  ACCURACY_ARGS=  more retro accuracy flags, e.g. --poses 5"
	@echo "  CC, OPT, CFLAGS the C compiler and its flags (default cc, -O2)"
	@echo
	@echo "Exports: make bench writes RESULTS/bench.json (google-benchmark's JSON, every repetition"
	@echo "and the run's context); make bench-csv converts it to RESULTS/bench.csv."

deps: ## install missing Debian packages (compiler, libraries, tools)
	$(Q)sh scripts/install-deps.sh

# Per-file flags by name, so a new file needs no line here. OpenMP only where threads are
# made: files named *omp.c or *omp_pool.c.
%omp.o %omp_pool.o: CFLAGS_FILE := -fopenmp
$(BUILD)/src/cli/view_window.o: CFLAGS_FILE = $(SDL_CFLAGS)

# ISA flags by folder and suffix: src/arch/x86/*_<isa>.c gets exactly its ISA, never
# -march=native and never -mfma (with -ffp-contract=off above, no multiply-add is fused).
ISA_FLAGS_sse2   := -msse2
ISA_FLAGS_avx2   := -mavx2
ISA_FLAGS_avx512 := -mavx2 -mavx512f -mavx512bw -mavx512vl -mavx512dq
$(foreach b,$(BUILD)/src/arch/x86 $(BUILD)/count/src/arch/x86 $(BUILD)/pic/src/arch/x86,\
  $(foreach i,sse2 avx2 avx512,$(eval $(b)/%_$(i).o: CFLAGS_ISA := $(ISA_FLAGS_$(i)))))

# The mesh module rounds binary32 results through (double)(float)x; gcc 12's SLP vectorizer
# drops that round trip when it packs two such stores (mesh_setup.c's cs and sn at -O2: the
# reference image then depends on the compiler), so the mesh objects are built without it.
$(BUILD)/src/mesh/%.o $(BUILD)/pic/src/mesh/%.o: CFLAGS_DIR := -fno-tree-slp-vectorize
# The mesh module's SIMD files by name: *_avx2.c, *_avx512.c; its threads in mesh_omp.c.
$(BUILD)/src/mesh/%_avx2.o $(BUILD)/pic/src/mesh/%_avx2.o: CFLAGS_ISA := -mavx2
$(BUILD)/src/mesh/%_avx512.o $(BUILD)/pic/src/mesh/%_avx512.o: \
  CFLAGS_ISA := -mavx2 -mavx512f -mavx512bw -mavx512vl -mavx512dq
$(BUILD)/src/mesh/mesh_omp.o $(BUILD)/pic/src/mesh/mesh_omp.o: CFLAGS_FILE := -fopenmp

$(BUILD)/src/cli/main.o: CFLAGS_FILE := -DRETRO_VERSION='"$(VERSION)"'

$(BUILD)/%.o: %.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(ALLCFLAGS) $(CFLAGS_FILE) $(CFLAGS_ISA) $(CFLAGS_DIR) $(PKG_CFLAGS) -c $< -o $@

$(BUILD)/count/%.o: %.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $< (counting writes)")
	$(Q)$(CC) $(ALLCFLAGS) $(CFLAGS_FILE) $(CFLAGS_ISA) -DRETRO_COUNT_WRITES -c $< -o $@

$(BUILD)/src/voxel/ybuffer_counted.o: src/voxel/kernel_ybuffer.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $< (counting samples)")
	$(Q)$(CC) $(ALLCFLAGS) -DRETRO_COUNT_SAMPLES -Dretro_kernel_ybuffer=retro_kernel_ybuffer_counted \
	  -Dretro_strip_ybuffer=retro_strip_ybuffer_counted -c $< -o $@

# The counting build of simd-avx512 (samples per SIMD group; hmax_pyramid.h), for --stats and
# the benchmark's samples/frame.
$(BUILD)/src/voxel/simd_avx512_counted.o: src/arch/x86/kernel_simd_avx512.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $< (counting samples)")
	$(Q)$(CC) $(ALLCFLAGS) $(ISA_FLAGS_avx512) -DRETRO_COUNT_SAMPLES \
	  -Dretro_kernel_simd_avx512=retro_kernel_simd_avx512_counted \
	  -Dretro_strip_simd_avx512=retro_strip_simd_avx512_counted -c $< -o $@

$(LIB): $(LIB_OBJ)
	$(Q)rm -f $@ && ar rcs $@ $^

$(COURSE_LIB): $(COURSE_SRC:%.c=$(BUILD)/%.o)
	$(Q)rm -f $@ && ar rcs $@ $^

$(RETRO): $(CLI_OBJ) $(COURSE_LIB) $(LIB)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SAN) -o $@ $(CLI_OBJ) $(COURSE_LIB) $(LIB) $(LDLIBS) $(SDL_LIBS)

$(VIEW_POSE): $(BUILD)/tests/view_pose.o $(COURSE_LIB) $(LIB)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SAN) -o $@ $< $(COURSE_LIB) $(LIB) $(LDLIBS)

$(TESTS): $(TEST_OBJ) $(COURSE_LIB) $(LIB)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SAN) -o $@ $(TEST_OBJ) $(COURSE_LIB) $(LIB) $(TEST_LIBS) $(LDLIBS)

$(COUNT_TESTS): $(COUNT_OBJ) $(COUNT_LIB_OBJ) $(COURSE_LIB)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SAN) -o $@ $(COUNT_OBJ) $(COURSE_LIB) $(COUNT_LIB_OBJ) $(TEST_LIBS) $(LDLIBS)

maps: $(RETRO) ## generate the default scenes and the analytic test maps under maps/
	$(Q)sh scripts/make-maps.sh $(RETRO)

check: deps ## run the tests (installs what is missing first)
	$(Q)$(MAKE) --no-print-directory $(RETRO) $(TESTS) $(COUNT_TESTS) $(BENCH_TESTS) $(VIEW_POSE) $(BENCH_BIN)
	$(Q)sh scripts/make-maps.sh $(RETRO)
	$(Q)RETRO_SHARED=$(SHARED) sh scripts/run-tests.sh $(RETRO) $(TESTS) $(COUNT_TESTS) $(BENCH_TESTS)

view: $(RETRO) ## fly through the islands scene in a window (retro view; keys in docs/VIEW.md)
	$(Q)sh scripts/make-maps.sh $(RETRO)
	$(Q)$(RETRO) view maps/islands.scene

verify: $(RETRO) ## every kernel in every mode against naive, byte for byte (full case set)
	$(Q)sh scripts/make-maps.sh $(RETRO)
	$(Q)RETRO_SHARED=$(SHARED) $(RETRO) verify

demo: deps ## render the default scenes to RESULTS/*.png (build/results; make publish commits them)
	$(Q)$(MAKE) --no-print-directory $(RETRO)
	$(Q)sh scripts/make-maps.sh $(RETRO)
	$(Q)sh scripts/demo.sh $(RETRO) $(RESULTS)

# Both compilers: each instruments and optimises differently, and clang builds the omp kernel
# on libomp. float-cast-overflow is named because gcc's -fsanitize=undefined leaves it out.
# The fuzz smoke test's clang build is shared by both runs (FUZZ_BUILD): it does not use CC.
ASAN_SAN := -fsanitize=address,undefined,float-cast-overflow \
  -fno-sanitize-recover=undefined,float-cast-overflow -fno-omit-frame-pointer
# A test can miss a report: Criterion's forked workers and the retro a shell test starts print
# to stderrs nobody reads. So every sanitized process logs to SAN_LOGS/CC/san.PID instead, and a
# half fails if any log is non-empty (scripts/sanitizer-logs.sh), whatever the tests counted.
# intercept_tls_get_addr=0: else clang 14's LeakSanitizer tracer crashes at exit on glibc 2.36.
SAN_LOGS  = $(abspath $(BUILD))/asan-logs
SAN_ENV   = ASAN_OPTIONS=log_path=$(SAN_LOGS)/$(1)/san:intercept_tls_get_addr=0:detect_leaks=1 \
  UBSAN_OPTIONS=log_path=$(SAN_LOGS)/$(1)/san:print_stacktrace=1:halt_on_error=1
.PHONY: asan-gcc asan-clang
asan: ## the tests under AddressSanitizer + UndefinedBehaviorSanitizer, built by gcc and by clang
	$(Q)$(MAKE) --no-print-directory asan-gcc
	$(Q)$(MAKE) --no-print-directory asan-clang
asan-gcc asan-clang: asan-%:
	$(Q)rm -rf $(SAN_LOGS)/$* && mkdir -p $(SAN_LOGS)/$*
	$(Q)$(call SAN_ENV,$*) FUZZ_BUILD=$(FUZZ_BUILD) $(MAKE) --no-print-directory check \
	  BUILD=$(BUILD)/asan-$* OPT=-O1 CC=$* CXX=$(if $(filter gcc,$*),g++,clang++) SAN="$(ASAN_SAN)"; \
	  rc=$$?; sh scripts/sanitizer-logs.sh $(SAN_LOGS)/$* "make asan ($*)" && [ $$rc -eq 0 ]

# --- fuzzing (tests/fuzz/, tests/fuzz_smoke.sh): libFuzzer targets, always clang ----------
# The library is rebuilt with coverage instrumentation into FUZZ_BUILD by a sub-make; each
# target links it (and the CLI's argument parsers). `make fuzz` runs every target for
# FUZZ_TIME seconds on a scratch copy of its seed corpus, so tests/ is never written, with the
# libFuzzer flags in tests/fuzz/TARGET.options if any.
FUZZ_CC      ?= clang
FUZZ_BUILD   ?= $(BUILD)/fuzz
FUZZ_TIME    ?= 60
FUZZ_SAN     := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
FUZZ_TARGETS := $(patsubst tests/fuzz/%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_LIBS    := $(FUZZ_BUILD)/src/cli/cli_args.o $(FUZZ_BUILD)/src/cli/view_keys.o $(FUZZ_BUILD)/libretro.a

.PHONY: fuzz fuzz-build
fuzz-build: ## build the libFuzzer targets into FUZZ_BUILD/bin (needs clang and libclang-rt-dev)
	$(Q)$(MAKE) --no-print-directory $(FUZZ_LIBS) BUILD=$(FUZZ_BUILD) CC=$(FUZZ_CC) OPT=-O1 \
	  SAN="-fsanitize=fuzzer-no-link $(FUZZ_SAN)"
	$(Q)$(MAKE) --no-print-directory $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/bin/%)

$(FUZZ_BUILD)/bin/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_string.h $(FUZZ_LIBS)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  FUZZ    $@")
	$(Q)$(FUZZ_CC) -std=c11 -D_POSIX_C_SOURCE=200809L -O1 -g $(WARN) $(FPFLAGS) -fsanitize=fuzzer \
	  $(FUZZ_SAN) $(INCS) $< $(FUZZ_LIBS) $(PKG_LIBS) -fopenmp -lm -o $@

fuzz: fuzz-build ## run every fuzz target for FUZZ_TIME seconds (default 60) from its seed corpus
	$(Q)for t in $(FUZZ_TARGETS); do \
	  rm -rf $(FUZZ_BUILD)/corpus/$$t && mkdir -p $(FUZZ_BUILD)/corpus/$$t $(FUZZ_BUILD)/artifacts && \
	  cp tests/fuzz/corpus/$$t/* $(FUZZ_BUILD)/corpus/$$t/ && \
	  echo "== $$t: $(FUZZ_TIME) s" && \
	  $(FUZZ_BUILD)/bin/$$t -max_total_time=$(FUZZ_TIME) -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_BUILD)/artifacts/$$t- $$(cat tests/fuzz/$$t.options 2>/dev/null) \
	    $(FUZZ_BUILD)/corpus/$$t || exit 1; \
	done
# --- end of fuzzing block -----------------------------------------------------------------

# --- benchmark (bench/, scripts/bench.sh): the only C++, google-benchmark and hwloc -------
BENCH_BIN  := $(BIN)/retro-bench
BENCH_PKGS := benchmark hwloc
BENCH_OBJ  := $(patsubst %,$(BUILD)/%.o,$(basename $(wildcard bench/*.c bench/*.cc))) $(PEER_SRC:%.c=$(BUILD)/%.o) \
              $(BUILD)/bench/submission.o $(BUILD)/bench/ybuffer_noeffects.o \
              $(BUILD)/src/cli/cli_args.o # the CLI's strict number parsers (fuzz_cli checks them)
SUBMISSION_SRC := $(shell find src include -name '*.[ch]' -not -path 'src/cli/*') scripts/make-submission.sh
QUICK      ?=
BENCH_ARGS ?=

$(BUILD)/bench/%.o: bench/%.cc
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CXX     $<")
	$(Q)$(CXX) $(ALLCXXFLAGS) $(shell pkg-config --cflags $(BENCH_PKGS) 2>/dev/null) -c $< -o $@

# The course's baseline and the generated submission are built as the course builds them: -O3
# alone. The submission's every global but render() is made local (it repeats the library's
# symbols) and render() becomes submission_render().
$(BUILD)/bench/course_painter.o: OPT := -O3
$(BUILD)/bench/submission.o: $(SUBMISSION_SRC)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      results/submission/render.c (-O3, for the benchmark)")
	$(Q)sh scripts/make-submission.sh $(BUILD)/bench/submission.c
	$(Q)$(CC) -O3 -Wall -Wextra -pedantic -Iinclude -c $(BUILD)/bench/submission.c -o $@.tmp.o
	$(Q)objcopy --redefine-sym render=submission_render $@.tmp.o $@.tmp2.o
	$(Q)objcopy --keep-global-symbol=submission_render $@.tmp2.o $@
	$(Q)rm -f $@.tmp.o $@.tmp2.o
# ybuffer without its effect code, to show that effects not called for cost nothing.
$(BUILD)/bench/ybuffer_noeffects.o: src/voxel/kernel_ybuffer.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $< (effects compiled out)")
	$(Q)$(CC) $(ALLCFLAGS) -DRETRO_NO_EFFECTS -Dretro_kernel_ybuffer=retro_kernel_ybuffer_noeffects \
	  -Dretro_strip_ybuffer=retro_strip_ybuffer_noeffects -c $< -o $@

# The run's record names the compiler and flags the kernels were built with.
$(BUILD)/bench/run_context.o: ALLCXXFLAGS += -DRETRO_BUILD_CC='"$(shell $(CC) --version | head -n 1)"' \
  -DRETRO_BUILD_CFLAGS='"$(strip $(CFLAGS) $(FPFLAGS) $(SAN))"'

$(BUILD)/tests/%.o: tests/%.cc
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CXX     $<")
	$(Q)$(CXX) $(ALLCXXFLAGS) -Ibench -c $< -o $@

$(BENCH_TESTS): $(BUILD)/tests/test_retime.o $(BUILD)/bench/retime.o
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CXX) $(SAN) -o $@ $^ $(TEST_LIBS)

$(BENCH_BIN): $(BENCH_OBJ) $(COURSE_LIB) $(LIB)
	@mkdir -p $(@D)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CXX) $(SAN) -o $@ $(BENCH_OBJ) $(COURSE_LIB) $(LIB) $(shell pkg-config --libs $(BENCH_PKGS)) -lpthread $(LDLIBS)

.PHONY: bench
bench: deps ## time every kernel (mode exact also with skipping off), scene and mode: RESULTS/BENCH.md, bench.json, charts, skip-columns (QUICK=1)
	$(Q)$(MAKE) --no-print-directory $(RETRO) $(BENCH_BIN)
	$(Q)sh scripts/make-maps.sh $(RETRO)
	$(Q)RETRO_SHARED=$(SHARED) sh scripts/bench.sh $(BENCH_BIN) $(RESULTS) $(BUILD)/bench-charts.gp \
	  $(if $(filter-out 0,$(QUICK)),--quick) --no-skip $(BENCH_ARGS)
	$(Q)sh scripts/skip-columns.sh $(RETRO) $(RESULTS)
	$(Q)$(call CODE_DIGEST,bench-code.txt,$(RETRO) $(BENCH_BIN))

.PHONY: study-replay
study-replay: deps ## where a skipping frame's time goes, by replaying probes and stores: RESULTS/study-replay.md (docs/studies/SKIPPING_LIMITS.md)
	$(Q)mkdir -p $(RESULTS)
	$(Q)sh scripts/study-replay.sh --shared $(SHARED) -o $(RESULTS)/study-replay.md
# --- end of benchmark block ---------------------------------------------------------------

ACCURACY_ARGS ?=
accuracy: $(RETRO) ## what accuracy costs: RESULTS/ACCURACY.md and a Pareto chart
	$(Q)sh scripts/make-maps.sh $(RETRO)
	$(Q)mkdir -p $(RESULTS)
	$(Q)RETRO_SHARED=$(SHARED) RETRO_COMMIT="$$(git describe --always --dirty --abbrev=12 2>/dev/null)" \
	  $(RETRO) accuracy -o $(RESULTS)/ACCURACY.md \
	  --chart $(RESULTS)/accuracy-pareto.svg $(ACCURACY_ARGS)
	$(Q)$(call CODE_DIGEST,accuracy-code.txt,$(RETRO))

# The machine code the run just timed, object by object, beside its results: the README then says
# which objects a later commit compiles differently (scripts/code_digest.py). Only where the
# binaries that ran ($(2)) are BUILD's own: binaries named from elsewhere have no objects here.
CODE_DIGEST = $(if $(filter-out $(BIN)/retro $(BIN)/retro-bench,$(2)), \
  echo "  note: no $(RESULTS)/$(1): $(2) not built in $(BUILD)", \
  python3 scripts/code_digest.py write $(BUILD) $(RESULTS)/$(1) \
  "commit: $$(git describe --always --dirty --abbrev=12 2>/dev/null)" && echo "  wrote $(RESULTS)/$(1)")

# The only target that writes the committed results/: a full (not quick) run of make bench,
# and make accuracy and make demo if they ran, then the README's generated figures.
.PHONY: bench-csv
bench-csv: ## the last run's bench.json as CSV: RESULTS/bench.csv
	$(Q)test -f $(RESULTS)/bench.json || { echo "error: no $(RESULTS)/bench.json (make bench first)" >&2; exit 2; }
	$(Q)python3 scripts/bench-csv.py $(RESULTS)/bench.json >$(RESULTS)/bench.csv.tmp || { rm -f $(RESULTS)/bench.csv.tmp; exit 2; }
	$(Q)mv $(RESULTS)/bench.csv.tmp $(RESULTS)/bench.csv && echo "  wrote $(RESULTS)/bench.csv"

.PHONY: publish publish-accuracy
publish: ## copy the last full run from RESULTS into results/ and refresh the README's figures
	$(Q)sh scripts/publish.sh $(RESULTS) results README.md

publish-accuracy: ## copy the last make accuracy run alone from RESULTS into results/ and refresh the README
	$(Q)sh scripts/publish.sh $(RESULTS) results README.md --accuracy

submission: ## the single-file course render.c (results/submission/render.c), built and tested as the course does
	$(Q)sh scripts/make-submission.sh results/submission/render.c
	@echo "  GEN     results/submission/render.c"
	$(Q)CC="$(CC)" sh scripts/check-submission.sh results/submission/render.c $(SHARED)

# --- installation: the CLI, libretro (static, and shared with a soname), headers, retro.pc,
# the man page. The shared library's objects are built again position-independent, so the
# static library and the binaries keep the code the benchmark times.
PREFIX ?= /usr/local
SO      := $(BUILD)/libretro.so.$(VERSION)
PIC_OBJ := $(LIB_SRC:%.c=$(BUILD)/pic/%.o)
MAN     := $(BUILD)/retro.1

$(BUILD)/pic/%.o: %.c
	@mkdir -p $(@D)
	@$(if $(Q),echo "  CC      $< (-fPIC)")
	$(Q)$(CC) $(ALLCFLAGS) -fPIC -fno-semantic-interposition $(CFLAGS_FILE) $(CFLAGS_ISA) $(CFLAGS_DIR) $(PKG_CFLAGS) \
	  -c $< -o $@

# --no-undefined: the library names every library it needs, so a program links with -lretro.
# Not under sanitizers: clang leaves their runtime to the executable.
$(SO): $(PIC_OBJ)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SAN) -shared -Wl,-soname,libretro.so.$(SOVERSION) $(if $(SAN),,-Wl,--no-undefined) \
	  -o $@ $^ $(LDLIBS)

# help2man (Debian package help2man) writes the page from retro --help and --version, and
# every subcommand's --help (scripts/man-include.sh).
$(MAN): $(RETRO) scripts/retro.h2m scripts/man-include.sh
	@$(if $(Q),echo "  MAN     $@")
	$(Q)sh scripts/man-include.sh $(RETRO) >$(BUILD)/retro.h2m
	$(Q)help2man --no-info --name="voxel-space terrain render kernels" \
	  --include=$(BUILD)/retro.h2m $(RETRO) -o $@.tmp && mv $@.tmp $@

.PHONY: shared
shared: $(SO) ## build the shared library, build/libretro.so.VERSION
install: $(RETRO) $(LIB) $(SO) $(MAN) ## install retro, libretro (.a, .so), headers, retro.pc, man page under PREFIX
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig \
	  $(DESTDIR)$(PREFIX)/include/retro $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 $(RETRO) $(DESTDIR)$(PREFIX)/bin/
	install -m 644 $(LIB) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(SO) $(DESTDIR)$(PREFIX)/lib/
	ln -sf libretro.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/libretro.so.$(SOVERSION)
	ln -sf libretro.so.$(SOVERSION) $(DESTDIR)$(PREFIX)/lib/libretro.so
	install -m 644 include/*.h include/*/*.h $(DESTDIR)$(PREFIX)/include/retro/
	sh scripts/make-pc.sh "$(PREFIX)" "$(VERSION)" "$(PKGS_LIB)" "-fopenmp -lm" \
	  >$(DESTDIR)$(PREFIX)/lib/pkgconfig/retro.pc
	install -m 644 $(MAN) $(DESTDIR)$(PREFIX)/share/man/man1/

clean: ## remove build outputs (generated maps too)
	rm -rf build maps/*.pgm maps/*.ppm maps/*.png results/verify

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
