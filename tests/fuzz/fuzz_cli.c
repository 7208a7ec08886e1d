/* libFuzzer target: the retro CLI's strict argument parsers (src/cli/cli_args.c) against a
 * grammar written out here. Each parser must accept exactly the well-formed strings in range,
 * return the value they spell, and leave its outputs alone when it fails:
 *   cli_int    [ws][+-]digits, in [lo, hi]          (strtol's leading blanks and sign)
 *   cli_u64    [ws][+]digits, below 2^64            (no minus sign anywhere)
 *   cli_float  [ws][+-] decimal or hex float, finite; the value strtof gives
 *   cli_size   INTxINT, each 1..2^30, split at the first 'x'
 *   cli_pair   FLOAT,FLOAT, split at the first ','
 *   cli_rgb    [#] and exactly six hex digits -> RRGGBB << 8
 *   cli_words  the runs of characters other than space and tab, in order (retro render
 *              --versus ARGS); none, too many or a buffer too small: an error
 *   retro_env_long  (the environment's integers, src/core/env.c) [-]digits, at most 18, in
 *              [lo, hi]; set but empty or malformed: -1 with a one-line reason
 *   OMP_NUM_THREADS  (retro_env_check) counts 1..1048576 of 1 to 15 digits, split by commas
 * cli_float must accept every well-formed number strtof takes to a finite float: one that
 * underflows (ERANGE) to a subnormal or zero is valid too. Besides the input string, values
 * decoded from the input are printed in canonical form and must parse back exactly. */
#include <ctype.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "env.h"
#include "fuzz_string.h"

#define MAX_LEN 200

static void fail(const char *parser, const char *s, const char *why)
{
    fprintf(stderr, "%s(\"", parser);
    for (const char *p = s; *p; p++)
        fprintf(stderr, isprint((unsigned char)*p) ? "%c" : "\\x%02x", (unsigned char)*p);
    fprintf(stderr, "\"): %s\n", why);
    abort();
}

static const char *blanks(const char *s)
{
    while (*s == ' ' || (*s >= '\t' && *s <= '\r'))
        s++;
    return s;
}

/* [ws][sign]digits with nothing after; *neg and the magnitude (saturated at 2^64 - 1 with
 * *over set) describe it. */
static int int_grammar(const char *s, int allow_minus, int *neg, uint64_t *mag, int *over)
{
    s = blanks(s);
    *neg = 0;
    if (*s == '+' || *s == '-') {
        if (*s == '-' && !allow_minus)
            return 0;
        *neg = *s == '-';
        s++;
    }
    if (!isdigit((unsigned char)*s))
        return 0;
    *mag = 0;
    *over = 0;
    for (; isdigit((unsigned char)*s); s++) {
        unsigned dgt = (unsigned)(*s - '0');
        if (*mag > (UINT64_MAX - dgt) / 10)
            *over = 1;
        else
            *mag = *mag * 10 + dgt;
    }
    return *s == 0;
}

/* The value of a well-formed integer string if it lies in [lo, hi]. */
static int int_in_range(const char *s, long lo, long hi, long *v)
{
    int neg, over;
    uint64_t mag;
    if (!int_grammar(s, 1, &neg, &mag, &over) || over)
        return 0;
    if (!neg && mag > (uint64_t)LONG_MAX)
        return 0;
    if (neg && mag > (uint64_t)LONG_MAX + 1)
        return 0;
    long x = neg ? (mag == (uint64_t)LONG_MAX + 1 ? LONG_MIN : -(long)mag) : (long)mag;
    if (x < lo || x > hi)
        return 0;
    *v = x;
    return 1;
}

static void check_int(const char *s, long lo, long hi)
{
    long want = 0, got = 12345;
    int ok = int_in_range(s, lo, hi, &want);
    int r = cli_int(s, lo, hi, &got);
    if (r != 0 && r != -1)
        fail("cli_int", s, "returned neither 0 nor -1");
    if (ok && r)
        fail("cli_int", s, "refused a well-formed integer in range");
    if (!ok && !r)
        fail("cli_int", s, "accepted a malformed or out-of-range integer");
    if (ok && got != want)
        fail("cli_int", s, "returned the wrong value");
    if (!ok && got != 12345)
        fail("cli_int", s, "wrote its output on failure");
}

