/* Colour maps in PNG, decoded by libspng once the file is known to be no larger than its
 * header allows: a tiny image padded with gigabytes of chunks is refused before it is read. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <spng.h>

#include "errf.h"
#include "image_read.h"
#include "retro.h"

/* Ancillary chunks (text, profiles) are never used; this much of them is allowed. */
#define PNG_EXTRA ((size_t)1 << 20)


static uint32_t be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* The largest file a PNG of this header may be: its filtered rows stored uncompressed (deflate
 * adds 5 bytes per 64 KiB), an eighth more for chunking, and PNG_EXTRA of other chunks. */
static int file_max(const char *path, const unsigned char *b, size_t len, size_t *max,
                    size_t *raw_out, char *err, size_t n)
{
    if (len < 33 || be32(b + 8) != 13 || memcmp(b + 12, "IHDR", 4))
        return retro_errf(err, n, "%s: bad PNG: no IHDR chunk first", path);
    uint32_t w = be32(b + 16), h = be32(b + 20);
    unsigned depth = b[24], type = b[25];
    static const unsigned channels[7] = {1, 0, 3, 1, 2, 0, 4};
    if (w < 1 || h < 1 || w > RETRO_MAX_MAP || h > RETRO_MAX_MAP)
        return retro_errf(err, n, "%s: PNG size %ux%u outside 1..%d", path, (unsigned)w, (unsigned)h,
                    RETRO_MAX_MAP);
    if (type > 6 || !channels[type] || (depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16))
        return retro_errf(err, n, "%s: bad PNG: colour type %u with bit depth %u", path, type, depth);
    size_t row = 1 + ((size_t)w * channels[type] * depth + 7) / 8;
    size_t raw = row * h;
    *max = raw + raw / 8 + PNG_EXTRA;
    *raw_out = raw;
    return 0;
}

/* Walks the chunks: each must fit in the file, and IEND must end it. *idat: the image data's
 * bytes. */
static int chunks_end(const char *path, const unsigned char *b, size_t len, size_t *idat,
                      char *err, size_t n)
{
    size_t at = 8;
    *idat = 0;
    for (;;) {
        if (len - at < 12)
            return retro_errf(err, n, "%s: bad PNG: truncated (no IEND chunk)", path);
        size_t clen = be32(b + at);
        if (clen > len - at - 12)
            return retro_errf(err, n, "%s: bad PNG: truncated chunk", path);
        int iend = !memcmp(b + at + 4, "IEND", 4);
        if (!memcmp(b + at + 4, "IDAT", 4))
            *idat += clen;
        at += 12 + clen;
        if (iend)
            break;
    }
    if (at != len)
        return retro_errf(err, n, "%s: %zu bytes of trailing data after the PNG's IEND chunk", path,
                    len - at);
    return 0;
}

static int decode(const char *path, unsigned char *b, size_t len, uint32_t **data, int *w,
                  int *h, char *err, size_t n)
{
    spng_ctx *ctx = spng_ctx_new(0);
    struct spng_ihdr ihdr;
    size_t size = 0;
    unsigned char *rgb = NULL;
    int e;
    if (!ctx)
        return retro_errf(err, n, "%s: out of memory", path);
    spng_set_image_limits(ctx, RETRO_MAX_MAP, RETRO_MAX_MAP);
    /* A compressed text chunk must not inflate into memory without bound either. */
    spng_set_chunk_limits(ctx, PNG_EXTRA, 4 * PNG_EXTRA);
    if ((e = spng_set_png_buffer(ctx, b, len)) || (e = spng_get_ihdr(ctx, &ihdr)) ||
        (e = spng_decoded_image_size(ctx, SPNG_FMT_RGB8, &size))) {
        spng_ctx_free(ctx);
        return retro_errf(err, n, "%s: bad PNG: %s", path, spng_strerror(e));
    }
    rgb = malloc(size);
    uint32_t *o = malloc((size_t)ihdr.width * ihdr.height * sizeof *o);
    if (!rgb || !o) {
        free(rgb);
        free(o);
        spng_ctx_free(ctx);
        return retro_errf(err, n, "%s: out of memory", path);
    }
    if ((e = spng_decode_image(ctx, rgb, size, SPNG_FMT_RGB8, SPNG_DECODE_TRNS))) {
        free(rgb);
        free(o);
        spng_ctx_free(ctx);
        return retro_errf(err, n, "%s: bad PNG: %s", path, spng_strerror(e));
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

int retro_png_read(retro_rfile *f, const unsigned char *head, size_t hl, uint32_t **data,
                   int *w, int *h, char *err, size_t n)
{
    size_t max = 0, raw = 0, idat = 0;
    if (file_max(f->path, head, hl, &max, &raw, err, n))
        return -1;
    if (f->size > max)
        return retro_errf(err, n, "%s: %zu bytes, more than a PNG of its size may hold (%zu)", f->path,
                    f->size, max);
    unsigned char *b = malloc(f->size);
    if (!b)
        return retro_errf(err, n, "%s: out of memory", f->path);
    memcpy(b, head, hl);
    int r = retro_rfile_read(f, b + hl, f->size - hl, err, n) || retro_rfile_at_end(f, err, n) ||
                    chunks_end(f->path, b, f->size, &idat, err, n)
                ? -1
                : 0;
    /* Deflate expands at most 1032-fold: image data too short for the declared size is refused
     * before the decoder allocates that size. */
    if (!r && raw / 1032 > idat + 64)
        r = retro_errf(err, n, "%s: truncated: %zu bytes of image data cannot hold %zu", f->path, idat, raw);
    if (!r)
        r = decode(f->path, b, f->size, data, w, h, err, n);
    free(b);
    return r;
}
