/* retro_fmod_fast must equal fmodf bit for bit wherever the fast kernels use it. */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "retro_internal.h"
#include "test_util.h"

static void same(float q, float k)
{
    float a = fmodf(q, k), b = retro_fmod_fast(q, k, 1.0f / k);
    uint32_t ba, bb;
    memcpy(&ba, &a, 4);
    memcpy(&bb, &b, 4);
    cr_assert_eq(ba, bb, "fmodf(%a, %g) = %a but fast gives %a", (double)q, (double)k, (double)a, (double)b);
    cr_assert_eq(retro_float_mod(q, k), retro_float_mod_fast(q, k, 1.0f / k));
}

Test(fmod, edges)
{
    static const float ks[] = {1, 2, 3, 999, 1023, 16383};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        float k = ks[i];
        float qs[] = {0.0f, -0.0f, k, -k, 2 * k, -2 * k, nextafterf(k, 0), nextafterf(-k, 0),
                      nextafterf(k, 2 * k), -1e-7f, 1e-7f, 1e-30f, -1e-30f, 4194303.75f, -4194303.75f,
                      4194304.0f, 1e9f, -1e9f, 8388607.5f, nextafterf(3 * k, 0), -nextafterf(3 * k, 0)};
        for (size_t j = 0; j < sizeof qs / sizeof qs[0]; j++)
            same(qs[j], k);
    }
}

Test(fmod, random)
{
    uint64_t s = 42;
    static const float ks[] = {1, 2, 3, 63, 999, 1023, 4095, 16383};
    for (int n = 0; n < 2000000; n++) {
        uint64_t r = rng_next(&s);
        uint32_t bits = (uint32_t)r;
        float q;
        memcpy(&q, &bits, 4);
        if (!isfinite(q))
            continue;
        if (n % 3 == 1) /* plenty of values in the range the kernels see */
            q = (float)((int64_t)(r >> 32) % 5000000) / 3.0f - 800000.0f;
        if (n % 3 == 2) /* and values next to multiples of k, where the quotient is off by one */
            q = nextafterf(ks[(r >> 20) % 8] * (float)((int64_t)(r >> 40) % 8000 - 4000),
                           (r & 1) ? 1e9f : -1e9f);
        same(q, ks[(r >> 20) % 8]);
    }
}
