/* Scene files: every value parsed, every problem one line naming FILE:LINE, [section] and key;
 * fly-through poses interpolated linearly, angles the short way round. */
#include <criterion/criterion.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "retro_scene.h"

static char dir[] = "/tmp/retro-scene-XXXXXX";
static char path[512];
static char err[2048];

static void setup(void) { cr_assert(mkdtemp(dir)); }
static void teardown(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    cr_assert_eq(system(cmd), 0);
}

TestSuite(scene, .init = setup, .fini = teardown);

/* Writes dir/NAME and sets path to it. */
static const char *put(const char *name, const char *text)
{
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    cr_assert(f, "cannot write %s", path);
    fputs(text, f);
    fclose(f);
    return path;
}

static void load_ok(const char *text, retro_scene *s)
{
    put("ok.scene", text);
    err[0] = 0;
    cr_assert_eq(retro_scene_load(path, s, err, sizeof err), 0, "%s", err);
}

/* The file fails to load with exactly "PATH:LINE: expect..." on one line. */
static void load_fails(const char *text, int line, const char *expect)
{
    retro_scene s;
    char want[1024];
    put("bad.scene", text);
    err[0] = 0;
    cr_assert_eq(retro_scene_load(path, &s, err, sizeof err), -1, "loaded, expected: %s", expect);
    snprintf(want, sizeof want, "%s:%d: %s", path, line, expect);
    cr_assert(!strncmp(err, want, strlen(want)), "got '%s', want '%s...'", err, want);
    cr_assert(!strchr(err, '\n'), "not one line: %s", err);
}

#define EQF(a, b) cr_assert_float_eq((double)(a), (double)(b), 1e-6, "%s = %g, want %g", #a, (double)(a), (double)(b))

Test(scene, defaults)
{
    retro_scene s;
    retro_scene_defaults(&s);
    cr_assert_str_eq(s.map, "");
    cr_assert_str_eq(s.morph_map, "");
    cr_assert_eq(s.sky, 0x66a3ff00u);
    cr_assert(isnan(s.x) && isnan(s.y), "position: the map's default view");
    cr_assert_eq(s.height, INT_MIN);
    cr_assert_eq(s.angle, 0);
    cr_assert_eq(s.W, 640);
    cr_assert_eq(s.H, 480);
    cr_assert_eq(s.D, 800);
    cr_assert_eq(s.frames, 0);
    cr_assert_eq(s.nkeys, 0);

    const retro_effects *fx = &s.fx;
    cr_assert_eq(fx->flags, 0u);
    cr_assert_eq(fx->fog_exp, 0);
    EQF(fx->fog_start, 300);
    EQF(fx->fog_end, 800);
    EQF(fx->fog_density, 0.003);
    double len = sqrt(-0.5 * -0.5 + -0.6 * -0.6 + 0.62 * 0.62);
    EQF(fx->sun[0], -0.5 / len);
    EQF(fx->sun[1], -0.6 / len);
    EQF(fx->sun[2], 0.62 / len);
    EQF(fx->ambient, 0.35);
    EQF(fx->diffuse, 0.8);
    cr_assert_eq(fx->water_level, 64);
    cr_assert_eq(fx->water_color, 0x1e5aa000u);
    EQF(fx->water_alpha0, 0.35);
    EQF(fx->water_alpha_per_unit, 0.03);
    EQF(s.lod, 0.02);
    cr_assert_eq(fx->pitch, 0);
    cr_assert_null(fx->morph_height);
    EQF(fx->morph_t, 0);
}

Test(scene, a_map_alone_keeps_every_default)
{
    retro_scene s, d;
    load_ok("[scene]\nmap = islands\n", &s);
    retro_scene_defaults(&d);
    strcpy(d.map, s.map);
    cr_assert(isnan(s.x) && isnan(s.y));
    s.x = s.y = d.x = d.y = 0; /* NaN != NaN */
    cr_assert(!memcmp(&s, &d, sizeof s), "a file naming only its map differs from the defaults");
}

