/* Shared by the image readers (src/io/image_io.c, src/io/png_read.c): docs/INPUT.md's limits. */
#ifndef RETRO_IMAGE_READ_H
#define RETRO_IMAGE_READ_H

#include <stddef.h>
#include <stdint.h>

#include "file_read.h"

/* No image file is opened beyond this; each format then bounds its size by its header. */
#define RETRO_IMAGE_FILE_MAX ((size_t)1 << 32)

/* Reads the colour map PNG f whose first hl bytes (at least 8, the signature) are head, once
 * its size is within what its header allows and its chunks end exactly at the end of the file;
 * decodes it to packed RGB (any colour type and bit depth; alpha is ignored). 0 or -1 with err. */
int retro_png_read(retro_rfile *f, const unsigned char *head, size_t hl, uint32_t **data,
                   int *w, int *h, char *err, size_t errlen);

#endif
