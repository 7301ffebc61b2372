#include "loop_delaunay.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace fairsurf::detail {
namespace {

// qhull reports through a FILE*; the library never prints, so its messages go to a memory stream
// that is thrown away.
class DiscardedStream {
 public:
  DiscardedStream() : file_(open_memstream(&buffer_, &size_)) {}
  ~DiscardedStream() {
    if (file_ != nullptr) std::fclose(file_);
    std::free(buffer_);
  }
  DiscardedStream(const DiscardedStream&) = delete;
  DiscardedStream& operator=(const DiscardedStream&) = delete;
  FILE* get() const { return file_; }

 private:
  char* buffer_ = nullptr;
  std::size_t size_ = 0;
  FILE* file_ = nullptr;
};

}  // namespace

std::set<TriangleKey> delaunay_triangles(const Vertices& V, std::span<const int> vertices) {
  std::set<TriangleKey> triangles;
  const int n = static_cast<int>(vertices.size());
  if (n < 4) return triangles;
  DiscardedStream messages;
  if (messages.get() == nullptr) return triangles;
  std::vector<coordT> points(static_cast<std::size_t>(3 * n));
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) points[static_cast<std::size_t>(3 * i + d)] = V(vertices[i], d);
  qhT context;
  qhT* qh = &context;
  qh_zero(qh, messages.get());
  // d: Delaunay; Qt: triangulated (simplicial) output; Qbb: last coordinate scaled, for precision;
  // Qz: a point at infinity, for the cospherical loops of round holes (qhull's recommended options).
  char command[] = "qhull d Qt Qbb Qz";
  const int exit_code = qh_new_qhull(qh, 3, n, points.data(), False, command, nullptr, messages.get());
  if (exit_code == 0) {
    facetT* facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      if (facet->upperdelaunay) continue;
      std::array<int, 4> corner{};
      int count = 0;
      bool finite = true;
      FOREACHvertex_(facet->vertices) {
        const int id = qh_pointid(qh, vertex->point);
        if (id < 0 || id >= n || count == 4) finite = false;
        else corner[static_cast<std::size_t>(count++)] = vertices[id];
      }
      if (!finite || count != 4) continue;
      for (int skip = 0; skip < 4; ++skip) {
        TriangleKey key{};
        int k = 0;
        for (int c = 0; c < 4; ++c)
          if (c != skip) key[static_cast<std::size_t>(k++)] = corner[static_cast<std::size_t>(c)];
        std::sort(key.begin(), key.end());
        triangles.insert(key);
      }
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int current_long = 0, total_long = 0;
  qh_memfreeshort(qh, &current_long, &total_long);
  if (exit_code != 0) triangles.clear();
  return triangles;
}

}  // namespace fairsurf::detail
