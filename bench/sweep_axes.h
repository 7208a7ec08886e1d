// The two sweeps' x axes, shared by the voxel and the mesh charts: for each point of the
// plan's resolution or distance sweep, its label, its x value on the chart and the
// (W, H, D) a case of that point was run at.
#pragma once

#include <algorithm>
#include <array>
#include <sstream>
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

// The gnuplot settings both sweep charts share. Log-log: kernels ten times apart stay readable,
// and a slope of one means time proportional to the swept quantity. The x range pads the
// first and last points by a quarter of their value, so neither sits on the border (where
// gnuplot dropped the first point's tick label). The key goes below the plot, where no line
// can run through it, and the tick labels are slanted: 1280x720 and 1920x1080 are a third of
// a decade apart and overlapped level.
inline std::string sweep_axes_gp(const std::vector<double> &xs)
{
    const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
    std::ostringstream o;
    o << "set ylabel 'ms/frame (log scale, lower is better)'\nset logscale xy\nset grid\n";
    if (!xs.empty())
        o << "set xrange [" << *lo / 1.25 << ":" << *hi * 1.25 << "]\n";
    o << "set xtics rotate by 25 right\nset key below\n";
    return o.str();
}
