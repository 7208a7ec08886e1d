/* mesh-omp's second pass: one band draws a recorded block stage (mesh_rec.h) in its rows
 * rlo..rhi. Each record is drawn as the block stage would have drawn it (the same functions on
 * the same values), so each pixel of the band sees the serial kernel's fragments in its order. */
#include "fast_raster.h"
#include "fast_ref.h"
#include "mesh_fragment.h"
#include "mesh_rec.h"

/* The reference's records of square (I, J)'s four corners, in mc's grid with stride 2. */
static void corners(retro_mesh_ctx *mc, int I, int J)
{
    uint32_t done[2] = {0, 0};
    for (int k = 0; k < 4; k++)
        fast_full_vertex(mc, done, 2, I, J, k & 1, k >> 1);
}

void mesh_replay(retro_mesh_ctx *mc, const uint32_t *w, size_t n)
{
    static const float fsx[2][3] = {{0.5f, 1.5f, 1.5f}, {0.5f, 0.5f, 1.5f}}, fsy[2][3] = {{0.5f, 1.5f, 0.5f}, {0.5f, 1.5f, 1.5f}};
    static const double tsx[2][3] = {{0.5, 1.5, 1.5}, {0.5, 0.5, 1.5}}, tsy[2][3] = {{0.5, 1.5, 0.5}, {0.5, 1.5, 1.5}};
    static const int cidx[2][3] = {{0, 3, 1}, {0, 2, 3}}; /* ACB, ADC in a 2 x 2 grid */
    const mesh_frame *f = &mc->f;
    /* the band's rows as a range of out indices: row r is stored at (H - r) W */
    const size_t lo = (size_t)(f->H - f->rhi) * (size_t)f->W, hi = (size_t)(f->H - f->rlo + 1) * (size_t)f->W;
    float *depth = (float *)mc->depth;
    uint64_t written = 0;
    for (size_t k = 0; k < n;) {
        const uint32_t *p = w + k;
        const int t = (int)(p[0] >> 8 & 1u);
        int32_t X[3], Y[3];
        switch (p[0] & 255u) {
        case REC_FRAG: {
            k += 4;
            const size_t idx = p[1];
            const float z = rec_float(p[2]);
            if (idx < lo || idx >= hi || !(z < depth[idx]))
                break; /* another band's pixel, or ties keep the fragment drawn first */
            written++;
            int ch[3];
            mesh_channels(f->color[p[3]], ch);
            if (f->fx & RETRO_FX_FOG)
                mesh_fog(ch, f->sky, fast_fog(f, z));
            depth[idx] = z;
            mc->out[idx] = mesh_pack(ch);
            break;
        }
        case REC_BIG: {
            float q[3];
            for (int c = 0; c < 3; c++) {
                X[c] = (int32_t)p[1 + c];
                Y[c] = (int32_t)p[4 + c];
                q[c] = rec_float(p[7 + c]);
            }
            fast_raster_nearest(mc, X, Y, q, fsx[t], fsy[t], (int)p[10], (int)p[11]);
            k += 12;
            break;
        }
        case REC_GENERIC: {
            const int I = (int32_t)p[1], J = (int32_t)p[2];
            for (int c = 0; c < 3; c++) {
                X[c] = (int32_t)p[3 + c];
                Y[c] = (int32_t)p[6 + c];
            }
            corners(mc, I, J);
            const uint64_t counted = mc->st.rasterized; /* by the block stage that recorded it */
            fast_generic(mc, cidx[t], tsx[t], tsy[t], I, J, (int)(p[0] >> 16 & 1u), X, Y);
            mc->st.rasterized = counted;
            k += 9;
            break;
        }
        default: { /* REC_SLOW */
            const int I = (int32_t)p[1], J = (int32_t)p[2];
            corners(mc, I, J);
            mesh_primitive_assembly(mc, mc->grid, mc->snap, 2, 0, I, J);
            k += 3;
            break;
        }
        }
    }
    mc->st.written += written;
}
