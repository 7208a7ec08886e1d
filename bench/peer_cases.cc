// Timing the peer: called as a course-style render() ("direct" cases), with a y-buffer that
// is allocated once, so its frames allocate nothing, like the kernels'.
#include "peer_cases.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_report.h"

extern "C" {
#include "peer/peer_voxelspace.h"
}

static std::vector<int> peer_ybuf;

static void peer_direct(const player_t *p, ctx_t *c)
{
    peer_voxelspace_render(p, c, PEER_VOXELSPACE_DZ_GROWTH, peer_ybuf.data());
}

static const retro_kernel peer_row = {"peer: classic demo (s-macke's VoxelSpace traversal)", nullptr, 0,
                                      RETRO_MODE_BIT(RETRO_MODE_EXACT), 0, "", nullptr, 0,
                                      &retro_family_voxel};

void plan_peer(BenchPlan *plan)
{
    peer_ybuf.assign(static_cast<size_t>(plan->W), 0);
    for (const bench_scene *s : plan->scenes) {
        auto c = std::make_unique<BenchCase>();
        c->kernel = &peer_row;
        c->kernel_index = -1;
        c->threads = 1;
        c->scene = s;
        c->mode = RETRO_MODE_EXACT;
        c->W = plan->W;
        c->H = plan->H;
        c->D = plan->D;
        c->groups = GROUP_PEER;
        c->label = "peer";
        c->name = std::string("peer/") + s->name + "/classic-voxelspace/1t/" + std::to_string(c->W) + "x" +
                  std::to_string(c->H) + "/D" + std::to_string(c->D);
        c->direct = peer_direct;
        plan->cases.push_back(std::move(c));
    }
}

void peer_table(std::ostream &o, const BenchPlan &plan)
{
    std::vector<const BenchCase *> cases;
    for (const auto &c : plan.cases)
        if ((c->groups & GROUP_PEER) && c->ran && c->error.empty())
            cases.push_back(c.get());
    if (cases.empty())
        return;
    const retro_kernel *yb = retro_kernel_find("ybuffer");
    int steps = 0; // the peer's distances below D, against retro's D - 1
    for (float z = 1, dz = 1; z < static_cast<float>(plan.D) && steps < 1 << 24; z += dz, dz += PEER_VOXELSPACE_DZ_GROWTH)
        steps++;
    o << "\n### Peer algorithm: the classic voxel-space demo (mode exact's camera, " << plan.W << "×" << plan.H
      << ", D " << plan.D << ")\n\nmedian ms/frame. Not a retro kernel: s-macke's VoxelSpace traversal "
         "(a distance step that starts at 1 and grows by 0.2 each distance: "
      << steps << " distances for D " << plan.D << " where retro samples " << plan.D - 1 << "), written for retro in src/peer/. It renders its own image, outside "
         "`make verify`; docs/ACCURACY.md and `make accuracy` measure its error against truth.\n\n"
      << "| scene | peer: classic demo | `ybuffer`, mode exact | peer vs ybuffer | max cv |\n|---|--:|--:|--:|--:|\n";
    for (const BenchCase *c : cases) {
        const BenchCase *y = plan.find(yb, 1, c->scene, RETRO_MODE_EXACT, c->W, c->H, c->D);
        double ym = y && y->ran && y->error.empty() ? y->median_ms : std::nan("");
        char ratio[32] = "–", cv[32] = "–";
        if (!std::isnan(ym))
            std::snprintf(ratio, sizeof ratio, "%.2f×", ym / c->median_ms);
        if (!std::isnan(c->cv))
            std::snprintf(cv, sizeof cv, "%.1f%%", 100 * c->cv);
        o << "| " << c->scene->name << " | " << report_ms_cell(c->median_ms) << " | " << report_ms_cell(ym) << " | "
          << ratio << " | " << cv << " |\n";
    }
}