Test(scene, every_section)
{
    retro_scene s;
    load_ok("; a comment\n"
            "[scene]\nmap = islands ; inline comment\nsky = 87b5e8\n"
            "[camera]\nx = 300.5\ny = -700\nheight = 140\nangle = 30\n"
            "[screen]\nwidth = 320\nheight = 200\ndistance = 1200\n"
            "[path]\nframes = 60\n"
            "key = 0.0 300 700 140 30 0.25\n"
            "key = 0.5, 500, 650, 145, 60\n"
            "key = 1.0 700 600 150 90 1\n"
            "[fog]\nstart = 100\nend = 900\ndensity = 0.005\n"
            "[shade]\nsun = 0, 3, 4\nambient = 0.25\ndiffuse = 1.5\n"
            "[water]\nlevel = 70\ncolor = #102030\nalpha0 = 0.5\nalpha_per_unit = 0.1\n"
            "[bilinear]\nenabled = true\n"
            "[lod]\nrate = 0.05\n"
            "[horizon]\npitch = -40\n"
            "[morph]\nmap = islands-low\nt = 0.75\n",
            &s);
    char want[600];
    snprintf(want, sizeof want, "%s/islands", dir);
    cr_assert_str_eq(s.map, want);
    snprintf(want, sizeof want, "%s/islands-low", dir);
    cr_assert_str_eq(s.morph_map, want);
    cr_assert_eq(s.sky, 0x87b5e800u);
    EQF(s.x, 300.5);
    EQF(s.y, -700);
    cr_assert_eq(s.height, 140);
    cr_assert_eq(s.angle, 30);
    cr_assert_eq(s.W, 320);
    cr_assert_eq(s.H, 200);
    cr_assert_eq(s.D, 1200);
    cr_assert_eq(s.frames, 60);
    cr_assert_eq(s.nkeys, 3);
    EQF(s.keys[1].t, 0.5);
    EQF(s.keys[1].x, 500);
    EQF(s.keys[1].y, 650);
    cr_assert_eq(s.keys[1].height, 145);
    cr_assert_eq(s.keys[1].angle, 60);
    EQF(s.keys[0].morph_t, 0.25);
    EQF(s.keys[1].morph_t, 0.75); /* none given: the [morph] t */
    EQF(s.keys[2].morph_t, 1);

    const retro_effects *fx = &s.fx;
    cr_assert_eq(fx->flags, (unsigned)RETRO_FX_VOXEL);
    cr_assert_eq(fx->fog_exp, 1);
    EQF(fx->fog_start, 100);
    EQF(fx->fog_end, 900);
    EQF(fx->fog_density, 0.005);
    EQF(fx->sun[0], 0);
    EQF(fx->sun[1], 0.6);
    EQF(fx->sun[2], 0.8);
    EQF(fx->ambient, 0.25);
    EQF(fx->diffuse, 1.5);
    cr_assert_eq(fx->water_level, 70);
    cr_assert_eq(fx->water_color, 0x10203000u);
    EQF(fx->water_alpha0, 0.5);
    EQF(fx->water_alpha_per_unit, 0.1);
    EQF(s.lod, 0.05);
    cr_assert_eq(fx->pitch, -40);
    EQF(fx->morph_t, 0.75);
    cr_assert_null(fx->morph_height, "the caller loads the keyframe");
}

Test(scene, effects_on_by_section_off_by_enabled_false)
{
    retro_scene s;
    load_ok("[scene]\nmap = m\n[bilinear]\n[fog]\nstart = 10\nenabled = false\n"
            "[water]\nenabled = no\n[water]\nenabled = yes\n[lod]\nenabled = off\n",
            &s);
    cr_assert_eq(s.fx.flags, (unsigned)(RETRO_FX_BILINEAR | RETRO_FX_WATER));
    cr_assert_eq(s.fx.fog_exp, 0, "linear unless density is given");
    EQF(s.fx.fog_start, 10);
}

Test(scene, maps_resolve_against_the_scene_folder)
{
    retro_scene s;
    char want[600];
    mkdir(strcat(strcpy(want, dir), "/sub"), 0777);
    put("sub/deep.scene", "[scene]\nmap = ../maps/islands\n[morph]\nmap = /abs/low\n");
    cr_assert_eq(retro_scene_load(path, &s, err, sizeof err), 0, "%s", err);
    snprintf(want, sizeof want, "%s/sub/../maps/islands", dir);
    cr_assert_str_eq(s.map, want);
    cr_assert_str_eq(s.morph_map, "/abs/low", "absolute prefixes stay as they are");

    cr_assert_eq(chdir(dir), 0);
    cr_assert_eq(retro_scene_load("sub/deep.scene", &s, err, sizeof err), 0, "%s", err);
    cr_assert_str_eq(s.map, "sub/../maps/islands");
    put("here.scene", "[scene]\nmap = islands\n");
    cr_assert_eq(retro_scene_load("here.scene", &s, err, sizeof err), 0, "%s", err);
    cr_assert_str_eq(s.map, "islands", "a scene in the current folder: the prefix as written");
}

