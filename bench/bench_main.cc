// retro-bench: registers one google-benchmark case per planned (kernel, threads, scene, mode,
// screen, distance), times retro_render() on it, and writes BENCH.md and the charts script.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench_report.h"
#include "busy.h"
#include "cases.h"
#include "extras.h"
extern "C" {
#include "hmax_pyramid.h"
#include "machine_probe.h"
}
#include "mesh_cases.h"
#include "options.h"
#include "peer_cases.h"
#include "pin.h"
#include "progress_reporter.h"
#include "retime.h"
#include "run_context.h"
#include "skip_large.h"
#include "steady.h"

// The case being timed keeps one context and one frame across all its runs (warm-up,
// iteration-count probing, repetitions), so nothing is allocated per frame; moving to the
// next case releases them, so a hundred cases never hold a hundred frames at once.
static struct {
    const BenchCase *owner = nullptr;
    retro_ctx *rc = nullptr;
    retro_render_opts opts = RETRO_RENDER_OPTS_DEFAULT; // what every frame of the case asks for
    std::vector<uint32_t> out;
    std::vector<double> frame_ms; // a frame_median case's frame times, reserved before timing
    retro_err first;             // the result of the case's first, untimed frame
} live;

// The bench thread runs on cores 0 .. n-1 for a case at n threads: a threaded kernel's
// workers inherit that set (the pthreads kernel) or are bound inside it by the kernel (omp
// binds thread t to core t). It is re-bound only when n changes, because the omp kernel
// remembers per thread where it bound it and would not notice being moved.
static int bound_cores = 0;

// Cores the checkpoints' clock and throughput probes visit: all, when the bench thread could be
// pinned (unpinned, "core 1" would be wherever the scheduler put it).
static int probe_cores = 1;

static void bind_for(int threads)
{
    if (threads == bound_cores)
        return;
    char note[160];
    pin_thread_to_cores(0, threads, note, sizeof note);
    bound_cores = threads;
}

// Samples a counting kernel evaluates in one frame of the case (its counters zeroed first);
// NaN when the frame fails.
static double counted_frame(const retro_kernel *k, retro_sample_counts *n, const player_t *p,
                            ctx_t *frame)
{
    std::memset(n, 0, sizeof *n);
    player_t q = *p;
    if (retro_render(live.rc, k, &live.opts, &q, frame))
        return std::nan("");
    return static_cast<double>(n->evaluated);
}

// A sample count as a share (%) of the reference's W x (D-1) samples.
static double share_of(const BenchCase *c, double count)
{
    return 100.0 * count / (c->W * static_cast<double>(c->D > 1 ? c->D - 1 : 1));
}

// Samples the counting build of the case's vector path evaluates in one frame (untimed,
// after the timed ones; hmax_pyramid.h): simd-avx512's for the kernels that run its strips
// (the simd kernels and the threaded ones, per group of 16 columns), ybuffer's for ybuffer;
// NaN for other kernels, modes other than exact, and frames the vector path does not render.
static double count_samples(const BenchCase *c, const player_t *p, ctx_t *frame)
{
    if (c->direct || c->mode != RETRO_MODE_EXACT || (c->groups & GROUP_STEADY))
        return std::nan("");
    const char *name = c->kernel->name;
    retro_kernel k;
    retro_sample_counts *n;
    if (!std::strcmp(name, "ybuffer")) {
        k = *c->kernel;
        k.fn = retro_kernel_ybuffer_counted;
        n = &retro_ybuffer_counts;
    } else if (!std::strncmp(name, "simd-", 5) || (c->kernel->flags & RETRO_KF_THREADED)) {
        const retro_kernel *v = retro_kernel_find("simd-avx512");
        if (!v || !retro_kernel_runs_here(v) || retro_kernel_check(v, c->mode, c->fx, nullptr, 0))
            return std::nan("");
        k = *v;
        k.fn = retro_kernel_simd_avx512_counted;
        n = &retro_simd_counts;
    } else
        return std::nan("");
    return counted_frame(&k, n, p, frame);
}

