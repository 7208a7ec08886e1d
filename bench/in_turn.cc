// Ratios timed in turn (in_turn.h).
#include "in_turn.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace {

// One case's frame, with the context and image it renders into.
struct Side {
    const BenchCase *c;
    retro_ctx *rc = nullptr;
    std::vector<uint32_t> out;
    retro_render_opts o;

    explicit Side(const BenchCase *cs)
        : c(cs), rc(retro_ctx_new()), out(static_cast<size_t>(cs->W) * static_cast<size_t>(cs->H)), o(case_opts(cs))
    {
    }
    ~Side() { retro_ctx_free(rc); }
    Side(const Side &) = delete;
    Side &operator=(const Side &) = delete;

    bool frame()
    {
        player_t p = c->scene->pose;
        ctx_t f = case_frame(c, out.data());
        return retro_render(rc, c->kernel, &o, &p, &f) == RETRO_OK;
    }

    // ms of one frame (after an untimed one when settle); NaN if a frame fails.
    double timed(bool settle)
    {
        using clock = std::chrono::steady_clock;
        if (settle && !frame())
            return std::nan("");
        const clock::time_point t0 = clock::now();
        if (!frame())
            return std::nan("");
        return std::chrono::duration<double, std::milli>(clock::now() - t0).count();
    }
};

} // namespace

bool in_turn(const BenchCase *a, BenchCase *b, int pairs, void (*bind)(int threads))
{
    if (a->direct || b->direct || pairs < 1 || retro_kernels_two_pools(a->kernel, a->threads, b->kernel, b->threads))
        return false;
    bind(std::max(a->threads, b->threads));
    Side sa(a), sb(b);
    if (!sa.rc || !sb.rc || !sa.frame() || !sb.frame())
        return false;
    const bool settle = a->kernel != b->kernel;
    std::vector<double> ratio;
    for (int i = 0; i < pairs; i++) {
        double ta, tb;
        if (i % 2) { // every other pair the other way round: neither always goes first
            tb = sb.timed(settle);
            ta = sa.timed(settle);
        } else {
            ta = sa.timed(settle);
            tb = sb.timed(settle);
        }
        if (std::isnan(ta) || std::isnan(tb))
            return false;
        ratio.push_back(tb / ta);
    }
    std::sort(ratio.begin(), ratio.end());
    const size_t n = ratio.size();
    b->in_turn = n % 2 ? ratio[n / 2] : 0.5 * (ratio[n / 2 - 1] + ratio[n / 2]);
    b->in_turn_q1 = ratio[n / 4];
    b->in_turn_q3 = ratio[3 * n / 4];
    return true;
}
