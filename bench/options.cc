// Command line: our options and the defaults handed to google-benchmark.
#include "options.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "retro.h"
#include "retro_scene.h"
extern "C" {
#include "cli.h" // the retro CLI's strict parsers, so both programs refuse the same values
}

// An int option's value: the whole string a number in [lo, hi] (cli_int's grammar).
static bool int_value(const std::string &v, long lo, long hi, int *out)
{
    long x;
    if (cli_int(v.c_str(), lo, hi, &x))
        return false;
    *out = static_cast<int>(x);
    return true;
}

void options_usage()
{
    std::printf(
        "usage: retro-bench [--quick] [--report=DIR] [--charts=FILE] [--scene=PREFIX]\n"
        "                   [--size=WxH] [--distance=D] [--modes=LIST] [--no-skip]\n"
        "                   [--benchmark_...]\n\n"
        "  --quick         3 repetitions of 0.01 s, no warm-up beyond each case's first\n"
        "                  frame, 3 points per sweep (make bench QUICK=1)\n"
        "  --report=DIR    write DIR/BENCH.md from the run\n"
        "  --charts=FILE   write the run's charts as a gnuplot script\n"
        "  --scene=PREFIX  only this map, at its default view (e.g. maps/test/flat-64); no extras\n"
        "  --no-extras     leave out the course-submission and effect-cost tables\n"
        "  --size=WxH      screen of the kernel-by-scene cases (default 640x480; each side\n"
        "                  1..16384, at most 2^26 pixels, as retro render takes)\n"
        "  --distance=D    distance of the kernel-by-scene cases (default 800; 1..4194304)\n"
        "  --modes=LIST    only these modes, e.g. exact,course (default: every mode)\n"
        "  --no-skip       time every mode exact case also with occlusion skipping off\n"
        "                  (docs/SKIPPING.md), as a twin named .../noskip\n"
        "  --retime=N      up to N rounds timing again the blocks of cases a slow checkpoint or\n"
        "                  a spread case shows disturbed (default 3; 0 with --quick), one block\n"
        "                  at a time, within the first pass's duration\n"
        "  --retime-budget=X  the re-timing, waits included, may take X times the first pass\n"
        "                  (default 1; 0.1..20): more for a machine quiet only in short spells\n"
        "  --retime-block=I  the first round re-times block I alone, whatever the timings (a test)\n"
        "  --quiet-wait=S  before each such block, wait up to S seconds (within the same budget)\n"
        "                  for the reference frame to run within 5%% of its fastest checkpoint; a\n"
        "                  machine still slow then ends the re-timing (default 120; 0 with --quick:\n"
        "                  no wait)\n"
        "\n"
        "Scenes: maps/{alpine,islands,canyon} at their default view and\n"
        "$RETRO_SHARED/course/{valley,island,pyramids} (default ../shared) at the course poses.\n"
        "With mode exact, omp at all cores is also timed at 1920x1080, D 4000 on every scene with\n"
        "and without skipping (BENCH.md: occlusion skipping at a large frame); the submission runs\n"
        "10 repetitions whatever --benchmark_repetitions says, for its spread.\n"
        "Every --benchmark_* flag of google-benchmark works; given flags override the\n"
        "defaults --benchmark_repetitions=5 --benchmark_min_time=0.05\n"
        "--benchmark_min_warmup_time=0.05 (quick: 3, 0.01, 0). --benchmark_out=FILE\n"
        "writes the JSON of each case's last timing at the end (json is the only format).\n");
}

// The last value given for --NAME=, or def.
static std::string flag_value(const std::vector<char *> &args, const char *name, const char *def)
{
    std::string key = std::string("--") + name + "=", v = def;
    for (const char *a : args)
        if (a && std::strncmp(a, key.c_str(), key.size()) == 0)
            v = a + key.size();
    return v;
}

