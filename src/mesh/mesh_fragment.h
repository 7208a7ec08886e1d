/* Small fragment-stage helpers shared by the raster loops of every mode. */
#ifndef RETRO_MESH_FRAGMENT_H
#define RETRO_MESH_FRAGMENT_H

#include "mesh_internal.h"

static inline void mesh_channels(uint32_t c, int ch[3])
{
    ch[0] = (int)((c >> 24) & 255);
    ch[1] = (int)((c >> 16) & 255);
    ch[2] = (int)((c >> 8) & 255);
}

static inline uint32_t mesh_pack(const int ch[3])
{
    return (uint32_t)ch[0] << 24 | (uint32_t)ch[1] << 16 | (uint32_t)ch[2] << 8;
}

/* Fog as docs/EFFECTS.md: each channel moves toward the sky's by F/256. */
static inline void mesh_fog(int ch[3], uint32_t sky, int F)
{
    int s[3];
    mesh_channels(sky, s);
    for (int k = 0; k < 3; k++)
        ch[k] = (ch[k] * (256 - F) + s[k] * F + 128) >> 8;
}

/* The colours at the four vertices of square (I, J): (I,J), (I+1,J), (I,J+1), (I+1,J+1). */
static inline void mesh_square_colors(const mesh_frame *f, int I, int J, int S, int c4[4][3])
{
    int I1 = I + 1 == S ? 0 : I + 1, J1 = J + 1 == S ? 0 : J + 1;
    mesh_channels(f->color[(size_t)J * (size_t)S + (size_t)I], c4[0]);
    mesh_channels(f->color[(size_t)J * (size_t)S + (size_t)I1], c4[1]);
    mesh_channels(f->color[(size_t)J1 * (size_t)S + (size_t)I], c4[2]);
    mesh_channels(f->color[(size_t)J1 * (size_t)S + (size_t)I1], c4[3]);
}

#endif
