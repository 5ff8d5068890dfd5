#pragma once
// The Embree 3 side of the ray tracer bench (built with -DWORKBENCH_EMBREE=ON).
#include <string>
#include <vector>

// Per scene, the ratios the goals of issue 21 name (ours/Embree: time of Embree's over ours).
struct EmbreeGoalRow {
    std::string scene;
    double eye = 0, shadow = 0;  // single rays, ours/Embree
    double packetsVsPackets = 0; // our eye packets / Embree's eye packets
    double packetsVsSingle = 0;  // our eye packets / Embree's single eye rays
};

// Markdown section: the same eye and shadow rays of each bench scene through our BVH
// and through Embree (triangles and spheres native, cones/cylinders as user geometry
// with our exact intersection), one thread, and ours/Embree.
std::string embreeSection(int size, int runs, const std::string& meshPath,
                          std::vector<EmbreeGoalRow>* goals = nullptr);

// Markdown section: the BVH builds alone, ours against Embree's, every scene of the Embree
// table, one thread (CPU time) and two (wall time), medians of `runs` alternated.
std::string embreeBuildSection(int runs, const std::string& meshPath);
