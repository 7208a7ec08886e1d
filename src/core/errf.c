#include "errf.h"

#include <stdarg.h>
#include <stdio.h>

int retro_errf(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (err && n) {
        vsnprintf(err, n, fmt, ap);
        /* One line whatever a quoted value holds (a newline in a path, a file's bytes, an
         * environment value): control bytes are shown as '?', as the CLI's errors are. */
        for (char *c = err; *c; c++)
            if ((unsigned char)*c < 0x20 || *c == 0x7f)
                *c = '?';
    }
    va_end(ap);
    return -1;
}
