/* Where out starts in memory decides how the SIMD strips group their columns and where the
 * threaded kernels cut their chunks (column_chunks.h, simd_strip_tpl.h's head): both follow
 * out's 64-byte lines. So every voxel kernel this CPU runs renders into out at each 4-byte
 * offset within a line, at a width that is a multiple of 16 and one that is not, in modes
 * exact (with and without skipping), lod and course, and must give naive's bytes there and
 * touch nothing around the frame. */
#include <criterion/criterion.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "retro.h"
#include "test_util.h"

#define SKY 0x66a3ff00u
#define GUARD 0xabababab
enum { S = 200, D = 300, LINE = 16, PAD = 2 * LINE };

typedef struct {
    int W, H;
    retro_mode mode;
    int no_skip;
} frame_case;

static retro_render_opts case_opts(const frame_case *fc, int threads)
{
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = fc->mode;
    o.no_skip = fc->no_skip;
    o.threads = threads;
    if (fc->mode == RETRO_MODE_LOD)
        o.lod = 0.02f;
    return o;
}

static retro_err render_into(retro_ctx *rc, const retro_kernel *k, const frame_case *fc, int threads,
                             const player_t *p, ctx_t *c)
{
    const retro_render_opts o = case_opts(fc, threads);
    return retro_render(rc, k, &o, p, c);
}

Test(alignment, every_kernel_at_every_offset_of_out_within_a_line)
{
    static const frame_case cases[] = {
        {640, 120, RETRO_MODE_EXACT, 0}, {640, 120, RETRO_MODE_EXACT, 1}, {101, 77, RETRO_MODE_EXACT, 0},
        {101, 77, RETRO_MODE_LOD, 0},    {640, 120, RETRO_MODE_COURSE, 0}, {101, 77, RETRO_MODE_COURSE, 0},
    };
    retro_map m;
    test_map("test/alpine-200", &m);
    const player_t p = {100.5f, 37.25f, 200, 250, 0, 0, 0};
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc);
    size_t checked = 0;
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        const frame_case *fc = &cases[ci];
        const size_t n = (size_t)fc->W * fc->H;
        uint32_t *want = malloc(n * 4);
        /* room for any offset within a line, with guards on both sides; aligned_alloc takes a
         * size that is a multiple of the alignment */
        uint32_t *block = aligned_alloc(64, ((n + 2 * PAD) * 4 + 63) / 64 * 64);
        cr_assert(want && block);
        ctx_t c = {fc->W, fc->H, S, D, SKY, m.height, m.color, want};
        cr_assert_eq(render_into(rc, retro_kernel_find("naive"), fc, 0, &p, &c), RETRO_OK);
        /* the sky's row stores and the terrain's both reach every group of columns */
        size_t sky = 0;
        for (size_t i = 0; i < n; i++)
            sky += want[i] == SKY;
        cr_log_info("case %zu: %zu of %zu pixels sky", ci, sky, n);
        cr_assert(sky > n / 10 && sky < n - n / 10, "case %zu: %zu of %zu pixels sky", ci, sky, n);
        for (size_t ki = 0; ki < retro_kernel_count; ki++) {
            const retro_kernel *k = &retro_kernels[ki];
            if (k->family != &retro_family_voxel || !strcmp(k->name, "naive"))
                continue;
            const retro_render_opts probe = case_opts(fc, 0);
            char why[160];
            if (retro_render_check(k, &probe, why, sizeof why) != RETRO_OK)
                continue; /* a mode or ISA level this kernel or CPU lacks */
            for (int threads = 1; threads <= 2; threads++)
                for (int off = 0; off < LINE; off++) {
                    for (size_t i = 0; i < n + 2 * PAD; i++)
                        block[i] = GUARD;
                    c.out = block + PAD + off;
                    cr_assert_eq(render_into(rc, k, fc, threads, &p, &c), RETRO_OK, "%s", k->name);
                    cr_assert_eq(memcmp(c.out, want, n * 4), 0,
                                 "%s, %d threads, %dx%d mode %d%s, out at word %d of a line: differs from naive",
                                 k->name, threads, fc->W, fc->H, (int)fc->mode, fc->no_skip ? " no-skip" : "", off);
                    for (int i = 0; i < PAD + off; i++)
                        cr_assert_eq(block[i], GUARD, "%s wrote before the frame (offset %d)", k->name, off);
                    for (size_t i = PAD + (size_t)off + n; i < n + 2 * PAD; i++)
                        cr_assert_eq(block[i], GUARD, "%s wrote after the frame (offset %d)", k->name, off);
                    checked++;
                }
        }
        free(want);
        free(block);
    }
    /* ybuffer at least, in every case, at every offset and both thread counts */
    cr_log_info("%zu renders checked", checked);
    cr_assert_geq(checked, sizeof cases / sizeof cases[0] * 2 * LINE, "only %zu renders checked", checked);
    retro_ctx_free(rc);
    retro_map_free(&m);
}
