/* retro accuracy across families: see accuracy_mesh.h. */
#include "timing.h"
#include "accuracy_mesh.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int acc_mesh_init(acc_mesh *am, int poses, int W, int H)
{
    memset(am, 0, sizeof *am);
    if (!(am->rc = retro_ctx_new()))
        return -1;
    retro_effects_defaults(&am->fx);
    am->fx.flags = RETRO_FX_CULL;
    for (int m = 0; m < ACC_MESH_MODES; m++)
        if (!(am->ms[m] = malloc(sizeof(double) * (size_t)(poses > 0 ? poses : 1))))
            return -1;
    am->ref = malloc(sizeof(uint32_t) * (size_t)W * (size_t)H);
    am->img = malloc(sizeof(uint32_t) * (size_t)W * (size_t)H);
    return am->ref && am->img ? 0 : -1;
}

void acc_mesh_free(acc_mesh *am)
{
    for (int m = 0; m < ACC_MESH_MODES; m++)
        free(am->ms[m]);
    free(am->ref);
    free(am->img);
    retro_ctx_free(am->rc);
}

const retro_kernel *acc_best_in_family(const retro_family *fam, int mode, const retro_effects *fx)
{
    const retro_kernel *best = NULL;
    for (size_t i = 0; i < retro_kernel_count; i++)
        if (retro_kernels[i].family == fam && retro_kernel_check(&retro_kernels[i], mode, fx, NULL, 0) == RETRO_OK)
            best = &retro_kernels[i];
    return best;
}

/* One warm-up frame, then the median of ACC_MESH_TIMED (a mesh frame costs far more than a
 * voxel one: fewer repetitions). The last frame stays in c->out. */
static double time_mode(acc_mesh *am, int mode, ctx_t *c, const player_t *p)
{
    const retro_kernel *k = acc_best_in_family(&retro_family_mesh, mode, &am->fx);
    double t[ACC_MESH_TIMED];
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT;
    o.mode = mode;
    o.fx = &am->fx;
    retro_render(am->rc, k, &o, p, c);
    for (int i = 0; i < ACC_MESH_TIMED; i++) {
        double t0 = cli_now_ms();
        retro_render(am->rc, k, &o, p, c);
        t[i] = cli_now_ms() - t0;
    }
    qsort(t, ACC_MESH_TIMED, sizeof t[0], cli_cmp_double);
    return t[ACC_MESH_TIMED / 2];
}

void acc_mesh_pose(acc_mesh *am, const ctx_t *c0, const player_t *p)
{
    static const int order[ACC_MESH_MODES] = {RETRO_MESH_BINARY64, RETRO_MESH_BINARY32, RETRO_MESH_INT};
    ctx_t c = *c0;
    for (int i = 0; i < ACC_MESH_MODES; i++) {
        int mode = order[i];
        c.out = mode == RETRO_MESH_BINARY64 ? am->ref : am->img;
        am->ms[mode][am->n] = time_mode(am, mode, &c, p);
        acc_compare(&am->stats[mode], am->ref, c.out, c.scr_width, c.scr_height, c.sky_color);
    }
    am->n++;
}

void acc_mesh_rows(acc_mesh *am, acc_row *rows, double exact_ms)
{
    static const char *const what[ACC_MESH_MODES] = {
        "triangles, binary32 (docs/MESH.md)", "triangles, binary64: the reference",
        "triangles, integer interpolation per fragment"};
    for (int m = 0; m < ACC_MESH_MODES; m++) {
        acc_row *r = &rows[m];
        memset(r, 0, sizeof *r);
        r->family = "mesh";
        r->label = (const char *[]){"mesh binary32", "mesh binary64", "mesh int"}[m];
        r->what = what[m];
        r->kernel = acc_best_in_family(&retro_family_mesh, m, &am->fx)->name;
        qsort(am->ms[m], (size_t)am->n, sizeof(double), cli_cmp_double);
        r->ms = am->n ? am->ms[m][am->n / 2] : 0;
        r->speedup = r->ms > 0 ? exact_ms / r->ms : 0;
        acc_summary(&am->stats[m], r);
    }
}

int acc_write_pair(const char *dir, const retro_map *m, int W, int H, int D, uint32_t sky, char *err, size_t n)
{
    struct retro_view view;
    retro_default_view(m, &view);
    player_t p = {view.x, view.y, 30, view.height, 0, 0, 0};
    size_t px = (size_t)W * (size_t)H;
    uint32_t *vox = malloc(px * sizeof *vox), *mesh = malloc(px * sizeof *mesh), *diff = malloc(px * sizeof *diff);
    retro_ctx *rc = retro_ctx_new();
    retro_effects fx;
    retro_effects_defaults(&fx);
    fx.flags = RETRO_FX_CULL;
    int status = -1;
    ctx_t c = {W, H, m->size, D, sky, m->height, m->color, vox};
    retro_render_opts vo = RETRO_RENDER_OPTS_DEFAULT, mo = RETRO_RENDER_OPTS_DEFAULT;
    mo.mode = RETRO_MESH_BINARY64;
    mo.fx = &fx;
    if (!vox || !mesh || !diff || !rc)
        snprintf(err, n, "out of memory for the picture pair");
    else if (retro_render(rc, retro_kernel_best(RETRO_MODE_EXACT), &vo, &p, &c))
        snprintf(err, n, "the voxel frame of the picture pair failed");
    else {
        c.out = mesh;
        if (retro_render(rc, retro_family_reference(&retro_family_mesh), &mo, &p, &c))
            snprintf(err, n, "the mesh frame of the picture pair failed: %s", retro_mesh_last_error(rc));
        else
            status = 0;
    }
    for (size_t i = 0; !status && i < px; i++) {
        uint32_t d = 0;
        for (int sh = 8; sh <= 24; sh += 8) {
            int a = (int)(vox[i] >> sh & 255), b = (int)(mesh[i] >> sh & 255);
            int e = 4 * abs(a - b);
            d |= (uint32_t)(e > 255 ? 255 : e) << sh;
        }
        diff[i] = d;
    }
    const char *names[3] = {"voxel", "mesh", "diff"};
    const uint32_t *imgs[3] = {vox, mesh, diff};
    for (int i = 0; i < 3 && !status; i++) {
        char path[1200];
        snprintf(path, sizeof path, "%s/accuracy-pair-%s.png", dir, names[i]);
        status = retro_image_write(path, imgs[i], W, H, err, n) ? -1 : 0;
    }
    retro_ctx_free(rc);
    free(vox);
    free(mesh);
    free(diff);
    return status;
}
