// Meshes with holes cut out, and distances to reference surfaces, for the hole-filling tests.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <functional>
#include <span>

namespace fairsurf::test {

/// `mesh` without every face that has a vertex where `inside(position)` holds; the vertices no face
/// uses any more are removed too (the others keep their relative order).
Mesh cut_hole(const Mesh& mesh, const std::function<bool(const Eigen::Vector3d&)>& inside);

/// `mesh` without every face whose three vertices lie in the closed ball (centre, radius), the
/// vertices no face uses any more removed (the others keep their order): the cut of the real-hole
/// measurement protocol.
Mesh cut_ball(const Mesh& mesh, const Eigen::Vector3d& centre, double radius);
/// `mesh` without the band of faces whose three vertices lie within `half_width` of the plane
/// through `point` normal to the unit vector `axis`, connected across edges to the vertex nearest
/// `point` (the vertices left keep their order): the cut of bench_real_holes' blend rows.
Mesh cut_slab(const Mesh& mesh, const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double half_width);

/// `mesh` without the faces listed in `faces`, the vertices no face uses any more removed (the others
/// keep their order): an irregular cut that a benchmark drew, replayed.
Mesh cut_faces(const Mesh& mesh, std::span<const int> faces);

/// Whether a face that `filled` appends to the faces of `holed` (the mesh before the fill, whose
/// faces `filled` keeps first) crosses a face of `filled` (face_intersection.h).
bool new_faces_cross(const Mesh& holed, const Mesh& filled);

/// An annulus whose inner border is an irregular, non-planar polygon of n vertices (random radii
/// 0.6–1.2 and angles, fixed seed) at height `amplitude` sin(waves θ) plus up to `height_jitter`
/// times `amplitude` at random, and whose outer border is a flat circle of radius 3; the hole is the
/// inner loop (the one through vertex 0). High crowns (amplitude 3–8) fold every triangulation.
Mesh wavy_annulus(int n, unsigned seed, double amplitude, int waves = 3, double height_jitter = 0.1);

/// A sheet bent into an S, z = 0.5 sin(πx) over [-1, 1]² (12 × 12 squares), with a small hole near
/// its edge: the rings of the hole and of the sheet's outer border overlap, so fill takes them as
/// one group, and every patch of the outer border crosses the sheet where it passes through the
/// border's plane. The outer border is the longer of its two loops.
Mesh s_sheet_with_hole();

/// A unit icosphere (level 3) with a ball hole round its north pole and, hanging at one vertex of
/// the hole's border, a lone triangle whose other two corners lie over the hole: debris a scan or a
/// cut leaves. Its loop pinches the hole's border at `pinch` (set when given).
Mesh sphere_hole_with_lone_triangle(int* pinch = nullptr);

/// A 16 × 16 grid (test::regular_grid, unit cells, vertex (x, y) at index 17y + x, every vertex
/// kept) with hole A, a square of 2 × 2 cells, touching hole B, 4 × 4 cells, at the corner (6, 6),
/// and one face of B's square left: a lone triangle hanging at a vertex of B's border. A chain of
/// pinches: B cannot be filled, A can alone (its patch joins the corner's two fans).
Mesh grid_with_chained_pinches();

/// Two capsules (test::ellipsoid(4, 0.5, 0.5, 1.2)), each cut across its middle by a slab (cut_slab):
/// first the blocked one, shifted to x = 4, whose gap (0.4 wide, the narrower) holds a thin closed
/// disk (ellipsoid(3, 0.8, 0.8, 0.03)) that every tube between its loops crosses, then the open one
/// at the origin, gap 0.6 wide. Four boundary loops; the blocked pair is the closest.
Mesh capsules_one_gap_blocked();

/// A unit icosphere (level 3) without two faces of vertex 0's fan that share no edge: two triangular
/// holes whose loops touch at vertex 0, a non-manifold vertex that repair splits.
Mesh sphere_with_two_holes_touching();

/// Moves every vertex of `mesh` along its area-weighted normal by a normal deviate of standard
/// deviation `sigma` (a scan's noise; the same `seed` gives the same draw).
void add_normal_noise(Mesh& mesh, double sigma, unsigned seed);

/// Distance from p to the triangle (a, b, c).
double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);

/// Distance from p to the surface of `mesh` (brute force over the faces, skipping those whose
/// bounding box is farther than the best distance so far).
double distance_to_mesh(const Eigen::Vector3d& p, const Mesh& mesh);

}  // namespace fairsurf::test
