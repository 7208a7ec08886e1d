/* libFuzzer target: the map loaders on arbitrary bytes. retro_pgm_read and retro_rgb_read
 * (PPM or PNG by the magic bytes) read the input through a memfd, so nothing touches the
 * disk; retro_map_load reads PREFIX.pgm and PREFIX.ppm or PREFIX.png from a private
 * directory, the input split where a second image starts. Contract checked: success gives a
 * size in 1..RETRO_MAX_MAP, a buffer that many pixels long (read to the end, so ASan sees an
 * overrun) and colours with a zero low byte; failure returns -1 with a message. */
#define _GNU_SOURCE
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "retro.h"
#include "retro_maps.h"

static char memfd_path[64], dir[64];
static int memfd = -1;

static void put(const char *path, int fd, const uint8_t *data, size_t size)
{
    if (fd < 0)
        fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    else if (ftruncate(fd, 0) != 0)
        abort();
    if (fd < 0 || (size && pwrite(fd, data, size, 0) != (ssize_t)size))
        abort();
    if (fd != memfd)
        close(fd);
}

static void expect_error(int r, const char *err, const char *what)
{
    if (r != -1 || !err[0]) {
        fprintf(stderr, "%s: returned %d with message '%s'\n", what, r, err);
        abort();
    }
}

static void check_size(int w, int h, const char *what)
{
    if (w < 1 || h < 1 || w > RETRO_MAX_MAP || h > RETRO_MAX_MAP) {
        fprintf(stderr, "%s: size %dx%d outside 1..%d\n", what, w, h, RETRO_MAX_MAP);
        abort();
    }
}

/* Sums every pixel (so a short buffer is an ASan report) and checks the colour contract. */
static unsigned walk_rgb(const uint32_t *px, size_t n, const char *what)
{
    unsigned sum = 0;
    for (size_t i = 0; i < n; i++) {
        if (px[i] & 0xffu) {
            fprintf(stderr, "%s: pixel %zu = %08x has a non-zero low byte\n", what, i, px[i]);
            abort();
        }
        sum += px[i] >> 8;
    }
    return sum;
}

static volatile unsigned sink;

static void cleanup(void)
{
    char path[96];
    static const char *const ext[] = {"pgm", "ppm", "png"};
    for (int i = 0; i < 3; i++) {
        snprintf(path, sizeof path, "%s/m.%s", dir, ext[i]);
        unlink(path);
    }
    rmdir(dir);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (memfd < 0) {
        memfd = memfd_create("fuzz_maps", 0);
        strcpy(dir, "/tmp/fuzz_maps.XXXXXX");
        if (memfd < 0 || !mkdtemp(dir))
            abort();
        atexit(cleanup);
        snprintf(memfd_path, sizeof memfd_path, "/proc/self/fd/%d", memfd);
    }
    put(memfd_path, memfd, data, size);
    char err[512];

    uint8_t *g = NULL;
    int w = 0, h = 0;
    err[0] = 0;
    int r = retro_pgm_read(memfd_path, &g, &w, &h, err, sizeof err);
    if (r == 0) {
        check_size(w, h, "pgm");
        if ((size_t)w * (size_t)h > size) {
            fprintf(stderr, "pgm: %dx%d pixels from %zu bytes\n", w, h, size);
            abort();
        }
        unsigned s = 0;
        for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
            s += g[i];
        sink = s;
        free(g);
    } else {
        expect_error(r, err, "pgm");
    }

    uint32_t *c = NULL;
    err[0] = 0;
    r = retro_rgb_read(memfd_path, &c, &w, &h, err, sizeof err);
    if (r == 0) {
        check_size(w, h, "rgb");
        sink = walk_rgb(c, (size_t)w * (size_t)h, "rgb");
        free(c);
    } else {
        expect_error(r, err, "rgb");
    }

    /* A whole map: the height map is the input up to the second image's magic. */
    size_t cut = size / 2;
    for (size_t i = 1; i + 1 < size; i++)
        if ((data[i] == 'P' && data[i + 1] == '6') || (data[i] == 0x89 && data[i + 1] == 'P')) {
            cut = i;
            break;
        }
    int png = cut + 1 < size && data[cut] == 0x89;
    char pgm[96], rgb[96], stale[96], prefix[80];
    snprintf(prefix, sizeof prefix, "%s/m", dir);
    snprintf(pgm, sizeof pgm, "%s.pgm", prefix);
    snprintf(rgb, sizeof rgb, "%s.%s", prefix, png ? "png" : "ppm");
    snprintf(stale, sizeof stale, "%s.%s", prefix, png ? "ppm" : "png");
    unlink(stale); /* the loader prefers .ppm: only this input's colour file may exist */
    put(pgm, -1, data, cut);
    put(rgb, -1, data + cut, size - cut);
    retro_map m;
    err[0] = 0;
    r = retro_map_load(prefix, &m, err, sizeof err);
    if (r == 0) {
        check_size(m.size, m.size, "map");
        size_t cells = (size_t)m.size * (size_t)m.size;
        unsigned s = walk_rgb(m.color, cells, "map");
        for (size_t i = 0; i < cells; i++)
            s += m.height[i];
        sink = s;
        retro_map_free(&m);
    } else {
        expect_error(r, err, "map");
    }
    return 0;
}
