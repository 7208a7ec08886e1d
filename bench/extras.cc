// The submission and effect tables of BENCH.md.
#include "extras.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_report.h"
#include "in_turn.h"

extern "C" {
// bench/course_painter.c, built with the course's -O3: the baseline of the submission target.
void painter_render(const player_t *p, ctx_t *c);
// results/submission/render.c, built alone with the course's -O3, its render() renamed.
void submission_render(const player_t *p, ctx_t *c);
// src/voxel/kernel_ybuffer.c built again with RETRO_NO_EFFECTS: the same kernel, no effect code.
void retro_kernel_ybuffer_noeffects(const void *frame, retro_ctx *rc);
}

static const unsigned COURSE = RETRO_MODE_BIT(RETRO_MODE_COURSE);
static const retro_kernel painter_row = {"course painter (-O3)", nullptr, 0, COURSE, 0, "", nullptr, 0,
                                         &retro_family_voxel};
static const retro_kernel submission_row = {"submission (-O3)", nullptr, 0, COURSE, RETRO_KF_THREADED, "",
                                            nullptr, 0, &retro_family_voxel};
static const retro_kernel noeffects_row = {"ybuffer, effect code compiled out", retro_kernel_ybuffer_noeffects, 0,
                                           RETRO_MODE_BIT(RETRO_MODE_EXACT), RETRO_KF_WRITE_ONCE, "", nullptr, 0,
                                           &retro_family_voxel};

// The effect sets timed, each alone and the default scenes' combinations.
struct EffectSet {
    const char *label;
    unsigned flags;
};
static const EffectSet effect_sets[] = {
    {"none", 0},
    {"fog", RETRO_FX_FOG},
    {"shade", RETRO_FX_SHADE},
    {"water", RETRO_FX_WATER},
    {"bilinear", RETRO_FX_BILINEAR},
    {"lod", RETRO_FX_LOD},
    {"horizon", RETRO_FX_HORIZON},
    {"morph", RETRO_FX_MORPH},
    {"water + fog (islands.scene)", RETRO_FX_WATER | RETRO_FX_FOG},
    {"all seven", RETRO_FX_VOXEL},
};
static const int n_sets = sizeof effect_sets / sizeof effect_sets[0];
static retro_effects effects[n_sets];
static std::vector<uint8_t> morph_heights;

static BenchCase *add(BenchPlan *plan, const retro_kernel *k, int threads, const bench_scene *s,
                      retro_mode mode, unsigned group, const std::string &label)
{
    auto c = std::make_unique<BenchCase>();
    c->kernel = k;
    c->kernel_index = -1;
    c->threads = threads;
    c->scene = s;
    c->mode = mode;
    c->W = plan->W;
    c->H = plan->H;
    c->D = plan->D;
    c->groups = group;
    c->label = label;
    c->name = std::string(group == GROUP_SUBMISSION ? "submission/" : "effects/") + s->name + "/" + label +
              "/" + k->name + "/" + std::to_string(threads) + "t";
    for (char &ch : c->name)
        ch = ch == ' ' ? '_' : ch;
    plan->cases.push_back(std::move(c));
    return plan->cases.back().get();
}

void plan_extras(BenchPlan *plan)
{
    for (const bench_scene *s : plan->scenes)
        if (!std::strcmp(s->origin, "course")) {
            add(plan, &painter_row, 1, s, RETRO_MODE_COURSE, GROUP_SUBMISSION, "painter")->direct = painter_render;
            BenchCase *sub = add(plan, &submission_row, plan->cores, s, RETRO_MODE_COURSE, GROUP_SUBMISSION, "submission");
            sub->direct = submission_render;
            sub->repetitions = SUBMISSION_RUNS;
            sub->min_time = SUBMISSION_RUN_SECONDS;
            sub->frame_median = true;
        }
    const bench_scene *islands = nullptr;
    for (const bench_scene *s : plan->scenes)
        if (!std::strcmp(s->name, "islands"))
            islands = s;
    if (!islands)
        return;
    // Morph blends toward the inverted heights: a keyframe as different as a map can be.
    morph_heights.resize(static_cast<size_t>(islands->map.size) * islands->map.size);
    for (size_t i = 0; i < morph_heights.size(); i++)
        morph_heights[i] = static_cast<uint8_t>(255 - islands->map.height[i]);
    for (int i = 0; i < n_sets; i++) {
        retro_effects_defaults(&effects[i]);
        effects[i].flags = effect_sets[i].flags;
        effects[i].morph_height = morph_heights.data();
        effects[i].morph_t = 0.5f;
        const retro_kernel *best = retro_kernel_best_fx(RETRO_MODE_EXACT, &effects[i]);
        const retro_kernel *yb = retro_kernel_find("ybuffer");
        for (const retro_kernel *k : {yb, best}) {
            int t = (k->flags & RETRO_KF_THREADED) ? plan->cores : 1;
            add(plan, k, t, islands, RETRO_MODE_EXACT, GROUP_EFFECTS, effect_sets[i].label)->fx = &effects[i];
        }
    }
    add(plan, &noeffects_row, 1, islands, RETRO_MODE_EXACT, GROUP_EFFECTS, "none");
}

