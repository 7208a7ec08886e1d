/* Scene files (include/io/retro_scene.h): INI read by inih, every value checked, the first problem
 * reported as one line FILE:LINE: [section] key: problem.
 *
 * inih's handler learns neither the line number (Debian builds it without
 * INI_HANDLER_LINENO) nor of sections without keys (nor INI_CALL_HANDLER_ON_NEW_SECTION), so
 * the file is fed through our own line reader: it knows which line inih is parsing, sees section
 * headers, and refuses over-long lines that inih would otherwise split in two. */
#include "retro_scene.h"

#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file_read.h"
#include "retro.h"

enum { SEC_SCENE, SEC_CAMERA, SEC_SCREEN, SEC_PATH, SEC_FOG, SEC_SHADE, SEC_WATER, SEC_BILINEAR,
       SEC_LOD, SEC_HORIZON, SEC_MORPH, SEC_TEXTURE, SEC_GOURAUD, SEC_WIREFRAME, SEC_CULL, SEC_COUNT };

static const struct {
    const char *name;
    unsigned fx;      /* the effect the section turns on, or 0 */
    const char *keys; /* for "unknown key" messages */
} SECTIONS[SEC_COUNT] = {
    {"scene", 0, "map, sky"},
    {"camera", 0, "x, y, height, angle"},
    {"screen", 0, "width, height, distance"},
    {"path", 0, "frames, key"},
    {"fog", RETRO_FX_FOG, "enabled, start, end, density"},
    {"shade", RETRO_FX_SHADE, "enabled, sun, ambient, diffuse"},
    {"water", RETRO_FX_WATER, "enabled, level, color, alpha0, alpha_per_unit"},
    {"bilinear", RETRO_FX_BILINEAR, "enabled"},
    {"lod", RETRO_FX_LOD, "enabled, rate"},
    {"horizon", RETRO_FX_HORIZON, "enabled, pitch"},
    {"morph", RETRO_FX_MORPH, "enabled, map, t"},
    {"texture", RETRO_FX_TEXTURE, "enabled"},
    {"gouraud", RETRO_FX_GOURAUD, "enabled"},
    {"wireframe", RETRO_FX_WIREFRAME, "enabled"},
    {"cull", RETRO_FX_CULL, "enabled"},
};

/* Bounds that keep every later computation in range (angle differences, pixel counts). */
#define MAX_COORD 1e9
#define MAX_HEIGHT 1000000
#define MAX_ANGLE 1000000
#define MAX_FRAMES 100000
/* A scene file is a few hundred bytes of text; this bounds what a hostile one makes us read. */
#define MAX_FILE ((size_t)1 << 20)

void retro_effects_defaults(retro_effects *fx)
{
    memset(fx, 0, sizeof *fx);
    fx->fog_start = 300.0f;
    fx->fog_end = 800.0f;
    fx->fog_density = 0.003f;
    const double sun[3] = {-0.5, -0.6, 0.62};
    double len = sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    for (int i = 0; i < 3; i++)
        fx->sun[i] = (float)(sun[i] / len);
    fx->ambient = 0.35f;
    fx->diffuse = 0.8f;
    fx->water_level = 64;
    fx->water_color = 0x1e5aa000u;
    fx->water_alpha0 = 0.35f;
    fx->water_alpha_per_unit = 0.03f;
}

void retro_scene_defaults(retro_scene *s)
{
    memset(s, 0, sizeof *s);
    s->sky = 0x66a3ff00u;
    s->lod = RETRO_LOD_DEFAULT;
    s->x = s->y = NAN;     /* the map's default view */
    s->height = INT_MIN;   /* the default view's height */
    s->W = 640;
    s->H = 480;
    s->D = 800;
    retro_effects_defaults(&s->fx);
}

typedef struct parser {
    retro_scene *s;
    const char *path;
    FILE *f;
    int line;               /* the line inih is parsing */
    int next;
    size_t bytes;           /* read so far: the file may grow while read */
    int read_errno;
    int named;              /* a key since the last header: inih continues it on indented lines */
    int sec_line[SEC_COUNT]; /* first header of each section, for problems found at the end */
    int frames_line;
    int err_line;           /* of the first problem, 0 while there is none */
    char err[400];
} parser;

