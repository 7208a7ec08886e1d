/* Shared by the retro subcommands: strict argument parsing and the one-line error. */
#ifndef RETRO_CLI_H
#define RETRO_CLI_H

#include <stddef.h>
#include <stdint.h>

/* Exit code for bad input, per the suite's convention. */
#define CLI_EBADINPUT 2

/* Prints "retro CMD: message" to stderr and returns CLI_EBADINPUT. */
int cli_error(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Strict parsers: the whole string must be a number in range. Return 0 on success. */
int cli_int(const char *s, long lo, long hi, long *out);
int cli_float(const char *s, float *out);
int cli_u64(const char *s, uint64_t *out);
int cli_size(const char *s, int *w, int *h);    /* "WxH" */
int cli_pair(const char *s, float *x, float *y); /* "X,Y" */
int cli_rgb(const char *s, uint32_t *rgb);       /* "RRGGBB" -> R<<24|G<<16|B<<8 */

/* Splits s into its words, the runs of characters other than space and tab: copies s to buf
 * (size bytes) with a NUL after each word and sets words[0..count) to them, words[count] to
 * NULL. Returns the count, or -1 when s has no word, more than max - 1 words, or does not fit
 * in buf (words and buf are then unspecified). */
int cli_words(const char *s, char *buf, size_t size, char **words, int max);

/* Takes the value of option argv[*i] (advancing *i), or NULL when it is missing. */
const char *cli_value(int argc, char **argv, int *i);

/* Whether a is one of names (a NULL-ended list). */
int cli_one_of(const char *a, const char *const *names);

/* The error for option a given last, without a value: that it needs one when it is known to
 * `retro CMD`, else that it is unknown (not one missing its value). Returns CLI_EBADINPUT. */
int cli_no_value(const char *cmd, const char *a, int known);

int cmd_render(int argc, char **argv);
int cmd_kernels(int argc, char **argv);
int cmd_genmap(int argc, char **argv);
int cmd_verify(int argc, char **argv);
int cmd_accuracy(int argc, char **argv);
int cmd_fly(int argc, char **argv);
int cmd_view(int argc, char **argv);

#endif
