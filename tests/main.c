/* The engine's test runner: `engine_tests [FILTER]` runs every test whose
 * "suite.test" name contains FILTER (all when absent). */
#include "test.h"

#define SUITE(name) extern const test_suite_t suite_##name;
#include "suites.h"
#undef SUITE

#define SUITE(name) &suite_##name,
static const test_suite_t *const suites[] = {
#include "suites.h"
};
#undef SUITE

int main(int argc, char **argv) {
    return test_run_suites(suites, sizeof suites / sizeof suites[0], argc > 1 ? argv[1] : NULL);
}
