#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "proto/geometry.pb.h"
#include "stages/geometry/edge_polygon.h"
#include "stages/geometry/site_triangulation.h"

namespace areagraph {

// The Delaunay triangulation of obstacle sites, classified by one alpha
// (the alpha complex of CGAL Alpha_shape_2 in GENERAL mode for that one
// alpha, alpha = squared radius, classified directly). Used twice:
// ag-prune takes the regions the shape encloses as the map's boundaries,
// ag-cut takes the empty regions (faces wider than the alpha disk) as rooms.
class SiteAlphaShape {
 public:
  SiteAlphaShape(const PointList& sites, double alpha_radius_px);
  // The same, freeing `sites` before it triangulates: on a big map the list
  // (16 bytes a site) need not live beside the triangulation.
  SiteAlphaShape(PointList&& sites, double alpha_radius_px);
  // On a triangulation of the sites made elsewhere (TriangulateSites, or the
  // one ag-voronoi kept, TakeSiteTriangulation): the same shape without
  // triangulating again. Its face labels are overwritten.
  SiteAlphaShape(SiteTriangulationPtr triangulation, double alpha_radius_px);
  ~SiteAlphaShape();
  SiteAlphaShape(const SiteAlphaShape&) = delete;
  SiteAlphaShape& operator=(const SiteAlphaShape&) = delete;

  // --- The boundary (ag-prune) ---

  // Finds the enclosed regions: the faces that the alpha complex (its
  // regular and singular edges) encloses, that is that infinity cannot reach
  // without crossing one of its edges, grouped into edge-connected pieces (a
  // building each). Returns the area (square pixels) of every region, by id;
  // empty when nothing is enclosed.
  std::vector<double> FindEnclosedRegions();
  // The region (of FindEnclosedRegions) containing `point`, or -1.
  int EnclosedRegionAt(const Eigen::Vector2d& point);
  // The same for Voronoi vertex `vertex` at `point` of the diagram this
  // triangulation is the dual of (BuildVoronoiDiagram's): the search starts
  // at the vertex's Delaunay face when the triangulation is voronoi's, and
  // the answer is always EnclosedRegionAt's.
  int EnclosedRegionAt(const Eigen::Vector2d& point, int vertex);
  // EnclosedRegionAt(points[v], v) for every v that `wanted` accepts, in
  // order (-1 for the others), with the same answers and the same state
  // left for later calls; the walks run over ranges of the points in
  // parallel (OpenCV's pool), so `wanted` is called from several threads.
  std::vector<int> EnclosedRegionsAt(const PointList& points,
                                     const std::function<bool(int)>& wanted);
  // For a triangulation made here rather than voronoi's (whose faces name no
  // Voronoi vertex): names each vertex's face by matching `positions`
  // (BuildVoronoiDiagram's, one per circle at its first face's circumcentre,
  // in face order) against the faces' circumcentres, so that the
  // EnclosedRegionAt walks above start next to their point. Answers never
  // depend on it (any start gives the same); a vertex left unmatched walks
  // from the last hint. Returns the number named: none once faces are named.
  int NameVertexFaces(const PointList& positions);
  // The outer ring of a region (rooms wider than alpha are inside it, not
  // holes); empty for an unknown region.
  proto::Polygon EnclosedRegionOutline(int region);
  // EnclosedRegionOutline of each of `regions`, in one pass over the faces.
  std::map<int, proto::Polygon> EnclosedRegionOutlines(const std::set<int>& regions);

  // --- Rooms (ag-cut) ---

  // Groups the faces outside the alpha shape (an empty disk of the alpha
  // radius fits) into rooms, connected across edges that are themselves
  // outside the shape: a door narrower than the disk is a singular edge and
  // separates two rooms. Faces whose centroid fails `inside_boundary` are no
  // room; it is called once per face, from several threads (OpenCV's pool).
  // Returns the number of rooms.
  int DetectRooms(const std::function<bool(const Eigen::Vector2d&)>& inside_boundary);
  // The area (square pixels) of every room, indexed by room id.
  std::vector<double> RoomAreas();
  // The room containing `point`, or -1.
  int RoomAt(const Eigen::Vector2d& point);
  // Renumbers rooms: room r becomes new_ids[r] (-1 drops it).
  void RenumberRooms(const std::vector<int>& new_ids);
  // Outline (outer ring and holes) of every room, indexed by room id.
  std::vector<proto::Polygon> RoomOutlines();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace areagraph