static const BenchCase *find(const BenchPlan &plan, unsigned group, const bench_scene *s, const char *label,
                             const retro_kernel *k)
{
    for (const auto &c : plan.cases)
        if ((c->groups & group) && c->scene == s && c->label == label && c->kernel == k)
            return c.get();
    return nullptr;
}

static std::string pct(double frac)
{
    char b[32];
    std::snprintf(b, sizeof b, "%+.1f%%", 100 * frac);
    return b;
}

static double ms_of(const BenchCase *c)
{
    return c && c->ran && c->error.empty() ? c->median_ms : std::nan("");
}

static void submission_table(std::ostream &o, const BenchPlan &plan)
{
    const retro_kernel *best = retro_kernel_best(RETRO_MODE_COURSE);
    bool any = false;
    for (const bench_scene *s : plan.scenes) {
        const BenchCase *painter = find(plan, GROUP_SUBMISSION, s, "painter", &painter_row);
        if (!painter)
            continue;
        if (!any) {
            o << "\n### The course submission (mode course, " << plan.W << "×" << plan.H << ", D " << plan.D
              << ")\n\nmedian ms/frame; `make submission`'s render.c and the plain course painter both built "
                 "alone with the course's `-O3`, the others with the suite's flags. Spread: the submission's "
                 "(max − min) / median over its runs (repetitions in this process, each the median ms of "
                 "its frames over at least " << SUBMISSION_RUN_SECONDS << " s, or over the run's repetition time "
                 "with --quick; the submission's time is the median of those); issue 18's target is at most 15% across " << SUBMISSION_RUNS << " runs.\n\n"
              << "| scene | course painter (-O3) | naive | " << best->name << ", " << plan.cores
              << " threads | submission (-O3) | submission vs painter | submission spread | runs |\n"
                 "|---|--:|--:|--:|--:|--:|--:|--:|\n";
            any = true;
        }
        const BenchCase *sub = find(plan, GROUP_SUBMISSION, s, "submission", &submission_row);
        const BenchCase *naive = plan.find(retro_kernel_find("naive"), 1, s, RETRO_MODE_COURSE, plan.W, plan.H, plan.D);
        const BenchCase *fast = plan.find(best, plan.cores, s, RETRO_MODE_COURSE, plan.W, plan.H, plan.D);
        double p = ms_of(painter), q = ms_of(sub);
        char ratio[32] = "–";
        if (!std::isnan(p) && !std::isnan(q))
            std::snprintf(ratio, sizeof ratio, "%.1f×", p / q);
        char spread[32] = "–";
        if (!std::isnan(q) && sub->reps > 1)
            std::snprintf(spread, sizeof spread, "%.1f%%", 100 * (sub->rep_max - sub->rep_min) / q);
        o << "| " << s->name << " | " << report_ms_cell(p) << " | " << report_ms_cell(ms_of(naive)) << " | " << report_ms_cell(ms_of(fast)) << " | "
          << report_ms_cell(q) << " | " << ratio << " | " << spread << " | " << (std::isnan(q) ? 0 : sub->reps) << " |\n";
    }
}

// The scene of the effect cases, or nullptr when none was planned.
static const bench_scene *effects_scene(const BenchPlan &plan)
{
    const bench_scene *s = nullptr;
    for (const auto &c : plan.cases)
        if (c->groups & GROUP_EFFECTS)
            s = c->scene;
    return s;
}

