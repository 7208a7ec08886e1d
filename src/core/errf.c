#include "errf.h"

#include <stdarg.h>
#include <stdio.h>

int retro_errf(char *err, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (err && n) {
        vsnprintf(err, n, fmt, ap);
        retro_one_line(err);
    }
    va_end(ap);
    return -1;
}

void retro_one_line(char *msg)
{
    for (; *msg; msg++)
        if ((unsigned char)*msg < 0x20 || *msg == 0x7f)
            *msg = '?';
}
