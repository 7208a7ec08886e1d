/* retro accuracy across families (docs/ACCURACY.md, "Across families"): the mesh in binary64 as
 * the common reference for the continuous terrain, the mesh modes timed and measured against
 * it, and a picture pair (voxel and mesh of one pose, and their difference). */
#ifndef RETRO_ACCURACY_MESH_H
#define RETRO_ACCURACY_MESH_H

#include "accuracy_metrics.h"
#include "retro.h"
#include "retro_maps.h"
#include "retro_mesh.h"
#include "retro_scene.h"

enum { ACC_MESH_MODES = 3, ACC_MESH_TIMED = 3 };

typedef struct {
    retro_ctx *rc;
    retro_effects fx;        /* `cull`: front faces only, as a terrain renderer draws them */
    acc_stats stats[ACC_MESH_MODES];
    double *ms[ACC_MESH_MODES]; /* per pose, the fastest mesh kernel for the mode */
    int n;
    uint32_t *ref;           /* this pose's binary64 frame: the common reference */
    uint32_t *img;
} acc_mesh;

int acc_mesh_init(acc_mesh *am, int poses, int W, int H);
void acc_mesh_free(acc_mesh *am);
/* The fastest kernel of fam this CPU runs for mode with effects fx (the family's last capable row). */
const retro_kernel *acc_best_in_family(const retro_family *fam, int mode, const retro_effects *fx);
/* Renders the pose in every mesh mode (binary64, the reference, into am->ref), timing each
 * (one warm-up frame, the median of ACC_MESH_TIMED), and measures each against the reference. */
void acc_mesh_pose(acc_mesh *am, const ctx_t *c, const player_t *p);
/* The mesh rows of the families table ("mesh binary32", ...), medians over the poses. */
void acc_mesh_rows(acc_mesh *am, acc_row *rows, double exact_ms);
/* Writes DIR/accuracy-pair-voxel.png, -mesh.png and -diff.png: the voxel frame (mode exact) and
 * the mesh frame (binary64) of map's default view turned to angle, and their difference
 * (|voxel - mesh| per channel, times 4, black where equal). Returns 0 or -1 with err. */
int acc_write_pair(const char *dir, const retro_map *m, int W, int H, int D, uint32_t sky, char *err, size_t n);

#endif
