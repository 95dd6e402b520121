#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

namespace areagraph {

// The Delaunay triangulation of a list of obstacle sites (defined with CGAL in
// site_triangulation_cgal.h, which only .cc files include). ag-voronoi builds
// it for the diagram and ag-prune's boundary shape needs the same one, so in
// one process (ag-pipeline, ag-run's workers, ag-live) voronoi hands it to
// prune instead of prune triangulating the same sites again.
struct SiteTriangulation;
// Deletes a SiteTriangulation where its type is complete.
struct SiteTriangulationDeleter {
  void operator()(SiteTriangulation* triangulation) const;
};
// Owns a triangulation; callers outside the CGAL files only pass it on.
using SiteTriangulationPtr = std::unique_ptr<SiteTriangulation, SiteTriangulationDeleter>;

// The triangulation of `sites`, each vertex's info its index in `sites`.
// CGAL's spatially sorted range insertion, with or without the indices, puts
// the same points in the same order with the same hints, so this is the
// triangulation (faces, their order, co-circular grid points' diagonals)
// that TriangulateSites gives for the same list.
SiteTriangulationPtr TriangulateIndexedSites(const std::vector<Eigen::Vector2d>& sites);
// The same without vertex indices (their info is left unset).
SiteTriangulationPtr TriangulateSites(const std::vector<Eigen::Vector2d>& sites);
// The same, freeing `sites` before it triangulates (on a big map the list,
// 16 bytes a site, need not live beside the triangulation).
SiteTriangulationPtr TriangulateSites(std::vector<Eigen::Vector2d>&& sites);

// A copy of `triangulation` (the same faces in the same order): a second
// alpha shape of the same sites without triangulating them again (a shape
// writes its labels into the faces).
SiteTriangulationPtr CopySiteTriangulation(const SiteTriangulation& triangulation);

// Bytes the triangulation's vertices and faces take (what keeping it costs).
size_t SiteTriangulationBytes(const SiteTriangulation& triangulation);

// Keeps `triangulation` of `sites` (inserted in this order) for a later
// TakeSiteTriangulation in this process, replacing any kept before. Kept at
// every size: prune would build the same one (about 176 bytes a site, 170 MB
// on a 50-megapixel map), and holding it from voronoi's end to prune's start
// stays under cut's and merge's peak memory there (512 MB against 561 MB),
// while triangulating again cost
// prune a tenth of its time.
void KeepSiteTriangulation(SiteTriangulationPtr triangulation, std::vector<Eigen::Vector2d> sites);
// The kept triangulation when it was made from exactly `sites` (the same
// points in the same order, so it is the one a new triangulation of `sites`
// would give), else null. Either way nothing stays kept.
SiteTriangulationPtr TakeSiteTriangulation(const std::vector<Eigen::Vector2d>& sites);
// Drops the kept triangulation, if any (a pipeline's end: nothing reads it).
void DropSiteTriangulation();

}  // namespace areagraph
