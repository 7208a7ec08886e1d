/* What the commands that time frames share: a monotonic clock and an order for medians. */
#ifndef RETRO_CLI_TIMING_H
#define RETRO_CLI_TIMING_H

/* Milliseconds on the monotonic clock. */
double cli_now_ms(void);
/* qsort order of doubles, ascending. */
int cli_cmp_double(const void *a, const void *b);

#endif
