/* One way for the library's parsers and file code to report an error: a one-line message
 * formatted into the caller's buffer (which may be NULL or empty), and -1 to return. */
#ifndef RETRO_ERRF_H
#define RETRO_ERRF_H

#include <stddef.h>

int retro_errf(char *err, size_t n, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Keeps a message to one line whatever a quoted value holds (a newline in a path, a file's
 * bytes, an environment value): its control bytes become '?'. */
void retro_one_line(char *msg);

#endif
