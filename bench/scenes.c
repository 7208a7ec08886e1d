/* Scene loading: which maps the benchmark uses and from where it looks at them. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "scenes.h"

/* The course's public render tests (../shared/course/README.md): the poses its reference
 * images were taken from, so the course scenes show what the course grades. */
static const struct {
    const char *map;
    float x, y;
    int height, angle;
} course_poses[] = {
    {"valley", 997.808716f, 559.177063f, 230, 0},
    {"island", 147.436798f, 539.899414f, 88, 0},
    {"pyramids", 110.388893f, 887.813843f, 164, 0},
};

static const char *const generated[] = {"alpine", "islands", "canyon"};

static int load(bench_scene *s, const char *prefix, const char *origin)
{
    char err[512];
    memset(s, 0, sizeof *s);
    if (retro_map_load(prefix, &s->map, err, sizeof err)) {
        fprintf(stderr, "note: scene %s skipped: %s\n", prefix, err);
        return -1;
    }
    const char *base = strrchr(prefix, '/');
    snprintf(s->name, sizeof s->name, "%s", base ? base + 1 : prefix);
    snprintf(s->origin, sizeof s->origin, "%s", origin);
    return 0;
}

int scenes_load_one(bench_scene *s, const char *prefix)
{
    if (load(s, prefix, "gen"))
        return -1;
    struct retro_view v;
    retro_default_view(&s->map, &v);
    s->pose.x = v.x;
    s->pose.y = v.y;
    s->pose.angle = v.angle;
    s->pose.height = v.height;
    return 0;
}

int scenes_load_default(bench_scene *out, int max, const char *shared)
{
    int n = 0;
    char path[1024];
    for (size_t i = 0; i < sizeof generated / sizeof generated[0] && n < max; i++) {
        snprintf(path, sizeof path, "maps/%s", generated[i]);
        if (!scenes_load_one(&out[n], path))
            n++;
    }
    struct stat st;
    snprintf(path, sizeof path, "%s/course", shared);
    if (stat(path, &st) || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "note: %s not found (set RETRO_SHARED): course scenes skipped\n", path);
        return n;
    }
    for (size_t i = 0; i < sizeof course_poses / sizeof course_poses[0] && n < max; i++) {
        snprintf(path, sizeof path, "%s/course/%s", shared, course_poses[i].map);
        if (load(&out[n], path, "course"))
            continue;
        out[n].pose.x = course_poses[i].x;
        out[n].pose.y = course_poses[i].y;
        out[n].pose.height = course_poses[i].height;
        out[n].pose.angle = course_poses[i].angle;
        n++;
    }
    return n;
}

void scenes_free(bench_scene *s, int n)
{
    for (int i = 0; i < n; i++)
        retro_map_free(&s[i].map);
}
