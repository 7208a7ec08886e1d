// Display reporter: one progress line per case on stderr, and each case's median kept in
// its BenchCase for BENCH.md. It also keeps every case's runs for the JSON, written once at
// the end through google-benchmark's own JSON reporter: a case timed again (retime.h) replaces
// its first timing there, which a file reporter given to each pass could not do.
#ifndef RETRO_BENCH_PROGRESS_REPORTER_H
#define RETRO_BENCH_PROGRESS_REPORTER_H

#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "cases.h"

class ProgressReporter : public benchmark::BenchmarkReporter {
  public:
    explicit ProgressReporter(BenchPlan *plan);
    bool ReportContext(const Context &context) override;
    void ReportRuns(const std::vector<Run> &runs) override;

    int cases_done() const { return done_; }
    double seconds() const;

    // Drops the case's runs: it is about to be timed again.
    void forget(const BenchCase *c) { runs_.erase(c); }

    // google-benchmark's JSON of the kept runs, cases in plan order, to path (through a
    // temporary file); false after a message when it cannot be written.
    bool write_json(const std::string &path) const;

  private:
    const BenchPlan *plan_;
    std::map<std::string, BenchCase *> by_name_; // registered name -> case
    std::map<const BenchCase *, std::vector<std::vector<Run>>> runs_; // as reported, per call
    int done_ = 0;
    bool started_ = false;
    std::chrono::steady_clock::time_point start_;
};

#endif
