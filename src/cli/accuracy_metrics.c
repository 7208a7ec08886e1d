#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "accuracy_metrics.h"
#include "chart_labels.h"

double acc_rand(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

/* Reduced to [0, S) in the float the renderer gets, so the cell below is inside the map. */
static float in_map(double v, int S)
{
    float f = (float)v;
    return f >= (float)S ? f - (float)S : f;
}

void acc_pose(uint64_t *rng, int S, const uint8_t *height, player_t *p)
{
    memset(p, 0, sizeof *p);
    p->x = in_map(acc_rand(rng) * S, S);
    p->y = in_map(acc_rand(rng) * S, S);
    p->angle = (int)(acc_rand(rng) * 360);
    size_t at = (size_t)p->y * (size_t)S + (size_t)p->x;
    p->height = height[at] + 20 + (int)(acc_rand(rng) * 180);
}

/* The highest terrain row of column u: rows count from the bottom, out is top to bottom. */
static int silhouette(const uint32_t *img, int W, int H, int u, uint32_t sky)
{
    for (int top = 0; top < H; top++)
        if (img[(size_t)top * (size_t)W + (size_t)u] != sky)
            return H - top;
    return 0;
}

void acc_compare(acc_stats *s, const uint32_t *truth, const uint32_t *img, int W, int H, uint32_t sky)
{
    size_t n = (size_t)W * (size_t)H, diff = 0;
    for (size_t i = 0; i < n; i++) {
        diff += truth[i] != img[i];
        for (int sh = 8; sh <= 24; sh += 8) {
            double e = (double)((truth[i] >> sh) & 255) - (double)((img[i] >> sh) & 255);
            s->sq_err += e * e;
        }
    }
    int cols = 0;
    for (int u = 0; u < W; u++) {
        int e = abs(silhouette(truth, W, H, u, sky) - silhouette(img, W, H, u, sky));
        cols += e != 0;
        s->sil_sum += e;
        s->sil_max = e > s->sil_max ? e : s->sil_max;
    }
    s->frames += 1;
    s->pixel_frac += (double)diff / (double)n;
    s->col_frac += (double)cols / W;
    s->columns += W;
    s->bytes += 3.0 * (double)n;
}

void acc_summary(const acc_stats *s, acc_row *r)
{
    r->pixel_pct = 100 * s->pixel_frac / s->frames;
    r->col_pct = 100 * s->col_frac / s->frames;
    r->sil_mean = s->sil_sum / s->columns;
    r->sil_max = s->sil_max;
    double mse = s->sq_err / s->bytes;
    r->psnr = mse > 0 ? 10 * log10(255.0 * 255.0 / mse) : INFINITY;
}

/* A path as a gnuplot single-quoted string: there a quote is written twice and nothing else is
 * special, so no file name can end the string and smuggle in a command (acc_path_ok() has
 * already refused control characters, which would end the line). */
static void put_gnuplot_string(FILE *g, const char *s)
{
    fputc('\'', g);
    for (; *s; s++) {
        if (*s == '\'')
            fputc('\'', g);
        fputc(*s, g);
    }
    fputc('\'', g);
}

int acc_path_ok(const char *path)
{
    size_t n = strlen(path);
    if (n == 0 || n >= ACC_PATH_MAX)
        return 0;
    for (; *path; path++)
        if ((unsigned char)*path < 0x20 || *path == 0x7f)
            return 0;
    return 1;
}

/* The charts' frame: the error axis is fixed (truth's 0 is plotted at 0.001), the time axis
 * whole decades around the points with room on the right for a label. Pixels are approximate
 * for the 800x560 chart with its key below; the labels' places need them only roughly. */
#define CHART_CANVAS_W 800.0
#define CHART_CANVAS_H 560.0

static chart_frame chart_frame_of(const acc_row *rows, int n, int families)
{
    double a = INFINITY, b = 0;
    for (int i = 0; i < 2 * n; i++) { /* the timed rows' times, and ybuffer's on the Pareto chart */
        const double t = i < n ? rows[i].ms : families ? NAN : rows[i - n].ms_y;
        if (t > 0 && isfinite(t)) {
            a = fmin(a, t);
            b = fmax(b, t);
        }
    }
    if (!(b > 0)) { /* no timed row: any decade will do */
        a = 1;
        b = 1;
    }
    return (chart_frame){pow(10, floor(log10(a) - 0.15)), pow(10, ceil(log10(b) + 0.6)), 0.0005, 100, 665, 425, 8.5, 16};
}

static double chart_error(const acc_row *r)
{
    return r->pixel_pct > 0 ? r->pixel_pct : 1e-3;
}

/* A `set label` per timed row, at the place chart_labels.c chose; none when out of memory. */
static void put_labels(FILE *g, const chart_frame *fr, const acc_row *rows, int n, int families)
{
    double *v = malloc(sizeof *v * (size_t)(4 * n + 1));
    const char **labels = malloc(sizeof *labels * (size_t)(n + 1));
    chart_place *at = malloc(sizeof *at * (size_t)(n + 1));
    if (v && labels && at) {
        /* the timed rows' points, and ybuffer's beside them (the Pareto chart marks both) */
        double *x = v, *y = v + n, *mx = v + 2 * n, *my = v + 3 * n;
        int k = 0, m = 0;
        for (int i = 0; i < n; i++) {
            if (rows[i].ms > 0 && isfinite(rows[i].ms)) {
                x[k] = rows[i].ms;
                y[k] = chart_error(&rows[i]);
                labels[k++] = rows[i].label;
            }
            if (!families && rows[i].ms_y > 0 && isfinite(rows[i].ms_y)) {
                mx[m] = rows[i].ms_y;
                my[m++] = chart_error(&rows[i]);
            }
        }
        if (chart_place_labels(fr, x, y, labels, k, mx, my, m, at) == 0)
            for (int i = 0; i < k; i++) {
                fprintf(g, "set label %d ", i + 1);
                put_gnuplot_string(g, labels[i]);
                fprintf(g, " at %.6g,%.6g %s offset screen %.4f,%.4f noenhanced front\n", x[i], y[i], at[i].align,
                        at[i].dx / CHART_CANVAS_W, at[i].dy / CHART_CANVAS_H);
                if (at[i].leader) /* from the point to where its label starts, stopping short of both */
                    fprintf(g, "set arrow %d from first %.6g, first %.6g rto screen %.4f, screen %.4f nohead "
                               "lc rgb '#666666' back\n",
                            i + 1, x[i], y[i], 0.8 * at[i].dx / CHART_CANVAS_W, 0.8 * at[i].dy / CHART_CANVAS_H);
            }
    }
    free(v);
    free(labels);
    free(at);
}

/* One gnuplot run for one terminal, the data inline, so nothing but the chart is written. The
 * key sits below the plot: inside it, it covered the cheapest variants' points. */
static int plot(const char *term, const char *out, const acc_row *rows, int n, int families)
{
    FILE *g = popen("gnuplot 2>/dev/null", "w");
    if (!g)
        return -1;
    fprintf(g, "$d << EOD\n");
    for (int i = 0; i < n; i++) /* error axis is logarithmic: truth (0) sits at its floor */
        fprintf(g, "\"%s\" %.4f %.6f %.4f %d\n", rows[i].label, rows[i].ms, chart_error(&rows[i]), rows[i].ms_y,
                rows[i].family && !strcmp(rows[i].family, "mesh"));
    fprintf(g, "EOD\nset terminal %s size %d,%d background rgb '#ffffff'\nset output ", term, (int)CHART_CANVAS_W, (int)CHART_CANVAS_H);
    put_gnuplot_string(g, out);
    const chart_frame fr = chart_frame_of(rows, n, families);
    fprintf(g, "\nset logscale xy\nset xrange [%g:%g]\nset yrange [%g:%g]\nset grid\nset key below horizontal\n", fr.xlo,
            fr.xhi, fr.ylo, fr.yhi);
    put_labels(g, &fr, rows, n, families);
    if (families) {
        fprintf(g, "set title 'Across families: time per frame against error (vs the mesh in binary64)'\n"
                   "set xlabel 'median ms/frame, 640x480, D 800 (log)'\n"
                   "set ylabel 'pixels differing from the mesh in binary64 (%%, log; itself at 0.001)'\n"
                   "plot $d using 2:($5 == 0 ? $3 : 1/0) with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'voxel', "
                   "$d using 2:($5 == 1 ? $3 : 1/0) with points pt 9 ps 1.4 lc rgb '#2ca02c' title 'mesh'\n");
        return pclose(g) == 0 ? 0 : -1;
    }
    fprintf(g, "set title 'What accuracy costs: time per frame against error (vs truth)'\n"
               "set xlabel 'median ms/frame, 640x480, D 800 (log)'\n"
               "set ylabel 'pixels differing from truth (%%, log; truth itself plotted at 0.001)'\n"
               "plot $d using 2:3 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'fastest kernel for the mode', "
               "$d using 4:3 with points pt 5 ps 1.0 lc rgb '#d62728' title 'ybuffer (same scalar kernel for all)'\n");
    return pclose(g) == 0 ? 0 : -1;
}

/* The SVG, and a PNG beside it (OUT.png for OUT.svg) where this gnuplot has a PNG terminal. */
static int write_chart(const char *svg, const acc_row *rows, int n, int families, char *err, size_t errlen)
{
    if (plot("svg dynamic", svg, rows, n, families)) {
        snprintf(err, errlen, "gnuplot failed on %s (is gnuplot-nox installed?)", svg);
        return -1;
    }
    size_t len = strlen(svg);
    char png[ACC_PATH_MAX + 8];
    if (len < 4 || strcmp(svg + len - 4, ".svg") || len >= sizeof png)
        return 0;
    snprintf(png, sizeof png, "%.*s.png", (int)(len - 4), svg);
    if (plot("pngcairo", png, rows, n, families) && plot("png", png, rows, n, families))
        remove(png); /* gnuplot-nox builds differ: SVG only */
    return 0;
}

static const char *base(const char *path)
{
    const char *slash = strrchr(path, '/'); /* charts and pictures are linked as they sit beside the table */
    return slash ? slash + 1 : path;
}

static void psnr_text(double psnr, char *buf, size_t n)
{
    if (isinf(psnr))
        snprintf(buf, n, "∞");
    else
        snprintf(buf, n, "%.1f", psnr);
}

static void write_families(FILE *f, const acc_families *fam)
{
    fprintf(f, "\n## Across families: against the mesh in binary64\n\nThe same terrain as a continuous "
               "surface: the mesh family (docs/MESH.md) in binary64, back faces culled, is the common "
               "reference for both families. %d poses (the first of each scene's), 640x480, D 800; "
               "voxel times are the medians of the table above, mesh times the median of %d frames per "
               "pose after one untimed frame, with the fastest mesh kernel for the mode.\n\n",
            fam->poses, 3);
    fprintf(f, "| family | variant | what | fastest kernel | ms/frame | vs voxel exact | pixels differ | "
               "silhouette columns differ | mean silhouette error (rows) | max silhouette error | PSNR (dB) |\n"
               "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < fam->n; i++) {
        const acc_row *r = &fam->rows[i];
        char psnr[32];
        psnr_text(r->psnr, psnr, sizeof psnr);
        fprintf(f, "| %s | %s | %s | %s | %.3f | %.2f× | %.3f%% | %.2f%% | %.3f | %d | %s |\n", r->family, r->label,
                r->what, r->kernel, r->ms, r->speedup, r->pixel_pct, r->col_pct, r->sil_mean, r->sil_max, psnr);
    }
    fprintf(f, "\n![time against error across families](%s)\n", base(fam->svg));
    if (fam->pair)
        fprintf(f, "\nOne pose, both families: voxel (mode exact) | mesh (binary64) | difference "
                   "(|voxel − mesh| per channel ×4, black where equal)\n\n"
                   "![voxel](%s-voxel.png) ![mesh](%s-mesh.png) ![difference](%s-diff.png)\n",
                base(fam->pair), base(fam->pair), base(fam->pair));
}

/* The first value of /proc/cpuinfo's field `key` (e.g. "model name"), or "" where there is none. */
static void cpuinfo_field(const char *key, char *out, size_t outlen)
{
    out[0] = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[512];
    const size_t k = strlen(key);
    while (fgets(line, sizeof line, f)) {
        const char *colon = strchr(line, ':');
        if (strncmp(line, key, k) || !colon || strspn(line + k, " \t") != (size_t)(colon - line - (ptrdiff_t)k))
            continue;
        snprintf(out, outlen, "%s", colon + 1 + strspn(colon + 1, " \t"));
        out[strcspn(out, "\n")] = 0;
        break;
    }
    fclose(f);
}

/* The machine the times were taken on, as the benchmark names it: the model name (virtual
 * machines often hide the rest) with family and model, and the cores online. */
static void machine_name(char *out, size_t outlen)
{
    char name[160], family[16], model[16];
    cpuinfo_field("model name", name, sizeof name);
    cpuinfo_field("cpu family", family, sizeof family);
    cpuinfo_field("model", model, sizeof model);
    const long cores = sysconf(_SC_NPROCESSORS_ONLN);
    if (family[0])
        snprintf(out, outlen, "%s (family %s, model %s), %ld cores", name[0] ? name : "unknown CPU", family, model,
                 cores);
    else
        snprintf(out, outlen, "%s, %ld cores", name[0] ? name : "unknown CPU", cores);
}

int acc_write_report(const char *md, const char *svg, const acc_row *rows, int n, int poses,
                     uint64_t seed, const acc_families *fam, const acc_steady *steady, char *err,
                     size_t errlen)
{
    if (write_chart(svg, rows, n, 0, err, errlen))
        return -1;
    if (fam && write_chart(fam->svg, fam->rows, fam->n, 1, err, errlen))
        return -1;
    char tmp[ACC_PATH_MAX + 8];
    snprintf(tmp, sizeof tmp, "%s.tmp", md);
    FILE *f = fopen(tmp, "w");
    if (!f) {
        snprintf(err, errlen, "%s: cannot write", md);
        return -1;
    }
    time_t t = time(NULL);
    char date[32], machine[256];
    strftime(date, sizeof date, "%Y-%m-%d %H:%M", gmtime(&t));
    machine_name(machine, sizeof machine);
    /* make accuracy names the commit (git describe); a run outside it says it does not know */
    const char *commit = getenv("RETRO_COMMIT");
    fprintf(f, "# What accuracy costs\n\nMeasured %s UTC by `make accuracy`: %d seeded random poses (seed %llu) of the "
               "default and course scenes, 640x480, D 800, each variant rendered by the fastest kernel for "
               "its mode and compared with mode `truth` (definitions: docs/ACCURACY.md).\n\n"
               "Machine: %s. Commit: %s.\n\n",
            date, poses, (unsigned long long)seed, machine, commit && commit[0] ? commit : "unknown (RETRO_COMMIT unset)");
    acc_steady_write_note(f, steady);
    fprintf(f, "Times are medians over the poses: with the fastest kernel for the variant's mode (the "
               "SIMD kernels exist for modes exact and course only), and with `ybuffer`, one scalar kernel "
               "for every variant, which isolates what the arithmetic itself costs.\n\n");
    fprintf(f, "| variant | what | fastest kernel | ms/frame | vs exact | ybuffer ms/frame | vs exact | "
               "pixels differ | silhouette columns differ | mean silhouette error (rows) | max silhouette "
               "error | PSNR (dB) |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < n; i++) {
        char psnr[32];
        psnr_text(rows[i].psnr, psnr, sizeof psnr);
        fprintf(f, "| %s | %s | %s | %.3f | %.2f× | %.3f | %.2f× | %.3f%% | %.2f%% | %.3f | %d | %s |\n",
                rows[i].label, rows[i].what, rows[i].kernel, rows[i].ms, rows[i].speedup, rows[i].ms_y,
                rows[i].speedup_y, rows[i].pixel_pct, rows[i].col_pct, rows[i].sil_mean, rows[i].sil_max, psnr);
    }
    fprintf(f, "\n![time against error](%s)\n", base(svg));
    if (fam)
        write_families(f, fam);
    acc_steady_write_table(f, steady);
    if (fclose(f) || rename(tmp, md)) {
        snprintf(err, errlen, "%s: cannot write", md);
        return -1;
    }
    return 0;
}
