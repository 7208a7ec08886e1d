// BENCH.md and the gnuplot script of the charts, written from the cases of one run.
#ifndef RETRO_BENCH_REPORT_H
#define RETRO_BENCH_REPORT_H

#include <string>
#include <vector>

#include "cases.h"
#include "run_context.h"

// One table row: a kernel at one thread count.
struct ReportRow {
    const retro_kernel *kernel;
    int threads;
    bool no_skip = false; // the --no-skip twins: occlusion skipping off
};

// The rows with at least one case in group and mode that ran, in kernel-table order.
std::vector<ReportRow> report_rows(const BenchPlan &plan, unsigned group, retro_mode mode);

// Median ms/frame of a case, NaN when it was not planned, not run or skipped.
double report_ms(const BenchPlan &plan, const ReportRow &row, const bench_scene *s,
                 retro_mode mode, int W, int H, int D);

// Geometric mean of the row's ms/frame over the matrix scenes it was timed on; NaN if none.
double report_geomean(const BenchPlan &plan, const ReportRow &row, retro_mode mode);

// Speedup of row over the single-threaded kernel named base: the ratio of their geometric
// means over the scenes both were timed on; NaN if there are none.
double report_speedup(const BenchPlan &plan, const ReportRow &row, retro_mode mode,
                      const char *base);

// Writes text to path through a temporary file; false (after a message) when it cannot.
bool report_write_file(const std::string &path, const std::string &text);

// A table cell of ms/frame: four significant digits whatever the magnitude, so columns stay
// comparable by eye; "–" for NaN.
std::string report_ms_cell(double v);

// The largest coefficient of variation over the repetitions of the row's matrix cases; NaN if
// none ran.
double report_max_cv(const BenchPlan &plan, const ReportRow &row, retro_mode mode);

// Rows of the mode tables whose spread exceeds NOISY_CV (busy.h), over every mode.
int report_noisy_rows(const BenchPlan &plan);

// Whether the row is noisy in any mode (the chart marks it).
bool report_row_noisy(const BenchPlan &plan, const ReportRow &row);

// "omp, 2 threads" for threaded kernels, the kernel's name otherwise.
std::string report_label(const ReportRow &row);

// Write the files; return false and print why on stderr when a file cannot be written.
// retimed: retime.h's sentence on what was timed again, or "".
bool write_bench_md(const std::string &path, const BenchPlan &plan, const RunContext &ctx,
                    double seconds, int cases_run, const std::string &retimed);
bool write_charts_gp(const std::string &path, const BenchPlan &plan, const RunContext &ctx);

#endif
