/* Image files: binary PGM/PPM by hand, PNG through libspng (reading: src/io/png_read.c). A file is
 * read only if it is a regular file whose size is what its header declares (docs/INPUT.md).
 * Writes go to a temporary file in the destination's directory and are renamed into place, so
 * a failed write leaves nothing. */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <spng.h>

#include "errf.h"
#include "file_read.h"
#include "image_read.h"
#include "out_file.h"
#include "retro.h"
#include "retro_maps.h"


/* Bytes of a PNM header read before the pixels: magic, three numbers and any comments. */
#define PNM_HEADER_MAX 4096

static int pnm_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/* Parses a binary PNM header ("P5"/"P6", width, height, maxval, one whitespace byte) in the
 * file's first len bytes; whole says they are the whole file. */
static int pnm_header(const char *path, const unsigned char *b, size_t len, int whole, char magic,
                      int *w, int *h, size_t *data, char *err, size_t n)
{
    const char *cut = whole ? "truncated or malformed header" : "header longer than 4096 bytes";
    if (len < 2 || b[0] != 'P' || b[1] != magic)
        return retro_errf(err, n, "%s: not a binary P%c file", path, magic);
    size_t i = 2;
    long val[3];
    for (int k = 0; k < 3; k++) {
        for (;;) {
            while (i < len && pnm_space(b[i]))
                i++;
            if (i < len && b[i] == '#') {
                while (i < len && b[i] != '\n')
                    i++;
                continue;
            }
            break;
        }
        if (i >= len)
            return retro_errf(err, n, "%s: %s", path, cut);
        if (b[i] < '0' || b[i] > '9')
            return retro_errf(err, n, "%s: truncated or malformed header", path);
        long v = 0;
        while (i < len && b[i] >= '0' && b[i] <= '9') {
            v = v * 10 + (b[i++] - '0');
            if (v > 1000000)
                return retro_errf(err, n, "%s: absurd header value", path);
        }
        val[k] = v;
    }
    if (i >= len)
        return retro_errf(err, n, "%s: %s", path, cut);
    if (!pnm_space(b[i]))
        return retro_errf(err, n, "%s: truncated or malformed header", path);
    i++;
    if (val[0] <= 0 || val[1] <= 0)
        return retro_errf(err, n, "%s: size %ldx%ld must be positive", path, val[0], val[1]);
    if (val[0] > RETRO_MAX_MAP || val[1] > RETRO_MAX_MAP)
        return retro_errf(err, n, "%s: absurd size %ldx%ld (limit %d)", path, val[0], val[1], RETRO_MAX_MAP);
    if (val[2] != 255)
        return retro_errf(err, n, "%s: maxval %ld, only 255 (8-bit) is supported", path, val[2]);
    *w = (int)val[0];
    *h = (int)val[1];
    *data = i;
    return 0;
}

/* The pixel bytes of a PNM file whose first hl bytes are head: exactly the size its header
 * declares, read only once the file's size matches it (nothing may follow: one image per file). */
static int pnm_pixels(retro_rfile *f, const unsigned char *head, size_t hl, char magic,
                      size_t channels, unsigned char **px, int *w, int *h, char *err, size_t n)
{
    size_t off = 0;
    if (pnm_header(f->path, head, hl, hl == f->size, magic, w, h, &off, err, n))
        return -1;
    size_t need = (size_t)*w * (size_t)*h * channels;
    if (f->size - off < need)
        return retro_errf(err, n, "%s: truncated: %zu of %zu pixel bytes", f->path, f->size - off, need);
    if (f->size - off > need)
        return retro_errf(err, n, "%s: %zu bytes of trailing data after the pixels (one image per file)",
                    f->path, f->size - off - need);
    unsigned char *b = malloc(need);
    if (!b)
        return retro_errf(err, n, "%s: out of memory", f->path);
    memcpy(b, head + off, hl - off);
    if (retro_rfile_read(f, b + (hl - off), need - (hl - off), err, n) || retro_rfile_at_end(f, err, n)) {
        free(b);
        return -1;
    }
    *px = b;
    return 0;
}

/* Opens an image file and reads its first bytes, the header of any format read here. */
static int open_image(retro_rfile *f, const char *path, unsigned char *head, size_t *hl,
                      char *err, size_t n)
{
    if (retro_rfile_open(f, path, RETRO_IMAGE_FILE_MAX, err, n))
        return -1;
    *hl = f->size < PNM_HEADER_MAX ? f->size : PNM_HEADER_MAX;
    if (retro_rfile_read(f, head, *hl, err, n)) {
        retro_rfile_close(f);
        return -1;
    }
    return 0;
}

int retro_pgm_read(const char *path, uint8_t **data, int *w, int *h, char *err, size_t n)
{
    retro_rfile f;
    unsigned char head[PNM_HEADER_MAX];
    size_t hl;
    if (open_image(&f, path, head, &hl, err, n))
        return -1;
    int r = pnm_pixels(&f, head, hl, '5', 1, data, w, h, err, n);
    retro_rfile_close(&f);
    return r;
}

