// Re-timing the disturbed blocks of a run. The checkpoints (steady.h) cut the run into blocks of
// cases. On a shared machine the speed changes for seconds at a time, most of all at two threads;
// a block timed while it was slow shows it at the checkpoints beside it, or in a case's spread.
// Such a block is timed again, with its checkpoints, so that every table can come from cases
// timed while the machine ran at its usual speed; BENCH.md says which blocks were re-timed, and
// a block still disturbed after the last round stays marked noisy as before.
//
// A round times its blocks one at a time, each after its own wait for a quiet machine, since a
// slow spell often lasts less than a round but longer than a block. Two adjacent blocks share a
// checkpoint, which each then times again; so a block is judged by its checkpoints as they were
// timed beside it (record()), not by their last timing, which a neighbour's re-timing may have
// taken seconds later.
#ifndef RETRO_BENCH_RETIME_H
#define RETRO_BENCH_RETIME_H

#include <map>
#include <string>
#include <vector>

#include "cases.h"

// The re-timing's default budget in first passes (--retime-budget).
constexpr double RETIME_BUDGET_DEFAULT = 1;

class Retimer {
  public:
    explicit Retimer(BenchPlan *plan) : plan_(plan) {}

    // The blocks to time again, in order: a checkpoint at either end, as recorded for the block,
    // ran more than NOISY_DRIFT slower than the fastest timing of its thread count so far, or a
    // case in it spread more than NOISY_CV; or block `forced` alone (>= 0: tests the re-timing).
    // Block i holds the cases between checkpoint i and checkpoint i + 1. Says why on stderr, one
    // line per block.
    std::vector<int> disturbed(int forced);

    // Starts a round: the blocks taken and the seconds waited until the next call count in it.
    void begin_round();

    // The cases of those blocks, each with the checkpoints at its ends, in plan order, their
    // results cleared for the new timing; they count in the current round.
    std::vector<BenchCase *> take(const std::vector<int> &blocks);

    // After those blocks' cases ran: the timings of their checkpoints, now, are the ones each
    // block is judged by.
    void record(const std::vector<int> &blocks);

    // The share of the cases that ran which re-timing those blocks would time again: an
    // estimate of the round's duration as a share of the first pass's.
    double share(const std::vector<int> &blocks) const;

    // The fastest checkpoint timing at this thread count so far (NaN before disturbed()).
    double fastest(int threads) const;

    // The re-timing's budget in first passes (--retime-budget), which the summary names when it
    // is not RETIME_BUDGET_DEFAULT.
    void set_budget(double first_passes) { budget_ = first_passes; }

    // A wait for a quiet machine in the current round (seconds; quiet: whether it came).
    void waited(double seconds, bool quiet);

    // BENCH.md's sentence on the re-timing ("" when nothing was re-timed), and blocks still
    // disturbed after the last round.
    std::string summary() const;

  private:
    std::vector<BenchCase *> cases_of(const std::vector<int> &blocks) const;
    void capture(int block);

    BenchPlan *plan_;
    std::map<int, double> fastest_;              // threads -> fastest checkpoint timing so far
    struct End {                                 // a checkpoint's timing as a block recorded it
        int checkpoint, threads;
        double ms;
    };
    std::map<int, std::vector<End>> ends_;       // block -> its checkpoints' timings beside it
    std::vector<std::vector<int>> rounds_;       // the blocks of each round
    std::vector<int> cases_;                     // cases re-timed in each round (checkpoints included)
    std::vector<int> left_;                      // blocks disturbed at the last look, not re-timed since
    std::vector<double> waits_;                  // seconds waited for a quiet machine in each round
    bool gave_up_ = false;                       // the last wait ended with the machine still slow
    int blocks_ = 0;                             // blocks in the run
    double budget_ = RETIME_BUDGET_DEFAULT;      // the re-timing's budget in first passes
};

#endif
