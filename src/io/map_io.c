/* Maps on disk: PREFIX.pgm holds the heights, PREFIX.ppm (or PREFIX.png) the colours. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "errf.h"
#include "out_file.h"
#include "retro.h"
#include "retro_maps.h"


int retro_map_alloc(retro_map *m, int size, char *err, size_t n)
{
    memset(m, 0, sizeof *m);
    if (size < 1 || size > RETRO_MAX_MAP)
        return retro_errf(err, n, "map size %d outside 1..%d", size, RETRO_MAX_MAP);
    size_t cells = (size_t)size * (size_t)size;
    m->height = calloc(cells, 1);
    m->color = calloc(cells, sizeof *m->color);
    if (!m->height || !m->color) {
        retro_map_free(m);
        return retro_errf(err, n, "out of memory for a %dx%d map", size, size);
    }
    m->size = size;
    return 0;
}

void retro_map_free(retro_map *m)
{
    free(m->height);
    free(m->color);
    memset(m, 0, sizeof *m);
}

int retro_map_load(const char *prefix, retro_map *m, char *err, size_t n)
{
    memset(m, 0, sizeof *m);
    size_t len = strlen(prefix) + 8;
    char *path = malloc(len);
    if (!path)
        return retro_errf(err, n, "out of memory");
    uint8_t *h = NULL;
    uint32_t *c = NULL;
    int hw, hh, cw, ch, r = -1;
    snprintf(path, len, "%s.pgm", prefix);
    if (retro_pgm_read(path, &h, &hw, &hh, err, n))
        goto out;
    if (hw != hh) {
        retro_errf(err, n, "%s: height map is %dx%d, not square", path, hw, hh);
        goto out;
    }
    snprintf(path, len, "%s.ppm", prefix);
    if (access(path, F_OK) != 0)
        snprintf(path, len, "%s.png", prefix);
    if (access(path, F_OK) != 0) {
        retro_errf(err, n, "%s: no colour map (%s.ppm or %s.png)", prefix, prefix, prefix);
        goto out;
    }
    if (retro_rgb_read(path, &c, &cw, &ch, err, n))
        goto out;
    if (cw != hw || ch != hh) {
        retro_errf(err, n, "%s: colour map is %dx%d but height map is %dx%d", path, cw, ch, hw, hh);
        goto out;
    }
    m->size = hw;
    m->height = h;
    m->color = c;
    h = NULL;
    c = NULL;
    r = 0;
out:
    free(h);
    free(c);
    free(path);
    return r;
}

/* Both files are written to temporaries first and renamed together (src/io/out_file.c): a
 * failure leaves neither, and never a new .pgm beside an old colour map. */
int retro_map_save(const char *prefix, const retro_map *m, int png, char *err, size_t n)
{
    size_t len = strlen(prefix) + 8, tlen = len + RETRO_TMP_EXTRA;
    char *path[2] = {malloc(len), malloc(len)}, *tmp[2] = {malloc(tlen), malloc(tlen)};
    int r = -1;
    if (!path[0] || !path[1] || !tmp[0] || !tmp[1]) {
        retro_errf(err, n, "out of memory");
        goto out;
    }
    snprintf(path[0], len, "%s.pgm", prefix);
    snprintf(path[1], len, "%s.%s", prefix, png ? "png" : "ppm");
    if (retro_gray_stage(path[0], m->height, m->size, m->size, tmp[0], tlen, err, n))
        goto out;
    if (retro_image_stage(path[1], m->color, m->size, m->size, tmp[1], tlen, err, n)) {
        unlink(tmp[0]);
        goto out;
    }
    r = retro_out_commit_pair(tmp, (const char *const *)path, err, n);
out:
    for (int i = 0; i < 2; i++) {
        free(path[i]);
        free(tmp[i]);
    }
    return r;
}
