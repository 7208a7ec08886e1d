/* Untrusted files (src/io/file_read.h). */
#include "errf.h"
#include "file_read.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


static const char *kind(mode_t m)
{
    return S_ISDIR(m) ? "a directory" : S_ISFIFO(m) ? "a FIFO" : S_ISCHR(m) || S_ISBLK(m) ? "a device"
         : S_ISSOCK(m) ? "a socket" : "not a regular file";
}

int retro_rfile_open(retro_rfile *f, const char *path, size_t max, char *err, size_t n)
{
    f->fd = -1;
    f->path = path;
    /* O_NONBLOCK: opening a FIFO without a writer would otherwise wait forever; the flag
     * changes nothing for the regular files that get past the check below. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return retro_errf(err, n, "%s: %s", path, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return retro_errf(err, n, "%s: %s", path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return retro_errf(err, n, "%s: is %s, not a regular file", path, kind(st.st_mode));
    }
    if (st.st_size < 0 || (unsigned long long)st.st_size > max) {
        close(fd);
        return retro_errf(err, n, "%s: %lld bytes, more than the %zu this file may hold", path,
                    (long long)st.st_size, max);
    }
    f->fd = fd;
    f->size = (size_t)st.st_size;
    return 0;
}

int retro_rfile_read(retro_rfile *f, void *buf, size_t len, char *err, size_t n)
{
    unsigned char *p = buf;
    size_t got = 0;
    while (got < len) {
        ssize_t r = read(f->fd, p + got, len - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            return retro_errf(err, n, "%s: read error: %s", f->path, strerror(errno));
        if (r == 0)
            return retro_errf(err, n, "%s: truncated while read (%zu of %zu bytes)", f->path, got, len);
        got += (size_t)r;
    }
    return 0;
}

int retro_rfile_at_end(retro_rfile *f, char *err, size_t n)
{
    unsigned char c;
    ssize_t r;
    while ((r = read(f->fd, &c, 1)) < 0 && errno == EINTR)
        ;
    if (r < 0)
        return retro_errf(err, n, "%s: read error: %s", f->path, strerror(errno));
    return r ? retro_errf(err, n, "%s: grew while read", f->path) : 0;
}

void retro_rfile_close(retro_rfile *f)
{
    if (f->fd >= 0)
        close(f->fd);
    f->fd = -1;
}
