// BENCH.md's mesh tables (see mesh_cases.h): per scene, over the scenes, and the two sweeps
// beside the best voxel kernel.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_report.h"
#include "mesh_cases.h"
#include "sweep_axes.h"

static const double NaN = std::nan("");

// The mesh case of kernel k at threads on scene s and frame (w, h, d), or nullptr.
static const BenchCase *mesh_find(const BenchPlan &plan, const retro_kernel *k, int threads, const bench_scene *s,
                                  int w, int h, int d)
{
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_MESH) && c->kernel == k && c->threads == threads && c->scene == s && c->W == w &&
            c->H == h && c->D == d)
            return c.get();
    return nullptr;
}

// The fastest voxel kernel of the matrix (mode exact, any thread count) on scene s, or nullptr.
static const BenchCase *best_voxel(const BenchPlan &plan, const bench_scene *s)
{
    const BenchCase *best = nullptr;
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_MATRIX) && c->scene == s && c->mode == RETRO_MODE_EXACT && c->W == plan.W &&
            c->H == plan.H && c->D == plan.D && case_timed(c.get()) && (!best || c->median_ms < best->median_ms))
            best = c.get();
    return best;
}

static std::string count_cell(double v, double per_second_scale)
{
    char b[32];
    if (std::isnan(v))
        return "–";
    std::snprintf(b, sizeof b, per_second_scale > 0 ? "%.1f" : "%.0f", per_second_scale > 0 ? v / per_second_scale : v);
    return b;
}

static std::string kernel_cell(const retro_kernel *k, int threads)
{
    std::string s = std::string("`") + k->name + "`";
    return (k->flags & RETRO_KF_THREADED) ? s + " " + std::to_string(threads) + "t" : s;
}

// The (kernel, threads) rows of the cases in group, in plan order.
static std::vector<std::pair<const retro_kernel *, int>> mesh_rows(const BenchPlan &plan, unsigned group)
{
    std::vector<std::pair<const retro_kernel *, int>> rows;
    for (const auto &c : plan.cases) {
        std::pair<const retro_kernel *, int> r{c->kernel, c->threads};
        if ((c->groups & group) && c->ran && std::find(rows.begin(), rows.end(), r) == rows.end())
            rows.push_back(r);
    }
    return rows;
}

// Geometric mean over the matrix scenes of a row's ms/frame; NaN unless every scene ran.
static double mesh_geomean(const BenchPlan &plan, const retro_kernel *k, int threads)
{
    double log_sum = 0;
    int n = 0;
    for (const bench_scene *s : plan.scenes) {
        const BenchCase *c = mesh_find(plan, k, threads, s, plan.W, plan.H, plan.D);
        if (!c)
            continue;
        if (!case_timed(c))
            return NaN;
        log_sum += std::log(c->median_ms);
        n++;
    }
    return n ? std::exp(log_sum / n) : NaN;
}

static std::string ratio_cell(double v)
{
    char b[32];
    if (std::isnan(v))
        return "–";
    std::snprintf(b, sizeof b, "%.2f×", v);
    return b;
}

static void per_scene(std::ostream &o, const BenchPlan &plan)
{
    o << "\n### Mesh family: the same scenes and poses as triangles (mode binary32, " << plan.W << "×" << plan.H
      << ", D " << plan.D << ", back faces culled)\n\nmedian ms/frame over " << MESH_REPETITIONS << " repetitions of "
      << MESH_ITERATIONS << " frames (" << MESH_QUICK_REPETITIONS << " with --quick, which times the sweep scene "
      << "only). Triangles: submitted (from blocks inside the view), drawn (after back-face culling and "
         "clipping); fragments: covered pixel centres (docs/MESH.md). Rates per second at the median. "
         "\"vs best voxel\": the mesh kernel's time over the fastest voxel kernel's in the mode exact table "
         "on the same scene (kernel and threads named).\n\n"
      << "| scene | kernel | ms/frame | triangles submitted | triangles drawn | fragments | Mtriangles/s | "
         "Mfragments/s | vs best voxel | max cv |\n|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const auto &c : plan.cases) {
        if (!(c->groups & GROUP_MESH) || !c->ran || c->W != plan.W || c->H != plan.H || c->D != plan.D)
            continue;
        bool ok = case_timed(c.get());
        double per_s = ok ? 1e3 / c->median_ms : NaN;
        const BenchCase *v = best_voxel(plan, c->scene);
        char ratio[96] = "–", cv[32] = "–";
        if (ok && v)
            std::snprintf(ratio, sizeof ratio, "%.0f× `%s`/%dt", c->median_ms / v->median_ms, v->kernel->name,
                          v->threads);
        if (!std::isnan(c->cv))
            std::snprintf(cv, sizeof cv, "%.1f%%", 100 * c->cv);
        o << "| " << c->scene->name << " | " << kernel_cell(c->kernel, c->threads) << " | "
          << report_ms_cell(ok ? c->median_ms : NaN) << " | " << count_cell(c->tri_submitted, 0) << " | "
          << count_cell(c->tri_drawn, 0) << " | " << count_cell(c->fragments, 0) << " | "
          << count_cell(c->tri_drawn * per_s, 1e6) << " | " << count_cell(c->fragments * per_s, 1e6) << " | " << ratio
          << " | " << cv << " |\n";
    }
}