static int ppm_decode(retro_rfile *f, const unsigned char *head, size_t hl, uint32_t **data,
                      int *w, int *h, char *err, size_t n)
{
    unsigned char *b;
    if (pnm_pixels(f, head, hl, '6', 3, &b, w, h, err, n))
        return -1;
    size_t px = (size_t)*w * (size_t)*h;
    uint32_t *o = malloc(px * sizeof *o);
    if (!o) {
        free(b);
        return retro_errf(err, n, "%s: out of memory", f->path);
    }
    const unsigned char *p = b;
    for (size_t i = 0; i < px; i++, p += 3)
        o[i] = (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8;
    free(b);
    *data = o;
    return 0;
}

int retro_rgb_read(const char *path, uint32_t **data, int *w, int *h, char *err, size_t n)
{
    retro_rfile f;
    unsigned char head[PNM_HEADER_MAX];
    size_t hl;
    if (open_image(&f, path, head, &hl, err, n))
        return -1;
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    int r = hl >= 8 && !memcmp(head, png_magic, 8) ? retro_png_read(&f, head, hl, data, w, h, err, n)
                                                          : ppm_decode(&f, head, hl, data, w, h, err, n);
    retro_rfile_close(&f);
    return r;
}

/* Writes hdr and body to a temporary file beside path (src/io/out_file.c) and renames it over
 * path, or with staged set leaves its path there for the caller to rename. */
static int write_atomic(const char *path, const void *hdr, size_t hlen, const void *body,
                        size_t blen, char *staged, size_t slen, char *err, size_t n)
{
    size_t tlen = staged ? slen : strlen(path) + RETRO_TMP_EXTRA;
    char *tmp = staged ? staged : malloc(tlen);
    if (!tmp)
        return retro_errf(err, n, "%s: out of memory", path);
    int fd = retro_out_open(path, tmp, tlen, err, n), r = -1;
    if (fd >= 0) {
        FILE *f = fdopen(fd, "wb");
        int ok = f && fwrite(hdr, 1, hlen, f) == hlen && fwrite(body, 1, blen, f) == blen;
        int e = errno;
        if (f ? fclose(f) != 0 : close(fd) != 0)
            ok = 0;
        if (!ok) {
            unlink(tmp);
            retro_errf(err, n, "%s: cannot write: %s", path, strerror(e));
        } else
            r = staged ? 0 : retro_out_commit(tmp, path, err, n);
    }
    if (!staged)
        free(tmp);
    return r;
}

static int has_ext(const char *path, const char *ext)
{
    size_t a = strlen(path), b = strlen(ext);
    return a >= b && !strcmp(path + a - b, ext);
}

static int png_encode(const char *path, const unsigned char *px, int w, int h, int channels,
                      char *staged, size_t slen, char *err, size_t n)
{
    spng_ctx *ctx = spng_ctx_new(SPNG_CTX_ENCODER);
    if (!ctx)
        return retro_errf(err, n, "%s: out of memory", path);
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
        return retro_errf(err, n, "%s: PNG encoding failed: %s", path, spng_strerror(e));
    int r = write_atomic(path, "", 0, png, len, staged, slen, err, n);
    free(png);
    return r;
}

static int write_pixels(const char *path, const unsigned char *px, int w, int h, int channels,
                        char *staged, size_t slen, char *err, size_t n)
{
    if (has_ext(path, ".png"))
        return png_encode(path, px, w, h, channels, staged, slen, err, n);
    if (!has_ext(path, channels == 3 ? ".ppm" : ".pgm"))
        return retro_errf(err, n, "%s: unknown image type (use .%s or .png)", path,
                    channels == 3 ? "ppm" : "pgm");
    char hdr[64];
    int hl = snprintf(hdr, sizeof hdr, "P%c\n%d %d\n255\n", channels == 3 ? '6' : '5', w, h);
    return write_atomic(path, hdr, (size_t)hl, px, (size_t)w * (size_t)h * (size_t)channels, staged,
                        slen, err, n);
}

int retro_image_stage(const char *path, const uint32_t *px, int w, int h, char *staged,
                      size_t slen, char *err, size_t n)
{
    size_t count = (size_t)w * (size_t)h;
    unsigned char *rgb = malloc(count * 3);
    if (!rgb)
        return retro_errf(err, n, "%s: out of memory", path);
    for (size_t i = 0; i < count; i++) {
        rgb[3 * i] = (unsigned char)(px[i] >> 24);
        rgb[3 * i + 1] = (unsigned char)(px[i] >> 16);
        rgb[3 * i + 2] = (unsigned char)(px[i] >> 8);
    }
    int r = write_pixels(path, rgb, w, h, 3, staged, slen, err, n);
    free(rgb);
    return r;
}

int retro_image_write(const char *path, const uint32_t *px, int w, int h, char *err, size_t n)
{
    return retro_image_stage(path, px, w, h, NULL, 0, err, n);
}

int retro_gray_stage(const char *path, const uint8_t *px, int w, int h, char *staged, size_t slen,
                     char *err, size_t n)
{
    return write_pixels(path, px, w, h, 1, staged, slen, err, n);
}

int retro_gray_write(const char *path, const uint8_t *px, int w, int h, char *err, size_t n)
{
    return retro_gray_stage(path, px, w, h, NULL, 0, err, n);
}