static int vfail(parser *P, const char *fmt, va_list ap)
{
    if (!P->err_line) {
        P->err_line = P->line;
        vsnprintf(P->err, sizeof P->err, fmt, ap);
    }
    return 0;
}

/* Records the first problem; returns 0, inih's "error" from a handler. */
static int fail(parser *P, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(parser *P, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfail(P, fmt, ap);
    va_end(ap);
    return 0;
}

static int find_section(const char *name)
{
    for (int i = 0; i < SEC_COUNT; i++)
        if (!strcmp(name, SECTIONS[i].name))
            return i;
    return -1;
}

static void section_header(parser *P, const char *name)
{
    int i = find_section(name);
    if (i < 0) {
        fail(P, "[%s]: unknown section (scene, camera, screen, path, fog, shade, water, "
                "bilinear, lod, horizon, morph, texture, gouraud, wireframe, cull)", name);
        return;
    }
    if (!P->sec_line[i])
        P->sec_line[i] = P->line;
    /* A bare [bilinear] should not silently do nothing: presence turns an effect on. */
    P->s->fx.flags |= SECTIONS[i].fx;
}

/* An fgets for inih that tracks lines and section headers the way ini_parse_stream reads them.
 * It reads byte by byte to see what fgets hides: a NUL inside a line (refused: it would end
 * the line early for inih and hide the rest of it) and the true length of a line. */
static char *read_line(char *buf, int n, void *stream)
{
    parser *P = stream;
    int c = EOF, len = 0, nul = 0, longer = 0;
    while (P->bytes <= MAX_FILE && (c = getc(P->f)) != EOF) {
        P->bytes++;
        if (len < n - 1)
            buf[len++] = (char)c;
        else
            longer = 1; /* skipped up to the line's end */
        nul |= c == 0;
        if (c == '\n')
            break;
    }
    if (c == EOF && ferror(P->f)) {
        P->read_errno = errno ? errno : EIO;
        return NULL;
    }
    if (P->bytes > MAX_FILE) {
        P->read_errno = EFBIG; /* grew past the limit since it was opened */
        return NULL;
    }
    if (!len)
        return NULL;
    buf[len] = 0;
    P->line = P->next++;
    if (longer) {
        fail(P, "line longer than %d characters", n - 3);
        /* Ends the line here, so no inih version goes on to swallow the next one. */
        buf[len - 1] = '\n';
    }
    if (nul) {
        fail(P, "NUL byte in the line (a scene file is text)");
        strcpy(buf, "\n"); /* inih sees an empty line */
    }
    const char *p = buf;
    if (P->line == 1 && !strncmp(p, "\xEF\xBB\xBF", 3))
        p += 3;
    int indented = isspace((unsigned char)*p);
    while (isspace((unsigned char)*p))
        p++;
    const char *end = *p == '[' && !(indented && P->named) ? strchr(p, ']') : NULL;
    if (end) {
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)(end - p - 1), p + 1);
        P->named = 0;
        section_header(P, name);
    }
    return buf;
}

/* ---- values ---------------------------------------------------------------------------- */

static int get_float(parser *P, const char *sec, const char *key, const char *v, double lo,
                     double hi, float *out)
{
    char *end;
    errno = 0;
    double d = strtod(v, &end);
    /* ERANGE on underflow gives a subnormal or zero, valid; an overflow gives an infinity. */
    if (!*v || *end || !isfinite(d))
        return fail(P, "[%s] %s: bad number '%s'", sec, key, v);
    if (d < lo || d > hi)
        return fail(P, "[%s] %s: %s out of range (%g..%g)", sec, key, v, lo, hi);
    *out = (float)d;
    return 1;
}

static int get_int(parser *P, const char *sec, const char *key, const char *v, long lo, long hi,
                   int *out)
{
    char *end;
    errno = 0;
    long l = strtol(v, &end, 10);
    if (!*v || *end || errno == ERANGE)
        return fail(P, "[%s] %s: bad integer '%s'", sec, key, v);
    if (l < lo || l > hi)
        return fail(P, "[%s] %s: %s out of range (%ld..%ld)", sec, key, v, lo, hi);
    *out = (int)l;
    return 1;
}

static int get_rgb(parser *P, const char *sec, const char *key, const char *v, uint32_t *out)
{
    const char *p = *v == '#' ? v + 1 : v;
    size_t n = strspn(p, "0123456789abcdefABCDEF");
    if (n != 6 || p[6])
        return fail(P, "[%s] %s: bad colour '%s' (RRGGBB)", sec, key, v);
    *out = (uint32_t)strtoul(p, NULL, 16) << 8;
    return 1;
}