static void check_u64(const char *s)
{
    int neg, over;
    uint64_t mag = 0, got = 777;
    int ok = int_grammar(s, 0, &neg, &mag, &over) && !over;
    int r = cli_u64(s, &got);
    if (ok != (r == 0))
        fail("cli_u64", s, ok ? "refused a well-formed value" : "accepted a malformed or negative value");
    if (ok && got != mag)
        fail("cli_u64", s, "returned the wrong value");
    if (!ok && got != 777)
        fail("cli_u64", s, "wrote its output on failure");
}

static int hexdigits(const char **p)
{
    int n = 0;
    while (isxdigit((unsigned char)**p))
        (*p)++, n++;
    return n;
}

static int digits(const char **p)
{
    int n = 0;
    while (isdigit((unsigned char)**p))
        (*p)++, n++;
    return n;
}

/* strtof's grammar for a finite number: [ws][+-] then a decimal with an optional exponent or
 * a hex float with an optional binary exponent. */
static int float_grammar(const char *s)
{
    s = blanks(s);
    if (*s == '+' || *s == '-')
        s++;
    int hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    /* "0x" with no hex digit after it is strtof's "0" followed by junk: malformed. */
    if (hex && !(isxdigit((unsigned char)s[2]) || (s[2] == '.' && isxdigit((unsigned char)s[3]))))
        return 0;
    if (hex)
        s += 2;
    int (*run)(const char **) = hex ? hexdigits : digits;
    int n = run(&s);
    if (*s == '.') {
        s++;
        n += run(&s);
    }
    if (!n)
        return 0;
    char e = hex ? 'p' : 'e';
    if (tolower((unsigned char)*s) == e) {
        const char *t = s + 1;
        if (*t == '+' || *t == '-')
            t++;
        if (digits(&t))
            s = t;
    }
    return *s == 0;
}

/* Well-formed and finite as a float: cli_float has no excuse to refuse it. */
static int float_must_parse(const char *s)
{
    return float_grammar(s) && isfinite(strtof(s, NULL));
}

static void check_float(const char *s)
{
    float got = 42.0f;
    int r = cli_float(s, &got);
    int wf = float_grammar(s);
    float want = strtof(s, NULL);
    if (r != 0 && r != -1)
        fail("cli_float", s, "returned neither 0 nor -1");
    if (!r && !wf)
        fail("cli_float", s, "accepted a malformed number");
    if (!r && (!isfinite(got) || memcmp(&got, &want, sizeof got)))
        fail("cli_float", s, "returned a value other than strtof's");
    if (r && float_must_parse(s))
        fail("cli_float", s, "refused a well-formed finite number");
    if (r && got != 42.0f)
        fail("cli_float", s, "wrote its output on failure");
}

/* Splits at the first sep into two strings of fewer than n bytes each; 0 if it cannot. */
static int split(const char *s, char sep, char *a, char *b, size_t n)
{
    const char *p = strchr(s, sep);
    if (!p || (size_t)(p - s) >= n || strlen(p + 1) >= n)
        return 0;
    memcpy(a, s, (size_t)(p - s));
    a[p - s] = 0;
    strcpy(b, p + 1);
    return 1;
}

static void check_size(const char *s)
{
    char a[32], b[32];
    long w = 0, h = 0;
    int ok = split(s, 'x', a, b, sizeof a) && int_in_range(a, 1, 1L << 30, &w) &&
             int_in_range(b, 1, 1L << 30, &h);
    int gw = -1, gh = -1;
    int r = cli_size(s, &gw, &gh);
    if (ok != (r == 0))
        fail("cli_size", s, ok ? "refused WxH in range" : "accepted a malformed or out-of-range size");
    if (ok && (gw != w || gh != h))
        fail("cli_size", s, "returned the wrong size");
    if (!ok && (gw != -1 || gh != -1))
        fail("cli_size", s, "wrote its output on failure");
}

