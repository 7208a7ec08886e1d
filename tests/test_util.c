#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>

#include "test_util.h"

const char *course_dir(void)
{
    static char path[1024];
    const char *s = getenv("RETRO_SHARED");
    snprintf(path, sizeof path, "%s/course", s && *s ? s : "../shared");
    return path;
}

int course_map(const char *name, retro_map *m)
{
    char prefix[1200], err[512];
    snprintf(prefix, sizeof prefix, "%s/%s", course_dir(), name);
    return retro_map_load(prefix, m, err, sizeof err);
}

void test_map(const char *name, retro_map *m)
{
    char prefix[512], err[512];
    snprintf(prefix, sizeof prefix, "maps/%s", name);
    if (retro_map_load(prefix, m, err, sizeof err))
        cr_assert_fail("%s (run make maps)", err);
}

long read_file(const char *path, unsigned char **buf)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    *buf = malloc((size_t)n + 1);
    if (fread(*buf, 1, (size_t)n, f) != (size_t)n)
        n = -1;
    fclose(f);
    return n;
}

uint64_t rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

void noise_map(retro_map *m, int S, uint64_t seed)
{
    char err[128];
    cr_assert_eq(retro_map_alloc(m, S, err, sizeof err), 0, "%s", err);
    for (size_t i = 0; i < (size_t)S * (size_t)S; i++) {
        uint64_t r = rng_next(&seed);
        m->height[i] = (uint8_t)r;
        m->color[i] = (uint32_t)(r >> 32) & 0xffffff00u;
    }
}

void render_with(const char *kernel, retro_mode mode, const player_t *p, ctx_t *c)
{
    render_threads(kernel, mode, p, c, 0);
}

void render_threads(const char *kernel, retro_mode mode, const player_t *p, ctx_t *c, int threads)
{
    const retro_kernel *k = retro_kernel_find(kernel);
    cr_assert(k, "no kernel %s", kernel);
    retro_ctx *rc = retro_ctx_new();
    cr_assert(rc, "out of memory");
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.threads = threads;
    retro_err e = retro_render(rc, k, &o, p, c);
    retro_ctx_free(rc);
    cr_assert_eq(e, RETRO_OK, "%s/%s: %s", kernel, retro_mode_name(mode), retro_strerror(e));
}
