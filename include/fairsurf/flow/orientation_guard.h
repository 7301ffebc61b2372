// fairsurf — a local guard against faces turning over during a move of the vertices: instead of
// rejecting a whole step because a few needle triangles of a raw scan would turn over, the vertices
// of those faces are held back towards where they came from (a per-vertex trust region, like the
// displacement clipping of flow.h), and the rest of the mesh moves as computed.
#pragma once

#include <fairsurf/mesh/mesh.h>

#include <Eigen/Core>

#include <span>
#include <vector>

namespace fairsurf {

/// A face of `faces` is turned over in `to` when its normal direction (b − a) × (c − a) does not
/// point within 90° of its row in every matrix `references` point to (each #faces by 3, the k-th row for
/// faces[k]; e.g. the directions before the move and those of the input). While some face is
/// turned over, the moves of its three vertices (to − from) are halved; after `max_halvings` rounds
/// of halving they are undone (put back at `from`) until no face is turned over. `from` and `to` are #V by 3. Faces that are turned over in
/// `from` itself cannot be helped and are left as they are. Returns the number of vertices held back.
/// Throws InvalidArgument when sizes do not match.
int hold_back_turned_faces(const Vertices& from, Vertices& to, const Faces& F, std::span<const int> faces,
                           std::span<const Eigen::MatrixX3d* const> references, int max_halvings = 8);

/// #faces by 3 unnormalized normals (b − a) × (c − a) of the listed faces at X.
Eigen::MatrixX3d face_directions(const Vertices& X, const Faces& F, std::span<const int> faces);

}  // namespace fairsurf