static void check_pair(const char *s)
{
    char a[64], b[64];
    float x = 42.0f, y = 42.0f;
    int r = cli_pair(s, &x, &y);
    int must = split(s, ',', a, b, sizeof a) && float_must_parse(a) && float_must_parse(b);
    if (r && must)
        fail("cli_pair", s, "refused two well-formed finite numbers");
    if (!r) {
        if (!split(s, ',', a, b, sizeof a) || !float_grammar(a) || !float_grammar(b))
            fail("cli_pair", s, "accepted a malformed pair");
        float wx = strtof(a, NULL), wy = strtof(b, NULL);
        if (!isfinite(x) || !isfinite(y) || memcmp(&x, &wx, sizeof x) || memcmp(&y, &wy, sizeof y))
            fail("cli_pair", s, "returned values other than strtof's");
    }
}

static void check_rgb(const char *s)
{
    const char *p = s[0] == '#' ? s + 1 : s;
    int ok = strlen(p) == 6;
    uint32_t want = 0;
    for (int i = 0; ok && i < 6; i++) {
        int c = tolower((unsigned char)p[i]);
        ok = isxdigit(c) != 0;
        want = want << 4 | (uint32_t)(isdigit(c) ? c - '0' : c - 'a' + 10);
    }
    uint32_t got = 0xdeadbeefu;
    int r = cli_rgb(s, &got);
    if (ok != (r == 0))
        fail("cli_rgb", s, ok ? "refused RRGGBB" : "accepted something other than [#]RRGGBB");
    if (ok && got != want << 8)
        fail("cli_rgb", s, "returned the wrong colour");
    if (!ok && got != 0xdeadbeefu)
        fail("cli_rgb", s, "wrote its output on failure");
}

/* cli_words against a scan of its own: each word is a maximal run without space or tab. */
static void check_words(const char *s)
{
    const size_t len = strlen(s);
    int count = 0;
    for (size_t i = 0; i < len; i++)
        count += s[i] != ' ' && s[i] != '\t' && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t');
    char buf[MAX_LEN + 1];
    char *words[MAX_LEN + 2];
    static const int maxes[] = {2, 3, 5, MAX_LEN + 2};
    for (size_t m = 0; m < sizeof maxes / sizeof maxes[0]; m++) {
        const int max = maxes[m];
        int n = cli_words(s, buf, len + 1, words, max);
        if (count == 0 || count > max - 1) {
            if (n != -1)
                fail("cli_words", s, "accepted no words or too many");
            continue;
        }
        if (n != count)
            fail("cli_words", s, "wrong word count");
        if (words[n] != NULL)
            fail("cli_words", s, "no NULL after the last word");
        const char *at = s;
        for (int w = 0; w < n; w++) {
            at += strspn(at, " \t");
            size_t wl = strcspn(at, " \t");
            if (strlen(words[w]) != wl || memcmp(words[w], at, wl) != 0)
                fail("cli_words", s, "a word differs from the input's");
            if (words[w] < buf || words[w] + wl > buf + len)
                fail("cli_words", s, "a word outside the buffer");
            at += wl;
        }
        if (cli_words(s, buf, len, words, max) != -1)
            fail("cli_words", s, "accepted a buffer without room for the NUL");
    }
}

/* Canonical spellings of values taken from the input must parse back exactly. */
static void one_line(const char *parser, const char *s, const char *err, size_t size)
{
    if (!fuzz_one_line(err, size))
        fail(parser, s, "no one-line reason for its refusal");
}

static void check_env_long(const char *s, long lo, long hi)
{
    const char *p = s + (*s == '-');
    size_t digits = strspn(p, "0123456789");
    int ok = digits >= 1 && digits <= 18 && !p[digits];
    long want = ok ? strtol(s, NULL, 10) : 0;
    ok = ok && want >= lo && want <= hi;
    long got = 12345;
    char err[128];
    memset(err, 'x', sizeof err);
    setenv("RETRO_FUZZ_VALUE", s, 1);
    int r = retro_env_long("RETRO_FUZZ_VALUE", lo, hi, &got, err, sizeof err);
    if (r != (ok ? 1 : -1))
        fail("retro_env_long", s, ok ? "refused a well-formed integer in range" : "accepted a malformed or out-of-range value");
    if (ok && got != want)
        fail("retro_env_long", s, "returned the wrong value");
    if (!ok && got != 12345)
        fail("retro_env_long", s, "wrote its output on failure");
    if (!ok)
        one_line("retro_env_long", s, err, sizeof err);
}

