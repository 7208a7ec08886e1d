// The command line of retro-bench: its own options, and google-benchmark's flags with the
// defaults that make a run fit the time budget.
#ifndef RETRO_BENCH_OPTIONS_H
#define RETRO_BENCH_OPTIONS_H

#include <string>
#include <vector>

#include "cases.h"
#include "retime.h"
#include "run_context.h"

struct Options {
    bool quick = false;     // --quick: fewer repetitions, shorter runs, fewer sweep points
    std::string report_dir; // --report: where BENCH.md goes
    std::string charts;     // --charts: the gnuplot script of the charts
    std::string scene;      // --scene: one map prefix instead of the default scenes
    bool no_extras = false; // --no-extras: leave out the submission and effect tables
    int retime = -1;        // --retime: rounds of re-timing disturbed blocks (retime.h); -1: 3, quick 0
    int retime_block = -1;  // --retime-block: the block the first round re-times alone (a test)
    double quiet_wait = -1; // --quiet-wait: most seconds to wait for a quiet machine before a round; -1: 120, quick 0
    double retime_budget = RETIME_BUDGET_DEFAULT; // --retime-budget: the re-timing's time, waits included, in first passes
};

void options_usage();

// google-benchmark's argv (null-terminated): argv[0], the defaults, then argv[1..], so that
// flags given on the command line win. Records the settings in effect in ctx. The JSON output
// is ours (progress_reporter.h): --benchmark_out's path goes to *json instead, and false
// (after a message) means a --benchmark_out_format other than json.
bool options_benchmark_args(int argc, char **argv, bool quick, RunContext *ctx, std::vector<char *> *args,
                            std::string *json);

// Parses what google-benchmark left in args[1..n-1] into o and plan (screen, distance, modes,
// sweep points). Returns false after a message on stderr.
bool options_parse(int n, char **args, Options *o, BenchPlan *plan);

#endif