static int get_bool(parser *P, const char *sec, const char *key, const char *v, int *out)
{
    static const char *const yes[] = {"true", "yes", "on", "1"}, *const no[] = {"false", "no", "off", "0"};
    for (int i = 0; i < 4; i++)
        if (!strcmp(v, yes[i]) || !strcmp(v, no[i])) {
            *out = !strcmp(v, yes[i]);
            return 1;
        }
    return fail(P, "[%s] %s: '%s' is not true or false", sec, key, v);
}

/* A map prefix relative to the scene file's folder (absolute ones stay as they are). */
static int get_map(parser *P, const char *sec, const char *key, const char *v, char *out, size_t n)
{
    if (!*v)
        return fail(P, "[%s] %s: empty", sec, key);
    const char *slash = strrchr(P->path, '/');
    int len = *v == '/' || !slash ? snprintf(out, n, "%s", v)
                                  : snprintf(out, n, "%.*s/%s", (int)(slash - P->path), P->path, v);
    if (len < 0 || (size_t)len >= n)
        return fail(P, "[%s] %s: path too long", sec, key);
    return 1;
}

/* Splits v at blanks and commas into at most max tokens in buf; returns their count, or -1. */
static int split(const char *v, char *buf, size_t n, char **tok, int max)
{
    if (strlen(v) >= n)
        return -1;
    strcpy(buf, v);
    int k = 0;
    for (char *p = strtok(buf, " \t,"); p; p = strtok(NULL, " \t,")) {
        if (k == max)
            return -1;
        tok[k++] = p;
    }
    return k;
}

static int get_key(parser *P, const char *v)
{
    retro_scene *s = P->s;
    char buf[256], *t[6];
    int n = split(v, buf, sizeof buf, t, 6);
    if (n < 5)
        return fail(P, "[path] key: '%s': expected t x y height angle [morph_t]", v);
    if (s->nkeys == RETRO_SCENE_MAX_KEYS)
        return fail(P, "[path] key: too many keys (at most %d)", RETRO_SCENE_MAX_KEYS);
    retro_keyframe k = {.morph_t = NAN};
    if (!get_float(P, "path", "key", t[0], 0, 1, &k.t) ||
        !get_float(P, "path", "key", t[1], -MAX_COORD, MAX_COORD, &k.x) ||
        !get_float(P, "path", "key", t[2], -MAX_COORD, MAX_COORD, &k.y) ||
        !get_int(P, "path", "key", t[3], -MAX_HEIGHT, MAX_HEIGHT, &k.height) ||
        !get_int(P, "path", "key", t[4], -MAX_ANGLE, MAX_ANGLE, &k.angle) ||
        (n == 6 && !get_float(P, "path", "key", t[5], 0, 1, &k.morph_t)))
        return 0;
    if (s->nkeys && k.t <= s->keys[s->nkeys - 1].t)
        return fail(P, "[path] key: t = %s does not increase (previous key: %g)", t[0],
                    (double)s->keys[s->nkeys - 1].t);
    s->keys[s->nkeys++] = k;
    return 1;
}

static int get_sun(parser *P, const char *v, float sun[3])
{
    char buf[256], *t[3];
    float d[3];
    if (split(v, buf, sizeof buf, t, 3) != 3)
        return fail(P, "[shade] sun: '%s': expected three numbers x, y, z", v);
    for (int i = 0; i < 3; i++)
        if (!get_float(P, "shade", "sun", t[i], -1e6, 1e6, &d[i]))
            return 0;
    double len = sqrt((double)d[0] * d[0] + (double)d[1] * d[1] + (double)d[2] * d[2]);
    if (!(len > 1e-9))
        return fail(P, "[shade] sun: '%s' has no direction", v);
    for (int i = 0; i < 3; i++)
        sun[i] = (float)(d[i] / len);
    return 1;
}

/* ---- the handler ----------------------------------------------------------------------- */

