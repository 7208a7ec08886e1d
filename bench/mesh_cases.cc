// Planning, counting and reporting the mesh cases (see mesh_cases.h).
#include "mesh_cases.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_report.h"
#include "retro_mesh.h"

// Front faces only, as a terrain renderer draws a heightfield (docs/MESH.md, "In the kernel table").
static retro_effects cull_fx;

void plan_mesh(BenchPlan *plan, bool quick)
{
    retro_effects_defaults(&cull_fx);
    cull_fx.flags = RETRO_FX_CULL;
    const int mode = RETRO_MESH_BINARY32;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (k->family != &retro_family_mesh || !(k->modes & RETRO_MODE_BIT(mode)))
            continue;
        for (const bench_scene *s : plan->scenes) {
            if (quick && s != plan->sweep_scene)
                continue;
            auto c = std::make_unique<BenchCase>();
            c->kernel = k;
            c->kernel_index = static_cast<int>(i);
            c->threads = 1;
            c->scene = s;
            c->mode = static_cast<retro_mode>(mode);
            c->W = plan->W;
            c->H = plan->H;
            c->D = plan->D;
            c->groups = GROUP_MESH;
            c->fx = &cull_fx;
            c->label = k->name;
            c->name = std::string(retro_family_mode_name(&retro_family_mesh, mode)) + "/" + s->name + "/" + k->name +
                      "/1t/" + std::to_string(c->W) + "x" + std::to_string(c->H) + "/D" + std::to_string(c->D);
            plan->cases.push_back(std::move(c));
        }
    }
}

void mesh_counters(void *state, const BenchCase *c, const retro_ctx *rc)
{
    auto &st = *static_cast<benchmark::State *>(state);
    const retro_mesh_stats *m = retro_mesh_last_stats(rc);
    if (!m)
        return;
    c->tri_submitted = static_cast<double>(m->submitted);
    c->tri_drawn = static_cast<double>(m->submitted - m->culled - m->clipped_out);
    c->fragments = static_cast<double>(m->fragments);
    using benchmark::Counter;
    st.counters["tri_submitted"] = c->tri_submitted;
    st.counters["tri_drawn"] = c->tri_drawn;
    st.counters["fragments"] = c->fragments;
    st.counters["triangles/s"] = Counter(c->tri_drawn, Counter::kIsIterationInvariantRate);
    st.counters["fragments/s"] = Counter(c->fragments, Counter::kIsIterationInvariantRate);
}

// The fastest voxel kernel of the matrix (mode exact, any thread count) on scene s, or nullptr.
static const BenchCase *best_voxel(const BenchPlan &plan, const bench_scene *s)
{
    const BenchCase *best = nullptr;
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_MATRIX) && c->scene == s && c->mode == RETRO_MODE_EXACT && c->W == plan.W &&
            c->H == plan.H && c->D == plan.D && c->ran && c->error.empty() && !std::isnan(c->median_ms) &&
            (!best || c->median_ms < best->median_ms))
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

void mesh_table(std::ostream &o, const BenchPlan &plan)
{
    std::vector<const BenchCase *> cases;
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_MESH) && c->ran)
            cases.push_back(c.get());
    if (cases.empty())
        return;
    o << "\n### Mesh family: the same scenes and poses as triangles (mode binary32, " << plan.W << "×" << plan.H
      << ", D " << plan.D << ", back faces culled)\n\nmedian ms/frame over " << MESH_REPETITIONS << " repetitions of "
      << MESH_ITERATIONS << " frames (" << MESH_QUICK_REPETITIONS << " with --quick, which times the sweep scene "
      << "only). Triangles: submitted (from blocks inside the view), drawn (after back-face culling and "
         "clipping); fragments: covered pixel centres (docs/MESH.md). Rates per second at the median. "
         "\"vs best voxel\": the mesh kernel's time over the fastest voxel kernel's in the mode exact table "
         "on the same scene (kernel and threads named).\n\n"
      << "| scene | kernel | ms/frame | triangles submitted | triangles drawn | fragments | Mtriangles/s | "
         "Mfragments/s | vs best voxel | max cv |\n|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const BenchCase *c : cases) {
        bool ok = c->error.empty() && !std::isnan(c->median_ms);
        double per_s = ok ? 1e3 / c->median_ms : std::nan("");
        const BenchCase *v = best_voxel(plan, c->scene);
        char ratio[96] = "–", cv[32] = "–";
        if (ok && v)
            std::snprintf(ratio, sizeof ratio, "%.0f× `%s`/%dt", c->median_ms / v->median_ms, v->kernel->name,
                          v->threads);
        if (!std::isnan(c->cv))
            std::snprintf(cv, sizeof cv, "%.1f%%", 100 * c->cv);
        o << "| " << c->scene->name << " | `" << c->kernel->name << "` | "
          << report_ms_cell(ok ? c->median_ms : std::nan("")) << " | " << count_cell(c->tri_submitted, 0) << " | "
          << count_cell(c->tri_drawn, 0) << " | " << count_cell(c->fragments, 0) << " | "
          << count_cell(c->tri_drawn * per_s, 1e6) << " | " << count_cell(c->fragments * per_s, 1e6) << " | " << ratio
          << " | " << cv << " |\n";
    }
}
