// bench/retime.h's judgement, on plans built by hand: which blocks a slow checkpoint or a spread
// case marks disturbed, and that a block re-timed on its own is judged by its checkpoints as
// they were timed beside it, not by a later neighbour's timing of a checkpoint they share.
#include <criterion/criterion.h>

#include <memory>
#include <string>

#include "retime.h"

namespace {

// A plan of `checkpoints` checkpoints at 1 and 2 threads with `between` cases after each but the
// last (block k: the cases between checkpoints k and k + 1), every one timed: checkpoints at 1.0
// ms (1 thread) and 0.5 ms (2 threads), the cases at 2.0 ms with a cv of 1%.
BenchPlan plan_of(int checkpoints, int between)
{
    BenchPlan p;
    auto add = [&p](unsigned groups, int checkpoint, int threads, double ms, const std::string &name) {
        auto c = std::make_unique<BenchCase>();
        c->groups = groups;
        c->checkpoint = checkpoint;
        c->threads = threads;
        c->ran = true;
        c->median_ms = ms;
        c->cv = 0.01;
        c->name = name;
        p.cases.push_back(std::move(c));
    };
    for (int k = 0; k < checkpoints; k++) {
        add(GROUP_STEADY, k, 1, 1.0, "check" + std::to_string(k) + "/1t");
        add(GROUP_STEADY, k, 2, 0.5, "check" + std::to_string(k) + "/2t");
        for (int i = 0; k + 1 < checkpoints && i < between; i++)
            add(GROUP_MATRIX, -1, 1, 2.0, "case" + std::to_string(k) + "." + std::to_string(i));
    }
    return p;
}

BenchCase *checkpoint(BenchPlan &p, int k, int threads)
{
    for (auto &c : p.cases)
        if ((c->groups & GROUP_STEADY) && c->checkpoint == k && c->threads == threads)
            return c.get();
    return nullptr;
}

// What a re-timing of `cases` measured: every case at its old time but the checkpoints, which get
// `ms` at 1 thread where given.
void run(std::vector<BenchCase *> cases, const std::map<int, double> &ms)
{
    for (BenchCase *c : cases) {
        c->ran = true;
        c->cv = 0.01;
        if (c->groups & GROUP_STEADY) {
            auto it = ms.find(c->checkpoint);
            c->median_ms = c->threads == 1 && it != ms.end() ? it->second : (c->threads == 1 ? 1.0 : 0.5);
        } else
            c->median_ms = 2.0;
    }
}

} // namespace

Test(retime, steady_plan_has_no_disturbed_block)
{
    BenchPlan p = plan_of(4, 3);
    Retimer r(&p);
    cr_assert(r.disturbed(-1).empty());
    cr_assert_eq(r.summary(), std::string());
}

Test(retime, slow_checkpoint_disturbs_both_its_blocks)
{
    BenchPlan p = plan_of(4, 3);
    checkpoint(p, 1, 1)->median_ms = 1.2; // 20% above the fastest: ends block 0, starts block 1
    Retimer r(&p);
    cr_assert(r.disturbed(-1) == (std::vector<int>{0, 1}));
    checkpoint(p, 1, 1)->median_ms = 1.05; // within NOISY_DRIFT
    Retimer q(&p);
    cr_assert(q.disturbed(-1).empty());
}

Test(retime, spread_case_disturbs_its_block_only)
{
    BenchPlan p = plan_of(4, 3);
    p.cases[2 + 3 + 2 + 1]->cv = 0.2; // the second case of block 1
    Retimer r(&p);
    cr_assert(r.disturbed(-1) == (std::vector<int>{1}));
}

Test(retime, take_returns_the_block_with_its_checkpoints)
{
    BenchPlan p = plan_of(4, 3);
    Retimer r(&p);
    r.disturbed(2);
    r.begin_round();
    std::vector<BenchCase *> c = r.take({2});
    cr_assert_eq(c.size(), 2u + 3u + 2u); // checkpoint 2, its three cases, checkpoint 3
    for (BenchCase *x : c)
        cr_assert(!x->ran);
    cr_assert_eq(c.front(), checkpoint(p, 2, 1));
    cr_assert_eq(c.back(), checkpoint(p, 3, 2));
}

