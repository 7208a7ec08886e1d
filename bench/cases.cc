// Case planning: the kernel-by-scene matrix in both modes, then the two sweeps.
#include "cases.h"

#include <algorithm>

static bool same(const BenchCase &c, const retro_kernel *k, int threads, const bench_scene *s,
                 retro_mode mode, int w, int h, int d, bool no_skip)
{
    if (c.no_skip != no_skip)
        return false;
    return !c.direct && !c.fx && !(c.groups & (GROUP_SUBMISSION | GROUP_EFFECTS | GROUP_STEADY)) && c.kernel == k &&
           c.threads == threads && c.scene == s && c.mode == mode && c.W == w &&
           c.H == h && c.D == d;
}

const BenchCase *BenchPlan::find(const retro_kernel *k, int threads, const bench_scene *s,
                                 retro_mode mode, int w, int h, int d, bool no_skip) const
{
    for (const auto &c : cases)
        if (same(*c, k, threads, s, mode, w, h, d, no_skip))
            return c.get();
    return nullptr;
}

ctx_t case_frame(const BenchCase *c, uint32_t *out)
{
    const bench_scene *s = c->scene;
    return {c->W, c->H, s->map.size, c->D, 0x66a3ff00u, s->map.height, s->map.color, out};
}

retro_render_opts case_opts(const BenchCase *c)
{
    retro_render_opts o = retro_render_opts_default();
    o.mode = c->mode;
    o.fx = c->fx;
    o.threads = c->threads;
    o.no_skip = c->no_skip;
    return o;
}

std::vector<int> plan_thread_counts(const retro_kernel *k, int cores)
{
    std::vector<int> t{1};
    if (!(k->flags & RETRO_KF_THREADED))
        return t;
    for (int n = 2; n < cores; n *= 2)
        t.push_back(n);
    if (cores > 1)
        t.push_back(cores);
    return t;
}

std::unique_ptr<BenchCase> make_case(const retro_kernel *k, int threads, const bench_scene *s, retro_mode mode, int w,
                                     int h, int d, unsigned group, bool no_skip)
{
    auto c = std::make_unique<BenchCase>();
    c->kernel = k;
    c->kernel_index = static_cast<int>(k - retro_kernels);
    c->threads = threads;
    c->scene = s;
    c->mode = mode;
    c->W = w;
    c->H = h;
    c->D = d;
    c->groups = group;
    c->no_skip = no_skip;
    c->name = std::string(retro_mode_name(mode)) + "/" + s->name + "/" + k->name + "/" +
              std::to_string(threads) + "t/" + std::to_string(w) + "x" + std::to_string(h) +
              "/D" + std::to_string(d) + (no_skip ? "/noskip" : "");
    return c;
}

void plan_add_case(BenchPlan *plan, const retro_kernel *k, int threads, const bench_scene *s,
                   retro_mode mode, int w, int h, int d, unsigned group, bool no_skip)
{
    for (auto &have : plan->cases)
        if (same(*have, k, threads, s, mode, w, h, d, no_skip)) {
            have->groups |= group;
            return;
        }
    plan->cases.push_back(make_case(k, threads, s, mode, w, h, d, group, no_skip));
}

// The case, and with --no-skip its twin without occlusion skipping (mode exact only: the
// mode that skips; naive never does), so both are timed in one run.
static void add(BenchPlan *plan, const retro_kernel *k, int threads, const bench_scene *s,
                retro_mode mode, int w, int h, int d, unsigned group)
{
    plan_add_case(plan, k, threads, s, mode, w, h, d, group, false);
    if (plan->no_skip_twins && mode == RETRO_MODE_EXACT && std::string(k->name) != "naive")
        plan_add_case(plan, k, threads, s, mode, w, h, d, group, true);
}

void plan_cases(BenchPlan *plan)
{
    for (retro_mode mode : plan->modes) {
        for (size_t i = 0; i < retro_kernel_count; i++) {
            const retro_kernel *k = &retro_kernels[i];
            // the matrix's modes are the voxel family's; mesh kernels get their own cases
            if (k->family != &retro_family_voxel || !retro_kernel_has_mode(k, mode))
                continue;
            for (int t : plan_thread_counts(k, plan->cores))
                for (const bench_scene *s : plan->scenes)
                    add(plan, k, t, s, mode, plan->W, plan->H, plan->D, GROUP_MATRIX);
        }
    }
    if (!plan->sweep_scene)
        return;
    // The sweeps compare the fastest kernel with the y-buffer baseline; a threaded best
    // kernel is swept at all cores, the way it would be used.
    std::vector<const retro_kernel *> sweep;
    for (const retro_kernel *k :
         {retro_kernel_find("ybuffer"), retro_kernel_best(RETRO_MODE_EXACT)})
        if (k && std::find(sweep.begin(), sweep.end(), k) == sweep.end())
            sweep.push_back(k);
    std::sort(sweep.begin(), sweep.end());
    for (const retro_kernel *k : sweep) {
        int t = plan_thread_counts(k, plan->cores).back();
        for (auto [w, h] : plan->resolutions)
            add(plan, k, t, plan->sweep_scene, RETRO_MODE_EXACT, w, h, plan->D, GROUP_RESOLUTION);
        for (int d : plan->distances)
            add(plan, k, t, plan->sweep_scene, RETRO_MODE_EXACT, plan->W, plan->H, d,
                GROUP_DISTANCE);
    }
}