static int on_key(parser *P, int sec, const char *k, const char *v)
{
    retro_scene *s = P->s;
    retro_effects *fx = &s->fx;
    const char *sn = SECTIONS[sec].name;
#define KEY(name) (!strcmp(k, name))
#define FLOAT(lo, hi, dst) get_float(P, sn, k, v, lo, hi, dst)
#define INT(lo, hi, dst) get_int(P, sn, k, v, lo, hi, dst)
    if (SECTIONS[sec].fx && KEY("enabled")) {
        int on = 0;
        if (!get_bool(P, sn, k, v, &on))
            return 0;
        fx->flags = on ? fx->flags | SECTIONS[sec].fx : fx->flags & ~SECTIONS[sec].fx;
        return 1;
    }
    switch (sec) {
    case SEC_SCENE:
        if (KEY("map"))
            return get_map(P, sn, k, v, s->map, sizeof s->map);
        if (KEY("sky"))
            return get_rgb(P, sn, k, v, &s->sky);
        break;
    case SEC_CAMERA:
        if (KEY("x"))
            return FLOAT(-MAX_COORD, MAX_COORD, &s->x);
        if (KEY("y"))
            return FLOAT(-MAX_COORD, MAX_COORD, &s->y);
        if (KEY("height"))
            return INT(-MAX_HEIGHT, MAX_HEIGHT, &s->height);
        if (KEY("angle"))
            return INT(-MAX_ANGLE, MAX_ANGLE, &s->angle);
        break;
    case SEC_SCREEN:
        if (KEY("width") || KEY("height")) {
            int *dst = KEY("width") ? &s->W : &s->H;
            if (!INT(1, RETRO_MAX_SCREEN, dst))
                return 0;
            if ((long)s->W * s->H > RETRO_MAX_PIXELS)
                return fail(P, "[%s] %s: %dx%d is more than %ld pixels", sn, k, s->W, s->H,
                            RETRO_MAX_PIXELS);
            return 1;
        }
        if (KEY("distance"))
            return INT(RETRO_MIN_DISTANCE, RETRO_MAX_DISTANCE, &s->D);
        break;
    case SEC_PATH:
        if (KEY("frames")) {
            P->frames_line = P->line;
            return INT(1, MAX_FRAMES, &s->frames);
        }
        if (KEY("key"))
            return get_key(P, v);
        break;
    case SEC_FOG:
        if (KEY("start"))
            return FLOAT(0, RETRO_FX_FOG_DIST_MAX, &fx->fog_start);
        if (KEY("end"))
            return FLOAT(0, RETRO_FX_FOG_DIST_MAX, &fx->fog_end);
        if (KEY("density")) {
            if (!FLOAT(0, RETRO_FX_FOG_DENSITY_MAX, &fx->fog_density))
                return 0;
            if (!(fx->fog_density > 0))
                return fail(P, "[%s] %s: must be above 0", sn, k);
            return fx->fog_exp = 1;
        }
        break;
    case SEC_SHADE:
        if (KEY("sun"))
            return get_sun(P, v, fx->sun);
        if (KEY("ambient"))
            return FLOAT(0, RETRO_FX_SHADE_GAIN_MAX, &fx->ambient);
        if (KEY("diffuse"))
            return FLOAT(0, RETRO_FX_SHADE_GAIN_MAX, &fx->diffuse);
        break;
    case SEC_WATER:
        if (KEY("level"))
            return INT(0, RETRO_FX_WATER_LEVEL_MAX, &fx->water_level);
        if (KEY("color"))
            return get_rgb(P, sn, k, v, &fx->water_color);
        if (KEY("alpha0"))
            return FLOAT(0, 1, &fx->water_alpha0);
        if (KEY("alpha_per_unit"))
            return FLOAT(0, 1, &fx->water_alpha_per_unit);
        break;
    case SEC_LOD:
        if (KEY("rate")) {
            if (!FLOAT(0, 100, &s->lod))
                return 0;
            return s->lod > 0 ? 1 : fail(P, "[%s] %s: must be above 0", sn, k);
        }
        break;
    case SEC_HORIZON:
        if (KEY("pitch"))
            return INT(-RETRO_MAX_SCREEN, RETRO_MAX_SCREEN, &fx->pitch);
        break;
    case SEC_MORPH:
        if (KEY("map"))
            return get_map(P, sn, k, v, s->morph_map, sizeof s->morph_map);
        if (KEY("t"))
            return FLOAT(0, 1, &fx->morph_t);
        break;
    }
#undef KEY
#undef FLOAT
#undef INT
    return fail(P, "[%s] %s: unknown key (%s)", sn, k, SECTIONS[sec].keys);
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
    parser *P = user;
    P->named = 1;
    int sec = find_section(section);
    if (sec < 0)
        return *section ? fail(P, "[%s] %s: unknown section", section, name)
                        : fail(P, "%s: outside any [section]", name);
    return on_key(P, sec, name, value);
}