// Blocks 0 and 1 re-timed one after the other: block 0 while quiet, then block 1, whose timing of
// their shared checkpoint 1 came in a slow spell. Block 0 stays judged by checkpoint 1 as it ran
// beside block 0; judged by the last timing it would look disturbed again.
Test(retime, a_block_is_judged_by_its_own_timing_of_a_shared_checkpoint)
{
    BenchPlan p = plan_of(4, 3);
    checkpoint(p, 1, 1)->median_ms = 1.3;
    Retimer r(&p);
    std::vector<int> blocks = r.disturbed(-1);
    cr_assert(blocks == (std::vector<int>{0, 1}));
    r.begin_round();
    run(r.take({0}), {{0, 1.0}, {1, 1.0}});
    r.record({0});
    run(r.take({1}), {{1, 1.4}, {2, 1.0}});
    r.record({1});
    cr_assert(r.disturbed(-1) == (std::vector<int>{1}));
    const std::string s = r.summary();
    cr_assert(s.find("2 blocks (14 cases with their checkpoints) in round 1") != std::string::npos, "%s", s.c_str());
    cr_assert(s.find("Still disturbed when re-timing stopped: 1 block.") != std::string::npos, "%s", s.c_str());
    cr_assert(s.find("--retime-budget") == std::string::npos, "%s", s.c_str());
    r.set_budget(4);
    cr_assert(r.summary().find("was given 4 times the first pass's duration") != std::string::npos, "%s",
              r.summary().c_str());
}

// A block taken leaves the list of those still disturbed; one not reached stays in it.
Test(retime, blocks_not_reached_stay_disturbed)
{
    BenchPlan p = plan_of(5, 2);
    checkpoint(p, 1, 2)->median_ms = 0.7;
    checkpoint(p, 3, 2)->median_ms = 0.7;
    Retimer r(&p);
    cr_assert(r.disturbed(-1) == (std::vector<int>{0, 1, 2, 3}));
    r.begin_round();
    r.waited(3.0, true);
    run(r.take({0}), {});
    r.record({0});
    r.waited(4.0, false); // the machine stayed slow: the other three are left
    const std::string s = r.summary();
    cr_assert(s.find("1 block (6 cases with their checkpoints) in round 1, after waiting 7 s in all") !=
                  std::string::npos,
              "%s", s.c_str());
    cr_assert(s.find("Still disturbed when re-timing stopped: 3 blocks, the machine having stayed slow") !=
                  std::string::npos,
              "%s", s.c_str());
}

// The fastest timing a checkpoint had, even one a later re-timing replaced, is the bar.
Test(retime, fastest_counts_replaced_timings)
{
    BenchPlan p = plan_of(3, 1);
    checkpoint(p, 0, 1)->median_ms = 0.8;
    Retimer r(&p);
    r.disturbed(-1); // checkpoints 1 and 2 are 25% above 0.8: blocks 0 and 1
    cr_assert_float_eq(r.fastest(1), 0.8, 1e-12);
    r.begin_round();
    run(r.take({0}), {{0, 1.0}, {1, 1.0}});
    r.record({0});
    cr_assert(r.disturbed(-1) == (std::vector<int>{0, 1}));
    cr_assert_float_eq(r.fastest(1), 0.8, 1e-12);
}

// A round that stops before its first block (the budget was spent, or the first wait ran out)
// re-timed nothing, so the summary names only the rounds that did.
Test(retime, a_round_that_took_no_block_is_not_reported)
{
    BenchPlan p = plan_of(4, 2);
    checkpoint(p, 1, 1)->median_ms = 1.3;
    Retimer r(&p);
    cr_assert(r.disturbed(-1) == (std::vector<int>{0, 1}));
    r.begin_round();
    run(r.take({0}), {{0, 1.0}, {1, 1.0}});
    r.record({0});
    r.begin_round(); // round 2 stops before taking block 1
    const std::string s = r.summary();
    cr_assert(s.find("1 block (") != std::string::npos && s.find("in round 1.") != std::string::npos, "%s", s.c_str());
    cr_assert(s.find("round 2") == std::string::npos && s.find("0 blocks") == std::string::npos, "%s", s.c_str());
    cr_assert(s.find("Still disturbed when re-timing stopped: 1 block.") != std::string::npos, "%s", s.c_str());
    cr_assert(s.find("--retime-budget") == std::string::npos, "%s", s.c_str());
    r.set_budget(4);
    cr_assert(r.summary().find("was given 4 times the first pass's duration") != std::string::npos, "%s",
              r.summary().c_str());
}
