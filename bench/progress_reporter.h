// Display reporter: one progress line per case on stderr, and each case's median kept in
// its BenchCase for BENCH.md. The JSON goes through google-benchmark's own file reporter.
#ifndef RETRO_BENCH_PROGRESS_REPORTER_H
#define RETRO_BENCH_PROGRESS_REPORTER_H

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <string>

#include "cases.h"

class ProgressReporter : public benchmark::BenchmarkReporter {
  public:
    explicit ProgressReporter(BenchPlan *plan);
    bool ReportContext(const Context &context) override;
    void ReportRuns(const std::vector<Run> &runs) override;

    int cases_done() const { return done_; }
    double seconds() const;

  private:
    std::map<std::string, BenchCase *> by_name_; // registered name -> case
    int done_ = 0;
    std::chrono::steady_clock::time_point start_;
};

#endif
