// The large-frame skipping table of BENCH.md (skip_large.h).
#include "skip_large.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_report.h"
#include "in_turn.h"

static const retro_kernel *omp_kernel()
{
    return retro_kernel_find("omp");
}

void plan_skip_large(BenchPlan *plan)
{
    const retro_kernel *k = omp_kernel();
    if (!k || std::find(plan->modes.begin(), plan->modes.end(), RETRO_MODE_EXACT) == plan->modes.end())
        return;
    int t = plan_thread_counts(k, plan->cores).back();
    for (const bench_scene *s : plan->scenes)
        for (bool no_skip : {false, true})
            plan_add_case(plan, k, t, s, RETRO_MODE_EXACT, SKIP_LARGE_W, SKIP_LARGE_H, SKIP_LARGE_D, GROUP_SKIP_LARGE,
                          no_skip);
}

static const BenchCase *ran(const BenchCase *c)
{
    return c && c->ran && c->error.empty() ? c : nullptr;
}

void skip_large_in_turn(BenchPlan *plan, void (*bind)(int threads))
{
    const retro_kernel *k = omp_kernel();
    if (!k)
        return;
    int t = plan_thread_counts(k, plan->cores).back();
    for (const bench_scene *s : plan->scenes) {
        const BenchCase *on = ran(plan->find(k, t, s, RETRO_MODE_EXACT, SKIP_LARGE_W, SKIP_LARGE_H, SKIP_LARGE_D));
        BenchCase *off = const_cast<BenchCase *>(
            ran(plan->find(k, t, s, RETRO_MODE_EXACT, SKIP_LARGE_W, SKIP_LARGE_H, SKIP_LARGE_D, true)));
        if (on && off && in_turn(on, off, SKIP_LARGE_PAIRS, bind))
            std::fprintf(stderr, "  skipping at %dx%d, D %d, %s: %d pairs timed in turn, ratio %.2f\n", SKIP_LARGE_W,
                         SKIP_LARGE_H, SKIP_LARGE_D, s->name, SKIP_LARGE_PAIRS, off->in_turn);
    }
}

static std::string share(const BenchCase *c)
{
    if (!c || std::isnan(c->samples))
        return "–";
    char b[32];
    std::snprintf(b, sizeof b, "%.1f%%", 100 * c->samples / (c->W * static_cast<double>(c->D - 1)));
    return b;
}

static std::string cv_cell(const BenchCase *a, const BenchCase *b)
{
    double v = std::max(a && !std::isnan(a->cv) ? a->cv : 0.0, b && !std::isnan(b->cv) ? b->cv : 0.0);
    char s[32];
    std::snprintf(s, sizeof s, "%.1f%%", 100 * v);
    return s;
}

void skip_large_table(std::ostream &o, const BenchPlan &plan)
{
    const retro_kernel *k = omp_kernel();
    if (!k)
        return;
    int t = plan_thread_counts(k, plan.cores).back();
    double log_on = 0, log_off = 0, log_turn = 0;
    int n = 0, n_turn = 0;
    bool head = false;
    for (const bench_scene *s : plan.scenes) {
        const BenchCase *on = ran(plan.find(k, t, s, RETRO_MODE_EXACT, SKIP_LARGE_W, SKIP_LARGE_H, SKIP_LARGE_D));
        const BenchCase *off =
            ran(plan.find(k, t, s, RETRO_MODE_EXACT, SKIP_LARGE_W, SKIP_LARGE_H, SKIP_LARGE_D, true));
        if (!on && !off)
            continue;
        if (!head) {
            o << "\n### Occlusion skipping at a large frame (`" << k->name << "`, " << t << " threads, mode exact, "
              << SKIP_LARGE_W << "×" << SKIP_LARGE_H << ", D " << SKIP_LARGE_D << ")\n\nmedian ms/frame with the "
                 "kernel's default skipping and with skipping off (`--no-skip`), timed in this run; ratio: "
                 "without over with. In turn: after the run, "
              << SKIP_LARGE_PAIRS
              << " pairs of frames with and without skipping timed one after the other, the median of "
                 "the per-pair ratios (quartiles in brackets): a change in the machine's speed falls on "
                 "both frames of a pair, where the two medians may have been taken at different speeds. "
                 "Evaluated: the samples the counting build of the kernel's vector path evaluates, as a "
                 "share of W×(D−1). Issue 18's target: the geometric mean ratio at least 4×.\n\n"
              << "| scene | with skipping | without | ratio | in turn | evaluated with | evaluated without | max cv "
                 "|\n|---|--:|--:|--:|--:|--:|--:|--:|\n";
            head = true;
        }
        char ratio[32] = "–", turn[64] = "–";
        if (off && !std::isnan(off->in_turn)) {
            std::snprintf(turn, sizeof turn, "%.2f× (%.2f–%.2f)", off->in_turn, off->in_turn_q1, off->in_turn_q3);
            log_turn += std::log(off->in_turn);
            n_turn++;
        }
        if (on && off) {
            std::snprintf(ratio, sizeof ratio, "%.2f×", off->median_ms / on->median_ms);
            log_on += std::log(on->median_ms);
            log_off += std::log(off->median_ms);
            n++;
        }
        o << "| " << s->name << " | " << report_ms_cell(on ? on->median_ms : std::nan("")) << " | "
          << report_ms_cell(off ? off->median_ms : std::nan("")) << " | " << ratio << " | " << turn << " | "
          << share(on) << " | "
          << share(off) << " | " << cv_cell(on, off) << " |\n";
    }
    if (n) {
        double a = std::exp(log_on / n), b = std::exp(log_off / n);
        char ratio[32];
        std::snprintf(ratio, sizeof ratio, "%.2f×", b / a);
        char turn[32] = "–";
        if (n_turn == n)
            std::snprintf(turn, sizeof turn, "%.2f×", std::exp(log_turn / n_turn));
        o << "| geomean (" << n << " scenes) | " << report_ms_cell(a) << " | " << report_ms_cell(b) << " | " << ratio
          << " | " << turn << " | | | |\n";
    }
}
