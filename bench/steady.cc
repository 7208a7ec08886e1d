// The checkpoints of steady.h and their section of BENCH.md.
#include "steady.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

static Spread spread_of(std::vector<double> t)
{
    std::sort(t.begin(), t.end());
    const double m = sorted_median(t);
    return {t.front(), m, t.back(), (t.back() - t.front()) / m};
}

static Spread spread_of(const std::vector<const BenchCase *> &cs)
{
    std::vector<double> t;
    for (const BenchCase *c : cs)
        t.push_back(c->median_ms);
    return spread_of(t);
}

// The 1-thread checkpoints that ran the probes (machine_probe.h), in checkpoint order.
static std::vector<const BenchCase *> probed(const BenchPlan &plan)
{
    std::vector<const BenchCase *> out;
    const auto by = checkpoints(plan); // kept: a range-for would not keep the map alive
    auto one = by.find(1);
    if (one == by.end())
        return out;
    for (const BenchCase *c : one->second)
        if (!c->probes.empty())
            out.push_back(c);
    return out;
}

// The probes' counter names, in the table's order: clock and throughput by core, then memory.
static std::vector<std::string> probe_names(const std::vector<const BenchCase *> &cs)
{
    std::vector<std::string> names;
    for (const BenchCase *c : cs)
        for (const auto &kv : c->probes)
            if (std::find(names.begin(), names.end(), kv.first) == names.end())
                names.push_back(kv.first);
    auto rank = [](const std::string &n) {
        int kind = n.rfind("clock", 0) == 0 ? 0 : n.rfind("throughput", 0) == 0 ? 1 : 2;
        size_t at = n.rfind("core ");
        return std::pair{kind, at == std::string::npos ? 0 : std::atoi(n.c_str() + at + 5)};
    };
    std::sort(names.begin(), names.end(), [&](const std::string &x, const std::string &y) { return rank(x) < rank(y); });
    return names;
}

// "clock, core 0" for "clock probe ms, core 0".
static std::string probe_title(const std::string &name)
{
    std::string t = name;
    t.erase(t.find(PROBE_COUNTER), std::string(PROBE_COUNTER).size());
    return t;
}

// "on core 1" for "clock probe ms, core 1"; "" for a probe of no one core.
static std::string probe_where(const std::string &name)
{
    size_t at = name.rfind("core ");
    return at == std::string::npos ? "" : " on " + name.substr(at);
}

// A second hardware thread on the core takes up to half of the throughput probe's units, with
// the clock unchanged; a spread well short of that is the probe's own scatter and short
// preemptions, which a quiet run shows too.
constexpr double SHARED_CORE_DRIFT = 0.25;

