// fairsurf — the paper's scenes (Liu & Xu, Figs 3, 4, 7, 8) and method.md §8.6's sphere cap, generated
// by code so that they serve as regression tests and as documentation figures (docs/blend.md).
//
// Every scene is a triangle mesh, counter-clockwise seen from outside (normals away from the axis
// or the sphere's centre, or up for the flat disk), in the units below, with edges of about
// SceneOptions::edge_length. A scene is either
//   a blend scene   (fig3, fig4): two open pieces; `blend_loops` are the two boundary loops to join
//                   (what `fairsurf blend` picks by itself as the closest pair), or
//   a region scene  (fig7, fig8, sphere-cap): a surface with a free region; `free_vertices` lists it
//                   and the mesh carries it as the per-vertex scalar "free" (1 free, 0 fixed), so that
//                   `fairsurf fair SCENE.ply --region-property free` fairs it.
//
//   fig3        A spherical cap above a flat disk with a hole (Fig 3a). Disk: z = 0, radii 1.5 to
//               2.75, normal +z. Cap: the sphere of radius 1 about (0, 0, 0.1), polar angle ≤ 60°
//               (rim radius √3/2 at z = 0.6). Blend the hole's loop with the cap's rim.
//   fig4        Two spherical caps facing each other (Fig 4a): the caps of the unit sphere within
//               polar angle 60° of its poles (rims of radius √3/2 at z = ±0.5). They are caps of one
//               sphere so that the blend has a known answer: the G2 blend with f = H (constant H is
//               stationary) must recover the sphere. (Farther apart, e.g. 2.2 between rims, no
//               catenoid spans the rims and the G0 membrane of the initial tube pinches off.)
//   fig7        An open unit cylinder, z ∈ [−1.5, 1.5], with the band |z| < 1 free (Fig 7): mean
//               curvature flow shrinks the band, Willmore flow inflates it, the sixth-order flow with
//               f = H keeps it (a cylinder has constant H).
//   fig8        A ring interpolating two circles (Fig 8): a wide, short unit-radius band, z ∈ [−0.55,
//               0.55], free for |z| < 0.25 with the two circles z = ±0.25 as the border of the free
//               region. The paper shows mean curvature plots only; this reading (a cylindrical ring,
//               whose constant H makes it stationary under f = H) is ours. Same comparison as fig7.
//   sphere-cap  method.md §8.6: the unit icosphere whose cap z > 0.5 is free and flattened onto the
//               plane z = 0.5; G2 fairing must bring it back to the sphere.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <string>
#include <vector>

namespace fairsurf {

struct SceneOptions {
  /// Target edge length (scene units). sphere-cap uses the icosphere level whose edges are closest.
  double edge_length = 0.1;
};

struct Scene {
  std::string name;
  std::string description;  ///< one line: what the scene is and what to do with it
  Mesh mesh;
  std::vector<int> free_vertices;            ///< region scenes: ascending; empty for blend scenes
  std::vector<std::vector<int>> blend_loops;  ///< blend scenes: the two loops (boundary_loops order)
};

/// "fig3", "fig4", "fig7", "fig8", "sphere-cap".
const std::vector<std::string>& scene_names();

/// Builds the scene `name`. Throws InvalidArgument for an unknown name (listing the names) or an
/// edge length that is not positive and finite.
Scene make_scene(const std::string& name, const SceneOptions& options = {});

/// The icosahedron subdivided `level` times, projected to the sphere of `radius` about the origin:
/// 10·4^level + 2 vertices (642, 2562, 10242 at levels 3, 4, 5). Throws InvalidArgument for a
/// negative level.
Mesh icosphere(int level, double radius = 1.0);

/// method.md §8.6's scene at a given icosphere level: vertices with z > z_cut flattened onto z = z_cut
/// and free.
Scene sphere_cap_scene(int level, double z_cut = 0.5);

}  // namespace fairsurf
