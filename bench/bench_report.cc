// BENCH.md: the run's context, then one markdown table per question a reader asks.
#include "bench_report.h"
#include "busy.h"
#include "extras.h"
#include "mesh_cases.h"
#include "peer_cases.h"
#include "skip_large.h"
#include "steady.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

bool report_write_file(const std::string &path, const std::string &text)
{
    // Through a temporary file renamed into place: a failed run leaves the previous report.
    const std::string tmp = path + ".tmp";
    std::ofstream f(tmp);
    f << text;
    f.close();
    if (!f || std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
        return false;
    }
    return true;
}

std::string report_ms_cell(double v)
{
    if (std::isnan(v))
        return "–";
    char b[32];
    std::snprintf(b, sizeof b, v < 10 ? "%.3f" : v < 100 ? "%.2f" : "%.1f", v);
    return b;
}

static std::string ms(double v)
{
    return report_ms_cell(v);
}

static std::string times(double v)
{
    if (std::isnan(v))
        return "–";
    char b[32];
    std::snprintf(b, sizeof b, "%.2f×", v);
    return b;
}

static std::string percent(double v)
{
    if (std::isnan(v))
        return "–";
    char b[32];
    std::snprintf(b, sizeof b, "%.1f%%", 100 * v);
    return b;
}

static std::string kernel_cell(const ReportRow &r)
{
    return std::string("`") + r.kernel->name + "`" + (r.no_skip ? " (no skipping)" : "") + " | " + std::to_string(r.threads);
}

static void matrix_table(std::ostream &o, const BenchPlan &plan, retro_mode mode)
{
    std::vector<ReportRow> rows = report_rows(plan, GROUP_MATRIX, mode);
    if (rows.empty())
        return;
    o << "\n## Mode " << retro_mode_name(mode) << ", " << plan.W << "×" << plan.H << ", D "
      << plan.D << ": median ms/frame\n\n| kernel | threads |";
    for (const bench_scene *s : plan.scenes)
        o << " " << s->name << " |";
    o << " geomean | vs naive | vs ybuffer | max cv |\n|---|--:|";
    for (size_t i = 0; i < plan.scenes.size() + 4; i++)
        o << "--:|";
    o << "\n";
    for (const ReportRow &r : rows) {
        o << "| " << kernel_cell(r) << " |";
        for (const bench_scene *s : plan.scenes)
            o << " " << ms(report_ms(plan, r, s, mode, plan.W, plan.H, plan.D)) << " |";
        o << " " << ms(report_geomean(plan, r, mode)) << " | "
          << times(report_speedup(plan, r, mode, "naive")) << " | "
          << times(report_speedup(plan, r, mode, "ybuffer")) << " | "
          << percent(report_max_cv(plan, r, mode))
          << (report_max_cv(plan, r, mode) > NOISY_CV ? " ⚠" : "") << " |\n";
    }
}

// A sweep table: one column per point, points given as (W, H, D) with their titles.
static void sweep_table(std::ostream &o, const BenchPlan &plan, unsigned group,
                        const std::string &title, const std::vector<std::string> &heads,
                        const std::vector<std::array<int, 3>> &points)
{
    std::vector<ReportRow> rows = report_rows(plan, group, RETRO_MODE_EXACT);
    if (rows.empty())
        return;
    o << "\n## " << title << "\n\n| kernel | threads |";
    for (const std::string &h : heads)
        o << " " << h << " |";
    o << "\n|---|--:|";
    for (size_t i = 0; i < heads.size(); i++)
        o << "--:|";
    o << "\n";
    for (const ReportRow &r : rows) {
        o << "| " << kernel_cell(r) << " |";
        for (const auto &p : points)
            o << " " << ms(report_ms(plan, r, plan.sweep_scene, RETRO_MODE_EXACT, p[0], p[1], p[2]))
              << " |";
        o << "\n";
    }
}

