# dexmill: plain GNU Make, out-of-tree objects under build/.
#
#   make              build build/dexmill
#   make run          build and run the built-in demo (writes out/)
#   make test         build and run every test (SAN=1: under ASan+UBSan)
#   make bless        rewrite every golden from this build's output, and nothing
#                     else: tests/golden/golden.out, hashes.txt and frames/,
#                     tests/gcode/paths/*.path, tests/run/pocket.report.golden
#                     (tests/golden/README.md: look at the pictures first, and
#                     say in the commit why the new output is right)
#   make CXX=clang++  the same with clang
#   make lib          build/libdexmill.a and .so (the C API, display/api/dexmill.h) and
#                     build/libdexmill_io.a (image files, platform/api/dexmill_io.h)
#   make install      PREFIX=/usr/local DESTDIR=...: the binary, the libraries, their
#                     headers and pkg-config file, the man page, the Python wrapper;
#                     make uninstall removes exactly those
#   make V=1          show every command (by default a compile prints nothing
#                     unless it fails, a link or archive one line)
#   make GLFW=1       build/glfw/dexmill, with the live window of `dexmill run --window`
#                     (libglfw3-dev: tools/scripts/install-deps.sh window); its own
#                     build folder, so switching does not rebuild the rest
#   make web          build/web/: the page that cuts and draws in a browser
#                     (WebAssembly; tools/scripts/install-deps.sh web), and
#                     make test-web its pixels against dexmill run's in Chromium
#
# core/ and display/ are compiled with -fno-exceptions -fno-rtti and with
# core/integer_only.h forced in, which poisons float and double (core/README.md,
# invariant 1). `make test` also proves that the poison works and that every
# header of core/ and display/ compiles on its own under those rules, and that
# the stage folders of every top-level folder include one way
# (tests/check_layers.sh).

CXX      ?= g++
SAN      ?=
OPT      ?= -O2
BUILD    ?= build$(if $(SAN),/san)$(if $(GLFW),/glfw)

# V=1 prints each command; otherwise compiles are silent and links say
# what they made, so `make run` shows a handful of lines.
V        ?=
ifeq ($(V),1)
Q        :=
say      :=
else
Q        := @
say       = @printf '  %-5s %s\n' $(1) $(2);
endif

