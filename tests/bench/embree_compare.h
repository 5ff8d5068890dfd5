#pragma once
// The Embree 3 side of the ray tracer bench (built with -DWORKBENCH_EMBREE=ON).
#include <string>

// Markdown section: the same eye and shadow rays of each bench scene through our BVH
// and through Embree (triangles and spheres native, cones/cylinders as user geometry
// with our exact intersection), one thread, and ours/Embree.
std::string embreeSection(int size, int runs, const std::string& meshPath);

// Markdown section: the BVH builds alone, ours against Embree's, every scene of the Embree
// table, one thread (CPU time) and two (wall time), medians of `runs` alternated.
std::string embreeBuildSection(int runs, const std::string& meshPath);
