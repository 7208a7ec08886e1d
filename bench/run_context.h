// What a reader needs to trust or reproduce a run: machine, binding, build, commit, settings.
#ifndef RETRO_BENCH_RUN_CONTEXT_H
#define RETRO_BENCH_RUN_CONTEXT_H

#include <string>

struct RunContext {
    std::string cpu_model;         // /proc/cpuinfo model name, family and model
    int cores = 1;                 // cores this process may use (hwloc)
    int pus = 1;                   // hardware threads this process may use (hwloc)
    std::string binding;           // where single-threaded cases run, or why unpinned
    std::string kernel_binding;    // how threaded kernels place their threads (retro_ctx_binding)
    std::string isa;               // the ISA level retro detected (RETRO_ISA may lower it)
    std::string cc;                // the C compiler the kernels were built with
    std::string cflags;            // its flags, before the per-file ISA flags
    std::string cxx;               // the C++ compiler of this harness
    std::string commit;            // git describe of the working tree, "-dirty" if edited
    std::string date;              // UTC, when the run started
    std::string load;              // 1-minute load average at the start: other work competes
    int repetitions = 1;           // --benchmark_repetitions in effect
    std::string min_time;          // --benchmark_min_time in effect, seconds
    std::string warmup;            // --benchmark_min_warmup_time in effect, seconds
    std::string filter;            // --benchmark_filter, empty when every case runs
    bool quick = false;            // --quick: fewer, shorter repetitions, not for publishing
    bool busy = false;             // other work was using the cores when the run started
    std::string machine;           // busy_sentence(): what else ran, from /proc
};

// Fills everything but binding and the benchmark settings.
void context_gather(RunContext *rc);

// Records the context in the JSON output (benchmark::AddCustomContext).
void context_publish(const RunContext &rc);

#endif