WARN     := -Wall -Wextra -Werror -Wshadow -Wvla -Wundef
BASEFLAGS := -std=c++17 $(OPT) -g $(WARN) -I. -MMD -MP
ifneq ($(SAN),)
# vptr checks need RTTI, which core/ and display/ do not have (host code holds
# core CanonSinks such as Mill and MotionSummary).
BASEFLAGS += -fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=all -fno-omit-frame-pointer
# The range arguments checked (core/config.h DEXMILL_CHECKED_ARITH): a product
# assumed to fit that does not is a UBSan report (tests/test_ranges.cpp).
BASEFLAGS += -DDEXMILL_CHECKED_ARITH=1
LDSAN    := -fsanitize=address,undefined
endif
# Rules of core/ and display/: integer only, no exceptions, no RTTI.
INTFLAGS := -fno-exceptions -fno-rtti -include core/integer_only.h
# core/ and display/ are compiled once for the binary, the tests and the
# libraries: position independent (the shared library) and hidden but for
# the C API's dm_ functions (display/api/dexmill.h DM_API). Not for the
# embedded checks, which take INTFLAGS alone.
PICFLAGS := -fPIC -fvisibility=hidden
HOSTFLAGS :=
LDFLAGS  += $(LDSAN)
LDLIBS   ?=
# The window (platform/live/window_glfw.cpp) needs GLFW and OpenGL.
GLFW     ?=
ifneq ($(GLFW),)
ifneq ($(shell pkg-config --exists glfw3 gl 2>/dev/null && echo yes),yes)
$(error GLFW=1 needs GLFW and OpenGL's development files (pkg-config glfw3 gl); install them with tools/scripts/install-deps.sh window)
endif
HOSTFLAGS += -DDEXMILL_GLFW $(shell pkg-config --cflags glfw3 gl)
LDLIBS   += $(shell pkg-config --libs glfw3 gl)
endif

# Each top-level folder has one folder per stage (README: "Where things live").
rwildcard = $(foreach d,$(wildcard $(1:=/*)),$(call rwildcard,$(d),$(2)) $(filter $(subst *,%,$(2)),$(d)))
CORE_SRC     := $(sort $(call rwildcard,core,*.cpp))
DISPLAY_SRC  := $(sort $(call rwildcard,display,*.cpp))
PLATFORM_SRC := $(sort $(filter-out platform/web/%,$(call rwildcard,platform,*.cpp)))  # web/: wasm32 only (make web)
TOOLS_SRC    := $(sort $(filter-out tools/cli/main.cpp tools/panel/%,$(call rwildcard,tools,*.cpp)))
TEST_SRC     := $(sort $(wildcard tests/*.cpp))
INT_HEADERS  := $(sort $(call rwildcard,core display,*.h))

obj = $(patsubst %.cpp,$(BUILD)/obj/%.o,$(1))
INT_OBJ  := $(call obj,$(CORE_SRC) $(DISPLAY_SRC))
HOST_OBJ := $(call obj,$(PLATFORM_SRC) $(TOOLS_SRC))
MAIN_OBJ := $(call obj,tools/cli/main.cpp)
TEST_OBJ := $(call obj,$(TEST_SRC))
HDR_STAMPS := $(patsubst %.h,$(BUILD)/hdr/%.ok,$(INT_HEADERS))

BIN      := $(BUILD)/dexmill
TEST_BIN := $(BUILD)/dexmill_tests

# Rebuild everything when the compiler or the flags change.
FLAGS_ID := $(CXX) $(BASEFLAGS) $(INTFLAGS) $(PICFLAGS) $(LDFLAGS) $(LDLIBS)
FLAGS_STAMP := $(BUILD)/.flags
$(shell mkdir -p $(BUILD) && (test -f $(FLAGS_STAMP) && [ "`cat $(FLAGS_STAMP)`" = "$(FLAGS_ID)" ] || echo "$(FLAGS_ID)" > $(FLAGS_STAMP)))

.PHONY: all run test test-unit bless check-golden-out check-bless check-readme check-headers check-poison check-layers \
        check-function-length check-comments check-c-api check-lib \
        test-embed test-python test-install test-sheet lib install uninstall clean
all: $(BIN)

$(BUILD)/obj/core/%.o $(BUILD)/obj/display/%.o: BUILD_KIND := int
$(BUILD)/obj/%.o: %.cpp $(FLAGS_STAMP)
	@mkdir -p $(dir $@)
	$(Q)$(CXX) $(BASEFLAGS) $(if $(filter int,$(BUILD_KIND)),$(INTFLAGS) $(PICFLAGS),$(HOSTFLAGS)) -c $< -o $@
# The io header includes dexmill.h as an embedder's program does.
$(BUILD)/obj/platform/api/dexmill_io.o: HOSTFLAGS += -Idisplay/api
# The sweep's column loops start on 64-byte boundaries. Unaligned, a change
# elsewhere in the file that moved them cost paper-w1..w3 10-16 % in wall
# time with the same instructions (callgrind within 0.5 %); aligned, the
# code before and after that change ran alike (tools/README.md, Benchmarks).
$(BUILD)/obj/core/cut/sweep_line.o $(BUILD)/obj/core/cut/sweep_line_w.o: INTFLAGS += -falign-loops=64 -falign-functions=64
# PNG's filters: -O3 vectorises the row loops that try all five filter
# types, which took a heightmap's PNG from 0.44 s to 0.32 s (4503² samples,
# platform/format/png.cpp), and Adler-32's block sums (platform/format/
# deflate.cpp: 162 M -> 148 M instructions for that heightmap); only on the
# default -O2, so a debug build stays as asked.
$(BUILD)/obj/platform/format/png.o $(BUILD)/obj/platform/format/deflate.o: HOSTFLAGS += $(if $(filter -O2,$(OPT)),-O3)

$(BIN): $(MAIN_OBJ) $(HOST_OBJ) $(INT_OBJ)
	$(call say,LINK,$@)
	$(Q)$(CXX) $(LDFLAGS) $^ -o $@ $(LDLIBS)

$(TEST_BIN): $(TEST_OBJ) $(HOST_OBJ) $(INT_OBJ)
	$(call say,LINK,$@)
	$(Q)$(CXX) $(LDFLAGS) $^ -o $@ $(LDLIBS)

# Every core/display header compiles alone under the integer-only rules.
$(BUILD)/hdr/%.ok: %.h $(FLAGS_STAMP)
	@mkdir -p $(dir $@)
	@$(CXX) $(BASEFLAGS) $(INTFLAGS) -include $< -MF $(@:.ok=.d) -MT $@ -x c++ -fsyntax-only /dev/null && touch $@
check-headers: $(HDR_STAMPS)

# The poison must reject floating point: this compile has to fail.
check-poison:
	@if $(CXX) -std=c++17 -I. $(INTFLAGS) -fsyntax-only -x c++ tests/negative/float_in_core.cc 2>/dev/null; then \
	  echo "FAIL: tests/negative/float_in_core.cc compiled; float/double are not poisoned"; exit 1; \
	else echo "ok: float/double are rejected in core/ and display/"; fi

# The pipeline runs one way: each stage folder of core/, display/, platform/
# and tools/ includes only those it may; the self-test first shows that a
# forbidden include in each row is caught.
check-layers:
	@tests/check_layers.sh --self-test && tests/check_layers.sh

# Comments point inside the repository: no issue numbers, no documents
# kept outside it (tests/check_comments.sh); the self-test first shows that
# it catches planted ones.
check-comments:
	@tests/check_comments.sh --self-test && tests/check_comments.sh

# No function of tools/ is longer than 120 lines; the check's self-test
# first shows that it catches one.
check-function-length:
	@tests/check_function_length.sh --self-test && tests/check_function_length.sh

# Every README block marked ```sh runnable runs as written, and each
# ```text output block after one is what it printed (in a scratch
# copy of the tree, with this build); the self-test shows a failing one fails.
check-readme: $(BIN)
	@tests/readme_blocks.sh --self-test $(BUILD) && tests/readme_blocks.sh $(BUILD)

# The cases run in TEST_JOBS worker processes (tests/runner.cpp --jobs).
# A frame golden that differs leaves its expected, actual and difference
# pictures in GOLDEN_DIFF (tests/golden_check.h); a DEXMILL_BLESS left in the
# environment must not turn the checks into writes.
TEST_JOBS ?= 2
GOLDEN_DIFF := $(BUILD)/golden-diff
test-unit: $(TEST_BIN) $(BIN)
	$(Q)DEXMILL_BLESS= DEXMILL=$(abspath $(BIN)) DEXMILL_GOLDEN_OUT=$(abspath $(GOLDEN_DIFF)) $(TEST_BIN) --jobs $(TEST_JOBS)

# The golden-output program (tests/golden/golden.h) built for this host as
# make xcheck builds it for every target: its output is tests/golden/golden.out.
GOLDEN_SRC := $(sort $(wildcard tests/golden/golden*.cpp))
GOLDEN_BIN := $(BUILD)/golden
$(BUILD)/obj/tests/golden/golden%.o: BUILD_KIND := int
$(GOLDEN_BIN): $(call obj,$(GOLDEN_SRC) tools/panel/text_out.cpp tools/panel/board_host.cpp) $(INT_OBJ)
	$(call say,LINK,$@)
	$(Q)$(CXX) $(LDFLAGS) $^ -o $@ $(LDLIBS)
check-golden-out: $(GOLDEN_BIN)
	@$(GOLDEN_BIN) > $(BUILD)/golden.out && cmp -s tests/golden/golden.out $(BUILD)/golden.out && \
	  echo "ok: the golden output is tests/golden/golden.out" || \
	  { echo "FAIL: $(BUILD)/golden.out differs from tests/golden/golden.out:"; \
	    diff tests/golden/golden.out $(BUILD)/golden.out | head -20; exit 1; }

# Every golden rewritten from this build (tests/bless.sh says which), in this
# tree; check-bless blesses a spoilt copy of tests/ and requires it to come
# back byte for byte, so bless writes each kind and nothing else.
BLESS_TOOLS = $(abspath $(GOLDEN_BIN)) $(abspath $(TEST_BIN)) $(abspath $(BIN)) $(TEST_JOBS)
bless: $(GOLDEN_BIN) $(TEST_BIN) $(BIN)
	$(Q)tests/bless.sh . $(BLESS_TOOLS)
check-bless: $(GOLDEN_BIN) $(TEST_BIN) $(BIN)
	$(Q)tests/bless_check.sh $(BLESS_TOOLS)

test: check-headers check-poison check-layers check-function-length check-comments check-c-api check-lib test-unit \
      check-golden-out \
      check-bless test-embed test-python test-install test-sheet test-web check-readme

run: $(BIN)
	$(BIN) run --demo pocket

clean:
	rm -rf build

# ---- the library: the C API over core/ and display/ (display/api/dexmill.h) --
# libdexmill.a and .so hold the same objects the binary links; the .so
# exports the dm_ functions only. libdexmill_io.a is the platform's image
# encoders behind platform/api/dexmill_io.h, with the display and core
# objects they use (the framebuffer, CRC-32), so it links beside either.
API_VERSION := $(shell sed -n 's/^\#define DEXMILL_API_VERSION \([0-9]*\).*/\1/p' display/api/dexmill.h)
API_CC   ?= $(if $(findstring clang,$(CXX)),clang,gcc)
C99FLAGS := -std=c99 -Wall -Wextra -Werror -pedantic
LIB_A    := $(BUILD)/libdexmill.a
LIB_SO   := $(BUILD)/libdexmill.so
LIB_IO   := $(BUILD)/libdexmill_io.a
IO_OBJ   := $(call obj,platform/api/dexmill_io.cpp platform/format/image_file.cpp platform/format/ppm.cpp platform/format/png.cpp platform/format/pgm.cpp \
              platform/os/read_file.cpp platform/format/deflate.cpp platform/os/parallel.cpp platform/os/output_file.cpp platform/os/output_set.cpp platform/os/temp_file.cpp platform/os/process.cpp \
              display/raster/framebuffer.cpp core/math/crc32.cpp)
EMBED    := $(BUILD)/embed
lib: $(LIB_A) $(LIB_SO) $(LIB_IO)
$(LIB_A): $(INT_OBJ)
	@rm -f $@
	$(call say,AR,$@)
	$(Q)ar rcs $@ $^
$(LIB_SO): $(INT_OBJ)
	$(call say,LINK,$@)
	$(Q)$(CXX) -shared $(LDFLAGS) $^ -o $@
$(LIB_IO): $(IO_OBJ)
	@rm -f $@
	$(call say,AR,$@)
	$(Q)ar rcs $@ $^
# The example embedder (tools/examples/embed.c), a C program on the libraries.
# Under SAN the C++ compiler links it: clang's UBSan puts the handlers the
# C++ objects call (-fsanitize=function) in a runtime only clang++ links.
$(EMBED): tools/examples/embed.c display/api/dexmill.h platform/api/dexmill_io.h $(LIB_A) $(LIB_IO) $(FLAGS_STAMP)
	$(call say,LINK,$@)
	$(Q)$(API_CC) $(C99FLAGS) -O2 -Idisplay/api -Iplatform/api -c $< -o $@.o
	$(Q)$(if $(SAN),$(CXX),$(API_CC)) $@.o $(LIB_IO) $(LIB_A) -lstdc++ $(LDSAN) -o $@

# The C API header compiles as C99 (and as C++: check-headers).
check-c-api:
	@$(API_CC) $(C99FLAGS) -fsyntax-only -x c display/api/dexmill.h && \
	  $(API_CC) $(C99FLAGS) -Idisplay/api -fsyntax-only -x c platform/api/dexmill_io.h && \
	  echo "ok: dexmill.h and dexmill_io.h compile as C99"
# The shared library exports the dm_ functions and nothing else.
# Under SAN, clang's -fsanitize=function adds the type descriptors of
# function types (_ZTIF..., _ZTSF...), which a shipped build does not have.
LIB_EXPORTS_OK := ^(dm_|_init$$|_fini$$$(if $(SAN),|_ZT[IS]F))
check-lib: $(LIB_SO)
	@bad=$$(nm -D --defined-only $< | awk '{ print $$NF }' | grep -v -E '$(LIB_EXPORTS_OK)'); \
	  if [ -n "$$bad" ]; then echo "FAIL: $< exports more than dm_*:"; echo "$$bad" | head; exit 1; fi; \
	  echo "ok: $< exports $$(nm -D --defined-only $< | grep -c ' dm_') dm_ functions and nothing else"
# embed.c's frames are `dexmill run`'s, byte for byte.
test-embed: $(EMBED) $(BIN)
	$(Q)tests/embed_check.sh $(abspath $(BIN)) $(abspath $(EMBED))
# The Python wrapper over the shared library (not under the sanitizers: the
# interpreter would have to load their runtime first).
test-python: $(LIB_SO) $(BIN)
	@if [ -n "$(SAN)" ]; then echo "skip: the Python wrapper under SAN"; else \
	  DEXMILL_LIB=$(abspath $(LIB_SO)) DEXMILL=$(abspath $(BIN)) python3 tests/test_python_api.py; fi
# The verification sheet in a real browser (chromium headless: PNG, PDF, no
# network request; SKIPPED, said so, without chromium: install-deps.sh browser).
test-sheet: $(BIN)
	$(Q)tools/scripts/sheet-test.sh $(abspath $(BIN))
# make install into a temporary DESTDIR, an embedder built from what it
# installed (pkg-config), make uninstall leaving nothing.
test-install: $(BIN) $(LIB_A) $(LIB_SO) $(LIB_IO) $(BUILD)/dexmill.1 $(EMBED)
	@if [ -n "$(SAN)" ]; then echo "skip: the installed libraries under SAN"; else \
	  tests/install_check.sh "$(MAKE)" $(API_CC) $(abspath $(EMBED)); fi

# ---- make install / uninstall ------------------------------------------------
# The Python wrapper goes to PREFIX/share/dexmill/python (add it to
# PYTHONPATH); it finds PREFIX/lib/libdexmill.so from there.
PREFIX   ?= /usr/local
DESTDIR  ?=
PYDIR    := share/dexmill/python
INSTALLED := bin/dexmill lib/libdexmill.a lib/libdexmill.so lib/libdexmill_io.a include/dexmill.h \
             include/dexmill_io.h lib/pkgconfig/dexmill.pc share/man/man1/dexmill.1 $(PYDIR)/dexmill.py \
             share/doc/dexmill/LICENSE
# The man page: tools/man/dexmill.1 with the option lists `dexmill
# --man-options` prints (roff) at its marker line; without that option the
# marker line is left out.
MAN_MARKER := ^\.\\" @OPTIONS@$$
$(BUILD)/dexmill.1: tools/man/dexmill.1 $(BIN)
	@if $(BIN) --man-options > $@.options 2>/dev/null; then \
	  sed -e '/$(MAN_MARKER)/{r $@.options' -e 'd;}' $< > $@; \
	else sed -e '/$(MAN_MARKER)/d' $< > $@; fi; rm -f $@.options
install: $(BIN) $(LIB_A) $(LIB_SO) $(LIB_IO) $(BUILD)/dexmill.1
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include \
	  $(DESTDIR)$(PREFIX)/share/man/man1 $(DESTDIR)$(PREFIX)/$(PYDIR) $(DESTDIR)$(PREFIX)/share/doc/dexmill
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/dexmill
	install -m 644 $(LIB_A) $(LIB_IO) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(LIB_SO) $(DESTDIR)$(PREFIX)/lib/
	install -m 644 display/api/dexmill.h platform/api/dexmill_io.h $(DESTDIR)$(PREFIX)/include/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(API_VERSION)|' tools/pkgconfig/dexmill.pc.in \
	  > $(DESTDIR)$(PREFIX)/lib/pkgconfig/dexmill.pc
	install -m 644 $(BUILD)/dexmill.1 $(DESTDIR)$(PREFIX)/share/man/man1/dexmill.1
	install -m 644 tools/python/dexmill.py $(DESTDIR)$(PREFIX)/$(PYDIR)/dexmill.py
	install -m 644 LICENSE $(DESTDIR)$(PREFIX)/share/doc/dexmill/LICENSE
uninstall:
	rm -f $(addprefix $(DESTDIR)$(PREFIX)/,$(INSTALLED))
	-rmdir $(DESTDIR)$(PREFIX)/$(PYDIR) $(DESTDIR)$(PREFIX)/share/dexmill $(DESTDIR)$(PREFIX)/share/doc/dexmill 2>/dev/null

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# ---- embedded checks (tools/scripts/; the scripts install their toolchains) --
#   make xcheck    golden output byte-identical on 17 compilers, opt levels and
#                  CPUs incl. big-endian and Cortex-M (XCHECK_ARGS=--bless re-pins
#                  tests/golden/golden.out; XCHECK_ARGS="-t gcc-O2,cm0-qemu" subsets)
#   make cortexm   core/ + display/ freestanding for Cortex-M4/M7/M0+: flash/RAM,
#                  and no heap, exceptions, RTTI or floating point
#   make panel     the Cortex-M4 panel demo under qemu; its hash against the host's
#   make panel-w3  a 256x256 job (paper-w3) cut and redrawn on the same board: its
#                  instruction counts, its hashes against the host's
EMBEDDED_ENV := DEXMILL_WARN='$(WARN)' DEXMILL_INTFLAGS='$(INTFLAGS)'
.PHONY: xcheck cortexm panel panel-w3
xcheck:
	$(EMBEDDED_ENV) tools/scripts/xcheck.sh $(XCHECK_ARGS)
# GCC may park 64-bit integers in FPU registers on hard-float CPUs (vmov,
# vldr, vstr: moves, not arithmetic); those are reported, any FPU arithmetic,
# conversion, soft-float helper or libm call still fails the check.
CORTEXM_ARGS ?= --allow-vfp-moves
cortexm:
	$(EMBEDDED_ENV) tools/scripts/cortexm.sh $(CORTEXM_ARGS)
panel:
	$(EMBEDDED_ENV) tools/scripts/panel.sh $(PANEL_ARGS)
panel-w3:
	$(EMBEDDED_ENV) tools/scripts/panel_w3.sh $(PANEL_ARGS)

# ---- the browser (platform/web/README.md) ------------------------------------
#   make web       build/web/: dexmill.wasm (core/, display/ and the C API,
#                  integer-only, with the glue of platform/web/), dexmill.js
#                  (the loader with the module inside as base64, so the page
#                  works from file://) and index.html
#   make test-web  the page in headless Chromium: its canvas's pixels hashed
#                  in the page against `dexmill run --image`'s (SKIPPED, said
#                  so, without Chromium or the wasm32 toolchain)
#   make test-web-stream  a 35 MB program read in pieces through the page's
#                  file input: the same bytes, the tab's peak memory
# Debian's clang and wasm-ld with wasi-libc for memcpy and the like; no
# start files, no entry: the page calls the exports of platform/web/web_api.cpp.
WEB      := build/web
WEB_CXX  ?= clang++ --target=wasm32-wasi
WEB_OPT  ?= -O2
WEB_SRC  := $(CORE_SRC) $(DISPLAY_SRC) $(sort $(wildcard platform/web/*.cpp))
WEB_OBJ  := $(patsubst %.cpp,build/wasm32/obj/%.o,$(WEB_SRC))  # not in $(WEB): that folder is what a panel serves
WEB_LDFLAGS_STRIP ?= -Wl,--strip-all  # empty: the functions named, for WEB_PAGE_PROFILE (tools/scripts/web_page.py)
WEB_LDFLAGS := -nostartfiles -Wl,--no-entry -Wl,--gc-sections -Wl,--stack-first -Wl,-z,stack-size=1048576 $(WEB_LDFLAGS_STRIP)
.PHONY: web test-web test-web-stream
web: $(WEB)/dexmill.wasm $(WEB)/dexmill.js $(WEB)/index.html
build/wasm32/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(Q)$(WEB_CXX) -std=c++17 $(WEB_OPT) $(WARN) -I. $(INTFLAGS) -MMD -MP -ffunction-sections -fdata-sections -c $< -o $@
# The libraries' members it links (--trace): string and memory functions and
# 128-bit arithmetic; never malloc or the C++ runtime (no heap, as on Cortex-M).
# An import would fail dexmill.js's instantiation (it gives none).
$(WEB)/dexmill.wasm: $(WEB_OBJ)
	@mkdir -p $(WEB)
	$(call say,LINK,$@)
	$(Q)$(WEB_CXX) $(WEB_OPT) $(WEB_LDFLAGS) $^ -o $@ -Wl,--trace > build/wasm32/link.trace
	$(Q)! grep -E 'malloc|libc\+\+' build/wasm32/link.trace || { echo "make web: the module links the heap or the C++ runtime (above)"; rm -f $@; exit 1; }
# The scripts in order: the loader and its topics, then the page and its.
WEB_JS   := platform/web/dexmill.js $(sort $(wildcard platform/web/engine_*.js)) platform/web/page.js \
            $(sort $(wildcard platform/web/page_*.js))
$(WEB)/dexmill.js: $(WEB)/dexmill.wasm $(WEB_JS) tools/scripts/web_embed.sh
	$(Q)tools/scripts/web_embed.sh $(WEB)/dexmill.wasm $(WEB_JS) > $@.tmp && mv $@.tmp $@
$(WEB)/index.html: platform/web/index.html
	@mkdir -p $(WEB)
	$(Q)cp $< $@
# In `make test` (about 8 s): built only where the toolchain and Chromium are (Debian's
# paths, as install-deps.sh web puts them); the script says SKIPPED otherwise.
WEB_CAN  := $(and $(wildcard /usr/lib/wasm32-wasi/libc.a),$(shell command -v wasm-ld),$(shell command -v chromium))
test-web: $(BIN) $(if $(WEB_CAN),web)
	$(Q)tools/scripts/web-test.sh $(abspath $(BIN))
# Not in `make test` (about 20 s): a 35 MB program through the page's
# file input, its frame against dexmill run's, the tab's peak memory.
test-web-stream: $(BIN) $(if $(WEB_CAN),web)
	$(Q)tools/scripts/web-stream-test.sh $(abspath $(BIN))
-include $(shell find build/wasm32 -name '*.d' 2>/dev/null)

# ---- fuzzing (libFuzzer, clang; Debian libclang-rt-14-dev) ------------------
#   make fuzz SECONDS=N           the pipeline target N seconds (default 60)
#   make fuzz FUZZ_TARGET=T ...   target T: pipeline, tool_table, stl, pgm, material, stock or machine
#   make fuzz-all SECONDS=N       every target, N seconds each, one after another
# Target T is tests/fuzz/fuzz_T.cpp; it runs over its corpus
# build/fuzz/corpus/T and its seeds tests/fuzz/seeds/T, with its dictionary.
# What it finds (crash-*, timeout-*, oom-*) lands in build/fuzz/found/T;
# kept in tests/fuzz/regress/T, `make test` replays it.
SECONDS ?= 60
FUZZ_TARGETS := pipeline tool_table stl pgm material stock machine
FUZZ_TARGET ?= pipeline
FUZZ_CXX := clang++ -std=c++17 -O1 -g -I. -fsanitize=fuzzer,address,undefined -fno-sanitize=vptr \
            -fno-sanitize-recover=all
FUZZ_OBJ := $(patsubst %.cpp,build/fuzz/obj/%.o,$(CORE_SRC) $(DISPLAY_SRC))
# The readers and run's backplot path are host code (std, exceptions),
# linked into every target.
FUZZ_HOST_OBJ := $(patsubst %.cpp,build/fuzz/obj/%.o,platform/format/tool_table.cpp platform/format/stl_read.cpp platform/format/pgm.cpp \
                   platform/os/read_file.cpp platform/os/output_file.cpp platform/os/temp_file.cpp platform/os/output_set.cpp \
                   platform/os/process.cpp platform/format/material_file.cpp platform/format/machine_file.cpp \
                   platform/format/machine_ini.cpp platform/format/machine_grbl.cpp platform/format/machine_var.cpp \
                   tools/run/run_path.cpp)
# Per target: the longest input (the pipeline's seeds are whole programs,
# binary STL seeds a hundred triangles), the dictionary, further options (a
# reader must not be made to allocate hundreds of MB by a few KB of input).
FUZZ_MAXLEN_pipeline := 8192
FUZZ_MAXLEN_tool_table := 4096
FUZZ_MAXLEN_stl := 8192
FUZZ_MAXLEN_pgm := 4096
FUZZ_MAXLEN_material := 4096
FUZZ_MAXLEN_stock := 8192
FUZZ_MAXLEN_machine := 4096
FUZZ_DICT_pipeline := tests/fuzz/gcode.dict
FUZZ_DICT_tool_table := tests/fuzz/tool_table.dict
FUZZ_DICT_stl := tests/fuzz/stl.dict
FUZZ_DICT_pgm := tests/fuzz/pgm.dict
FUZZ_DICT_material := tests/fuzz/material.dict
FUZZ_OPTS_tool_table := -malloc_limit_mb=64
FUZZ_OPTS_stl := -malloc_limit_mb=64
FUZZ_OPTS_pgm := -malloc_limit_mb=64
FUZZ_OPTS_material := -malloc_limit_mb=64
FUZZ_OPTS_stock := -malloc_limit_mb=128
FUZZ_OPTS_machine := -malloc_limit_mb=64
.PHONY: fuzz fuzz-all
# Objects reached through the build/fuzz/fuzz_% pattern are kept, not
# deleted as intermediates.
.SECONDARY: $(FUZZ_OBJ) $(FUZZ_HOST_OBJ)
build/fuzz/obj/core/%.o build/fuzz/obj/display/%.o: FUZZ_KIND := int
build/fuzz/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(FUZZ_CXX) $(if $(filter int,$(FUZZ_KIND)),$(INTFLAGS)) -MMD -MP -c $< -o $@
build/fuzz/fuzz_%: tests/fuzz/fuzz_%.cpp $(FUZZ_OBJ) $(FUZZ_HOST_OBJ)
	$(FUZZ_CXX) -MMD -MP -MF $@.d -MT $@ $< $(FUZZ_OBJ) $(FUZZ_HOST_OBJ) -o $@
fuzz: build/fuzz/fuzz_$(FUZZ_TARGET)
	@mkdir -p build/fuzz/corpus/$(FUZZ_TARGET) build/fuzz/found/$(FUZZ_TARGET)
	$< -max_total_time=$(SECONDS) -max_len=$(FUZZ_MAXLEN_$(FUZZ_TARGET)) -timeout=10 -print_final_stats=1 \
	  -artifact_prefix=build/fuzz/found/$(FUZZ_TARGET)/ \
	  $(if $(FUZZ_DICT_$(FUZZ_TARGET)),-dict=$(FUZZ_DICT_$(FUZZ_TARGET))) $(FUZZ_OPTS_$(FUZZ_TARGET)) \
	  build/fuzz/corpus/$(FUZZ_TARGET) tests/fuzz/seeds/$(FUZZ_TARGET)
# Every target even when one fails; fails if any did.
fuzz-all: $(addprefix build/fuzz/fuzz_,$(FUZZ_TARGETS))
	@failed=; for t in $(FUZZ_TARGETS); do \
	  $(MAKE) --no-print-directory fuzz FUZZ_TARGET=$$t SECONDS=$(SECONDS) || failed="$$failed $$t"; done; \
	  if [ -n "$$failed" ]; then echo "fuzz-all: failed:$$failed"; exit 1; fi
-include $(shell find build/fuzz -name '*.d' 2>/dev/null)
