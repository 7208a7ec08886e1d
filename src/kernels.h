/* Prototypes of the kernels, one per file kernel_<name>.c; the table is in kernels.c. */
#ifndef RETRO_KERNELS_H
#define RETRO_KERNELS_H

#include "retro.h"

void retro_kernel_naive(const retro_frame *f, retro_ctx *rc);
void retro_kernel_ybuffer(const retro_frame *f, retro_ctx *rc);

#endif