// Samples the counting ybuffer evaluates with the ideal walk (hmax_pyramid.h,
// retro_skip_ideal; blocks down to the pyramid's finest) and the bound kind (max, or the
// oracle that skips exactly the runs that paint nothing): how far any max bound, and any bound
// at all with those runs, could take skipping on this frame, beside what the kernel evaluates.
// omp's skipping cases only.
static double ideal_samples(const BenchCase *c, const player_t *p, ctx_t *frame, int kind)
{
    if (c->direct || c->mode != RETRO_MODE_EXACT || c->no_skip || std::strcmp(c->kernel->name, "omp") ||
        (c->groups & GROUP_STEADY))
        return std::nan("");
    retro_kernel k = *retro_kernel_find("ybuffer");
    k.fn = retro_kernel_ybuffer_counted;
    retro_skip_ideal = RETRO_PYR_LMIN;
    retro_skip_ideal_kind = kind;
    double n = counted_frame(&k, &retro_ybuffer_counts, p, frame);
    retro_skip_ideal = -1;
    retro_skip_ideal_kind = RETRO_IDEAL_MAX;
    return n;
}

// A frame_median case: each frame timed alone on the steady clock, the repetition's time
// the median of them (FRAME_MEDIAN_COUNTER). The clock reads cost tens of nanoseconds
// against a frame of a fraction of a millisecond; the frame times' storage is reserved
// before the loop, so timing allocates nothing.
static void time_frames(benchmark::State &st, const BenchCase *c, player_t *p, ctx_t *frame)
{
    using clock = std::chrono::steady_clock;
    std::vector<double> &t = live.frame_ms;
    t.clear();
    t.reserve(static_cast<size_t>(st.max_iterations));
    for (auto _ : st) {
        const clock::time_point t0 = clock::now();
        c->direct(p, frame);
        benchmark::ClobberMemory();
        t.push_back(std::chrono::duration<double, std::milli>(clock::now() - t0).count());
    }
    if (t.empty())
        return;
    std::sort(t.begin(), t.end());
    st.counters[FRAME_MEDIAN_COUNTER] = sorted_median(t);
}

static void run_case(benchmark::State &st, const BenchCase *c)
{
    if (!retro_kernel_runs_here(c->kernel)) {
        st.SkipWithError("this CPU (or RETRO_ISA) lacks the instruction set the kernel needs");
        return;
    }
    player_t p = c->scene->pose;
    ctx_t frame = case_frame(c, nullptr);
    if (live.owner != c) {
        retro_ctx_free(live.rc);
        live.rc = retro_ctx_new();
        live.opts = case_opts(c);
        live.out.assign(static_cast<size_t>(c->W) * static_cast<size_t>(c->H), 0);
        live.owner = c;
        bind_for(c->threads);
        // Once per case, untimed: it validates the input and grows the context (and a
        // threaded kernel's pool), so that no timed frame allocates.
        frame.out = live.out.data();
        live.first = !live.rc ? RETRO_ENOMEM
                     : c->direct ? RETRO_OK
                                 : retro_render(live.rc, c->kernel, &live.opts, &p, &frame);
    }
    frame.out = live.out.data();
    if (live.first) {
        st.SkipWithError(retro_strerror(live.first));
        return;
    }
    if (c->direct && c->frame_median)
        time_frames(st, c, &p, &frame);
    else if (c->direct)
        for (auto _ : st) {
            c->direct(&p, &frame);
            benchmark::ClobberMemory();
        }
    else
        for (auto _ : st) {
            retro_render(live.rc, c->kernel, &live.opts, &p, &frame);
            benchmark::ClobberMemory();
        }
    using benchmark::Counter;
    // Timed after the frames: why this checkpoint was slow, if it was. The clock and throughput
    // probes on every core in turn (the thread moved there and back), the memory probe on the
    // first.
    if ((c->groups & GROUP_STEADY) && c->threads == 1) {
        char note[160], name[64];
        for (int core = 0; core < probe_cores; core++) {
            if (core > 0 && pin_thread_to_cores(core, 1, note, sizeof note) != 0)
                break;
            std::snprintf(name, sizeof name, "clock%s, core %d", PROBE_COUNTER, core);
            st.counters[name] = machine_probe_clock_ms();
            std::snprintf(name, sizeof name, "throughput%s, core %d", PROBE_COUNTER, core);
            st.counters[name] = machine_probe_throughput_ms();
        }
        if (probe_cores > 1)
            pin_thread_to_cores(0, 1, note, sizeof note);
        double m = machine_probe_memory_ms();
        if (!std::isnan(m))
            st.counters[std::string("memory") + PROBE_COUNTER] = m;
    }
    double evaluated = count_samples(c, &p, &frame);
    if (!std::isnan(evaluated)) {
        const_cast<BenchCase *>(c)->samples = evaluated;
        st.counters["evaluated/frame"] = evaluated;
        st.counters["evaluated%"] = share_of(c, evaluated);
    }
    double ideal = ideal_samples(c, &p, &frame, RETRO_IDEAL_MAX);
    if (!std::isnan(ideal))
        st.counters["ideal%"] = share_of(c, ideal);
    double oracle = ideal_samples(c, &p, &frame, RETRO_IDEAL_ORACLE);
    if (!std::isnan(oracle))
        st.counters["oracle%"] = share_of(c, oracle);
    // Inverting a per-iteration rate of 1e-3 gives milliseconds per frame, computed on the
    // same clock (CPU or real) as the case's own time.
    const auto ms_flags = Counter::kIsIterationInvariantRate | Counter::kInvert;
    st.counters["ms/frame"] = Counter(1e-3, static_cast<Counter::Flags>(ms_flags));
    st.counters["Mpixel/s"] =
        Counter(c->W * static_cast<double>(c->H) / 1e6, Counter::kIsIterationInvariantRate);
    if (c->groups & GROUP_MESH)
        mesh_counters(&st, c, live.rc);
    else // nominal: the W x (D-1) samples of the reference; kernels that stop early take fewer
        st.counters["samples/s"] = Counter(c->W * static_cast<double>(c->D > 1 ? c->D - 1 : 0),
                                           Counter::kIsIterationInvariantRate);
}