// Over the scenes: each row's geometric mean, its speedup over mesh-zbuffer and over the best
// single-threaded mesh kernel of the run (the two targets).
static void summary(std::ostream &o, const BenchPlan &plan)
{
    const auto rows = mesh_rows(plan, GROUP_MESH);
    const retro_kernel *ref = retro_family_reference(&retro_family_mesh);
    double ref_g = ref ? mesh_geomean(plan, ref, 1) : NaN, best_g = NaN;
    for (auto [k, t] : rows)
        if (!(k->flags & RETRO_KF_THREADED)) {
            double g = mesh_geomean(plan, k, t);
            if (!std::isnan(g) && (std::isnan(best_g) || g < best_g))
                best_g = g;
        }
    o << "\n### Mesh family over the scenes (mode binary32, " << plan.W << "×" << plan.H << ", D " << plan.D
      << ", back faces culled)\n\nGeometric mean of the median ms/frame over the scenes above; \"vs best single\": "
         "over the fastest single-threaded mesh kernel of this run.\n\n"
         "| kernel | geomean ms/frame | vs mesh-zbuffer | vs best single |\n|---|--:|--:|--:|\n";
    for (auto [k, t] : rows) {
        double g = mesh_geomean(plan, k, t);
        o << "| " << kernel_cell(k, t) << " | " << report_ms_cell(g) << " | " << ratio_cell(ref_g / g) << " | "
          << ratio_cell(best_g / g) << " |\n";
    }
}

// A sweep's data: the mesh sweep rows, then the voxel sweep's fastest kernel, ms/frame at each
// point (W, H, D).
struct SweepRow {
    std::string cell, label; // markdown cell, plain chart label
    bool voxel;
    std::vector<double> ms;
};

static std::vector<SweepRow> sweep_data(const BenchPlan &plan, unsigned voxel_group,
                                        const std::vector<std::array<int, 3>> &points)
{
    std::vector<SweepRow> out;
    for (auto [k, t] : mesh_rows(plan, GROUP_MESH_SWEEP)) {
        bool thr = k->flags & RETRO_KF_THREADED;
        SweepRow r{kernel_cell(k, t), std::string(k->name) + (thr ? ", " + std::to_string(t) + " threads" : ""),
                   false, {}};
        for (const auto &p : points) {
            const BenchCase *c = mesh_find(plan, k, t, plan.sweep_scene, p[0], p[1], p[2]);
            r.ms.push_back(case_timed(c) ? c->median_ms : NaN);
        }
        out.push_back(r);
    }
    const retro_kernel *vk = retro_kernel_best(RETRO_MODE_EXACT);
    if (out.empty() || !vk)
        return out;
    const int vt = plan_thread_counts(vk, plan.cores).back();
    bool thr = vk->flags & RETRO_KF_THREADED;
    SweepRow r{std::string("`") + vk->name + "`" + (thr ? " " + std::to_string(vt) + "t" : ""),
               std::string(vk->name) + (thr ? ", " + std::to_string(vt) + " threads" : "") + " (voxel, exact)", true,
               {}};
    for (const auto &p : points) {
        const BenchCase *c = plan.find(vk, vt, plan.sweep_scene, RETRO_MODE_EXACT, p[0], p[1], p[2]);
        r.ms.push_back(c && (c->groups & voxel_group) && case_timed(c) ? c->median_ms : NaN);
    }
    out.push_back(r);
    return out;
}

// A sweep table, with the best mesh time over the best voxel time at each point.
static void sweep(std::ostream &o, const BenchPlan &plan, const std::string &title, unsigned voxel_group,
                  const std::vector<std::string> &heads, const std::vector<std::array<int, 3>> &points)
{
    const std::vector<SweepRow> rows = sweep_data(plan, voxel_group, points);
    if (rows.empty())
        return;
    o << "\n### " << title << "\n\n| kernel | family |";
    for (const std::string &h : heads)
        o << " " << h << " |";
    o << "\n|---|---|";
    for (size_t i = 0; i < heads.size(); i++)
        o << "--:|";
    o << "\n";
    std::vector<double> best(points.size(), NaN);
    for (const SweepRow &r : rows) {
        o << "| " << r.cell << " | " << (r.voxel ? "voxel (mode exact)" : "mesh") << " |";
        for (size_t i = 0; i < points.size(); i++) {
            if (!r.voxel && !std::isnan(r.ms[i]) && (std::isnan(best[i]) || r.ms[i] < best[i]))
                best[i] = r.ms[i];
            o << " " << report_ms_cell(r.ms[i]) << " |";
        }
        o << "\n";
    }
    if (rows.back().voxel) {
        o << "| best mesh ÷ best voxel | |";
        for (size_t i = 0; i < points.size(); i++)
            o << " " << ratio_cell(best[i] / rows.back().ms[i]) << " |";
        o << "\n";
    }
}