static void check_omp_threads(const char *s)
{
    int ok = 1;
    for (const char *p = s;; p++) {
        size_t digits = strspn(p, "0123456789");
        long v = digits >= 1 && digits <= 15 ? strtol(p, NULL, 10) : 0;
        if (v < 1 || v > 1048576) {
            ok = 0;
            break;
        }
        p += digits;
        if (!*p)
            break;
        if (*p != ',') {
            ok = 0;
            break;
        }
    }
    char err[128];
    memset(err, 'x', sizeof err);
    setenv("OMP_NUM_THREADS", s, 1);
    int r = retro_env_check(err, sizeof err);
    unsetenv("OMP_NUM_THREADS");
    if (r != (ok ? 0 : -1))
        fail("OMP_NUM_THREADS", s, ok ? "refused a list of counts" : "accepted a malformed list");
    if (!ok)
        one_line("OMP_NUM_THREADS", s, err, sizeof err);
}

static void round_trips(const uint8_t *data, size_t size)
{
    uint8_t b[12] = {0};
    memcpy(b, data, size < sizeof b ? size : sizeof b);
    char s[96];
    uint32_t bits;
    memcpy(&bits, b, 4);
    float f;
    memcpy(&f, &bits, 4);
    if (isfinite(f)) { /* subnormals included */
        float got;
        const char *fmts[] = {"%.9g", "%a", "%.20e"};
        for (int i = 0; i < 3; i++) {
            snprintf(s, sizeof s, fmts[i], (double)f);
            if (cli_float(s, &got) || memcmp(&got, &f, sizeof f))
                fail("cli_float", s, "did not read back the float it spells");
        }
    }
    long l;
    int64_t i64;
    memcpy(&i64, b + 4, 8);
    snprintf(s, sizeof s, "%" PRId64, i64);
    if (cli_int(s, LONG_MIN, LONG_MAX, &l) || l != (long)i64)
        fail("cli_int", s, "did not read back the integer it spells");
    uint64_t u;
    snprintf(s, sizeof s, "%" PRIu64, (uint64_t)i64);
    if (cli_u64(s, &u) || u != (uint64_t)i64)
        fail("cli_u64", s, "did not read back the integer it spells");
    int w, h;
    int ww = 1 + (int)(bits % (1u << 30)), hh = 1 + (int)((uint32_t)i64 % (1u << 30));
    snprintf(s, sizeof s, "%dx%d", ww, hh);
    if (cli_size(s, &w, &h) || w != ww || h != hh)
        fail("cli_size", s, "did not read back the size it spells");
    uint32_t rgb;
    snprintf(s, sizeof s, b[0] & 1 ? "#%06X" : "%06x", bits >> 8);
    if (cli_rgb(s, &rgb) || rgb != (bits >> 8) << 8)
        fail("cli_rgb", s, "did not read back the colour it spells");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char s[MAX_LEN + 1];
    fuzz_string(data, size, s, MAX_LEN);
    static const long ranges[][2] = {{LONG_MIN, LONG_MAX}, {INT_MIN, INT_MAX}, {1, 64},
                                     {-2147483647L - 1, 1L << 22}, {1, 16384}, {-5, 5}};
    for (size_t i = 0; i < sizeof ranges / sizeof ranges[0]; i++)
        check_int(s, ranges[i][0], ranges[i][1]);
    check_u64(s);
    check_float(s);
    check_size(s);
    check_pair(s);
    check_rgb(s);
    check_words(s);
    check_env_long(s, LONG_MIN, LONG_MAX);
    check_env_long(s, 1, 64);
    check_omp_threads(s);
    round_trips(data, size);
    return 0;
}
