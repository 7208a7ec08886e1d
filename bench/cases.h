// The benchmark's cases: every (kernel, threads, scene, mode, screen, distance) it times,
// planned from the one kernel table so new kernels appear without editing the bench.
#ifndef RETRO_BENCH_CASES_H
#define RETRO_BENCH_CASES_H

#include <cmath>
#include <limits>
#include <memory>
#include <map>
#include <string>
#include <vector>

#include "retro.h"
#include "retro_scene.h"
#include "scenes.h"

// Which tables of BENCH.md show a case; the sweeps share their 640x480, D 800 point with the
// kernel-by-scene table, so one case can belong to several.
enum : unsigned {
    GROUP_MATRIX = 1u << 0,
    GROUP_RESOLUTION = 1u << 1,
    GROUP_DISTANCE = 1u << 2,
    GROUP_SUBMISSION = 1u << 3, // extras.cc: the course painter and the submission
    GROUP_EFFECTS = 1u << 4,    // extras.cc: what each effect costs
    GROUP_PEER = 1u << 5,       // peer_cases.cc: the classic demo's algorithm, not a kernel
    GROUP_MESH = 1u << 6,       // mesh_cases.cc: the mesh family's kernels, mode binary32
    GROUP_MESH_SWEEP = 1u << 7, // mesh_cases.cc: the mesh kernels swept over resolution, distance
    GROUP_SKIP_LARGE = 1u << 8, // skip_large.cc: omp with and without skipping at a large frame
    GROUP_STEADY = 1u << 9,     // steady.cc: the reference frame at checkpoints through the run
};

// The median of times sorted in increasing order (not empty).
inline double sorted_median(const std::vector<double> &t)
{
    const size_t n = t.size();
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

// The counter that carries a frame_median case's time per repetition, in ms.
constexpr const char *FRAME_MEDIAN_COUNTER = "frame median ms";
// The checkpoints' machine probes (machine_probe.h), ms, in bench.json beside the frame's time:
// counters named "KIND probe ms" (memory) or "KIND probe ms, core N" (clock, throughput).
constexpr const char *PROBE_COUNTER = " probe ms";

struct BenchCase {
    const retro_kernel *kernel;
    int kernel_index;            // row of retro_kernels[], for stable ordering
    int threads;                 // retro_render_opts.threads; 1 for kernels without RETRO_KF_THREADED
    const bench_scene *scene;
    retro_mode mode;
    int W, H, D;
    bool no_skip = false;        // retro_render_opts.no_skip: occlusion skipping off (--no-skip twins)
    unsigned groups;             // GROUP_* bits
    std::string name;            // mode/scene/kernel/threads/WxH/D: the benchmark's name
    // Extras (extras.cc), never matched as matrix cases: a course-style render() called
    // directly instead of a kernel, or the effects the frame simulates.
    void (*direct)(const player_t *, ctx_t *) = nullptr;
    const retro_effects *fx = nullptr;
    std::string label;           // the row's name in its extra table
    int repetitions = 0;         // its own repetition count; 0: the run's --benchmark_repetitions
    double min_time = 0;         // its own least seconds per repetition (not with --quick); 0: the run's
    // A repetition's time is the median of its frames' times, not their mean (the submission:
    // its spread across runs is a target, and the mean of a run follows any burst of the
    // machine's other work). Every frame is then timed alone (bench_main.cc).
    bool frame_median = false;
    int checkpoint = -1;         // GROUP_STEADY: which checkpoint of the run (steady.h)

    // Filled by the reporter once the case has run.
    bool ran = false;
    double median_ms = std::numeric_limits<double>::quiet_NaN(); // median ms/frame
    double samples = std::numeric_limits<double>::quiet_NaN();   // evaluated per frame (counted)
    double cv = std::numeric_limits<double>::quiet_NaN();        // spread over repetitions
    int reps = 0;                // repetitions that ran, and their least and greatest ms/frame
    double rep_min = std::numeric_limits<double>::quiet_NaN();
    double rep_max = std::numeric_limits<double>::quiet_NaN();
    std::string error;           // non-empty when the case was skipped
    double done_at = std::numeric_limits<double>::quiet_NaN(); // seconds into the run when it finished
    // GROUP_STEADY at one thread: the medians of machine_probe.h's probes over its repetitions,
    // by counter name.
    std::map<std::string, double> probes;
    // The median and quartiles of the ratios of this case's frames to another's, timed in turn
    // after the run (in_turn.h): the large-frame table's twins without skipping (skip_large.h),
    // the effect table's fastest kernel for each effect set against none (extras.h).
    double in_turn = std::numeric_limits<double>::quiet_NaN();
    double in_turn_q1 = std::numeric_limits<double>::quiet_NaN();
    double in_turn_q3 = std::numeric_limits<double>::quiet_NaN();
    // Mesh cases: the frame's counts (retro_mesh_stats), the same every frame of the case.
    mutable double tri_submitted = std::numeric_limits<double>::quiet_NaN();
    mutable double tri_drawn = std::numeric_limits<double>::quiet_NaN(); // after culling and clipping
    mutable double fragments = std::numeric_limits<double>::quiet_NaN();
};

struct BenchPlan {
    std::vector<std::unique_ptr<BenchCase>> cases;
    std::vector<retro_mode> modes;                  // the matrix modes, in table order
    std::vector<const bench_scene *> scenes;        // the matrix columns
    const bench_scene *sweep_scene = nullptr;       // the scene both sweeps render
    std::vector<std::pair<int, int>> resolutions;   // resolution sweep, D = matrix D
    std::vector<int> distances;                     // distance sweep, screen = matrix screen
    int W = 640, H = 480, D = 800;                  // the matrix frame
    int cores = 1;
    bool no_skip_twins = false;                     // --no-skip: every mode exact case twice

    // The case with exactly these parameters, or nullptr.
    const BenchCase *find(const retro_kernel *k, int threads, const bench_scene *s,
                          retro_mode mode, int W, int H, int D, bool no_skip = false) const;
};

// Whether the case ran and has a median (not skipped); c may be null.
inline bool case_timed(const BenchCase *c)
{
    return c && c->ran && c->error.empty() && !std::isnan(c->median_ms);
}

// How many of the plan's cases ran (skipped ones included).
inline int plan_cases_ran(const BenchPlan &plan)
{
    int n = 0;
    for (const auto &c : plan.cases)
        n += c->ran;
    return n;
}

// The frame a case renders (its pose is c->scene->pose) into out, and what it asks for.
ctx_t case_frame(const BenchCase *c, uint32_t *out);
retro_render_opts case_opts(const BenchCase *c);

// Thread counts a kernel is timed at: 1 unless threaded, else 1, 2, 4 ... and cores.
std::vector<int> plan_thread_counts(const retro_kernel *k, int cores);

// Fills plan->cases from the kernel table, the modes, scenes and sweep lists already in plan.
void plan_cases(BenchPlan *plan);

// A kernel case of group, named mode/scene/kernel/threads/WxH/D[/noskip], not yet in any plan.
std::unique_ptr<BenchCase> make_case(const retro_kernel *k, int threads, const bench_scene *s, retro_mode mode, int w,
                                     int h, int d, unsigned group, bool no_skip);

// Adds one kernel case to group (the case itself when planned already: it joins group).
void plan_add_case(BenchPlan *plan, const retro_kernel *k, int threads, const bench_scene *s, retro_mode mode,
                   int W, int H, int D, unsigned group, bool no_skip);

#endif