// Cases between two checkpoints of the reference frame (steady.h): the blocks retime.h times
// again, short enough that the machine seldom changes speed within one; 29 checkpoints in a
// full run.
constexpr int STEADY_EVERY = 15;

static void register_case(BenchCase *c, bool quick)
{
    auto *b = benchmark::RegisterBenchmark(c->name.c_str(), run_case, c);
    b->Unit(benchmark::kMillisecond);
    if (c->kernel->flags & RETRO_KF_THREADED)
        b->UseRealTime(); // CPU time is this thread's alone and misses the workers
    if (c->groups & GROUP_MESH)
        b->Iterations(MESH_ITERATIONS)->Repetitions(quick ? MESH_QUICK_REPETITIONS : MESH_REPETITIONS);
    else if (c->repetitions)
        b->Repetitions(c->repetitions);
    if (c->min_time > 0 && !quick)
        b->MinTime(c->min_time);
}

// The reference frame's mean ms over a batch of frames (at least 10, for at least 0.2 s of wall
// clock, as a checkpoint times its repetitions: a batch shorter than the scheduler's time slice
// would miss another program sharing the cores), rendered with the checkpoint case c's kernel,
// frame and threads in a context of its own; NaN if a frame fails.
static double reference_batch(const BenchCase *c, retro_ctx *rc, std::vector<uint32_t> *out)
{
    using clock = std::chrono::steady_clock;
    player_t p = c->scene->pose;
    ctx_t frame = case_frame(c, out->data());
    const retro_render_opts o = case_opts(c);
    const clock::time_point t0 = clock::now();
    double elapsed = 0;
    int n = 0;
    for (; n < 10 || elapsed < 0.2; n++) {
        if (retro_render(rc, c->kernel, &o, &p, &frame) != RETRO_OK)
            return std::nan("");
        elapsed = std::chrono::duration<double>(clock::now() - t0).count();
    }
    return 1e3 * elapsed / n;
}

