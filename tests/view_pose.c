/* The course's update_player applied to a start pose, one "v v_height v_angular" line of stdin
 * per frame; prints the final pose as retro view does ("x y height angle"). tests/view.sh
 * compares it with retro view's replay of the same keys. */
#include <stdio.h>
#include <stdlib.h>

#include "render.h"
#include "retro_maps.h"

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: retro-view-pose MAP X Y HEIGHT ANGLE < velocities\n");
        return 2;
    }
    retro_map m;
    char err[1400];
    if (retro_map_load(argv[1], &m, err, sizeof err)) {
        fprintf(stderr, "retro-view-pose: %s\n", err);
        return 2;
    }
    player_t p = {strtof(argv[2], NULL), strtof(argv[3], NULL), atoi(argv[5]), atoi(argv[4]), 0, 0, 0};
    ctx_t c = {1, 1, m.size, 1, 0, m.height, m.color, NULL};
    while (scanf("%d %d %d", &p.v, &p.v_height, &p.v_angular) == 3)
        update_player(&p, &c);
    printf("%.9g %.9g %d %d\n", (double)p.x, (double)p.y, p.height, p.angle);
    retro_map_free(&m);
    return 0;
}
