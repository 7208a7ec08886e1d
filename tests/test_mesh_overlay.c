/* A mesh frame overlays a voxel frame of the same pose (docs/MESH.md, "Pixel centres"): on a
 * flat map, where the two surfaces are the same plane, the frames are byte-identical when the
 * far edges (voxel: last sample d = D - 1; mesh: far plane z = D) fall in the same row. */
#include "mesh_util.h"
#include "test_util.h"

Test(mesh_overlay, flat_map_equals_voxel_frame)
{
    enum { W = 64, H = 48, S = 16 };
    uint8_t h[S * S];
    uint32_t col[S * S], vox[W * H], mesh[W * H];
    memset(h, 50, sizeof h);
    for (int i = 0; i < S * S; i++)
        col[i] = 0x20a04000u;
    /* voxel top row floor(32/99*(-30) + 24) = 14, mesh floor(32/100*(-30) + 24) = 14 */
    for (int a = -30; a < 400; a += 23) {
        player_t p = {5.3f + (float)a, 7.9f, a, 80, 0, 0, 0};
        ctx_t c = {W, H, S, 100, MSKY, h, col, vox};
        render_with("naive", RETRO_MODE_EXACT, &p, &c);
        c.out = mesh;
        for (int m = 0; m < RETRO_MESH_MODE_COUNT; m++) {
            mrender_ok(RETRO_MESH_ZBUFFER, (retro_mesh_mode)m, &p, &c, NULL, 0);
            cr_assert(!memcmp(vox, mesh, sizeof vox), "angle %d mode %s", a, retro_mesh_mode_name((retro_mesh_mode)m));
        }
    }
}

/* A checkerboard of colours on flat ground: the same pixels are terrain in both frames, but
 * the colours differ by design where the voxel frame's sample (the first integer distance d
 * whose projection reaches the row) lies in another cell than the exact surface point the
 * mesh colours by (docs/MESH.md, "Against the voxel frame"). The count is logged. */
Test(mesh_overlay, flat_checker_same_coverage)
{
    enum { W = 64, H = 48, S = 16 };
    uint8_t h[S * S];
    uint32_t col[S * S], vox[W * H], mesh[W * H];
    memset(h, 50, sizeof h);
    for (int i = 0; i < S * S; i++)
        col[i] = ((i + i / S) & 1) ? 0xffffff00u : 0x10101000u;
    player_t p = {5.3f, 7.9f, 37, 80, 0, 0, 0};
    ctx_t c = {W, H, S, 100, MSKY, h, col, vox};
    render_with("naive", RETRO_MODE_EXACT, &p, &c);
    c.out = mesh;
    mrender_ok(RETRO_MESH_ZBUFFER, RETRO_MESH_BINARY64, &p, &c, NULL, 0);
    int differ = 0, terrain = 0;
    for (int i = 0; i < W * H; i++) {
        cr_assert_eq(vox[i] == MSKY, mesh[i] == MSKY, "pixel %d", i);
        differ += vox[i] != mesh[i];
        terrain += vox[i] != MSKY;
    }
    cr_log_info("flat checker: %d of %d terrain pixels take another cell's colour than the voxel frame", differ,
                terrain);
    cr_assert_gt(terrain, 500);
}
