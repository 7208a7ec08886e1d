/* Strict argument parsing: "12abc", "", out-of-range and non-finite values are errors. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "errf.h"

int cli_error(const char *cmd, const char *fmt, ...)
{
    char msg[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    retro_one_line(msg);
    fprintf(stderr, "retro %s: %s\n", cmd, msg);
    return CLI_EBADINPUT;
}

int cli_int(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (!*s || *end || errno || v < lo || v > hi)
        return -1;
    *out = v;
    return 0;
}

int cli_u64(const char *s, uint64_t *out)
{
    char *end;
    errno = 0;
    /* strtoull skips blanks and negates after a minus sign: " -5" would be 2^64 - 5. */
    if (!*s || strchr(s, '-'))
        return -1;
    unsigned long long v = strtoull(s, &end, 10);
    if (*end || errno)
        return -1;
    *out = (uint64_t)v;
    return 0;
}

int cli_float(const char *s, float *out)
{
    char *end;
    errno = 0;
    float v = strtof(s, &end);
    /* ERANGE on underflow still gives the nearest float (a subnormal or 0), which is valid;
     * on overflow it gives an infinity, refused as not finite. */
    if (!*s || *end || !isfinite(v))
        return -1;
    *out = v;
    return 0;
}

/* Splits "AsepB" at the first sep into two NUL-terminated copies. */
static int split(const char *s, char sep, char *a, char *b, size_t n)
{
    const char *p = strchr(s, sep);
    if (!p || (size_t)(p - s) >= n || strlen(p + 1) >= n)
        return -1;
    memcpy(a, s, (size_t)(p - s));
    a[p - s] = 0;
    strcpy(b, p + 1);
    return 0;
}

int cli_size(const char *s, int *w, int *h)
{
    char a[32], b[32];
    long x, y;
    if (split(s, 'x', a, b, sizeof a) || cli_int(a, 1, 1L << 30, &x) || cli_int(b, 1, 1L << 30, &y))
        return -1;
    *w = (int)x;
    *h = (int)y;
    return 0;
}

int cli_pair(const char *s, float *x, float *y)
{
    char a[64], b[64];
    if (split(s, ',', a, b, sizeof a) || cli_float(a, x) || cli_float(b, y))
        return -1;
    return 0;
}

int cli_rgb(const char *s, uint32_t *rgb)
{
    const char *p = s[0] == '#' ? s + 1 : s;
    char *end;
    if (strlen(p) != 6)
        return -1;
    /* Six hex digits only: strtoul would also take blanks, a sign or 0x ("-00001" is ffffff). */
    for (int i = 0; i < 6; i++)
        if (!isxdigit((unsigned char)p[i]))
            return -1;
    unsigned long v = strtoul(p, &end, 16);
    if (*end)
        return -1;
    *rgb = (uint32_t)v << 8;
    return 0;
}

int cli_one_of(const char *a, const char *const *names)
{
    for (; *names; names++)
        if (!strcmp(a, *names))
            return 1;
    return 0;
}

int cli_no_value(const char *cmd, const char *a, int known)
{
    return known ? cli_error(cmd, "option %s needs a value (retro %s --help)", a, cmd)
                 : cli_error(cmd, "unknown option '%s' (retro %s --help)", a, cmd);
}

const char *cli_value(int argc, char **argv, int *i)
{
    if (*i + 1 >= argc)
        return NULL;
    return argv[++*i];
}

int cli_words(const char *s, char *buf, size_t size, char **words, int max)
{
    size_t len = strlen(s);
    if (len >= size || max < 2)
        return -1;
    memcpy(buf, s, len + 1);
    int n = 0;
    for (char *c = buf; *c;) {
        if (*c == ' ' || *c == '\t') {
            *c++ = 0;
            continue;
        }
        if (n == max - 1)
            return -1;
        words[n++] = c;
        while (*c && *c != ' ' && *c != '\t')
            c++;
    }
    words[n] = NULL;
    return n ? n : -1;
}
