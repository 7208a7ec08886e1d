/* Whole-or-nothing output files (src/io/out_file.h). */
#include "errf.h"
#include "out_file.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


int retro_out_open(const char *path, char *tmp, size_t tmplen, char *err, size_t n)
{
    const char *slash = strrchr(path, '/');
    int dir = slash ? (int)(slash - path + 1) : 0;
    int len = snprintf(tmp, tmplen, "%.*sretro-tmp.XXXXXX", dir, path);
    if (len < 0 || (size_t)len >= tmplen)
        return retro_errf(err, n, "%s: path too long", path);
    int fd = mkstemp(tmp);
    if (fd < 0)
        return retro_errf(err, n, "%s: cannot write: %s", path, strerror(errno));
    fchmod(fd, 0644);
    return fd;
}

int retro_out_commit(const char *tmp, const char *path, char *err, size_t n)
{
    if (rename(tmp, path) == 0)
        return 0;
    int e = errno;
    unlink(tmp);
    return retro_errf(err, n, "%s: cannot write: %s", path, strerror(e));
}

/* A destination rename cannot replace: a folder (rename's EISDIR comes too late for a pair). */
static int replaceable(const char *path, char *err, size_t n)
{
    struct stat st;
    if (lstat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return retro_errf(err, n, "%s: cannot write: is a directory", path);
    return 0;
}

int retro_out_commit_pair(char *const tmp[2], const char *const path[2], char *err, size_t n)
{
    if (replaceable(path[0], err, n) || replaceable(path[1], err, n)) {
        unlink(tmp[0]);
        unlink(tmp[1]);
        return -1;
    }
    /* The old first file, kept under a second name while the second is renamed. */
    size_t blen = strlen(tmp[0]) + 8;
    char *backup = malloc(blen);
    int have_backup = 0, had_first = access(path[0], F_OK) == 0;
    if (backup) {
        snprintf(backup, blen, "%s.old", tmp[0]);
        have_backup = had_first && link(path[0], backup) == 0;
    }
    int r = -1;
    if (retro_out_commit(tmp[0], path[0], err, n) == 0) {
        if (retro_out_commit(tmp[1], path[1], err, n) == 0)
            r = 0;
        else if (have_backup) {
            rename(backup, path[0]);
            have_backup = 0;
        } else if (!had_first)
            unlink(path[0]);
    } else
        unlink(tmp[1]);
    if (have_backup)
        unlink(backup);
    free(backup);
    return r;
}
