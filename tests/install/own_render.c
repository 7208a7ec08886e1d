/* A program of a library user: it defines the course's render() itself, drawing with retro.
 * It links only because libretro exports no course names (render, draw_line, ...). */
#include <retro.h>
#include <stdio.h>

void render(const player_t *p, ctx_t *c)
{
    retro_ctx rc;
    retro_ctx_init(&rc);
    if (retro_render(&rc, retro_kernel_best(RETRO_MODE_EXACT), RETRO_MODE_EXACT, p, c) != RETRO_OK)
        fprintf(stderr, "render failed\n");
    retro_ctx_free(&rc);
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
