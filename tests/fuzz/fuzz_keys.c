/* libFuzzer target: retro view's --keys script parser (view_script_parse, src/cli/view_keys.c)
 * against the grammar written out here, independently of the parser's own walk:
 *   script = item { "," item }
 *   item   = NAME [ "*" COUNT ]      NAME: a key name view_key_parse knows (test_view_keys.c
 *                                   checks that table); COUNT: 1 to 7 digits, 1..1000000
 * The script is one frame per item, COUNT frames for a repeated one, at most 1000000 in all.
 * On success the frames must be exactly the expansion; on failure the script must be empty
 * (nothing to free) and the reason one line that fits the buffer. ASan sees leaks. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_string.h"
#include "view_keys.h"

#define MAX_LEN 4096

static void fail(const char *s, const char *why)
{
    fprintf(stderr, "view_script_parse(\"%.200s\"): %s\n", s, why);
    abort();
}

/* COUNT of the grammar, or -1. */
static long count_of(const char *s, size_t len)
{
    if (len < 1 || len > 7)
        return -1;
    long n = 0;
    for (size_t i = 0; i < len; i++) {
        if (s[i] < '0' || s[i] > '9')
            return -1;
        n = n * 10 + (s[i] - '0');
    }
    return n >= 1 && n <= VIEW_SCRIPT_MAX_FRAMES ? n : -1;
}

/* The grammar's expansion of s: the number of frames, or -1 when s is not a script. With got,
 * also checks that got->frames holds those frames. */
static long expand(const char *s, const view_script *got)
{
    long total = 0;
    size_t start = 0, n = strlen(s);
    for (size_t i = 0; i <= n; i++) {
        if (i < n && s[i] != ',')
            continue;
        const char *item = s + start;
        size_t len = i - start, name = 0;
        while (name < len && item[name] != '*')
            name++;
        view_action a;
        if (name == 0 || view_key_parse(item, name, &a))
            return -1;
        long c = name == len ? 1 : count_of(item + name + 1, len - name - 1);
        if (c < 0 || total + c > VIEW_SCRIPT_MAX_FRAMES)
            return -1;
        if (got)
            for (long k = 0; k < c; k++)
                if (got->frames[total + k] != a)
                    fail(s, "a frame differs from the grammar's expansion");
        total += c;
        start = i + 1;
    }
    return total;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char s[MAX_LEN + 1];
    fuzz_string(data, size, s, MAX_LEN);
    const long want = expand(s, NULL);
    view_script got = {(view_action *)1, 12345}; /* the parser must set both, whatever it finds */
    char err[96];
    memset(err, 'x', sizeof err);
    const int r = view_script_parse(s, &got, err, sizeof err);
    if (r != 0 && r != -1)
        fail(s, "returned neither 0 nor -1");
    if (r == 0) {
        if (want < 0)
            fail(s, "accepted a script outside the grammar");
        if (got.n != (size_t)want || !got.frames)
            fail(s, "returned another number of frames than the grammar's");
        expand(s, &got);
        view_script_free(&got);
        if (got.frames || got.n)
            fail(s, "view_script_free left the script set");
        return 0;
    }
    if (want >= 0)
        fail(s, "refused a script of the grammar");
    if (got.frames || got.n)
        fail(s, "left frames behind after failing");
    if (!fuzz_one_line(err, sizeof err))
        fail(s, "no one-line reason in the error buffer");
    return 0;
}
