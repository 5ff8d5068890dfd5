#include "cdt2.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>


namespace wb::rad::detail {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
} // namespace

Cdt2 meshRegion(const std::vector<glm::dvec2>& points, const std::vector<std::array<int, 2>>& segments,
                double maxEdge) {
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handle;
    handle.reserve(points.size());
    for (const glm::dvec2& p : points) handle.push_back(cdt.insert(K::Point_2(p.x, p.y)));
    for (const auto& s : segments)
        cdt.insert_constraint(handle[static_cast<std::size_t>(s[0])], handle[static_cast<std::size_t>(s[1])]);
    CGAL::refine_Delaunay_mesh_2(cdt, Criteria(kMinAngleSin2, maxEdge));
    Cdt2 out;
    out.points = points;
    // Steiner points get the indices after the inputs (their info is not initialised by CGAL).
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info() = -1;
    for (std::size_t i = handle.size(); i-- > 0;) handle[i]->info() = static_cast<int>(i); // duplicates: the first
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info() >= 0) continue;
        v->info() = static_cast<int>(out.points.size());
        out.points.emplace_back(v->point().x(), v->point().y());
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        out.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
        out.constrained.push_back({f->is_constrained(0), f->is_constrained(1), f->is_constrained(2)});
    }
    return out;
}

} // namespace wb::rad::detail
