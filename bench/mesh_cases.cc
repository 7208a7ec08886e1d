// Planning, counting and reporting the mesh cases (see mesh_cases.h).
#include "mesh_cases.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "retro_mesh.h"

// Front faces only, as a terrain renderer draws a heightfield (docs/MESH.md, "In the kernel table").
static retro_effects cull_fx;

// The mesh case with these parameters, made once; group is added to its groups.
static void mesh_case(BenchPlan *plan, const retro_kernel *k, int threads, const bench_scene *s, int w, int h, int d,
                      unsigned group)
{
    for (auto &c : plan->cases)
        if ((c->groups & GROUP_MESH) && c->kernel == k && c->threads == threads && c->scene == s && c->W == w &&
            c->H == h && c->D == d) {
            c->groups |= group;
            return;
        }
    const int mode = RETRO_MESH_BINARY32;
    auto c = std::make_unique<BenchCase>();
    c->kernel = k;
    c->kernel_index = static_cast<int>(k - retro_kernels);
    c->threads = threads;
    c->scene = s;
    c->mode = static_cast<retro_mode>(mode);
    c->W = w;
    c->H = h;
    c->D = d;
    c->groups = GROUP_MESH | group;
    c->fx = &cull_fx;
    c->label = k->name;
    c->name = std::string(retro_family_mode_name(&retro_family_mesh, mode)) + "/" + s->name + "/" + k->name + "/" +
              std::to_string(threads) + "t/" + std::to_string(w) + "x" + std::to_string(h) + "/D" + std::to_string(d);
    plan->cases.push_back(std::move(c));
}

static bool mesh_b32(const retro_kernel *k)
{
    return k->family == &retro_family_mesh && (k->modes & RETRO_MODE_BIT(RETRO_MESH_BINARY32));
}

// The fastest single-threaded mesh kernel this CPU runs: the last such row (slowest first).
static const retro_kernel *best_single_mesh()
{
    const retro_kernel *best = nullptr;
    for (size_t i = 0; i < retro_kernel_count; i++)
        if (mesh_b32(&retro_kernels[i]) && !(retro_kernels[i].flags & RETRO_KF_THREADED) &&
            retro_kernel_runs_here(&retro_kernels[i]))
            best = &retro_kernels[i];
    return best;
}

void plan_mesh(BenchPlan *plan, bool quick)
{
    retro_effects_defaults(&cull_fx);
    cull_fx.flags = RETRO_FX_CULL;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (!mesh_b32(k))
            continue;
        for (int t : plan_thread_counts(k, plan->cores))
            for (const bench_scene *s : plan->scenes)
                if (!quick || s == plan->sweep_scene)
                    mesh_case(plan, k, t, s, plan->W, plan->H, plan->D, 0);
    }
    // The sweeps: the best single-threaded mesh kernel, and the threaded one at all cores.
    if (!plan->sweep_scene)
        return;
    std::vector<std::pair<const retro_kernel *, int>> sweep;
    if (const retro_kernel *k = best_single_mesh())
        sweep.push_back({k, 1});
    for (size_t i = 0; i < retro_kernel_count; i++)
        if (mesh_b32(&retro_kernels[i]) && (retro_kernels[i].flags & RETRO_KF_THREADED))
            sweep.push_back({&retro_kernels[i], plan_thread_counts(&retro_kernels[i], plan->cores).back()});
    for (auto [k, t] : sweep) {
        for (auto [w, h] : plan->resolutions)
            mesh_case(plan, k, t, plan->sweep_scene, w, h, plan->D, GROUP_MESH_SWEEP);
        for (int d : plan->distances)
            mesh_case(plan, k, t, plan->sweep_scene, plan->W, plan->H, d, GROUP_MESH_SWEEP);
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
