# Fuzzing the scene-file parser (docs/scenes.md, "Fuzzing"). Included by the
# top Makefile.
#
#   make fuzz                   libFuzzer for FUZZ_SECONDS seconds (default 60)
#   make fuzz FUZZ_SECONDS=600
#   make fuzz-merge             folds the new inputs into tests/fuzz/corpus
#
# The target is built with clang, libFuzzer, AddressSanitizer (leaks included)
# and UndefinedBehaviorSanitizer, from the engine's and the scene-file
# module's sources. It starts from tests/fuzz/corpus and the presets and
# writes what it finds to build/fuzz/corpus; tests/fuzz/corpus is what
# make check replays (scene_file.fuzz_corpus_replays_cleanly).

FUZZ_CC ?= clang
FUZZ_SECONDS ?= 60
FUZZ_FLAGS := -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
FUZZ_SRC := $(ENGINE_SRC) $(SCENEFILE_SRC) tests/scene_file_check.c tests/fuzz/fuzz_scene_file.c
FUZZ_RUN := -dict=tests/fuzz/scene.dict -max_len=4096 -timeout=10 -print_final_stats=1

.PHONY: fuzz fuzz-merge

build/fuzz/fuzz_scene_file: $(FUZZ_SRC) $(ENGINE_HDR) $(SCENEFILE_HDR) tests/scene_file_check.h tests/fuzz/fuzz.mk
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(CSTD) $(FUZZ_FLAGS) $(ENGINE_INC) -Itests $(FUZZ_SRC) -pthread -lm -o $@

fuzz: build/fuzz/fuzz_scene_file
	@mkdir -p build/fuzz/corpus build/fuzz/crashes
	build/fuzz/fuzz_scene_file $(FUZZ_RUN) -max_total_time=$(FUZZ_SECONDS) \
	    -artifact_prefix=build/fuzz/crashes/ build/fuzz/corpus tests/fuzz/corpus assets/scenes

fuzz-merge: build/fuzz/fuzz_scene_file
	build/fuzz/fuzz_scene_file -merge=1 -max_len=4096 tests/fuzz/corpus build/fuzz/corpus
