// The checkpoints of steady.h and their section of BENCH.md.
#include "steady.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "bench_report.h"

static std::vector<int> steady_threads(const retro_kernel *k, int cores)
{
    std::vector<int> t{1};
    int all = plan_thread_counts(k, cores).back();
    if (all > 1)
        t.push_back(all);
    return t;
}

static std::unique_ptr<BenchCase> checkpoint(const BenchPlan &plan, const retro_kernel *k, int threads, int index)
{
    auto c = make_case(k, threads, plan.sweep_scene, RETRO_MODE_EXACT, plan.W, plan.H, plan.D, GROUP_STEADY, false);
    c->checkpoint = index;
    // short: the checkpoints are many and each needs only a steady median
    c->repetitions = 3;
    c->min_time = 0.02;
    char n[16];
    std::snprintf(n, sizeof n, "/check%02d", index);
    c->name = "steady/" + c->name.substr(c->name.find('/') + 1) + n; // steady/ in place of exact/
    return c;
}

void plan_steady(BenchPlan *plan, int every)
{
    const retro_kernel *k = retro_kernel_best(RETRO_MODE_EXACT);
    if (!plan->sweep_scene || !k || every < 1)
        return;
    std::vector<std::unique_ptr<BenchCase>> cases;
    int index = 0;
    auto add = [&]() {
        for (int t : steady_threads(k, plan->cores))
            cases.push_back(checkpoint(*plan, k, t, index));
        index++;
    };
    for (size_t i = 0; i < plan->cases.size(); i++) {
        if (i % static_cast<size_t>(every) == 0)
            add();
        cases.push_back(std::move(plan->cases[i]));
    }
    add();
    plan->cases = std::move(cases);
}

// Per thread count, the medians of the checkpoints that ran, in checkpoint order.
static std::map<int, std::vector<const BenchCase *>> checkpoints(const BenchPlan &plan)
{
    std::map<int, std::vector<const BenchCase *>> by;
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_STEADY) && case_timed(c.get()))
            by[c->threads].push_back(c.get());
    return by;
}

struct Spread {
    double min, median, max, drift; // drift: (max - min) / median
};

static Spread spread_of(const std::vector<const BenchCase *> &cs)
{
    std::vector<double> t;
    for (const BenchCase *c : cs)
        t.push_back(c->median_ms);
    std::sort(t.begin(), t.end());
    const double m = sorted_median(t);
    return {t.front(), m, t.back(), (t.back() - t.front()) / m};
}

bool steady_noisy(const BenchPlan &plan, int *threads, double *drift)
{
    auto by = checkpoints(plan);
    double worst = -1;
    for (const auto &[t, cs] : by) {
        if (cs.size() < 3)
            return false;
        const double d = spread_of(cs).drift;
        if (d > worst) {
            worst = d;
            *threads = t;
        }
    }
    *drift = worst;
    return worst > NOISY_DRIFT;
}

std::string steady_note(const BenchPlan &plan)
{
    int t = 0;
    double d = 0;
    if (!steady_noisy(plan, &t, &d))
        return "";
    char b[256];
    std::snprintf(b, sizeof b,
                  "The reference frame's time at %d thread%s spread %.0f%% across the run's checkpoints "
                  "(Machine steadiness, below): the machine's speed changed during the run, so rows timed "
                  "at different moments may differ by as much.",
                  t, t == 1 ? "" : "s", 100 * d);
    return b;
}

void steady_table(std::ostream &o, const BenchPlan &plan)
{
    auto by = checkpoints(plan);
    if (by.empty() || by.begin()->second.size() < 3)
        return;
    const BenchCase *first = by.begin()->second.front();
    o << "\n### Machine steadiness\n\nThe same frame (`" << first->kernel->name << "`, mode exact, "
      << first->scene->name << ", " << first->W << "×" << first->H << ", D " << first->D
      << ") timed at checkpoints spread through the run, " << first->reps
      << " short repetitions each: median ms/frame, and when the checkpoint finished. A case's cv only sees noise "
         "within its own fraction of a second; these see the machine slowing down or speeding up between cases. "
         "Spread: (max − min) / median; above "
      << static_cast<int>(NOISY_DRIFT * 100) << "% the run is marked noisy.\n\n| checkpoint | at |";
    for (const auto &[t, cs] : by)
        o << " " << t << (t == 1 ? " thread" : " threads") << " |";
    o << "\n|--:|--:|";
    for (size_t i = 0; i < by.size(); i++)
        o << "--:|";
    o << "\n";
    std::map<int, std::map<int, const BenchCase *>> rows; // checkpoint -> threads -> case
    for (const auto &[t, cs] : by)
        for (const BenchCase *c : cs)
            rows[c->checkpoint][t] = c;
    for (const auto &[i, cells] : rows) {
        double at = 0;
        for (const auto &cell : cells)
            at = std::max(at, cell.second->done_at);
        char when[32];
        std::snprintf(when, sizeof when, "%.0f s", at);
        o << "| " << i << " | " << when << " |";
        for (const auto &[t, cs] : by) {
            auto it = cells.find(t);
            o << " " << report_ms_cell(it == cells.end() ? std::nan("") : it->second->median_ms) << " |";
        }
        o << "\n";
    }
    o << "| spread | |";
    for (const auto &[t, cs] : by) {
        Spread s = spread_of(cs);
        char b[96];
        std::snprintf(b, sizeof b, " %.1f%% (%s – %s)", 100 * s.drift, report_ms_cell(s.min).c_str(),
                      report_ms_cell(s.max).c_str());
        o << b << (s.drift > NOISY_DRIFT ? " ⚠" : "") << " |";
    }
    o << "\n";
}
