/* Reading a file without trusting it (docs/INPUT.md): only a regular file is opened, so a
 * FIFO cannot block and a device cannot stream forever; its size is known and checked
 * against a limit before anything is allocated; reads are exact, so a file that is shorter
 * than it declares, or grows while read, is an error rather than a surprise. */
#ifndef RETRO_FILE_READ_H
#define RETRO_FILE_READ_H

#include <stddef.h>

typedef struct retro_rfile {
    int fd;
    size_t size;      /* at open */
    const char *path; /* for messages */
} retro_rfile;

/* Opens path for reading if it is a regular file of at most max bytes. 0, or -1 with err. */
int retro_rfile_open(retro_rfile *f, const char *path, size_t max, char *err, size_t errlen);
/* Reads exactly len bytes at the current offset. 0, or -1 with err ("truncated" if short). */
int retro_rfile_read(retro_rfile *f, void *buf, size_t len, char *err, size_t errlen);
/* 0 if nothing follows the current offset, -1 with err if the file grew while read. */
int retro_rfile_at_end(retro_rfile *f, char *err, size_t errlen);
void retro_rfile_close(retro_rfile *f);

#endif
