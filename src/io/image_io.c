/* Image files: binary PGM/PPM by hand, PNG through libspng. Writes go to a temporary file in
 * the destination's directory and are renamed into place, so a failed write leaves nothing. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <spng.h>

#include "retro.h"
#include "retro_maps.h"

static int fail(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (err && n)
        vsnprintf(err, n, fmt, ap);
    va_end(ap);
    return -1;
}

/* Reads a whole file; images are at most a few hundred MiB by the size limits. */
static int slurp(const char *path, unsigned char **buf, size_t *len, char *err, size_t n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return fail(err, n, "%s: %s", path, strerror(errno));
    size_t cap = 1 << 16, used = 0;
    unsigned char *b = malloc(cap);
    while (b) {
        used += fread(b + used, 1, cap - used, f);
        if (used < cap)
            break;
        unsigned char *nb = realloc(b, cap * 2);
        if (!nb) {
            free(b);
            b = NULL;
            break;
        }
        b = nb;
        cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (!b)
        return fail(err, n, "%s: out of memory", path);
    if (bad) {
        free(b);
        return fail(err, n, "%s: read error", path);
    }
    *buf = b;
    *len = used;
    return 0;
}

/* Parses a binary PNM header ("P5"/"P6", width, height, maxval, one whitespace byte). */
static int pnm_header(const char *path, const unsigned char *b, size_t len, char magic,
                      int *w, int *h, size_t *data, char *err, size_t n)
{
    if (len < 2 || b[0] != 'P' || b[1] != magic)
        return fail(err, n, "%s: not a binary P%c file", path, magic);
    size_t i = 2;
    long val[3];
    for (int k = 0; k < 3; k++) {
        for (;;) {
            while (i < len && strchr(" \t\r\n", b[i]))
                i++;
            if (i < len && b[i] == '#') {
                while (i < len && b[i] != '\n')
                    i++;
                continue;
            }
            break;
        }
        if (i >= len || b[i] < '0' || b[i] > '9')
            return fail(err, n, "%s: truncated or malformed header", path);
        long v = 0;
        while (i < len && b[i] >= '0' && b[i] <= '9') {
            v = v * 10 + (b[i++] - '0');
            if (v > 1000000)
                return fail(err, n, "%s: absurd header value", path);
        }
        val[k] = v;
    }
    if (i >= len || !strchr(" \t\r\n", b[i]))
        return fail(err, n, "%s: truncated or malformed header", path);
    i++;
    if (val[0] <= 0 || val[1] <= 0)
        return fail(err, n, "%s: size %ldx%ld must be positive", path, val[0], val[1]);
    if (val[0] > RETRO_MAX_MAP || val[1] > RETRO_MAX_MAP)
        return fail(err, n, "%s: absurd size %ldx%ld (limit %d)", path, val[0], val[1], RETRO_MAX_MAP);
    if (val[2] != 255)
        return fail(err, n, "%s: maxval %ld, only 255 (8-bit) is supported", path, val[2]);
    *w = (int)val[0];
    *h = (int)val[1];
    *data = i;
    return 0;
}

int retro_pgm_read(const char *path, uint8_t **data, int *w, int *h, char *err, size_t n)
{
    unsigned char *b;
    size_t len, off;
    if (slurp(path, &b, &len, err, n))
        return -1;
    if (pnm_header(path, b, len, '5', w, h, &off, err, n)) {
        free(b);
        return -1;
    }
    size_t need = (size_t)*w * (size_t)*h;
    if (len - off < need) {
        free(b);
        return fail(err, n, "%s: truncated: %zu of %zu pixel bytes", path, len - off, need);
    }
    memmove(b, b + off, need);
    *data = b;
    return 0;
}

static int ppm_decode(const char *path, unsigned char *b, size_t len, uint32_t **data, int *w,
                      int *h, char *err, size_t n)
{
    size_t off;
    if (pnm_header(path, b, len, '6', w, h, &off, err, n))
        return -1;
    size_t px = (size_t)*w * (size_t)*h;
    if (len - off < 3 * px)
        return fail(err, n, "%s: truncated: %zu of %zu pixel bytes", path, len - off, 3 * px);
    uint32_t *o = malloc(px * sizeof *o);
    if (!o)
        return fail(err, n, "%s: out of memory", path);
    const unsigned char *p = b + off;
    for (size_t i = 0; i < px; i++, p += 3)
        o[i] = (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8;
    *data = o;
    return 0;
}

static int png_decode(const char *path, unsigned char *b, size_t len, uint32_t **data, int *w,
                      int *h, char *err, size_t n)
{
    spng_ctx *ctx = spng_ctx_new(0);
    struct spng_ihdr ihdr;
    size_t size = 0;
    unsigned char *rgb = NULL;
    int e;
    if (!ctx)
        return fail(err, n, "%s: out of memory", path);
    spng_set_image_limits(ctx, RETRO_MAX_MAP, RETRO_MAX_MAP);
    if ((e = spng_set_png_buffer(ctx, b, len)) || (e = spng_get_ihdr(ctx, &ihdr)) ||
        (e = spng_decoded_image_size(ctx, SPNG_FMT_RGB8, &size))) {
        spng_ctx_free(ctx);
        return fail(err, n, "%s: bad PNG: %s", path, spng_strerror(e));
    }
    rgb = malloc(size);
    uint32_t *o = malloc((size_t)ihdr.width * ihdr.height * sizeof *o);
    if (!rgb || !o) {
        free(rgb);
        free(o);
        spng_ctx_free(ctx);
        return fail(err, n, "%s: out of memory", path);
    }
    if ((e = spng_decode_image(ctx, rgb, size, SPNG_FMT_RGB8, SPNG_DECODE_TRNS))) {
        free(rgb);
        free(o);
        spng_ctx_free(ctx);
        return fail(err, n, "%s: bad PNG: %s", path, spng_strerror(e));
    }
    size_t px = (size_t)ihdr.width * ihdr.height;
    for (size_t i = 0; i < px; i++)
        o[i] = (uint32_t)rgb[3 * i] << 24 | (uint32_t)rgb[3 * i + 1] << 16 | (uint32_t)rgb[3 * i + 2] << 8;
    *w = (int)ihdr.width;
    *h = (int)ihdr.height;
    *data = o;
    free(rgb);
    spng_ctx_free(ctx);
    return 0;
}

int retro_rgb_read(const char *path, uint32_t **data, int *w, int *h, char *err, size_t n)
{
    unsigned char *b;
    size_t len;
    if (slurp(path, &b, &len, err, n))
        return -1;
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    int r = len >= 8 && !memcmp(b, png_magic, 8) ? png_decode(path, b, len, data, w, h, err, n)
                                                  : ppm_decode(path, b, len, data, w, h, err, n);
    free(b);
    return r;
}

/* Writes len bytes to a temporary file beside path and renames it over path. */
static int write_atomic(const char *path, const void *hdr, size_t hlen, const void *body,
                        size_t blen, char *err, size_t n)
{
    size_t plen = strlen(path);
    char *tmp = malloc(plen + 16);
    if (!tmp)
        return fail(err, n, "%s: out of memory", path);
    snprintf(tmp, plen + 16, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        int e = errno;
        free(tmp);
        return fail(err, n, "%s: cannot write: %s", path, strerror(e));
    }
    fchmod(fd, 0644);
    FILE *f = fdopen(fd, "wb");
    int ok = f && fwrite(hdr, 1, hlen, f) == hlen && fwrite(body, 1, blen, f) == blen;
    int e = errno;
    if (f ? fclose(f) != 0 : close(fd) != 0)
        ok = 0;
    if (ok && rename(tmp, path) != 0) {
        e = errno;
        ok = 0;
    }
    if (!ok) {
        unlink(tmp);
        free(tmp);
        return fail(err, n, "%s: cannot write: %s", path, strerror(e));
    }
    free(tmp);
    return 0;
}

static int has_ext(const char *path, const char *ext)
{
    size_t a = strlen(path), b = strlen(ext);
    return a >= b && !strcmp(path + a - b, ext);
}

static int png_encode(const char *path, const unsigned char *px, int w, int h, int channels,
                      char *err, size_t n)
{
    spng_ctx *ctx = spng_ctx_new(SPNG_CTX_ENCODER);
    if (!ctx)
        return fail(err, n, "%s: out of memory", path);
    struct spng_ihdr ihdr = {0};
    ihdr.width = (uint32_t)w;
    ihdr.height = (uint32_t)h;
    ihdr.bit_depth = 8;
    ihdr.color_type = channels == 3 ? SPNG_COLOR_TYPE_TRUECOLOR : SPNG_COLOR_TYPE_GRAYSCALE;
    spng_set_option(ctx, SPNG_ENCODE_TO_BUFFER, 1);
    spng_set_ihdr(ctx, &ihdr);
    size_t len = (size_t)w * (size_t)h * (size_t)channels;
    int e = spng_encode_image(ctx, px, len, SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE);
    void *png = e ? NULL : spng_get_png_buffer(ctx, &len, &e);
    spng_ctx_free(ctx);
    if (!png)
        return fail(err, n, "%s: PNG encoding failed: %s", path, spng_strerror(e));
    int r = write_atomic(path, "", 0, png, len, err, n);
    free(png);
    return r;
}

static int write_pixels(const char *path, const unsigned char *px, int w, int h, int channels,
                        char *err, size_t n)
{
    if (has_ext(path, ".png"))
        return png_encode(path, px, w, h, channels, err, n);
    if (!has_ext(path, channels == 3 ? ".ppm" : ".pgm"))
        return fail(err, n, "%s: unknown image type (use .%s or .png)", path,
                    channels == 3 ? "ppm" : "pgm");
    char hdr[64];
    int hl = snprintf(hdr, sizeof hdr, "P%c\n%d %d\n255\n", channels == 3 ? '6' : '5', w, h);
    return write_atomic(path, hdr, (size_t)hl, px, (size_t)w * (size_t)h * (size_t)channels, err, n);
}

int retro_image_write(const char *path, const uint32_t *px, int w, int h, char *err, size_t n)
{
    size_t count = (size_t)w * (size_t)h;
    unsigned char *rgb = malloc(count * 3);
    if (!rgb)
        return fail(err, n, "%s: out of memory", path);
    for (size_t i = 0; i < count; i++) {
        rgb[3 * i] = (unsigned char)(px[i] >> 24);
        rgb[3 * i + 1] = (unsigned char)(px[i] >> 16);
        rgb[3 * i + 2] = (unsigned char)(px[i] >> 8);
    }
    int r = write_pixels(path, rgb, w, h, 3, err, n);
    free(rgb);
    return r;
}

int retro_gray_write(const char *path, const uint8_t *px, int w, int h, char *err, size_t n)
{
    return write_pixels(path, px, w, h, 1, err, n);
}
