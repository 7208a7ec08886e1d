/* Output files that appear whole or not at all. Each is written to a temporary with a short
 * name in its destination's folder (so a destination name of up to 255 bytes still works) and
 * renamed into place once complete; a pair (a map's .pgm and colour file) is renamed only when
 * both are complete, and the first is put back if the second cannot be. */
#ifndef RETRO_OUT_FILE_H
#define RETRO_OUT_FILE_H

#include <stddef.h>
#include <stdint.h>

/* Room for the temporary's path: path's folder plus a short name. */
#define RETRO_TMP_EXTRA 24

/* Creates the temporary for path; tmp gets its path (at least strlen(path) + RETRO_TMP_EXTRA
 * bytes). Returns the open descriptor, or -1 with err. */
int retro_out_open(const char *path, char *tmp, size_t tmplen, char *err, size_t errlen);
/* Renames tmp to path, or removes tmp. 0, or -1 with err. */
int retro_out_commit(const char *tmp, const char *path, char *err, size_t errlen);
/* Renames tmp[0] to path[0] and tmp[1] to path[1], both or neither (as far as the file system
 * allows: the destinations are checked first, and path[0] is restored if path[1] fails).
 * The temporaries are gone afterwards. 0, or -1 with err. */
int retro_out_commit_pair(char *const tmp[2], const char *const path[2], char *err, size_t errlen);

/* retro_image_write() and retro_gray_write() (src/io/image_io.c) stopped before the rename: the
 * complete temporary's path is left in tmp for retro_out_commit_pair(). */
int retro_image_stage(const char *path, const uint32_t *px, int w, int h, char *tmp,
                      size_t tmplen, char *err, size_t errlen);
int retro_gray_stage(const char *path, const uint8_t *px, int w, int h, char *tmp, size_t tmplen,
                     char *err, size_t errlen);

#endif
