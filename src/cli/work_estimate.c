/* Bounded work: a frame's cost is estimated before it is rendered, and one that may take more
 * than a few seconds is announced on stderr, so a user who asked the slow reference for a large
 * screen or distance (hours at the documented limits) knows at once. The model is rough and
 * errs high: naive paints every sample's line, about W*H*D pixel steps of a nanosecond or so;
 * the y-buffer kernels take each column's D samples once (W*D) and write each pixel once. */
#include <stdio.h>
#include <string.h>

#include "work_estimate.h"

#define NAIVE_NS_PER_STEP 1.2
#define YBUFFER_NS_PER_SAMPLE 3.0
#define NS_PER_PIXEL 1.0

double work_seconds(const retro_kernel *k, int W, int H, long D)
{
    double w = W, h = H, d = D > 1 ? (double)D : 1.0;
    double ns = !strcmp(k->name, "naive") ? w * h * d * NAIVE_NS_PER_STEP
                                          : w * d * YBUFFER_NS_PER_SAMPLE + w * h * NS_PER_PIXEL;
    return ns * 1e-9;
}

int work_warn(const char *cmd, const retro_kernel *k, int W, int H, long D)
{
    double s = work_seconds(k, W, H, D);
    if (s <= WORK_WARN_SECONDS)
        return 0;
    char t[32];
    if (s < 120)
        snprintf(t, sizeof t, "%.0f s", s);
    else if (s < 7200)
        snprintf(t, sizeof t, "%.0f min", s / 60);
    else
        snprintf(t, sizeof t, "%.0f h", s / 3600);
    fprintf(stderr, "retro %s: warning: each frame may take about %s (kernel %s, %dx%d, D %ld)%s\n",
            cmd, t, k->name, W, H, D,
            !strcmp(k->name, "naive") ? "; -k ybuffer renders the same bytes far faster" : "");
    return 1;
}