Test(scene, missing_file)
{
    retro_scene s;
    snprintf(path, sizeof path, "%s/none.scene", dir);
    cr_assert_eq(retro_scene_load(path, &s, err, sizeof err), -1);
    char want[600];
    snprintf(want, sizeof want, "%s: No such file or directory", path);
    cr_assert_str_eq(err, want);
}

Test(scene, unknown_section) { load_fails("[scene]\nmap = m\n[fgo]\nstart = 3\n", 3, "[fgo]: unknown section"); }
Test(scene, unknown_empty_section) { load_fails("[scene]\nmap = m\n\n[sahde]\n", 4, "[sahde]: unknown section"); }
Test(scene, key_outside_a_section) { load_fails("map = m\n", 1, "map: outside any [section]"); }
Test(scene, unknown_key) { load_fails("[scene]\nmap = m\n[camera]\nx = 1\nangel = 3\n", 5, "[camera] angel: unknown key"); }
Test(scene, unknown_key_in_effect) { load_fails("[scene]\nmap = m\n[bilinear]\nrate = 2\n", 4, "[bilinear] rate: unknown key"); }
Test(scene, bad_number) { load_fails("[scene]\nmap = m\n[camera]\nx = 12abc\n", 4, "[camera] x: bad number '12abc'"); }
Test(scene, non_finite_number) { load_fails("[scene]\nmap = m\n[camera]\ny = nan\n", 4, "[camera] y: bad number 'nan'"); }
Test(scene, bad_integer) { load_fails("[scene]\nmap = m\n[camera]\nheight = 1.5\n", 4, "[camera] height: bad integer '1.5'"); }
Test(scene, empty_value) { load_fails("[scene]\nmap = m\n[screen]\nwidth =\n", 4, "[screen] width: bad integer ''"); }
Test(scene, bad_colour) { load_fails("[scene]\nsky = 87b5e\nmap = m\n", 2, "[scene] sky: bad colour '87b5e'"); }
Test(scene, bad_bool) { load_fails("[scene]\nmap = m\n[bilinear]\nenabled = maybe\n", 4, "[bilinear] enabled: 'maybe' is not true or false"); }
Test(scene, out_of_range) { load_fails("[scene]\nmap = m\n[water]\nlevel = 300\n", 4, "[water] level: 300 out of range (0..255)"); }
Test(scene, out_of_range_float) { load_fails("[scene]\nmap = m\n[morph]\nmap = n\nt = 1.5\n", 5, "[morph] t: 1.5 out of range (0..1)"); }
Test(scene, zero_screen) { load_fails("[scene]\nmap = m\n[screen]\nheight = 0\n", 4, "[screen] height: 0 out of range"); }
Test(scene, too_many_pixels) { load_fails("[scene]\nmap = m\n[screen]\nwidth = 16384\nheight = 16384\n", 5, "[screen] height: 16384x16384 is more than"); }
Test(scene, zero_density) { load_fails("[scene]\nmap = m\n[fog]\ndensity = 0\n", 4, "[fog] density: must be above 0"); }
Test(scene, sun_without_direction) { load_fails("[scene]\nmap = m\n[shade]\nsun = 0, 0, 0\n", 4, "[shade] sun: '0, 0, 0' has no direction"); }
Test(scene, sun_needs_three) { load_fails("[scene]\nmap = m\n[shade]\nsun = 1, 2\n", 4, "[shade] sun: '1, 2': expected three numbers"); }
Test(scene, syntax_error) { load_fails("[scene]\nmap = m\n[camera]\nx 3\n", 4, "expected [section] or key = value"); }
Test(scene, first_problem_wins) { load_fails("[scene]\nmap = m\n[camera]\nx = a\ny = b\n[nope]\n", 4, "[camera] x: bad number 'a'"); }
Test(scene, syntax_error_before_a_bad_value) { load_fails("[scene]\nmap = m\nbroken\n[camera]\nx = a\n", 3, "expected [section] or key = value"); }

