/* The peer algorithm (src/peer/): the classic demo's traversal. Its image is its own, so these
 * tests pin what it shares with mode exact and what it does differently, not pixel identity. */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "peer/peer_voxelspace.h"
#include "test_util.h"

enum { W = 64, H = 48 };

static uint32_t out_peer[W * H], out_exact[W * H];
static int ybuf[W];

static ctx_t frame(const retro_map *m, uint32_t *out, int D)
{
    ctx_t c = {W, H, m->size, D, 0x66a3ff00u, m->height, m->color, out};
    return c;
}

/* On a flat map of one colour every sample has the same colour and height, so an image can
 * differ only in how high each column reaches: with a step that never grows the peer samples
 * d = 1 .. D-1 as mode exact does, so the highest projected row, and the image, must agree. */
Test(peer, flat_map_without_step_growth_matches_exact)
{
    retro_map m;
    test_map("test/flat-64", &m);
    player_t p = {.x = 10.5f, .y = 20.25f, .angle = 37, .height = 80};
    ctx_t a = frame(&m, out_peer, 120), b = frame(&m, out_exact, 120);
    cr_assert_eq(peer_voxelspace_render(&p, &a, 0.0f, ybuf), 0);
    render_with("naive", RETRO_MODE_EXACT, &p, &b);
    cr_assert(memcmp(out_peer, out_exact, sizeof out_peer) == 0);
    retro_map_free(&m);
}

/* With the demo's growth the farthest sample is the last z = 1 + 1 + 1.2 + 1.4 + ... below D,
 * not D - 1: on the flat map the horizon of terrain lies lower than mode exact's. */
Test(peer, growing_step_stops_short_of_the_last_distance)
{
    retro_map m;
    test_map("test/flat-64", &m);
    player_t p = {.x = 10.5f, .y = 20.25f, .angle = 0, .height = 70};
    ctx_t a = frame(&m, out_peer, 40), b = frame(&m, out_exact, 40);
    cr_assert_eq(peer_voxelspace_render(&p, &a, PEER_VOXELSPACE_DZ_GROWTH, ybuf), 0);
    render_with("naive", RETRO_MODE_EXACT, &p, &b);
    int top_peer = 0, top_exact = 0; /* terrain rows in column 0, from the bottom */
    for (int r = 1; r <= H; r++) {
        top_peer += out_peer[(size_t)(H - r) * W] != a.sky_color;
        top_exact += out_exact[(size_t)(H - r) * W] != b.sky_color;
    }
    /* Distances 1, 2, 3.2, 4.6, 6.2, 8, 10, 12.2, 14.6, 17.2, 20, 23, 26.2, 29.6, 33.2, 37 < 40. */
    float k = 0.5f * W / 37.0f, ke = 0.5f * W / 39.0f;
    int dh = 50 - 70;
    cr_assert_eq(top_peer, (int)(k * (float)dh + 0.5f * H));
    cr_assert_eq(top_exact, (int)(ke * (float)dh + 0.5f * H));
    cr_assert_lt(top_peer, top_exact);
    retro_map_free(&m);
}

Test(peer, refuses_what_retro_refuses_and_writes_nothing)
{
    retro_map m;
    test_map("test/flat-64", &m);
    player_t p = {.x = 1, .y = 1, .angle = 0, .height = 100};
    memset(out_peer, 0xab, sizeof out_peer);
    ctx_t c = frame(&m, out_peer, 100);
    c.scr_width = 0;
    cr_assert_eq(peer_voxelspace_render(&p, &c, 0.2f, ybuf), -1);
    c = frame(&m, out_peer, 100);
    p.x = 1.0f / 0.0f;
    cr_assert_eq(peer_voxelspace_render(&p, &c, 0.2f, ybuf), -1);
    p.x = 1;
    cr_assert_eq(peer_voxelspace_render(&p, &c, -1.0f, ybuf), -1);
    cr_assert_eq(out_peer[0], 0xabababab);
    retro_map_free(&m);
}
