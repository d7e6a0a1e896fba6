/*
 * libFuzzer target for scene files (make fuzz). Every input goes through
 * scene_file_round_trip (tests/scene_file_check.c): refused with a
 * FILE:LINE:COLUMN message, or loaded, written, reloaded to the same scene and
 * written to the same text. Anything else aborts, which libFuzzer reports as
 * a crash; so do a crash, a leak, a sanitizer report, or the engine stopping
 * the program on a value the parser let through.
 */
#include <stdio.h>
#include <stdlib.h>
#include "scene_file_check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char why[512];
    if (!scene_file_round_trip(data, size, "fuzz", why, sizeof why)) {
        fprintf(stderr, "scene file round trip failed: %s\n", why);
        abort();
    }
    return 0;
}