Test(scene, keys_not_increasing)
{
    load_fails("[scene]\nmap = m\n[path]\nframes = 10\nkey = 0.5 0 0 100 0\nkey = 0.5 1 1 100 0\n", 6,
               "[path] key: t = 0.5 does not increase");
}
Test(scene, key_too_short) { load_fails("[scene]\nmap = m\n[path]\nframes = 2\nkey = 0 1 2 3\n", 5, "[path] key: '0 1 2 3': expected t x y height angle"); }
Test(scene, key_bad_number) { load_fails("[scene]\nmap = m\n[path]\nframes = 2\nkey = 0 1 2 3.5 0\n", 5, "[path] key: bad integer '3.5'"); }
Test(scene, key_t_out_of_range) { load_fails("[scene]\nmap = m\n[path]\nframes = 2\nkey = 1.5 1 2 3 0\n", 5, "[path] key: 1.5 out of range (0..1)"); }

Test(scene, too_many_keys)
{
    char text[8192];
    int n = snprintf(text, sizeof text, "[scene]\nmap = m\n[path]\nframes = 100\n");
    for (int i = 0; i <= RETRO_SCENE_MAX_KEYS; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, "key = %g 0 0 100 0\n", i / 100.0);
    char want[64];
    snprintf(want, sizeof want, "[path] key: too many keys (at most %d)", RETRO_SCENE_MAX_KEYS);
    load_fails(text, 4 + RETRO_SCENE_MAX_KEYS + 1, want);
}

Test(scene, missing_map_at_the_scene_header) { load_fails("[camera]\nx = 1\n\n[scene]\nsky = 000000\n", 4, "[scene] map: missing"); }
Test(scene, missing_map_without_scene_section) { load_fails("[camera]\nx = 1\n", 1, "[scene] map: missing"); }
Test(scene, missing_morph_map) { load_fails("[scene]\nmap = m\n\n[morph]\nt = 0.5\n", 4, "[morph] map: missing"); }
Test(scene, frames_without_keys) { load_fails("[scene]\nmap = m\n[path]\nframes = 10\n", 4, "[path] key: missing"); }
Test(scene, keys_without_frames) { load_fails("[scene]\nmap = m\n[path]\nkey = 0 1 2 3 4\n", 3, "[path] frames: missing"); }

Test(scene, line_too_long)
{
    char text[1024];
    snprintf(text, sizeof text, "[scene]\nmap = m\n[camera]\nx = 1%0400d\n", 0);
    load_fails(text, 4, "line longer than");
}

/* ---- poses ----------------------------------------------------------------------------- */

static retro_scene path_scene(int frames, int n, const retro_keyframe *keys)
{
    retro_scene s;
    retro_scene_defaults(&s);
    s.frames = frames;
    s.nkeys = n;
    memcpy(s.keys, keys, (size_t)n * sizeof *keys);
    return s;
}

static void expect_pose(const retro_scene *s, int frame, float x, float y, int height, int angle)
{
    player_t p;
    retro_scene_pose(s, frame, &p, NULL);
    cr_assert_float_eq(p.x, x, 1e-4, "frame %d: x %g, want %g", frame, (double)p.x, (double)x);
    cr_assert_float_eq(p.y, y, 1e-4, "frame %d: y %g, want %g", frame, (double)p.y, (double)y);
    cr_assert_eq(p.height, height, "frame %d: height %d, want %d", frame, p.height, height);
    cr_assert_eq(p.angle, angle, "frame %d: angle %d, want %d", frame, p.angle, angle);
    cr_assert_eq(p.v, 0);
}

Test(scene, pose_without_path_is_the_camera)
{
    retro_scene s;
    retro_scene_defaults(&s);
    s.x = 10;
    s.y = 20;
    s.height = 30;
    s.angle = 40;
    s.fx.morph_t = 0.5f;
    float t = -1;
    player_t p;
    retro_scene_pose(&s, 7, &p, &t);
    cr_assert(p.x == 10 && p.y == 20 && p.height == 30 && p.angle == 40);
    EQF(t, 0.5);
}

Test(scene, pose_linear_between_keys)
{
    retro_keyframe k[2] = {{0, 0, 0, 100, 30, 0}, {1, 100, 50, 200, 90, 0}};
    retro_scene s = path_scene(5, 2, k);
    expect_pose(&s, 0, 0, 0, 100, 30);
    expect_pose(&s, 1, 25, 12.5f, 125, 45);
    expect_pose(&s, 2, 50, 25, 150, 60);
    expect_pose(&s, 4, 100, 50, 200, 90);
    expect_pose(&s, 9, 100, 50, 200, 90);   /* past the end: the last key */
    expect_pose(&s, -3, 0, 0, 100, 30);     /* before the start: the first */
}