// The machine's slow spells last from seconds to minutes on a shared VM, and a round started
// inside one is disturbed again. So before a round the reference frame (the checkpoint at the
// most threads, the one that drifts most) is rendered in batches until a batch's mean comes
// within half of NOISY_DRIFT of that checkpoint's fastest timing, for at most `limit` seconds.
// Whether it did; *waited gets the seconds spent. The blocks re-timed after it are judged by
// their own checkpoints as before: the wait only chooses when to start.
static bool wait_for_quiet(const BenchPlan &plan, const Retimer &r, double limit, double *waited)
{
    using clock = std::chrono::steady_clock;
    const clock::time_point t0 = clock::now();
    *waited = 0;
    const BenchCase *ref = nullptr;
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_STEADY) && (!ref || c->threads > ref->threads))
            ref = c.get();
    const double best = ref ? r.fastest(ref->threads) : std::nan("");
    if (std::isnan(best))
        return true; // nothing to compare with: no wait
    retro_ctx *rc = retro_ctx_new();
    if (!rc)
        return true; // nothing to measure with: no wait
    std::vector<uint32_t> out(static_cast<size_t>(ref->W) * static_cast<size_t>(ref->H));
    bind_for(ref->threads);
    bool quiet = false;
    double next_note = 0, now = 0, t = 0;
    for (;;) {
        t = reference_batch(ref, rc, &out);
        now = std::chrono::duration<double>(clock::now() - t0).count();
        if (std::isnan(t) || t <= best * (1 + NOISY_DRIFT / 2)) {
            quiet = !std::isnan(t);
            break;
        }
        if (now >= limit)
            break;
        if (now >= next_note) {
            std::fprintf(stderr, "  waiting for a quiet machine: the reference frame takes %.3f ms, %.0f%% above "
                         "its fastest %.3f ms (%.0f s of at most %.0f s)\n", t, 100 * (t / best - 1), best, now, limit);
            next_note = now + 10;
        }
    }
    retro_ctx_free(rc);
    *waited = now;
    if (quiet)
        std::fprintf(stderr, "  the machine is quiet: the reference frame takes %.3f ms (fastest %.3f ms), after %.0f s\n",
                     t, best, now);
    else
        std::fprintf(stderr, "  the machine stayed slow for %.0f s: the reference frame takes %.3f ms, %.0f%% above "
                     "its fastest %.3f ms\n", now, t, 100 * (t / best - 1), best);
    return quiet;
}

// Rounds of retime.h after the first pass, each timing its disturbed blocks one at a time after
// a wait for a quiet machine, while the re-timing so far and the next block's estimate (its
// share of the cases, of the first pass's duration) fit in --retime-budget first passes. The
// budget bounds a run on a machine slow for good; by default (1) a noisy run at most doubles:
// twice was tried on a VM whose slow spells were shorter than a block, and it tripled the run
// and left it as noisy (docs/COMMANDS.md).
static void retime(const BenchPlan &plan, Retimer *r, ProgressReporter *progress, const Options &opt, bool quick)
{
    const double first = progress->seconds(), budget = opt.retime_budget * first;
    r->set_budget(opt.retime_budget);
    for (int round = 1; round <= opt.retime; round++) {
        std::fprintf(stderr, "looking for disturbed blocks (round %d of %d):\n", round, opt.retime);
        std::vector<int> blocks = r->disturbed(round == 1 ? opt.retime_block : -1);
        if (blocks.empty()) {
            std::fprintf(stderr, "  none\n");
            return;
        }
        r->begin_round();
        for (size_t i = 0; i < blocks.size(); i++) {
            const std::vector<int> one{blocks[i]};
            const double left = budget - (progress->seconds() - first) - r->share(one) * first;
            if (left < 0) {
                std::fprintf(stderr, "  %zu left as they are: the re-timing has taken its %.0f s (%g× the first pass)\n",
                             blocks.size() - i, budget, opt.retime_budget);
                return;
            }
            if (opt.quiet_wait > 0) {
                double waited;
                const bool quiet = wait_for_quiet(plan, *r, std::min(opt.quiet_wait, left), &waited);
                r->waited(waited, quiet);
                if (!quiet) {
                    std::fprintf(stderr, "  %zu left as they are: re-timing them now would be disturbed again\n",
                                 blocks.size() - i);
                    return;
                }
            }
            benchmark::ClearRegisteredBenchmarks();
            std::vector<BenchCase *> cases = r->take(one);
            for (BenchCase *c : cases) {
                progress->forget(c);
                register_case(c, quick);
            }
            std::fprintf(stderr, "re-timing %zu cases (block %d, %zu of %zu this round)\n", cases.size(), blocks[i],
                         i + 1, blocks.size());
            benchmark::RunSpecifiedBenchmarks(progress);
            r->record(one);
        }
    }
    if (opt.retime > 0) {
        std::fprintf(stderr, "looking for disturbed blocks (after the last round):\n");
        if (r->disturbed(-1).empty())
            std::fprintf(stderr, "  none\n");
    }
}

