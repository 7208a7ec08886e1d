// The checkpoints of steady.h and their section of BENCH.md.
#include "steady.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "bench_report.h"
#include "machine_probe.h"

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

static Spread spread_of(std::vector<double> t);

static Spread spread_of(const std::vector<const BenchCase *> &cs)
{
    std::vector<double> t;
    for (const BenchCase *c : cs)
        t.push_back(c->median_ms);
    return spread_of(t);
}

// The 1-thread checkpoints' probes (machine_probe.h), in checkpoint order; empty without them.
static std::vector<const BenchCase *> probed(const BenchPlan &plan)
{
    std::vector<const BenchCase *> out;
    const auto by = checkpoints(plan); // kept: a range-for would not keep the map alive
    auto one = by.find(1);
    if (one == by.end())
        return out;
    for (const BenchCase *c : one->second)
        if (!std::isnan(c->probe_clock_ms))
            out.push_back(c);
    return out;
}

static Spread spread_of(std::vector<double> t)
{
    std::sort(t.begin(), t.end());
    const double m = sorted_median(t);
    return {t.front(), m, t.back(), (t.back() - t.front()) / m};
}

// Pearson's r of two equally long series; NaN when either is constant.
static double correlation(const std::vector<double> &x, const std::vector<double> &y)
{
    const size_t n = x.size();
    double mx = 0, my = 0;
    for (size_t i = 0; i < n; i++) {
        mx += x[i] / n;
        my += y[i] / n;
    }
    double sxy = 0, sxx = 0, syy = 0;
    for (size_t i = 0; i < n; i++) {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
    }
    return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : std::nan("");
}

static std::string steady_probe_note(const BenchPlan &plan)
{
    std::vector<const BenchCase *> cs = probed(plan);
    if (cs.size() < 3)
        return "";
    std::vector<double> frame, clock, memory;
    for (const BenchCase *c : cs) {
        frame.push_back(c->median_ms);
        clock.push_back(c->probe_clock_ms);
        memory.push_back(c->probe_memory_ms);
    }
    const double clock_drift = spread_of(clock).drift;
    char b[512];
    if (clock_drift > NOISY_DRIFT / 2) {
        std::snprintf(b, sizeof b, "The clock probe spread %.0f%% across the same checkpoints: the core's clock changed "
                      "during the run.", 100 * clock_drift);
        return b;
    }
    int n = std::snprintf(b, sizeof b, "The clock probe spread only %.1f%% across the same checkpoints, so the core's "
                          "clock held: the frame waited longer on something else, such as memory or a core shared "
                          "with other work", 100 * clock_drift);
    if (std::none_of(memory.begin(), memory.end(), [](double m) { return std::isnan(m); })) {
        const double r = correlation(frame, memory);
        n += std::snprintf(b + n, sizeof b - n, " (the memory probe spread %.0f%%", 100 * spread_of(memory).drift);
        if (!std::isnan(r))
            n += std::snprintf(b + n, sizeof b - n, "; its correlation with the frame's time at one thread: r = %.2f", r);
        std::snprintf(b + n, sizeof b - n, ")");
    }
    return std::string(b) + ".";
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
    std::string why = steady_probe_note(plan);
    return why.empty() ? b : std::string(b) + " " + why;
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
      << static_cast<int>(NOISY_DRIFT * 100) << "% the run is marked noisy.";
    const bool probes = probed(plan).size() >= 3;
    if (probes)
        o << " After the frames of each 1-thread checkpoint, on the same core, two probes (bench/machine_probe.h), "
             "ms: the clock probe, a chain of dependent multiplies, waits only on the core's clock; the memory "
             "probe, a chain of dependent loads through "
          << (MACHINE_PROBE_BYTES >> 20)
          << " MiB, on the caches shared with other cores and on memory. A frame that slows while the clock "
             "probe holds was not clocked down.";
    o << "\n\n| checkpoint | at |";
    for (const auto &[t, cs] : by)
        o << " " << t << (t == 1 ? " thread" : " threads") << " |";
    if (probes)
        o << " clock probe | memory probe |";
    o << "\n|--:|--:|";
    for (size_t i = 0; i < by.size() + (probes ? 2 : 0); i++)
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
        if (probes) {
            auto it = cells.find(1);
            const BenchCase *c = it == cells.end() ? nullptr : it->second;
            o << " " << report_ms_cell(c ? c->probe_clock_ms : std::nan("")) << " | "
              << report_ms_cell(c ? c->probe_memory_ms : std::nan("")) << " |";
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
    if (probes) {
        std::vector<double> clock, memory;
        for (const BenchCase *c : probed(plan)) {
            clock.push_back(c->probe_clock_ms);
            if (!std::isnan(c->probe_memory_ms))
                memory.push_back(c->probe_memory_ms);
        }
        for (const std::vector<double> *v : {&clock, &memory}) {
            if (v->empty()) {
                o << " – |";
                continue;
            }
            Spread s = spread_of(*v);
            char b[96];
            std::snprintf(b, sizeof b, " %.1f%% (%s – %s) |", 100 * s.drift, report_ms_cell(s.min).c_str(),
                          report_ms_cell(s.max).c_str());
            o << b;
        }
    }
    o << "\n";
}
