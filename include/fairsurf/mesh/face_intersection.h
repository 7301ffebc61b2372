// fairsurf — finding faces of a mesh that cross each other near a set of query faces.
//
// Hole filling checks that a new patch does not run through the surrounding surface. Only the
// neighbourhood of the query faces is searched: the faces whose bounding boxes meet the query
// faces' bounding box go into a uniform grid (cells about one mean query edge long), and each query
// face is tested against the faces sharing a cell with it.
//
// The pair test: two triangles that share no vertex cross when an edge of one passes strictly
// through the interior of the other (each segment–triangle test is done both ways), or when they
// lie in one plane (within a relative 1e-12) and their interiors overlap there: an edge of one
// properly crosses an edge of the other, or a corner or the centroid of one lies strictly inside
// the other (a tube laid flat over the sheet it joins, a copy of a face). Touching contacts
// (within a relative 1e-12 of the edge lengths) and pairs that share a vertex are not reported:
// hole patches meet their surroundings exactly at shared vertices, and a fold between faces that
// share a vertex shows up as an inverted face elsewhere (flow.h).
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <span>
#include <vector>

namespace fairsurf {

struct FaceIntersection {
  int query_face = 0;  ///< a face of `query_faces`
  int other_face = 0;  ///< a face of F it crosses (may itself be a query face)
};

/// Crossings between the faces `query_faces` of (V, F) and any face of F, each unordered pair once,
/// at most `max_results` of them (0: all), in the order of `query_faces`, then by other face.
/// Throws InvalidArgument for a query face outside [0, #F).
std::vector<FaceIntersection> find_face_intersections(const Vertices& V, const Faces& F,
                                                      std::span<const int> query_faces,
                                                      int max_results = 0);

/// Whether segment (p, q) passes strictly through the interior of triangle (a, b, c) (touching
/// within the relative tolerance of the header does not count).
bool segment_crosses_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Whether triangles (a0, a1, a2) and (b0, b1, b2), which share no vertex, cross or overlap in one
/// plane (see the header).
bool triangles_cross(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                     const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

}  // namespace fairsurf