Test(scene, pose_angles_the_short_way)
{
    retro_keyframe k[2] = {{0, 0, 0, 0, 350, 0}, {1, 0, 0, 0, 10, 0}};
    retro_scene s = path_scene(5, 2, k);
    expect_pose(&s, 1, 0, 0, 0, 355);
    expect_pose(&s, 2, 0, 0, 0, 0);
    expect_pose(&s, 3, 0, 0, 0, 5);
    retro_keyframe r[2] = {{0, 0, 0, 0, 10, 0}, {1, 0, 0, 0, 350, 0}};
    s = path_scene(5, 2, r);
    expect_pose(&s, 1, 0, 0, 0, 5);
    expect_pose(&s, 3, 0, 0, 0, 355);
    retro_keyframe w[2] = {{0, 0, 0, 0, -90, 0}, {1, 0, 0, 0, 720, 0}};
    s = path_scene(3, 2, w);
    expect_pose(&s, 1, 0, 0, 0, 315); /* -90 = 270 to 720 = 0: a quarter turn up */
}

Test(scene, pose_uneven_keys_and_rounding)
{
    retro_keyframe k[3] = {{0, 0, 0, 0, 0, 0}, {0.25f, 100, 0, 1, 0, 0}, {1, 400, 0, 4, 0, 0}};
    retro_scene s = path_scene(9, 3, k);
    expect_pose(&s, 1, 50, 0, 1, 0);  /* height 0.5 rounds to 1 */
    expect_pose(&s, 2, 100, 0, 1, 0);
    expect_pose(&s, 5, 250, 0, 3, 0); /* 2.5 rounds away from zero */
    expect_pose(&s, 8, 400, 0, 4, 0);
}

Test(scene, pose_one_frame_is_the_start)
{
    retro_keyframe k[2] = {{0.2f, 5, 6, 7, 8, 0}, {1, 50, 60, 70, 80, 0}};
    retro_scene s = path_scene(1, 2, k);
    expect_pose(&s, 0, 5, 6, 7, 8);
}

Test(scene, pose_morph_time)
{
    retro_scene s;
    load_ok("[scene]\nmap = m\n[path]\nframes = 11\n"
            "key = 0 0 0 100 0 0\nkey = 0.5 0 0 100 0\nkey = 1 0 0 100 0 1\n"
            "[morph]\nmap = n\nt = 0.2\n", &s);
    float t;
    player_t p;
    retro_scene_pose(&s, 0, &p, &t);
    EQF(t, 0);
    retro_scene_pose(&s, 3, &p, &t);
    EQF(t, 0.12); /* 0 to 0.2 (the [morph] t of the middle key) */
    retro_scene_pose(&s, 5, &p, &t);
    EQF(t, 0.2);
    retro_scene_pose(&s, 8, &p, &t);
    EQF(t, 0.68);
    retro_scene_pose(&s, 10, &p, &t);
    EQF(t, 1);
}

Test(scene, committed_scenes_load)
{
    static const char *const names[] = {"islands", "alpine", "canyon", "tide"};
    for (int i = 0; i < 4; i++) {
        retro_scene s;
        char file[64];
        snprintf(file, sizeof file, "maps/%s.scene", names[i]);
        cr_assert_eq(retro_scene_load(file, &s, err, sizeof err), 0, "%s", err);
        cr_assert(s.fx.flags, "%s calls for no effect", file);
    }
}

Test(scene, longest_line_and_bom)
{
    retro_scene s;
    char text[1024], line[256];
    /* 197 characters: the longest line inih promises to take (200 with \r\n\0). */
    snprintf(line, sizeof line, "x = 12 ;%0189d", 0);
    cr_assert_eq(strlen(line), 197);
    snprintf(text, sizeof text, "\xEF\xBB\xBF[scene]\nmap = m\n[camera]\n%s\ny = 5\n", line);
    load_ok(text, &s);
    EQF(s.x, 12);
    EQF(s.y, 5);
    snprintf(text, sizeof text, "[scene]\nmap = m\n[camera]\n%s00\ny = 5\n", line);
    load_fails(text, 4, "line longer than 197 characters");
}