bool options_benchmark_args(int argc, char **argv, bool quick, RunContext *ctx, std::vector<char *> *out,
                            std::string *json)
{
    // Warm-up is the global flag: this google-benchmark (1.7) ignores ->MinWarmUpTime()
    // unless ->MinTime() is set too, which would in turn override --benchmark_min_time.
    // Quick runs rely on the untimed first frame of each case alone.
    static char reps[] = "--benchmark_repetitions=5", qreps[] = "--benchmark_repetitions=3";
    static char mt[] = "--benchmark_min_time=0.05", qmt[] = "--benchmark_min_time=0.01";
    static char wu[] = "--benchmark_min_warmup_time=0.05";
    static char qwu[] = "--benchmark_min_warmup_time=0";
    std::vector<char *> args{argv[0], quick ? qreps : reps, quick ? qmt : mt, quick ? qwu : wu};
    static const char out_key[] = "--benchmark_out=", format_key[] = "--benchmark_out_format=";
    std::string format = "json";
    for (int i = 1; i < argc; i++)
        if (!std::strncmp(argv[i], out_key, sizeof out_key - 1))
            *json = argv[i] + sizeof out_key - 1;
        else if (!std::strncmp(argv[i], format_key, sizeof format_key - 1))
            format = argv[i] + sizeof format_key - 1;
        else
            args.push_back(argv[i]);
    if (format != "json") {
        std::fprintf(stderr, "retro-bench: --benchmark_out_format=%s: only json is written\n", format.c_str());
        return false;
    }
    ctx->repetitions = std::atoi(flag_value(args, "benchmark_repetitions", "1").c_str());
    ctx->min_time = flag_value(args, "benchmark_min_time", "");
    ctx->warmup = flag_value(args, "benchmark_min_warmup_time", "");
    ctx->filter = flag_value(args, "benchmark_filter", "");
    args.push_back(nullptr);
    *out = args;
    return true;
}

// Every mode of the API unless --modes names some, so new modes are timed unasked.
static bool parse_modes(const std::string &list, std::vector<retro_mode> *modes)
{
    for (int m = 0; list.empty() && m < RETRO_MODE_COUNT; m++)
        modes->push_back(static_cast<retro_mode>(m));
    for (size_t at = 0; !list.empty() && at <= list.size();) {
        size_t end = std::min(list.find(',', at), list.size());
        retro_mode m;
        if (retro_mode_parse(list.substr(at, end - at).c_str(), &m)) {
            std::string all;
            for (int i = 0; i < RETRO_MODE_COUNT; i++)
                all += std::string(i ? ", " : "") + retro_mode_name(static_cast<retro_mode>(i));
            std::fprintf(stderr, "retro-bench: bad --modes '%s' (%s)\n", list.c_str(), all.c_str());
            return false;
        }
        modes->push_back(m);
        at = end + 1;
    }
    return true;
}

static bool option(const std::string &a, const char *key, std::string *v)
{
    size_t n = std::strlen(key);
    if (a.compare(0, n, key) != 0)
        return false;
    *v = a.substr(n);
    return true;
}

bool options_parse(int n, char **args, Options *o, BenchPlan *plan)
{
    std::string modes;
    for (int i = 1; i < n; i++) {
        std::string a = args[i], v;
        bool ok = option(a, "--report=", &o->report_dir) || option(a, "--charts=", &o->charts) ||
                  option(a, "--scene=", &o->scene) || option(a, "--modes=", &modes);
        if (a == "--quick")
            ok = o->quick = true;
        else if (a == "--no-extras")
            ok = o->no_extras = true;
        else if (a == "--no-skip")
            ok = plan->no_skip_twins = true;
        else if (!ok && option(a, "--size=", &v)) // the limits retro render takes
            ok = !cli_size(v.c_str(), &plan->W, &plan->H) && plan->W <= RETRO_MAX_SCREEN &&
                 plan->H <= RETRO_MAX_SCREEN && static_cast<long>(plan->W) * plan->H <= RETRO_MAX_PIXELS;
        else if (!ok && option(a, "--distance=", &v))
            ok = int_value(v, RETRO_MIN_DISTANCE, RETRO_MAX_DISTANCE, &plan->D);
        else if (!ok && option(a, "--retime=", &v))
            ok = int_value(v, 0, 1000, &o->retime);
        else if (!ok && option(a, "--retime-block=", &v))
            ok = int_value(v, 0, 1000000, &o->retime_block);
        else if (!ok && option(a, "--quiet-wait=", &v)) {
            float w;
            ok = !cli_float(v.c_str(), &w) && w >= 0 && w <= 86400;
            o->quiet_wait = w;
        } else if (!ok && option(a, "--retime-budget=", &v)) {
            float x;
            ok = !cli_float(v.c_str(), &x) && x >= 0.1f && x <= 20;
            o->retime_budget = x;
        }
        if (!ok) {
            std::fprintf(stderr, "retro-bench: unknown or bad argument '%s' (--help)\n", args[i]);
            return false;
        }
    }
    if (o->retime < 0)
        o->retime = o->quick ? 0 : 3;
    if (o->quiet_wait < 0)
        o->quiet_wait = o->quick ? 0 : 120;
    if (o->quick) {
        plan->resolutions = {{320, 240}, {640, 480}, {1920, 1080}};
        plan->distances = {100, 800, 3000};
    } else {
        plan->resolutions = {{320, 240}, {640, 480}, {1280, 720}, {1920, 1080}};
        plan->distances = {100, 200, 400, 800, 1600, 3000};
    }
    return parse_modes(modes, &plan->modes);
}
