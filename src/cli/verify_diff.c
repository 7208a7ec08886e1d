/* retro verify's diff image: the reference dimmed to grey, differing pixels in magenta. */
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "retro_maps.h"
#include "verify_cases.h"

/* Dimmed reference with differing pixels in magenta, so a mismatch can be seen at a glance. */
void verify_write_diff(const char *outdir, const char *name, const uint32_t *ref, const uint32_t *got,
                       int W, int H)
{
    size_t n = (size_t)W * (size_t)H;
    uint32_t *img = malloc(n * sizeof *img);
    if (!img)
        return;
    for (size_t i = 0; i < n; i++) {
        uint32_t r = ref[i] >> 24 & 255, g = ref[i] >> 16 & 255, b = ref[i] >> 8 & 255;
        uint32_t y = (r + g + b) / 6;
        img[i] = ref[i] == got[i] ? (y << 24 | y << 16 | y << 8) : 0xff00ff00u;
    }
    char path[1024], err[512];
    mkdir("results", 0755);
    mkdir(outdir, 0755);
    snprintf(path, sizeof path, "%s/%s.png", outdir, name);
    if (retro_image_write(path, img, W, H, err, sizeof err))
        fprintf(stderr, "retro verify: %s\n", err);
    free(img);
}
