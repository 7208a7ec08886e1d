/* Whether the machine kept its speed through a retro accuracy run. The variants of one pose are
 * timed in turn, but the table's medians pool poses timed up to a minute apart, so a machine
 * that slows down between scenes moves them; a reference frame timed at checkpoints through
 * the run says whether it did, as make bench's Machine steadiness does for its run. */
#ifndef RETRO_ACCURACY_STEADY_H
#define RETRO_ACCURACY_STEADY_H

#include <stdio.h>

enum { ACC_STEADY_MAX = 256 };
/* Above this spread of the reference frame's checkpoints the run is marked noisy, the
 * threshold of make bench. */
#define ACC_STEADY_NOISY 0.10
/* A checkpoint times each kernel for at least this many frames and this long. Fifteen frames
 * of the fastest kernel last about 2 ms, short enough that one preemption of the virtual CPU
 * moves their median; tens of milliseconds see the machine's speed, not one moment of it. */
enum { ACC_STEADY_MIN_FRAMES = 15, ACC_STEADY_MAX_FRAMES = 1024 };
#define ACC_STEADY_MIN_MS 40.0

typedef struct {
    double at_s;       /* when the checkpoint finished, seconds into the run */
    double best, ybuf; /* the reference frame's median ms: fastest exact kernel, ybuffer */
    char where[64];    /* e.g. "before valley, pose 5" */
} acc_checkpoint;

typedef struct {
    acc_checkpoint cp[ACC_STEADY_MAX];
    int n;
    const char *best_kernel; /* the fastest kernel's name */
    const char *ref;         /* what the reference frame is, for the report */
} acc_steady;

/* (max - min) / median of one column (ybuf when 1, else best) over the checkpoints; 0 for
 * fewer than two. */
double acc_steady_spread(const acc_steady *s, int ybuf);
int acc_steady_noisy(const acc_steady *s);
/* The note that goes at the top of a noisy run's report; nothing for a steady one. */
void acc_steady_write_note(FILE *f, const acc_steady *s);
/* The report's Machine steadiness section: every checkpoint and the two spreads. */
void acc_steady_write_table(FILE *f, const acc_steady *s);

#endif