static void fail_at(parser *P, int line, const char *msg)
{
    P->line = line;
    fail(P, "%s", msg);
}

/* What only the whole file tells: a missing map, a half-given path. Problems are placed at the
 * header of the section that lacks something. */
static void check_whole(parser *P)
{
    retro_scene *s = P->s;
    int top = P->sec_line[SEC_SCENE] ? P->sec_line[SEC_SCENE] : 1;
    if (!s->map[0])
        fail_at(P, top, "[scene] map: missing (the map's prefix, relative to this file)");
    if ((s->fx.flags & RETRO_FX_MORPH) && !s->morph_map[0])
        fail_at(P, P->sec_line[SEC_MORPH] ? P->sec_line[SEC_MORPH] : top,
                "[morph] map: missing (the second height keyframe's prefix)");
    if (s->frames && !s->nkeys)
        fail_at(P, P->frames_line, "[path] key: missing (a path needs at least one key)");
    if (s->nkeys && !s->frames)
        fail_at(P, P->sec_line[SEC_PATH] ? P->sec_line[SEC_PATH] : top,
                "[path] frames: missing (how many frames the path lasts)");
    for (int i = 0; i < s->nkeys; i++)
        if (isnan(s->keys[i].morph_t))
            s->keys[i].morph_t = s->fx.morph_t;
}

int retro_scene_load(const char *path, retro_scene *s, char *err, size_t errlen)
{
    retro_scene_defaults(s);
    parser P = {.s = s, .path = path, .next = 1};
    retro_rfile rf;
    if (retro_rfile_open(&rf, path, MAX_FILE, err, errlen))
        return -1;
    if (!(P.f = fdopen(rf.fd, "r"))) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        retro_rfile_close(&rf);
        return -1;
    }
    int line = ini_parse_stream(read_line, &P, handler, &P);
    fclose(P.f);
    if (P.read_errno) {
        snprintf(err, errlen, "%s: %s", path, strerror(P.read_errno));
        return -1;
    }
    if (line > 0 && (!P.err_line || line < P.err_line)) {
        snprintf(err, errlen, "%s:%d: expected [section] or key = value", path, line);
        return -1;
    }
    if (!P.err_line)
        check_whole(&P);
    if (P.err_line) {
        snprintf(err, errlen, "%s:%d: %s", path, P.err_line, P.err);
        return -1;
    }
    return 0;
}

/* ---- poses ----------------------------------------------------------------------------- */

void retro_scene_pose(const retro_scene *s, int frame, player_t *p, float *morph_t)
{
    memset(p, 0, sizeof *p);
    if (s->nkeys == 0) {
        p->x = s->x;
        p->y = s->y;
        p->height = s->height;
        p->angle = s->angle;
        if (morph_t)
            *morph_t = s->fx.morph_t;
        return;
    }
    double u = s->frames > 1 ? (double)frame / (double)(s->frames - 1) : 0.0;
    const retro_keyframe *a = &s->keys[0], *b = a;
    double w = 0.0;
    if (u >= (double)s->keys[s->nkeys - 1].t)
        a = b = &s->keys[s->nkeys - 1];
    else if (u > (double)a->t) {
        while ((double)b->t <= u)
            a = b++;
        w = (u - (double)a->t) / ((double)b->t - (double)a->t);
    }
    p->x = (float)((double)a->x + ((double)b->x - (double)a->x) * w);
    p->y = (float)((double)a->y + ((double)b->y - (double)a->y) * w);
    p->height = (int)lround(a->height + (b->height - a->height) * w);
    int turn = ((b->angle - a->angle) % 360 + 360) % 360; /* the short way: -179..180 */
    if (turn > 180)
        turn -= 360;
    long angle = lround(a->angle + turn * w) % 360;
    p->angle = (int)(angle < 0 ? angle + 360 : angle);
    if (morph_t)
        *morph_t = (float)((double)a->morph_t + ((double)b->morph_t - (double)a->morph_t) * w);
}
