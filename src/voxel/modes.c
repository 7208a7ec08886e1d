/* The voxel family's mode names and the library's error strings. */
#include <string.h>

#include "kernels.h"

const char *const retro_voxel_mode_names[RETRO_MODE_COUNT] = {"exact", "course", "truth", "fixed", "lod"};

const char *retro_mode_name(retro_mode mode)
{
    return (unsigned)mode < RETRO_MODE_COUNT ? retro_voxel_mode_names[mode] : "?";
}

int retro_mode_parse(const char *name, retro_mode *mode)
{
    for (int m = 0; m < RETRO_MODE_COUNT; m++)
        if (!strcmp(name, retro_voxel_mode_names[m])) {
            *mode = (retro_mode)m;
            return 0;
        }
    return -1;
}

const char *retro_strerror(retro_err e)
{
    switch (e) {
    case RETRO_OK: return "ok";
    case RETRO_EINVAL: return "input outside the valid domain";
    case RETRO_ENOMEM: return "out of memory";
    case RETRO_EUNSUPPORTED: return "kernel does not support this mode or CPU";
    }
    return "unknown error";
}
