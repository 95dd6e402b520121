#pragma once

// The CGAL type behind SiteTriangulation. Heavy templates: include only from
// the .cc files that run CGAL on it (voronoi_builder.cc, site_alpha_shape.cc,
// site_triangulation.cc), never from a header.

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Core>
#include <vector>

#include "stages/geometry/site_triangulation.h"

namespace areagraph {

// What the users of a site triangulation write on its faces: the Voronoi
// builder's face number, and SiteAlphaShape's labels (`interior` and
// `in_complex`, bit i for edge i, are the face's and its edges' places in the
// alpha complex; `walked` marks boundary edges already put in a ring).
struct SiteFaceInfo {
  int number = -1;
  int filled_region = -1;
  int room = -1;
  bool outside = false;
  bool interior = false;
  unsigned char in_complex = 0;
  unsigned char walked = 0;
};

namespace site_cgal {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
// Vertices carry their index in the site list (set by TriangulateIndexedSites).
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<SiteFaceInfo, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
}  // namespace site_cgal

struct SiteTriangulation {
  site_cgal::Delaunay dt;
};

}  // namespace areagraph