static std::string gp_num(double v)
{
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return std::isnan(v) ? "NaN" : b;
}

// One log-log chart of a sweep (the gnuplot conventions of bench_charts.cc).
static void sweep_chart(std::ostream &o, const BenchPlan &plan, unsigned voxel_group, const char *block,
                        const std::vector<std::string> &labels, const std::vector<double> &xs,
                        const std::vector<std::array<int, 3>> &points, const std::string &title, const char *xlabel)
{
    const std::vector<SweepRow> rows = sweep_data(plan, voxel_group, points);
    if (rows.empty())
        return;
    std::string data = "$";
    for (const char *c = block; *c; c++) /* a data block's name is an identifier */
        if (*c != '-')
            data += *c;
    o << data << " << EOD\n";
    for (size_t i = 0; i < points.size(); i++) {
        o << "\"" << labels[i] << "\" " << gp_num(xs[i]);
        for (const SweepRow &r : rows)
            o << " " << gp_num(r.ms[i]);
        o << "\n";
    }
    o << "EOD\nreset\nset output out.'/bench-" << block << ".'.ext\nset title \"" << title << "\"\nset xlabel '"
      << xlabel << "'\n" << sweep_axes_gp(xs) << "plot";
    for (size_t j = 0; j < rows.size(); j++)
        o << (j ? ", ''" : (" " + data)) << " using 2:" << j + 3 << (j ? "" : ":xtic(1)")
          << " with linespoints lw 2 pt " << (rows[j].voxel ? 5 : 7) << " title \"" << rows[j].label << "\"";
    o << "\n\n";
}

void mesh_charts(std::ostream &o, const BenchPlan &plan)
{
    if (!plan.sweep_scene)
        return;
    const SweepAxis r = resolution_axis(plan), d = distance_axis(plan);
    sweep_chart(o, plan, GROUP_RESOLUTION, "mesh-resolution", r.labels, r.xs, r.points,
                std::string("mesh and voxel ms/frame against resolution: ") + plan.sweep_scene->name + ", D " +
                    std::to_string(plan.D),
                "Mpixel per frame (log scale)");
    sweep_chart(o, plan, GROUP_DISTANCE, "mesh-distance", d.labels, d.xs, d.points,
                std::string("mesh and voxel ms/frame against distance: ") + plan.sweep_scene->name + ", " +
                    std::to_string(plan.W) + "x" + std::to_string(plan.H),
                "distance D (log scale)");
}

void mesh_table(std::ostream &o, const BenchPlan &plan)
{
    if (mesh_rows(plan, GROUP_MESH).empty())
        return;
    per_scene(o, plan);
    summary(o, plan);
    if (!plan.sweep_scene)
        return;
    std::vector<std::string> heads;
    std::vector<std::array<int, 3>> points;
    for (auto [w, h] : plan.resolutions) {
        heads.push_back(std::to_string(w) + "×" + std::to_string(h));
        points.push_back({w, h, plan.D});
    }
    sweep(o, plan,
          std::string("Mesh and voxel cost against resolution: ") + plan.sweep_scene->name + ", D " +
              std::to_string(plan.D) + ", median ms/frame (mesh: binary32, back faces culled)",
          GROUP_RESOLUTION, heads, points);
    heads.clear();
    points.clear();
    for (int d : plan.distances) {
        heads.push_back("D " + std::to_string(d));
        points.push_back({plan.W, plan.H, d});
    }
    sweep(o, plan,
          std::string("Mesh and voxel cost against distance: ") + plan.sweep_scene->name + ", " +
              std::to_string(plan.W) + "×" + std::to_string(plan.H) +
              ", median ms/frame (mesh: binary32, back faces culled; the mesh's far plane stops at 4096)",
          GROUP_DISTANCE, heads, points);
    if (!mesh_rows(plan, GROUP_MESH_SWEEP).empty())
        o << "\n![mesh and voxel ms/frame against resolution](bench-mesh-resolution.svg)\n"
          << "![mesh and voxel ms/frame against distance](bench-mesh-distance.svg)\n";
}
