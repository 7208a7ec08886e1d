// The charts as one self-contained gnuplot script: the run's numbers as inline data blocks,
// then the plots. The terminal is chosen by whoever runs it (scripts/bench.sh), so the same
// script yields SVG and, where gnuplot has it, PNG.
#include "bench_report.h"
#include "mesh_cases.h"
#include "busy.h"
#include "steady.h"
#include "sweep_axes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

static std::string num(double v)
{
    if (std::isnan(v))
        return "NaN";
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

// gnuplot strings in double quotes; our labels hold no quotes or backslashes, but be safe.
static std::string quoted(const std::string &s)
{
    std::string q = "\"";
    for (char ch : s)
        if (ch != '"' && ch != '\\')
            q += ch;
    return q + "\"";
}

// The chart carries the same warning as the top of BENCH.md, a clause per line: on one line
// the three clauses ran past both edges of an 800-pixel chart.
static std::vector<std::string> noisy_note(const BenchPlan &plan, const RunContext &ctx)
{
    std::vector<std::string> lines;
    if (ctx.busy)
        lines.push_back("the machine was busy when the run started");
    if (int n = report_noisy_rows(plan))
        lines.push_back(std::to_string(n) + (n == 1 ? " row" : " rows") + " spread over " +
                        std::to_string(static_cast<int>(NOISY_CV * 100)) + "% (marked noisy)");
    int t = 0;
    double drift = 0;
    if (steady_noisy(plan, &t, &drift))
        lines.push_back("the reference frame at " + std::to_string(t) + (t == 1 ? " thread" : " threads") +
                        " drifted " + std::to_string(static_cast<int>(std::lround(100 * drift))) + "% across the run");
    if (!lines.empty())
        lines.front() = "NOISY RUN: " + lines.front();
    return lines;
}

// The note's lines as one gnuplot string: quoted() keeps a newline, which becomes the escape
// that gnuplot's double quotes read as one.
static std::string note_label(const std::vector<std::string> &lines)
{
    std::string joined;
    for (const std::string &l : lines)
        joined += (joined.empty() ? "" : "\n") + l;
    std::string q;
    for (char ch : quoted(joined))
        q += ch == '\n' ? std::string("\\n") : std::string(1, ch);
    return q;
}

static void speedup_chart(std::ostream &o, const BenchPlan &plan, const RunContext &ctx)
{
    std::set<std::pair<int, int>> keys; // rows of any mode, in table order
    std::vector<retro_mode> modes;      // modes with at least one speedup
    double top = 1;
    for (retro_mode m : plan.modes) {
        bool any = false; // gnuplot stops at a histogram column without a single value
        for (const ReportRow &r : report_rows(plan, GROUP_MATRIX, m)) {
            keys.insert({static_cast<int>(r.kernel - retro_kernels), r.threads});
            double v = report_speedup(plan, r, m, "naive");
            any |= !std::isnan(v);
            top = std::isnan(v) ? top : std::max(top, v);
        }
        if (any)
            modes.push_back(m);
    }
    if (modes.empty())
        return;
    const std::vector<std::string> note = noisy_note(plan, ctx);
    o << "$speedup << EOD\n";
    for (auto [k, t] : keys) {
        ReportRow r{&retro_kernels[k], t};
        o << quoted(report_label(r) + (report_row_noisy(plan, r) ? " (noisy)" : ""));
        for (retro_mode m : modes)
            o << " " << num(report_speedup(plan, r, m, "naive"));
        o << "\n";
    }
    o << "EOD\n"
      << "reset\nset output out.'/bench-speedup.'.ext\n"
      << "set title " << quoted("Speedup over naive (geometric mean over the scenes), " +
                                std::to_string(plan.W) + "x" + std::to_string(plan.H) +
                                ", D " + std::to_string(plan.D))
      << "\nset label 1 " << note_label(note)
      << " at graph 0.5, graph 0.97 center front textcolor rgb 'red'"
      << "\nset ylabel 'times faster than naive (log scale)'\n"
      << "set style data histograms\nset style histogram clustered gap 1\n"
      << "set style fill solid 0.85 border -1\nset grid ytics\n"
      // Log scale: the fastest kernels are two orders of magnitude ahead of naive.
      // Room above the tallest bar for its value; the key below the plot, clear of the bars
      // (outside at the top, gnuplot puts it above the title). A line of the noisy note takes
      // about half a decade of this axis.
      << "set logscale y\nset yrange [0.5:" << num(top * 4 * std::pow(10.0, 0.5 * note.size())) << "]\n"
      << "set key below\nset xtics rotate by 25 right\n"
      << "plot";
    // Clustered bars: n columns and gap 1 put column j at x = i + (j - (n-1)/2) / (n+1).
    const double n = static_cast<double>(modes.size());
    for (size_t j = 0; j < modes.size(); j++)
        o << (j ? ", ''" : " $speedup") << " using " << j + 2 << (j ? "" : ":xtic(1)")
          << " title 'mode " << retro_mode_name(modes[j]) << "'";
    for (size_t j = 0; j < modes.size(); j++) {
        double dx = (static_cast<double>(j) - (n - 1) / 2) / (n + 1);
        o << ", \\\n  '' using ($0" << std::showpos << dx << std::noshowpos << "):" << j + 2
          << ":(sprintf('%.1f', $" << j + 2
          << ")) with labels rotate by 90 left offset 0,0.4 font ',8' notitle";
    }
    o << "\n\n";
}

// One line per sweep row; x is column 2 when a label sits in column 1.
static void sweep_chart(std::ostream &o, const BenchPlan &plan, unsigned group, const char *block,
                        const std::vector<std::string> &labels, const std::vector<double> &xs,
                        const std::vector<std::array<int, 3>> &points, const std::string &title,
                        const char *xlabel)
{
    std::vector<ReportRow> rows = report_rows(plan, group, RETRO_MODE_EXACT);
    if (rows.empty())
        return;
    o << "$" << block << " << EOD\n";
    for (size_t i = 0; i < points.size(); i++) {
        o << quoted(labels[i]) << " " << num(xs[i]);
        for (const ReportRow &r : rows)
            o << " " << num(report_ms(plan, r, plan.sweep_scene, RETRO_MODE_EXACT, points[i][0],
                                      points[i][1], points[i][2]));
        o << "\n";
    }
    o << "EOD\nreset\nset output out.'/bench-" << block << ".'.ext\n"
      << "set title " << quoted(title) << "\nset xlabel '" << xlabel << "'\n"
      << sweep_axes_gp(xs) << "plot";
    for (size_t j = 0; j < rows.size(); j++)
        o << (j ? ", ''" : (" $" + std::string(block))) << " using 2:" << j + 3
          << (j ? "" : ":xtic(1)") << " with linespoints lw 2 pt 7 title "
          << quoted(report_label(rows[j]));
    o << "\n\n";
}

bool write_charts_gp(const std::string &path, const BenchPlan &plan, const RunContext &ctx)
{
    std::ostringstream o;
    o << "# Charts of the retro benchmark run of " << ctx.date << " (commit " << ctx.commit
      << "), written by retro-bench.\n"
      << "# usage: gnuplot -e \"term='svg'; ext='svg'; out='results'\" " << path << "\n"
      << "if (!exists('term')) term = \"svg size 800,450 dynamic background rgb 'white'\"\n"
      << "if (!exists('ext')) ext = 'svg'\nif (!exists('out')) out = 'results'\n"
      << "eval('set terminal '.term)\nset termoption noenhanced\nset encoding utf8\n\n";
    speedup_chart(o, plan, ctx);
    if (plan.sweep_scene) {
        const SweepAxis r = resolution_axis(plan), d = distance_axis(plan);
        sweep_chart(o, plan, GROUP_RESOLUTION, "resolution", r.labels, r.xs, r.points,
                    std::string("ms/frame against resolution: mode exact, ") +
                        plan.sweep_scene->name + ", D " + std::to_string(plan.D),
                    "Mpixel per frame (log scale)");
        sweep_chart(o, plan, GROUP_DISTANCE, "distance", d.labels, d.xs, d.points,
                    std::string("ms/frame against distance: mode exact, ") +
                        plan.sweep_scene->name + ", " + std::to_string(plan.W) + "x" +
                        std::to_string(plan.H),
                    "distance D, samples per column (log scale)");
    }
    mesh_charts(o, plan);
    return report_write_file(path, o.str());
}