void extras_in_turn(BenchPlan *plan, void (*bind)(int threads))
{
    const bench_scene *s = effects_scene(*plan);
    if (!s)
        return;
    const BenchCase *none = find(*plan, GROUP_EFFECTS, s, "none", retro_kernel_best_fx(RETRO_MODE_EXACT, &effects[0]));
    if (!case_timed(none))
        return;
    int n = 0;
    for (int i = 1; i < n_sets; i++) {
        const retro_kernel *best = retro_kernel_best_fx(RETRO_MODE_EXACT, &effects[i]);
        auto *c = const_cast<BenchCase *>(find(*plan, GROUP_EFFECTS, s, effect_sets[i].label, best));
        n += case_timed(c) && in_turn(none, c, EFFECT_PAIRS, bind);
    }
    std::fprintf(stderr, "  effects on %s: %d sets timed in turn against none, %d pairs each\n", s->name, n,
                 EFFECT_PAIRS);
}

static void effects_table(std::ostream &o, const BenchPlan &plan)
{
    const bench_scene *s = effects_scene(plan);
    if (!s)
        return;
    const retro_kernel *yb = retro_kernel_find("ybuffer");
    double yb_none = ms_of(find(plan, GROUP_EFFECTS, s, "none", yb));
    o << "\n### What each effect costs (mode exact, " << s->name << ", " << plan.W << "×" << plan.H << ", D "
      << plan.D << ")\n\nmedian ms/frame; cost: ybuffer against itself with no effect, and the fastest "
         "kernel for the effects against the fastest with none (×); in turn: the same, from "
      << EFFECT_PAIRS
      << " pairs of the two frames timed one after the other after the run, the median of the per-pair "
         "ratios (quartiles in brackets), which a change in the machine's speed moves less. Baked effects "
         "(shade, water, morph) are paid once per change of their inputs, not per frame.\n\n"
      << "| effects | ybuffer | cost | fastest kernel for them | ms | cost | in turn |\n"
         "|---|--:|--:|---|--:|--:|--:|\n";
    double best_none = std::nan("");
    for (int i = 0; i < n_sets; i++) {
        const retro_kernel *best = retro_kernel_best_fx(RETRO_MODE_EXACT, &effects[i]);
        const BenchCase *b = find(plan, GROUP_EFFECTS, s, effect_sets[i].label, best);
        double y = ms_of(find(plan, GROUP_EFFECTS, s, effect_sets[i].label, yb)), m = ms_of(b);
        if (i == 0)
            best_none = m;
        // Relative to no effects: ybuffer against itself; the fastest kernel for the effects
        // against the fastest for none, which per-sample effects can make a slower kernel.
        char c1[32] = "–", c2[32] = "–", c3[64] = "–";
        if (i && b && !std::isnan(b->in_turn))
            std::snprintf(c3, sizeof c3, "%.2f× (%.2f–%.2f)", b->in_turn, b->in_turn_q1, b->in_turn_q3);
        if (i && !std::isnan(y))
            std::snprintf(c1, sizeof c1, "%+.0f%%", 100 * (y / yb_none - 1));
        if (i && !std::isnan(m))
            std::snprintf(c2, sizeof c2, "%.2f×", m / best_none);
        std::string who = std::string(best->name) + (b && (best->flags & RETRO_KF_THREADED) ? ", " +
                          std::to_string(b->threads) + " threads" : "");
        o << "| " << effect_sets[i].label << " | " << report_ms_cell(y) << " | " << c1 << " | " << who << " | " << report_ms_cell(m)
          << " | " << c2 << " | " << c3 << " |\n";
    }
    double off = ms_of(find(plan, GROUP_EFFECTS, s, "none", &noeffects_row));
    if (!std::isnan(off) && !std::isnan(yb_none))
        o << "\nEffects not called for cost nothing: ybuffer renders the plain frame in " << report_ms_cell(yb_none)
          << " ms with its effect code compiled in and " << report_ms_cell(off) << " ms with it compiled out ("
          << pct(yb_none / off - 1) << ").\n";
}

void extras_tables(std::ostream &o, const BenchPlan &plan)
{
    submission_table(o, plan);
    effects_table(o, plan);
}
