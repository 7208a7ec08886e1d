/* Shared by the fuzz targets of string parsers (fuzz_cli, fuzz_keys). */
#ifndef RETRO_FUZZ_STRING_H
#define RETRO_FUZZ_STRING_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* The input as the parsers meet it in an argv entry or an environment value: a C string, cut
 * at the first NUL and at max bytes (s holds max + 1). */
static inline void fuzz_string(const uint8_t *data, size_t size, char *s, size_t max)
{
    size_t n = size < max ? size : max;
    memcpy(s, data, n);
    s[n] = 0;
}

/* Whether err holds a parser's reason as the suite's errors must be: not empty, ended within
 * its size bytes, one line. */
static inline int fuzz_one_line(const char *err, size_t size)
{
    const char *end = memchr(err, 0, size);
    return end && end != err && !memchr(err, '\n', (size_t)(end - err));
}

#endif