static void header(std::ostream &o, const BenchPlan &plan, const RunContext &ctx,
                   double seconds, int cases_run, const std::string &retimed)
{
    o << "# retro benchmark\n\n| | |\n|---|---|\n"
      << "| CPU | " << ctx.cpu_model << "; " << ctx.cores << " cores, " << ctx.pus
      << " hardware threads; retro ISA level " << ctx.isa << " |\n"
      << "| binding | single-threaded kernels: " << ctx.binding
      << "; a threaded kernel at n threads: bench thread on cores 0 to n-1, the kernel's own "
         "placement within them (" << ctx.kernel_binding << ") |\n"
      << "| C compiler | " << ctx.cc << " |\n"
      << "| C flags | `" << ctx.cflags << "` (plus per-file ISA flags) |\n"
      << "| harness | " << ctx.cxx << ", google-benchmark; " << ctx.repetitions
      << " repetitions of at least " << ctx.min_time << " s each, after one untimed frame "
      << "and " << ctx.warmup << " s of warm-up per case; CPU time for single-threaded "
         "kernels, wall time for threaded ones; medians |\n";
    if (!ctx.filter.empty()) {
        std::string f; // a regex's | would end the table cell
        for (char ch : ctx.filter)
            f += ch == '|' ? std::string("\\|") : std::string(1, ch);
        o << "| filter | `" << f << "` (a partial run) |\n";
    }
    o << "| date | " << ctx.date << "; load average " << ctx.load << " at the start |\n"
      << "| machine | " << ctx.machine << " |\n"
      << "| settings | " << (ctx.quick ? "quick run (make bench QUICK=1): fewer, shorter "
                                         "repetitions and sweep points; not for publishing"
                                       : "full run") << " |\n"
      << "| commit | " << ctx.commit << " |\n"
      << "| run | " << cases_run << " cases in " << static_cast<int>(std::lround(seconds))
      << " s |\n\nTimes are the median milliseconds per frame over the repetitions (lower is "
         "better). Speedups divide geometric means over the scenes (higher is better). "
         "Max cv is the largest coefficient of variation of a row's repetitions: where it is "
         "high, other work shared the machine. Scenes:";
    for (const bench_scene *s : plan.scenes)
        o << " " << s->name << (std::string(s->origin) == "course" ? " (course test pose)" : "")
          << (s == plan.scenes.back() ? "." : ",");
    o << " Generated maps are seen from their default view.\n\n"
      // Debian builds libbenchmark without NDEBUG, so its JSON says so; see below.
      << "The JSON's `library_build_type: debug` describes Debian's libbenchmark (built "
         "without NDEBUG), not the timed code: the timing loop is inlined from the header into "
         "the harness, built with " << ctx.cxx << " at the harness's -O level, and each "
         "iteration calls retro_render() in libretro, built with the C flags above. The "
         "library's own asserts run only between timed loops.\n";
    if (!retimed.empty())
        o << "\n" << retimed << "\n";
    int noisy = report_noisy_rows(plan);
    std::string drift = steady_note(plan);
    bool flag = ctx.busy || noisy || !drift.empty();
    if (flag)
        o << "\n> **Noisy run.**";
    if (noisy)
        o << " " << noisy << (noisy == 1 ? " row has" : " rows have")
          << " a spread over repetitions above " << static_cast<int>(NOISY_CV * 100)
          << "% (max cv marked ⚠): its medians may be off by as much.";
    if (!drift.empty())
        o << " " << drift;
    if (ctx.busy)
        o << " The machine was busy when the run started (" << ctx.machine << ").";
    if (flag)
        o << " Rerun on a quiet machine before drawing conclusions.\n";
}

bool write_bench_md(const std::string &path, const BenchPlan &plan, const RunContext &ctx,
                    double seconds, int cases_run, const std::string &retimed)
{
    std::ostringstream o;
    header(o, plan, ctx, seconds, cases_run, retimed);
    for (retro_mode mode : plan.modes)
        matrix_table(o, plan, mode);
    if (plan.sweep_scene) {
        std::vector<std::string> heads;
        std::vector<std::array<int, 3>> points;
        for (auto [w, h] : plan.resolutions) {
            heads.push_back(std::to_string(w) + "×" + std::to_string(h));
            points.push_back({w, h, plan.D});
        }
        sweep_table(o, plan, GROUP_RESOLUTION,
                    std::string("Resolution sweep: mode exact, ") + plan.sweep_scene->name +
                        ", D " + std::to_string(plan.D) + ": median ms/frame",
                    heads, points);
        heads.clear();
        points.clear();
        for (int d : plan.distances) {
            heads.push_back("D " + std::to_string(d));
            points.push_back({plan.W, plan.H, d});
        }
        sweep_table(o, plan, GROUP_DISTANCE,
                    std::string("Distance sweep: mode exact, ") + plan.sweep_scene->name + ", " +
                        std::to_string(plan.W) + "×" + std::to_string(plan.H) +
                        ": median ms/frame",
                    heads, points);
    }
    skip_large_table(o, plan);
    extras_tables(o, plan);
    peer_table(o, plan);
    mesh_table(o, plan);
    steady_table(o, plan);
    std::map<std::string, std::string> skipped; // kernel -> first reason
    for (const auto &c : plan.cases)
        if (c->ran && !c->error.empty())
            skipped.emplace(c->kernel->name, c->error);
    if (!skipped.empty()) {
        o << "\nSkipped (– in the tables):\n\n";
        for (const auto &[k, why] : skipped)
            o << "- `" << k << "`: " << why << "\n";
    }
    o << "\n![speedup over naive](bench-speedup.svg)\n"
      << "![ms/frame against resolution](bench-resolution.svg)\n"
      << "![ms/frame against distance](bench-distance.svg)\n";
    return report_write_file(path, o.str());
}