static double probe_of(const BenchCase *c, const std::string &name)
{
    auto it = c->probes.find(name);
    return it == c->probes.end() ? std::nan("") : it->second;
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

// The values of one probe over the checkpoints that have it and, when frame is given, the
// 1-thread frame's times at the same checkpoints.
static std::vector<double> series(const std::vector<const BenchCase *> &cs, const std::string &name,
                                  std::vector<double> *frame = nullptr)
{
    std::vector<double> probe;
    for (const BenchCase *c : cs)
        if (double x = probe_of(c, name); !std::isnan(x)) {
            probe.push_back(x);
            if (frame)
                frame->push_back(c->median_ms);
        }
    return probe;
}

// The probe of one kind whose values spread most across the checkpoints: its name and spread.
struct Worst {
    std::string name;
    Spread spread{};
};

static Worst worst_of(const std::vector<const BenchCase *> &cs, const std::vector<std::string> &names,
                      const char *kind)
{
    Worst w;
    w.spread.drift = -1;
    for (const std::string &n : names) {
        if (n.rfind(kind, 0) != 0)
            continue;
        const std::vector<double> v = series(cs, n);
        if (v.size() < 3)
            continue;
        const Spread sp = spread_of(v);
        if (sp.drift > w.spread.drift)
            w = {n, sp};
    }
    return w;
}

// What the probes say about a noisy run whose reference frame spread frame_drift: whether the
// clocks moved as much as the frame did, and how the first core's throughput and memory probes
// moved with the 1-thread frame, which runs on that core.
static std::string steady_probe_note(const BenchPlan &plan, double frame_drift)
{
    const std::vector<const BenchCase *> cs = probed(plan);
    if (cs.size() < 3)
        return "";
    const std::vector<std::string> names = probe_names(cs);
    const Worst clock = worst_of(cs, names, "clock");
    if (clock.spread.drift < 0)
        return "";
    char b[512];
    std::string note;
    if (clock.spread.drift >= frame_drift / 2) {
        std::snprintf(b, sizeof b, "The clock probe%s spread %.1f%% across the same checkpoints, as much as the frame: "
                      "the core's clock changed during the run.", probe_where(clock.name).c_str(),
                      100 * clock.spread.drift);
        note = b;
    } else {
        std::snprintf(b, sizeof b, "The clock probes spread at most %.1f%% on any core, well short of the frame's "
                      "%.0f%%: the clocks do not explain it.", 100 * clock.spread.drift, 100 * frame_drift);
        note = b;
    }
    const Worst units = worst_of(cs, names, "throughput");
    if (clock.spread.drift < frame_drift / 2 && units.spread.drift > SHARED_CORE_DRIFT) {
        std::snprintf(b, sizeof b, " The throughput probe%s spread %.0f%% (%s to %s ms) at those clocks: for part of "
                      "the run that core gave it fewer of its units, as when another hardware thread shares the "
                      "physical core.", probe_where(units.name).c_str(), 100 * units.spread.drift,
                      report_ms_cell(units.spread.min).c_str(), report_ms_cell(units.spread.max).c_str());
        note += b;
    }
    // The first core's probes against the 1-thread frame timed on it just before.
    std::string with;
    for (const std::string &n : names) {
        if (n.rfind("clock", 0) == 0 || (n.find("core ") != std::string::npos && probe_where(n) != " on core 0"))
            continue;
        std::vector<double> frame;
        const std::vector<double> probe = series(cs, n, &frame);
        if (probe.size() < 3)
            continue;
        const double r = correlation(frame, probe);
        std::string kind = n.substr(0, n.find(PROBE_COUNTER));
        if (std::isnan(r))
            std::snprintf(b, sizeof b, "%s the %s probe spread %.0f%%", with.empty() ? "" : ";", kind.c_str(),
                          100 * spread_of(probe).drift);
        else
            std::snprintf(b, sizeof b, "%s the %s probe spread %.0f%%, r = %.2f", with.empty() ? "" : ";",
                          kind.c_str(), 100 * spread_of(probe).drift, r);
        with += b;
    }
    if (!with.empty())
        note += " On the first core, with Pearson's r against the 1-thread frame's time there:" + with + ".";
    return note;
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
    std::string why = steady_probe_note(plan, d);
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
    const std::vector<const BenchCase *> cs1 = probed(plan);
    const std::vector<std::string> probes = cs1.size() >= 3 ? probe_names(cs1) : std::vector<std::string>{};
    if (!probes.empty())
        o << " After the frames of each 1-thread checkpoint, probes of the machine (bench/machine_probe.h), ms: "
             "on each core in turn, the clock probe (a chain of dependent multiplies, which waits only on the "
             "core's clock) and the throughput probe (eight independent chains, which keep the core's multipliers "
             "busy and slow down when another hardware thread shares the physical core); then on the first core "
             "the memory probe (dependent loads through "
          << (MACHINE_PROBE_BYTES >> 20) << " MiB, which wait on the caches shared with other cores and on memory).";
    o << "\n\n| checkpoint | at |";
    for (const auto &[t, cs] : by)
        o << " " << t << (t == 1 ? " thread" : " threads") << " |";
    for (const std::string &n : probes)
        o << " " << probe_title(n) << " |";
    o << "\n|--:|--:|";
    for (size_t i = 0; i < by.size() + probes.size(); i++)
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
        auto one = cells.find(1);
        for (const std::string &n : probes)
            o << " " << report_ms_cell(one == cells.end() ? std::nan("") : probe_of(one->second, n)) << " |";
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
    for (const std::string &n : probes) {
        const std::vector<double> v = series(cs1, n);
        if (v.empty()) {
            o << " – |";
            continue;
        }
        Spread s = spread_of(v);
        char b[96];
        std::snprintf(b, sizeof b, " %.1f%% (%s – %s) |", 100 * s.drift, report_ms_cell(s.min).c_str(),
                      report_ms_cell(s.max).c_str());
        o << b;
    }
    o << "\n";
}
