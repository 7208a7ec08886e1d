/* Error of a frame against mode truth (docs/ACCURACY.md, "Error figures") and the report. */
#ifndef RETRO_ACCURACY_METRICS_H
#define RETRO_ACCURACY_METRICS_H

#include <stddef.h>
#include <stdint.h>

#include "accuracy_steady.h"
#include "render.h"

typedef struct {
    double frames;
    double pixel_frac;   /* sum over frames of the fraction of differing pixels */
    double col_frac;     /* sum over frames of the fraction of columns whose silhouette differs */
    double sil_sum;      /* sum of |silhouette error| in rows over all columns of all frames */
    double columns;
    int sil_max;
    double sq_err;       /* sum of squared byte errors over R, G, B */
    double bytes;
} acc_stats;

typedef struct {
    const char *family;        /* "voxel" or "mesh" (the families table) */
    const char *label, *what, *kernel;
    double ms, speedup;        /* the fastest kernel for the variant's mode */
    double ms_y, speedup_y;    /* ybuffer, the same scalar kernel for every variant */
    double pixel_pct, col_pct, sil_mean, psnr;
    int sil_max;
} acc_row;

/* A uniform double in [0, 1) from a splitmix64 state: the poses are seeded and portable. */
double acc_rand(uint64_t *state);
/* A seeded random pose over an S x S height map: x, y in [0, S) (rand * S rounds up to S for
 * draws near 1, so the position is reduced modulo S), angle 0..359, height 20..199 above the
 * ground under it. */
void acc_pose(uint64_t *rng, int S, const uint8_t *height, player_t *p);
void acc_compare(acc_stats *s, const uint32_t *truth, const uint32_t *img, int W, int H, uint32_t sky);
void acc_summary(const acc_stats *s, acc_row *row);
/* Longest report or chart path accepted, so derived names (.tmp, .png) always fit. */
#define ACC_PATH_MAX 4000
/* 1 when path may name a report or chart: not empty, shorter than ACC_PATH_MAX, and free of
 * control characters (gnuplot reads it inside its script). */
int acc_path_ok(const char *path);

/* The families table (docs/ACCURACY.md, "Across families"): every row against the mesh in
 * binary64, over fam_poses poses, and its chart. */
typedef struct {
    const acc_row *rows;
    int n, poses;
    const char *svg;
    const char *pair; /* the picture pair's prefix beside the table, or NULL */
} acc_families;

/* Writes the Markdown table to md and the Pareto chart to svg (through gnuplot), then the
 * families table and its chart when fam is not NULL, then the run's steadiness. */
int acc_write_report(const char *md, const char *svg, const acc_row *rows, int n, int poses,
                     uint64_t seed, const acc_families *fam, const acc_steady *steady, char *err,
                     size_t errlen);

#endif
