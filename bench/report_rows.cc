// The numbers BENCH.md and the charts share: rows, medians, geometric means, speedups.
#include "bench_report.h"
#include "busy.h"

#include <algorithm>

#include <cmath>
#include <set>
#include <tuple>

static const double NaN = std::nan("");

std::vector<ReportRow> report_rows(const BenchPlan &plan, unsigned group, retro_mode mode)
{
    std::set<std::tuple<int, int, bool>> seen;
    for (const auto &c : plan.cases)
        if ((c->groups & group) && c->mode == mode && c->ran)
            seen.insert({c->kernel_index, c->threads, c->no_skip});
    std::vector<ReportRow> rows;
    for (auto [k, t, n] : seen)
        rows.push_back({&retro_kernels[k], t, n});
    return rows;
}

double report_ms(const BenchPlan &plan, const ReportRow &row, const bench_scene *s,
                 retro_mode mode, int W, int H, int D)
{
    const BenchCase *c = plan.find(row.kernel, row.threads, s, mode, W, H, D, row.no_skip);
    return c && c->ran && c->error.empty() ? c->median_ms : NaN;
}

// Geometric mean over the scenes both rows were timed on (all of them in a full run), so a
// partial run still compares like with like.
static double geomean_common(const BenchPlan &plan, const ReportRow &row, const ReportRow *other,
                             retro_mode mode)
{
    double log_sum = 0;
    int n = 0;
    for (const bench_scene *s : plan.scenes) {
        double v = report_ms(plan, row, s, mode, plan.W, plan.H, plan.D);
        double w = other ? report_ms(plan, *other, s, mode, plan.W, plan.H, plan.D) : 1;
        if (!std::isnan(v) && !std::isnan(w)) {
            log_sum += std::log(v);
            n++;
        }
    }
    return n ? std::exp(log_sum / n) : NaN;
}

double report_geomean(const BenchPlan &plan, const ReportRow &row, retro_mode mode)
{
    return geomean_common(plan, row, nullptr, mode);
}

double report_speedup(const BenchPlan &plan, const ReportRow &row, retro_mode mode,
                      const char *base)
{
    const retro_kernel *b = retro_kernel_find(base);
    if (!b)
        return NaN;
    ReportRow brow{b, 1};
    return geomean_common(plan, brow, &row, mode) / geomean_common(plan, row, &brow, mode);
}

std::string report_label(const ReportRow &row)
{
    std::string skip = row.no_skip ? ", no skipping" : "";
    if (!(row.kernel->flags & RETRO_KF_THREADED))
        return row.kernel->name + skip;
    return std::string(row.kernel->name) + ", " + std::to_string(row.threads) +
           (row.threads == 1 ? " thread" : " threads") + skip;
}

double report_max_cv(const BenchPlan &plan, const ReportRow &row, retro_mode mode)
{
    double worst = NaN;
    for (const bench_scene *s : plan.scenes) {
        const BenchCase *c = plan.find(row.kernel, row.threads, s, mode, plan.W, plan.H, plan.D, row.no_skip);
        if (c && c->ran && c->error.empty() && !std::isnan(c->cv))
            worst = std::isnan(worst) ? c->cv : std::max(worst, c->cv);
    }
    return worst;
}

int report_noisy_rows(const BenchPlan &plan)
{
    int n = 0;
    for (retro_mode m : plan.modes)
        for (const ReportRow &r : report_rows(plan, GROUP_MATRIX, m))
            n += report_max_cv(plan, r, m) > NOISY_CV;
    return n;
}

bool report_row_noisy(const BenchPlan &plan, const ReportRow &row)
{
    for (retro_mode m : plan.modes)
        if (report_max_cv(plan, row, m) > NOISY_CV)
            return true;
    return false;
}
