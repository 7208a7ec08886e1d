/* The strip table (src/voxel/strips.h) and the one list of ISA levels (src/core/isa.h): the
 * kernel rows agree with their strips, the frame's strip is the one the table picks, and that
 * pick is what walking the kernel table (the dispatch this replaced) picked, at every level. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "env.h"
#include "isa.h"
#include "retro_scene.h"
#include "strips.h"
#include "test_util.h"

/* The effect sets a frame can carry per sample (retro_frame.fx). */
static const unsigned fx_sets[] = {0, RETRO_FX_FOG, RETRO_FX_BILINEAR, RETRO_FX_FOG | RETRO_FX_BILINEAR};

Test(strips, kernel_rows_match_their_strips)
{
    int rows = 0;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (!k->strip)
            continue;
        rows++;
        char name[32];
        snprintf(name, sizeof name, "%s", k->name);
        for (char *c = name; *c; c++)
            *c = *c == '-' ? '_' : *c;
        cr_assert_str_eq(k->strip->name, name, "row %s points at strip %s", k->name, k->strip->name);
        cr_assert_eq(k->cpu, k->strip->cpu, "%s: cpu %#x, strip %#x", k->name, k->cpu, k->strip->cpu);
        cr_assert_eq(k->modes, k->strip->modes, "%s: modes differ from its strip's", k->name);
        cr_assert_eq(k->fx, k->strip->fx, "%s: effects differ from its strip's", k->name);
        cr_assert(k->family == &retro_family_voxel && !(k->flags & RETRO_KF_THREADED), "%s", k->name);
    }
    cr_assert_eq(rows, RETRO_STRIP_COUNT, "every strip has its single-thread row (%d of %d)", rows,
                 RETRO_STRIP_COUNT);
}

Test(strips, table_ascends_through_the_isa_levels)
{
    cr_assert_eq(retro_isa_count, RETRO_ISA_LEVEL_COUNT);
    cr_assert_eq(retro_strips[0].level, RETRO_ISA_NONE, "the first strip runs everywhere");
    cr_assert_eq(retro_strips[0].modes, (1u << RETRO_MODE_COUNT) - 1, "the first strip renders every mode");
    for (int i = 0; i < RETRO_STRIP_COUNT; i++) {
        const retro_strip *s = &retro_strips[i];
        cr_assert(s->level >= 0 && s->level < retro_isa_count, "%s", s->name);
        cr_assert_eq(s->cpu, retro_isa_cpu(s->level), "%s: cpu of level %s", s->name, retro_isa_names[s->level]);
        cr_assert_not_null(s->fn, "%s", s->name);
        if (i)
            cr_assert_geq(s->level, retro_strips[i - 1].level, "%s is out of ISA order", s->name);
    }
}

Test(strips, isa_names_are_one_list)
{
    for (int i = 0; i < retro_isa_count; i++) {
        cr_assert_eq(retro_cpu_level_index(retro_isa_names[i]), i);
        cr_assert_eq(retro_cpu_level(retro_isa_cpu(i)), i, "level %s", retro_isa_names[i]);
        cr_assert_eq(retro_isa_cpu(i) & retro_isa_cpu(i > 0 ? i - 1 : 0), retro_isa_cpu(i > 0 ? i - 1 : 0),
                     "each level allows the ones below");
    }
    cr_assert_eq(retro_cpu_level_index("avx3"), -1);
    char buf[64];
    cr_assert_str_eq(retro_isa_list(buf, sizeof buf), "none, sse2, avx2, avx512");
    char small[8];
    cr_assert_str_eq(retro_isa_list(small, sizeof small), "none", "a short buffer keeps whole names");
}

/* What the threaded kernels ran before the strip table: the strip of the last single-thread
 * kernel row this CPU runs for the mode and effects. */
static retro_strip_fn by_kernel_rows(retro_mode mode, unsigned fx)
{
    retro_strip_fn best = NULL;
    for (size_t i = 0; i < retro_kernel_count; i++) {
        const retro_kernel *k = &retro_kernels[i];
        if (k->strip && retro_kernel_runs_here(k) && retro_kernel_has_mode(k, mode) && !(fx & ~k->fx))
            best = k->strip->fn;
    }
    return best;
}

Test(strips, best_strip_at_every_level)
{
    int levels_run = 0;
    for (int l = 0; l < retro_isa_count; l++) {
        cr_assert_eq(retro_cpu_limit(retro_isa_names[l]), RETRO_OK);
        levels_run++;
        for (int m = 0; m < RETRO_MODE_COUNT; m++)
            for (size_t f = 0; f < sizeof fx_sets / sizeof fx_sets[0]; f++) {
                retro_strip_fn got = retro_strip_best((retro_mode)m, fx_sets[f]);
                cr_assert_not_null(got);
                cr_assert(got == by_kernel_rows((retro_mode)m, fx_sets[f]), "level %s mode %d fx %#x",
                          retro_isa_names[l], m, fx_sets[f]);
                if (l == RETRO_ISA_NONE || (m != RETRO_MODE_EXACT && m != RETRO_MODE_COURSE && m != RETRO_MODE_LOD))
                    cr_assert(got == retro_strip_ybuffer, "scalar strip expected");
            }
    }
    retro_cpu_limit(NULL);
    cr_assert_eq(levels_run, retro_isa_count);
}

/* Frame setup chooses the strip once per frame, from the table, for the effective mode. */
Test(strips, frame_setup_chooses_the_strip)
{
    retro_map m;
    noise_map(&m, 64, 5);
    uint32_t out[40 * 30];
    ctx_t c = {40, 30, 64, 90, 0x102030u, m.height, m.color, out};
    player_t p = {10.5f, 20.25f, 30, 200, 0, 0, 0};
    retro_effects fog;
    memset(&fog, 0, sizeof fog);
    fog.flags = RETRO_FX_FOG;
    fog.fog_start = 10;
    fog.fog_end = 80;
    for (int l = 0; l < retro_isa_count; l++) {
        retro_cpu_limit(retro_isa_names[l]);
        for (int m2 = 0; m2 < RETRO_MODE_COUNT; m2++)
            for (int withfog = 0; withfog < 2; withfog++) {
                if (withfog && m2 != RETRO_MODE_EXACT)
                    continue;
                retro_ctx *rc = retro_ctx_new();
                cr_assert(rc);
                retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
                o.mode = m2;
                o.fx = withfog ? &fog : NULL;
                const retro_frame *f = NULL;
                cr_assert_eq(retro_frame_prepare(rc, &o, &p, &c, &f), RETRO_OK);
                cr_assert(f->strip == retro_strip_best((retro_mode)m2, f->fx), "level %s mode %d",
                          retro_isa_names[l], m2);
                cr_assert_eq(f->fx, withfog ? (unsigned)RETRO_FX_FOG : 0u);
                retro_ctx_free(rc);
            }
    }
    retro_cpu_limit(NULL);
    retro_map_free(&m);
}
