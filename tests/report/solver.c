#include "report.h"
void report_write_solver(FILE *md, FILE *gp, const report_options_t *options);
void report_write_solver(FILE *md, FILE *gp, const report_options_t *options) {
    (void)md, (void)gp, (void)options;
}
