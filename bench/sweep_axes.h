// The two sweeps' x axes, shared by the voxel and the mesh charts: for each point of the
// plan's resolution or distance sweep, its label, its x value on the chart and the
// (W, H, D) a case of that point was run at.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cases.h"

struct SweepAxis {
    std::vector<std::string> labels;
    std::vector<double> xs;
    std::vector<std::array<int, 3>> points;
};

// Mpixels per frame at the plan's distance.
inline SweepAxis resolution_axis(const BenchPlan &plan)
{
    SweepAxis a;
    for (auto [w, h] : plan.resolutions) {
        a.labels.push_back(std::to_string(w) + "x" + std::to_string(h));
        a.xs.push_back(w * static_cast<double>(h) / 1e6);
        a.points.push_back({w, h, plan.D});
    }
    return a;
}

// The distance D at the plan's screen size.
inline SweepAxis distance_axis(const BenchPlan &plan)
{
    SweepAxis a;
    for (int d : plan.distances) {
        a.labels.push_back(std::to_string(d));
        a.xs.push_back(d);
        a.points.push_back({plan.W, plan.H, d});
    }
    return a;
}