static int load_scenes(bench_scene *scenes, const Options &o, BenchPlan *plan)
{
    const char *shared = std::getenv("RETRO_SHARED");
    int n = o.scene.empty()
                ? scenes_load_default(scenes, SCENES_MAX, shared ? shared : "../shared")
                : (scenes_load_one(&scenes[0], o.scene.c_str()) ? 0 : 1);
    for (int i = 0; i < n; i++) {
        plan->scenes.push_back(&scenes[i]);
        if (!std::strcmp(scenes[i].name, "alpine"))
            plan->sweep_scene = &scenes[i];
    }
    if (!plan->sweep_scene && n)
        plan->sweep_scene = &scenes[0];
    return n;
}

int main(int argc, char **argv)
{
    bool quick = false;
    for (int i = 1; i < argc; i++) {
        if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
            options_usage();
            return 0;
        }
        quick |= !std::strcmp(argv[i], "--quick");
    }
    RunContext ctx;
    std::vector<char *> args;
    std::string json;
    if (!options_benchmark_args(argc, argv, quick, &ctx, &args, &json))
        return 2;
    int n = static_cast<int>(args.size()) - 1;
    benchmark::Initialize(&n, args.data());
    Options opt;
    BenchPlan plan;
    if (!options_parse(n, args.data(), &opt, &plan))
        return 2;

    context_gather(&ctx);
    ctx.quick = quick;
    BusyReport busy = busy_sample(1.0, ctx.cores);
    ctx.busy = busy.busy;
    ctx.machine = busy_sentence(busy);
    if (busy.busy)
        std::fprintf(stderr, "warning: the machine is %s.\nwarning: timings will be noisy; "
                     "BENCH.md and the chart will say so. Rerun on a quiet machine to publish.\n",
                     ctx.machine.c_str());
    else
        std::fprintf(stderr, "%s\n", ctx.machine.c_str());
    char note[160];
    bool pinned = pin_thread_to_cores(0, 1, note, sizeof note) == 0;
    if (!pinned)
        std::fprintf(stderr, "note: %s; timing unpinned\n", note);
    ctx.binding = pinned ? std::string("bench thread on ") + note + " (hwloc)" : note;
    bound_cores = 1;

    static bench_scene scenes[SCENES_MAX];
    int nscenes = load_scenes(scenes, opt, &plan);
    if (nscenes == 0) {
        std::fprintf(stderr, "retro-bench: no scene could be loaded (make maps)\n");
        return 1;
    }
    plan.cores = ctx.cores;
    plan_cases(&plan);
    if (!opt.no_extras && opt.scene.empty())
        plan_extras(&plan);
    plan_peer(&plan);
    plan_skip_large(&plan);
    plan_mesh(&plan, quick);
    plan_steady(&plan, STEADY_EVERY);
    probe_cores = pinned ? ctx.cores : 1;
    if (machine_probe_init() != 0)
        std::fprintf(stderr, "note: no memory for the memory probe; the checkpoints run the clock and throughput probes only\n");
    for (const auto &c : plan.cases)
        register_case(c.get(), quick);

    context_publish(ctx);
    ProgressReporter progress(&plan);
    size_t ran = benchmark::RunSpecifiedBenchmarks(&progress);
    Retimer retimer(&plan);
    if (ran)
        retime(plan, &retimer, &progress, opt, quick);
    retro_ctx_free(live.rc); // its workers, if any, leave the cores to the pairs below
    live.rc = nullptr;
    if (ran) {
        skip_large_in_turn(&plan, bind_for);
        extras_in_turn(&plan, bind_for);
    }
    int status = ran ? 0 : 1;
    // before Shutdown(), which frees the custom context the JSON's header reads
    if (progress.cases_done() > 0 && !json.empty() && !progress.write_json(json))
        status = 1;
    benchmark::Shutdown();
    if (progress.cases_done() > 0) { // none with --benchmark_list_tests
        const int cases = plan_cases_ran(plan);
        std::fprintf(stderr, "%d cases in %.0f s\n", cases, progress.seconds());
        if (!opt.report_dir.empty() && !write_bench_md(opt.report_dir + "/BENCH.md", plan, ctx,
                                                       progress.seconds(), cases, retimer.summary()))
            status = 1;
        if (!opt.charts.empty() && !write_charts_gp(opt.charts, plan, ctx))
            status = 1;
    }
    scenes_free(scenes, nscenes);
    machine_probe_free();
    return status;
}
