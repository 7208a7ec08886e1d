// Is the machine quiet enough to time on? Read from /proc before the run starts.
#ifndef RETRO_BENCH_BUSY_H
#define RETRO_BENCH_BUSY_H

#include <string>

// A row is marked noisy when a case's coefficient of variation over its repetitions exceeds
// this: the medians of such a row may be off by about as much.
constexpr double NOISY_CV = 0.10;

struct BusyReport {
    double load1 = -1;      // 1-minute load average, -1 if unreadable
    double busy_cores = 0;  // CPU time used by other work during the sample, in cores
    std::string top;        // the processes that used most of it: "name (pid) 0.95 cores, ..."
    bool busy = false;      // worth a warning
};

// Samples /proc/stat and /proc/PID/stat for `seconds` while this process sleeps, so every
// CPU tick seen is another program's. cores: the cores the run will use.
BusyReport busy_sample(double seconds, int cores);

// One sentence for the terminal and BENCH.md: "quiet: ..." or "busy: ...".
std::string busy_sentence(const BusyReport &b);

#endif
