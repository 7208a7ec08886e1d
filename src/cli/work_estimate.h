/* How long a frame may take, estimated before rendering (src/cli/work_estimate.c). */
#ifndef RETRO_CLI_WORK_ESTIMATE_H
#define RETRO_CLI_WORK_ESTIMATE_H

#include "retro.h"

/* Above this estimate a frame is announced on stderr. */
#define WORK_WARN_SECONDS 5.0

/* A rough upper estimate, in seconds on one core, of one W x H frame at distance D with k. */
double work_seconds(const retro_kernel *k, int W, int H, long D);
/* Prints "retro CMD: warning: ..." (one line) if the estimate exceeds WORK_WARN_SECONDS;
 * returns whether it did. */
int work_warn(const char *cmd, const retro_kernel *k, int W, int H, long D);

#endif
