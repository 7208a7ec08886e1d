// The re-timing of retime.h.
#include "retime.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "busy.h"
#include "steady.h"

std::vector<int> Retimer::disturbed(int forced)
{
    for (const auto &c : plan_->cases)
        if ((c->groups & GROUP_STEADY) && case_timed(c.get())) {
            auto it = fastest_.find(c->threads);
            if (it == fastest_.end() || c->median_ms < it->second)
                fastest_[c->threads] = c->median_ms;
        }
    // Per block, why it is disturbed (the first reason found); blocks in order.
    std::map<int, std::string> why;
    int block = -1, last = -1;
    for (const auto &c : plan_->cases) {
        char b[160];
        if (c->groups & GROUP_STEADY) {
            block = c->checkpoint;
            last = std::max(last, block);
            if (!case_timed(c.get()))
                continue;
            const double best = fastest_[c->threads];
            if (c->median_ms <= best * (1 + NOISY_DRIFT))
                continue;
            std::snprintf(b, sizeof b, "checkpoint %d at %d thread%s took %.3f ms, %.0f%% above the fastest %.3f ms",
                          c->checkpoint, c->threads, c->threads == 1 ? "" : "s", c->median_ms,
                          100 * (c->median_ms / best - 1), best);
            // the checkpoint ends block - 1 and starts block
            for (int k : {block - 1, block})
                if (k >= 0 && !why.count(k))
                    why[k] = b;
        } else if (block >= 0 && case_timed(c.get()) && c->cv > NOISY_CV && !why.count(block)) {
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

std::vector<BenchCase *> Retimer::take(const std::vector<int> &blocks)
{
    std::vector<BenchCase *> cases = cases_of(blocks);
    for (BenchCase *c : cases) {
        c->ran = false;
        c->median_ms = c->cv = c->rep_min = c->rep_max = c->done_at = std::nan("");
        c->probes.clear();
        c->reps = 0;
        c->error.clear();
    }
    rounds_.push_back(blocks);
    cases_.push_back(static_cast<int>(cases.size()));
    left_.clear();
    return cases;
}

double Retimer::fastest(int threads) const
{
    auto it = fastest_.find(threads);
    return it == fastest_.end() ? std::nan("") : it->second;
}

void Retimer::waited(double seconds, bool quiet)
{
    waits_.push_back(seconds);
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
        char b[96];
        std::snprintf(b, sizeof b, "%s (%d cases with their checkpoints) in round %zu", blocks_of(rounds_[r].size()).c_str(),
                      cases_[r], r + 1);
        s += std::string(r == 0 ? "" : "; ") + b;
        if (r < waits_.size() && waits_[r] >= 1) {
            std::snprintf(b, sizeof b, ", after waiting %.0f s for a quiet machine", waits_[r]);
            s += b;
        }
    }
    if (!s.empty())
        s = "Re-timed, of the run's " + std::to_string(blocks_) +
            " blocks of cases (the cases between two checkpoints, Machine steadiness below): " + s +
            ". A block is re-timed when a checkpoint at an end of it ran more than " +
            std::to_string(static_cast<int>(NOISY_DRIFT * 100)) +
            "% slower than the fastest at its thread count, or a case in it spread more than " +
            std::to_string(static_cast<int>(NOISY_CV * 100)) +
            "% over its repetitions. The tables show each case's last timing.";
    if (!left_.empty())
        s += std::string(s.empty() ? "" : " ") + "Still disturbed when re-timing stopped: " + blocks_of(left_.size()) +
             (gave_up_ ? ", the machine having stayed slow through the wait for a quiet one" : "") + ".";
    return s;
}
