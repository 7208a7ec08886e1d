/* A course-style driver for the generated single-file submission: it is compiled with that
 * file alone (plus render.h), the way the course builds a submission, and knows nothing of
 * the library. Two uses:
 *   driver selftest SHARED_DIR   the course's public render tests, test image and player tests
 *   driver frame MAP W H D X Y HEIGHT ANGLE OUT.ppm   one mode-course frame, as a P6 file */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"

static unsigned char *slurp(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)*n);
    if (b && fread(b, 1, (size_t)*n, f) != (size_t)*n) {
        free(b);
        b = NULL;
    }
    fclose(f);
    return b;
}

/* The maps are the course's own files: P5/P6, one-line header "P? S S\n255\n". */
static int load_map(const char *prefix, int *S, uint8_t **h, uint32_t **c)
{
    char path[1024];
    long n;
    int w, hh, maxv, off;
    snprintf(path, sizeof path, "%s.pgm", prefix);
    unsigned char *b = slurp(path, &n);
    if (!b || sscanf((char *)b, "P5 %d %d %d%n", &w, &hh, &maxv, &off) != 3 || w != hh)
        return -1;
    *S = w;
    *h = malloc((size_t)w * (size_t)w);
    memcpy(*h, b + off + 1, (size_t)w * (size_t)w);
    free(b);
    snprintf(path, sizeof path, "%s.ppm", prefix);
    b = slurp(path, &n);
    if (!b || sscanf((char *)b, "P6 %d %d %d%n", &w, &hh, &maxv, &off) != 3 || w != *S)
        return -1;
    *c = malloc(sizeof(uint32_t) * (size_t)w * (size_t)w);
    const unsigned char *p = b + off + 1;
    for (long i = 0; i < (long)w * w; i++, p += 3)
        (*c)[i] = (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8;
    free(b);
    return 0;
}

static void write_ppm(const char *path, const uint32_t *px, int W, int H)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        perror(path);
        exit(2);
    }
    fprintf(f, "P6\n%d %d\n255\n", W, H);
    for (long i = 0; i < (long)W * H; i++) {
        unsigned char rgb[3] = {(unsigned char)(px[i] >> 24), (unsigned char)(px[i] >> 16),
                                (unsigned char)(px[i] >> 8)};
        fwrite(rgb, 1, 3, f);
    }
    fclose(f);
}

static int same_file(const char *a, const char *b)
{
    long na, nb;
    unsigned char *x = slurp(a, &na), *y = slurp(b, &nb);
    int same = x && y && na == nb && !memcmp(x, y, (size_t)na);
    free(x);
    free(y);
    return same;
}

static int frame(const char *map, int W, int H, int D, float x, float y, int height, int angle,
                 const char *out)
{
    int S;
    uint8_t *hm;
    uint32_t *cm;
    if (load_map(map, &S, &hm, &cm)) {
        fprintf(stderr, "driver: cannot load %s\n", map);
        return 2;
    }
    uint32_t *px = malloc(sizeof(uint32_t) * (size_t)W * (size_t)H);
    ctx_t c = {W, H, S, D, 0x66a3ff00u, hm, cm, px};
    player_t p = {x, y, angle, height, 0, 0, 0};
    render(&p, &c);
    write_ppm(out, px, W, H);
    free(px);
    free(hm);
    free(cm);
    return 0;
}

static int test_image(const char *shared)
{
    enum { W = 321, H = 241 };
    static uint32_t px[W * H];
    ctx_t c = {W, H, 0, 0, 0, NULL, NULL, px};
    for (int i = 0; i < W * H; i++)
        px[i] = 0x55555500u;
    draw_line(&c, 1, 0, H, 0xff000000u);
    draw_line(&c, W, 0, H, 0xff000000u);
    for (int u = 1; u <= W; u++) {
        draw_line(&c, u, 0, 1, 0x0000ff00u);
        draw_line(&c, u, H - 1, H, 0x0000ff00u);
    }
    draw_line(&c, 161, 0, H, 0);
    for (int u = 1; u <= W; u++)
        draw_line(&c, u, 120, 121, 0xffffff00u);
    int s = 161 / 5;
    draw_line(&c, s, 121, 151, 0xff000000u);
    draw_line(&c, 2 * s, 121, 181, 0x00ff0000u);
    draw_line(&c, 3 * s, 121, 211, 0x0000ff00u);
    draw_line(&c, 161 + s, 30, 121, 0x00ffff00u);
    draw_line(&c, 161 + 2 * s, 60, 121, 0xff00ff00u);
    draw_line(&c, 161 + 3 * s, 90, 121, 0xffff0000u);
    char ref[1024];
    snprintf(ref, sizeof ref, "%s/course/test_image_ref.ppm", shared);
    write_ppm("driver-test-image.ppm", px, W, H);
    int ok = same_file("driver-test-image.ppm", ref);
    printf("%s test image\n", ok ? "ok  " : "FAIL");
    return !ok;
}

static int players(void)
{
    static uint8_t h[128 * 128];
    ctx_t c = {640, 480, 128, 100, 0, h, NULL, NULL};
    player_t a = {100, 100, 90, 100, 5, 0, 0}, b = {100, 100, 90, 100, 0, 5, 0}, d = {100, 100, 90, 100, 0, 0, 5};
    update_player(&a, &c);
    update_player(&b, &c);
    update_player(&d, &c);
    int ok = a.y > 94.999f && a.y < 95.001f && b.height == 105 && d.angle == 95;
    printf("%s player tests\n", ok ? "ok  " : "FAIL");
    return !ok;
}

static int selftest(const char *shared)
{
    static const struct {
        const char *map, *ref;
        int W, H, D;
        float x, y;
        int height;
    } t[] = {{"island", "public.island01.ppm", 800, 600, 600, 147.436798f, 539.899414f, 88},
             {"pyramids", "public.pyramids01.ppm", 640, 480, 800, 110.388893f, 887.813843f, 164},
             {"valley", "public.valley01.ppm", 640, 480, 800, 997.808716f, 559.177063f, 230}};
    int fails = players() + test_image(shared);
    for (int i = 0; i < 3; i++) {
        char map[1024], ref[1024];
        snprintf(map, sizeof map, "%s/course/%s", shared, t[i].map);
        snprintf(ref, sizeof ref, "%s/course/%s", shared, t[i].ref);
        int bad = frame(map, t[i].W, t[i].H, t[i].D, t[i].x, t[i].y, t[i].height, 0, "driver-frame.ppm") ||
                  !same_file("driver-frame.ppm", ref);
        printf("%s %s\n", bad ? "FAIL" : "ok  ", t[i].ref);
        fails += bad;
    }
    printf("bonus_implemented() = %d\n", bonus_implemented());
    return fails || bonus_implemented() != 1;
}

int main(int argc, char **argv)
{
    if (argc == 3 && !strcmp(argv[1], "selftest"))
        return selftest(argv[2]);
    if (argc == 11 && !strcmp(argv[1], "frame"))
        return frame(argv[2], atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), strtof(argv[6], NULL),
                     strtof(argv[7], NULL), atoi(argv[8]), atoi(argv[9]), argv[10]);
    fprintf(stderr, "usage: driver selftest SHARED | driver frame MAP W H D X Y HEIGHT ANGLE OUT.ppm\n");
    return 2;
}
