/* retro render --columns (render_columns.h). */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "ctx.h"
#include "hmax_pyramid.h"
#include "kernels.h"
#include "out_file.h"
#include "render_columns.h"
#include "ybuffer_columns.h"

int columns_count(render_job *j, const player_t *p, const retro_render_opts *opts, retro_column_counts *cols)
{
    retro_kernel counted = *retro_kernel_find("ybuffer");
    counted.fn = retro_kernel_ybuffer_counted;
    memset(cols, 0, (size_t)j->c.scr_width * sizeof *cols);
    retro_ybuffer_columns = cols;
    retro_err e = retro_render(j->rc, &counted, opts, p, &j->c);
    retro_ybuffer_columns = NULL;
    return e ? cli_error("render", "%s", retro_strerror(e)) : 0;
}

static int write_csv(int fd, const render_job *j, const retro_column_counts *on, const retro_column_counts *off)
{
    const retro_frame *f = retro_ctx_frame(j->rc);
    const int n = f->mode == RETRO_MODE_LOD ? f->ndist : f->D;
    FILE *out = fdopen(fd, "w");
    if (!out) {
        close(fd);
        return -1;
    }
    fprintf(out, "column,samples,evaluated,painting,evaluated_noskip,painting_noskip\n");
    for (int u = 0; u < j->c.scr_width; u++)
        fprintf(out, "%d,%d,%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 "\n", u, n > 1 ? n - 1 : 0,
                on[u].evaluated, on[u].painting, off[u].evaluated, off[u].painting);
    int bad = ferror(out);
    return fclose(out) || bad ? -1 : 0;
}

int columns_stage(render_columns *rc, render_job *j, const player_t *p)
{
    rc->tmp = NULL;
    if (j->k->family != &retro_family_voxel)
        return cli_error("render", "--columns counts the voxel ybuffer kernel's samples: not for kernel %s (family %s)",
                         j->k->name, j->k->family->name);
    struct stat st;
    if (!lstat(rc->path, &st) && S_ISDIR(st.st_mode))
        return cli_error("render", "%s: cannot write: is a directory", rc->path);
    const size_t W = (size_t)j->c.scr_width;
    retro_column_counts *on = calloc(2 * W, sizeof *on), *off = on + W;
    size_t tlen = strlen(rc->path) + RETRO_TMP_EXTRA;
    char *tmp = malloc(tlen), err[1400];
    if (!on || !tmp) {
        free(on);
        free(tmp);
        return cli_error("render", "out of memory");
    }
    retro_render_opts noskip = j->opts;
    noskip.no_skip = 1;
    int r = columns_count(j, p, &j->opts, on);
    if (!r)
        r = columns_count(j, p, &noskip, off);
    int fd = -1;
    if (!r && (fd = retro_out_open(rc->path, tmp, tlen, err, sizeof err)) < 0)
        r = cli_error("render", "%s", err);
    if (!r && write_csv(fd, j, on, off)) {
        r = cli_error("render", "%s: cannot write: %s", rc->path, strerror(errno));
        unlink(tmp);
    }
    free(on);
    if (r) {
        free(tmp);
        return r;
    }
    rc->tmp = tmp;
    return 0;
}

int columns_finish(render_columns *rc, int commit)
{
    if (!rc->tmp)
        return 0;
    char err[1400];
    int r = 0;
    if (!commit)
        unlink(rc->tmp);
    else if (retro_out_commit(rc->tmp, rc->path, err, sizeof err))
        r = cli_error("render", "%s", err);
    free(rc->tmp);
    rc->tmp = NULL;
    return r;
}
