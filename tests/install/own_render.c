/* A program of a library user: it defines the course's render() itself, drawing with retro.
 * It links only because libretro exports no course names (render, draw_line, ...). */
#include <retro.h>
#include <stdio.h>

void render(const player_t *p, ctx_t *c)
{
    retro_ctx *rc = retro_ctx_new();
    retro_render_opts o = RETRO_RENDER_OPTS_DEFAULT; /* mode exact, no effects */
    char why[160];
    const retro_kernel *k = retro_family_best(&retro_family_voxel, o.mode, o.fx);
    if (!rc || retro_render_check(k, &o, why, sizeof why) != RETRO_OK || retro_render(rc, k, &o, p, c) != RETRO_OK)
        fprintf(stderr, "render failed: %s\n", rc ? why : "out of memory");
    retro_ctx_free(rc);
}

int main(void)
{
    enum { S = 64, W = 32, H = 24 };
    static uint8_t height[S * S];
    static uint32_t color[S * S], out[W * H];
    for (int i = 0; i < S * S; i++) {
        height[i] = (uint8_t)(i % 50);
        color[i] = 0x10203000u;
    }
    ctx_t c = {W, H, S, 50, 0x66a3ff00u, height, color, out};
    player_t p = {.x = 5, .y = 5, .angle = 30, .height = 40};
    render(&p, &c);
    int terrain = 0;
    for (int i = 0; i < W * H; i++)
        terrain += out[i] == 0x10203000u;
    printf("%d terrain pixels\n", terrain);
    return terrain > 0 && terrain < W * H ? 0 : 1;
}
