// Private to fill_holes: one group's fill from one start of its patch (the membrane, the refined
// triangulation, or that triangulation unfaired): the patch, its fairing (jointly, then hole by hole
// where the joint fairing fell to its floor), the crossing check, and the group's reports. fill.cpp
// chains the starts and retries (its fallback chain) around it.
#pragma once

#include <fairsurf/applications/fair_region.h>
#include <fairsurf/applications/fill.h>
#include <fairsurf/mesh/mesh.h>
#include <fairsurf/mesh/topology.h>
#include <fairsurf/patch/patch.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace fairsurf::fill_detail {

/// Whether a rejected patch crosses the mesh, and if so whether a flow's result does.
enum class PatchCrossing { none, flow, other };

/// What a group's fairing starts from: the membrane (PatchOptions::relax, the default); the refined
/// triangulation, where every fairing from the membrane failed (a membrane folded against the border
/// gives the cotangent weights that fold the fairing too); or that triangulation unfaired, the last
/// resort.
enum class PatchStart { membrane, refined, unfaired };

/// A group's patch, built once and handed to every attempt of the fallback chain, which fairs the
/// same triangulation and refinement again and again: a hole whose chain runs to its end built it up
/// to eleven times, each triangulation with up to max_crossing_rounds rounds where the loop's faces
/// cross the mesh. The start without the membrane is the membrane's patch with its free vertices put
/// back (without_membrane), not a second triangulation. A build that threw throws the same again at
/// each attempt. Valid while the mesh and its connectivity are those it was built on.
class GroupPatches {
 public:
  GroupPatches(const Mesh& mesh, const Topology& topo, const std::vector<std::vector<int>>& loops,
               const PatchOptions& options)
      : mesh_(mesh), topo_(topo), loops_(loops), options_(options) {}

  const InitialPatch& get(PatchStart start) {
    const bool relax = start == PatchStart::membrane && options_.relax;
    Built& built = relax ? relaxed_ : unrelaxed_;
    if (!built.patch && !built.error) {
      try {
        built.patch = relax ? hole_patch(mesh_, topo_, loops_, options_) : unrelaxed();
      } catch (...) {
        built.error = std::current_exception();
      }
    }
    if (built.error) std::rethrow_exception(built.error);
    return *built.patch;
  }

 private:
  struct Built {
    std::optional<InitialPatch> patch;
    std::exception_ptr error;
  };
  InitialPatch unrelaxed() {
    if (options_.relax && relaxed_.patch) return without_membrane(*relaxed_.patch);
    PatchOptions options = options_;
    options.relax = false;
    return hole_patch(mesh_, topo_, loops_, options);
  }
  const Mesh& mesh_;
  const Topology& topo_;
  const std::vector<std::vector<int>>& loops_;
  const PatchOptions& options_;
  Built relaxed_, unrelaxed_;
};

/// The linear floor under one hole's delivered flow (FairRegionReport::floor_positions): the
/// hole's free vertices, rows of the filled mesh, and where the floor had them, one row each.
struct HoleFloor {
  int hole = -1;
  std::vector<int> vertices;
  Vertices positions;
};

/// A group's filled mesh (the input's vertices and faces first, then the patch) and its connectivity,
/// not yet committed to the input: another start's fill may still take its place. `floors`: the
/// holes of the group delivered as a flow over a linear floor.
struct FilledMesh {
  Vertices V;
  Faces F;
  Topology topology;
  std::vector<HoleFloor> floors;
};

/// Fills the holes `group` jointly on `mesh` from the group's patch for `start` (PatchStart; built on
/// `mesh` and its connectivity by `patches`); on success moves the filled mesh into `out` and fills
/// the reports; on failure throws or returns the reason the patch was rejected. `crossed` says
/// whether the rejected patch crosses the mesh, and whether it was a flow's.
std::string fill_group(const Mesh& mesh, const std::vector<std::vector<int>>& loops, const std::vector<int>& group,
                       GroupPatches& patches, const FillOptions& options, const FairRegionOptions& fairing_options,
                       PatchStart start, const FillObserver& observer, std::vector<HoleReport>& reports,
                       FilledMesh& out, PatchCrossing& crossed);

}  // namespace fairsurf::fill_detail
