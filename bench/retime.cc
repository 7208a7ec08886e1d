// The re-timing of retime.h.
#include "retime.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "busy.h"
#include "steady.h"

// Block k's checkpoints (k and k + 1) at every thread count, as timed now.
void Retimer::capture(int block)
{
    std::vector<End> &e = ends_[block];
    e.clear();
    for (const auto &c : plan_->cases)
        if ((c->groups & GROUP_STEADY) && (c->checkpoint == block || c->checkpoint == block + 1) &&
            case_timed(c.get()))
            e.push_back({c->checkpoint, c->threads, c->median_ms});
}

std::vector<int> Retimer::disturbed(int forced)
{
    auto faster = [this](int threads, double ms) {
        auto it = fastest_.find(threads);
        if (it == fastest_.end() || ms < it->second)
            fastest_[threads] = ms;
    };
    int last = -1;
    for (const auto &c : plan_->cases)
        if (c->groups & GROUP_STEADY) {
            last = std::max(last, c->checkpoint);
            if (case_timed(c.get()))
                faster(c->threads, c->median_ms);
        }
    for (int k = 0; k < last; k++) // the first look: every block by the first pass's checkpoints
        if (!ends_.count(k))
            capture(k);
    for (const auto &[k, ends] : ends_) // timings a later re-timing has replaced count too
        for (const End &e : ends)
            faster(e.threads, e.ms);
    // Per block, why it is disturbed (the first reason found); blocks in order.
    std::map<int, std::string> why;
    for (const auto &[k, ends] : ends_)
        for (const End &e : ends) {
            const double best = fastest_[e.threads];
            if (e.ms <= best * (1 + NOISY_DRIFT) || why.count(k))
                continue;
            char b[160];
            std::snprintf(b, sizeof b, "checkpoint %d at %d thread%s took %.3f ms, %.0f%% above the fastest %.3f ms",
                          e.checkpoint, e.threads, e.threads == 1 ? "" : "s", e.ms, 100 * (e.ms / best - 1), best);
            why[k] = b;
        }
    int block = -1;
    for (const auto &c : plan_->cases) {
        if (c->groups & GROUP_STEADY)
            block = c->checkpoint;
        else if (block >= 0 && block < last && case_timed(c.get()) && c->cv > NOISY_CV && !why.count(block)) {
            char b[160];
            std::snprintf(b, sizeof b, "%s spread %.0f%% over its repetitions", c->name.c_str(), 100 * c->cv);
            why[block] = b;
        }
    }
    if (forced >= 0 && forced < last) // a test: that block alone, whatever the timings say
        why = {{forced, "asked for (--retime-block)"}};
    blocks_ = std::max(last, 0);
    std::vector<int> blocks;
    for (const auto &[k, reason] : why)
        if (k < last) { // the last checkpoint starts no block
            blocks.push_back(k);
            std::fprintf(stderr, "  block %d: %s\n", k, reason.c_str());
        }
    left_ = blocks;
    return blocks;
}

// The cases that ran in those blocks, with the checkpoints at their ends, in plan order.
std::vector<BenchCase *> Retimer::cases_of(const std::vector<int> &blocks) const
{
    const std::set<int> want(blocks.begin(), blocks.end());
    std::vector<BenchCase *> cases;
    int block = -1;
    for (const auto &c : plan_->cases) {
        bool in;
        if (c->groups & GROUP_STEADY) {
            block = c->checkpoint;
            in = want.count(block) || want.count(block - 1);
        } else
            in = block >= 0 && want.count(block);
        if (in && c->ran)
            cases.push_back(c.get());
    }
    return cases;
}

double Retimer::share(const std::vector<int> &blocks) const
{
    const int ran = plan_cases_ran(*plan_);
    return ran ? static_cast<double>(cases_of(blocks).size()) / ran : 0;
}

void Retimer::begin_round()
{
    rounds_.emplace_back();
    cases_.push_back(0);
    waits_.push_back(0);
}

std::vector<BenchCase *> Retimer::take(const std::vector<int> &blocks)
{
    if (rounds_.empty())
        begin_round();
    std::vector<BenchCase *> cases = cases_of(blocks);
    for (BenchCase *c : cases) {
        c->ran = false;
        c->median_ms = c->cv = c->rep_min = c->rep_max = c->done_at = std::nan("");
        c->probes.clear();
        c->reps = 0;
        c->error.clear();
    }
    rounds_.back().insert(rounds_.back().end(), blocks.begin(), blocks.end());
    cases_.back() += static_cast<int>(cases.size());
    for (int b : blocks)
        left_.erase(std::remove(left_.begin(), left_.end(), b), left_.end());
    return cases;
}

void Retimer::record(const std::vector<int> &blocks)
{
    for (int b : blocks)
        capture(b);
}

double Retimer::fastest(int threads) const
{
    auto it = fastest_.find(threads);
    return it == fastest_.end() ? std::nan("") : it->second;
}

void Retimer::waited(double seconds, bool quiet)
{
    if (rounds_.empty())
        begin_round();
    waits_.back() += seconds;
    gave_up_ = !quiet;
}

static std::string blocks_of(size_t n)
{
    return std::to_string(n) + (n == 1 ? " block" : " blocks");
}

std::string Retimer::summary() const
{
    std::string s;
    for (size_t r = 0; r < rounds_.size(); r++) {
        if (rounds_[r].empty()) // stopped (by the budget or a wait) before its first block
            continue;
        char b[96];
        std::snprintf(b, sizeof b, "%s (%d cases with their checkpoints) in round %zu", blocks_of(rounds_[r].size()).c_str(),
                      cases_[r], r + 1);
        s += std::string(s.empty() ? "" : "; ") + b;
        if (r < waits_.size() && waits_[r] >= 1) {
            std::snprintf(b, sizeof b, ", after waiting %.0f s in all for a quiet machine", waits_[r]);
            s += b;
        }
    }
    if (!s.empty())
        s = "Re-timed, of the run's " + std::to_string(blocks_) +
            " blocks of cases (the cases between two checkpoints, Machine steadiness below): " + s +
            ". A round times its blocks one at a time, each with its checkpoints and after its own wait for a "
            "quiet machine; a block is re-timed when a checkpoint at an end of it, as timed beside it, ran more than " +
            std::to_string(static_cast<int>(NOISY_DRIFT * 100)) +
            "% slower than the fastest at its thread count, or a case in it spread more than " +
            std::to_string(static_cast<int>(NOISY_CV * 100)) +
            "% over its repetitions. The tables show each case's last timing.";
    if (!s.empty() && budget_ != RETIME_BUDGET_DEFAULT) {
        char b[160];
        std::snprintf(b, sizeof b, " The re-timing, waits included, was given %g times the first pass's duration "
                      "(--retime-budget; the default is once).", budget_);
        s += b;
    }
    if (!left_.empty())
        s += std::string(s.empty() ? "" : " ") + "Still disturbed when re-timing stopped: " + blocks_of(left_.size()) +
             (gave_up_ ? ", the machine having stayed slow through the wait for a quiet one" : "") + ".";
    return s;
}
