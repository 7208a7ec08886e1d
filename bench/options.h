// The command line of retro-bench: its own options, and google-benchmark's flags with the
// defaults that make a run fit the time budget.
#ifndef RETRO_BENCH_OPTIONS_H
#define RETRO_BENCH_OPTIONS_H

#include <string>
#include <vector>

#include "cases.h"
#include "run_context.h"

struct Options {
    bool quick = false;     // --quick: fewer repetitions, shorter runs, fewer sweep points
    std::string report_dir; // --report: where BENCH.md goes
    std::string charts;     // --charts: the gnuplot script of the charts
    std::string scene;      // --scene: one map prefix instead of the default scenes
    bool no_extras = false; // --no-extras: leave out the submission and effect tables
};

void options_usage();

// google-benchmark's argv (null-terminated): argv[0], the defaults, then argv[1..], so that
// flags given on the command line win. Records the settings in effect in ctx.
std::vector<char *> options_benchmark_args(int argc, char **argv, bool quick, RunContext *ctx);

// Parses what google-benchmark left in args[1..n-1] into o and plan (screen, distance, modes,
// sweep points). Returns false after a message on stderr.
bool options_parse(int n, char **args, Options *o, BenchPlan *plan);

#endif
