// Shell nesting by point-in-solid tests on a few vertices of each shell (acd/algo/shells.hpp).
#include <acd/algo/shells.hpp>
#include <acd/algo/inside.hpp>

#include <algorithm>
#include <memory>

namespace acd {

ShellNesting classifyShells(const std::vector<TriMesh>& shells) {
  const int n = static_cast<int>(shells.size());
  ShellNesting out;
  out.depth.assign(n, 0);
  out.overlaps.assign(n, 0);
  if (n < 2) return out;
  std::vector<Box3> boxes(n);
  for (int i = 0; i < n; ++i) boxes[i] = boundingBox(shells[i]);
  auto boxesMeet = [&](int a, int b) {
    return (boxes[a].lo.array() <= boxes[b].hi.array()).all() && (boxes[b].lo.array() <= boxes[a].hi.array()).all();
  };
  std::vector<std::unique_ptr<InsideTest>> tests(n);  // built on first use
  for (int a = 0; a < n; ++a)      // container
    for (int b = 0; b < n; ++b) {  // candidate inside it
      if (a == b || !boxesMeet(a, b)) continue;
      if (!tests[a]) tests[a] = std::make_unique<InsideTest>(shells[a]);
      const auto& vertices = shells[b].vertices;
      const std::size_t stride = std::max<std::size_t>(1, vertices.size() / 64);
      int inside = 0, tested = 0;
      for (std::size_t v = 0; v < vertices.size(); v += stride, ++tested) inside += tests[a]->inside(vertices[v]);
      const bool boxInside = (boxes[b].lo.array() >= boxes[a].lo.array()).all() &&
                             (boxes[b].hi.array() <= boxes[a].hi.array()).all();
      if (inside == tested && boxInside)
        ++out.depth[b];
      else if (inside > 0)
        out.overlaps[a] = out.overlaps[b] = 1;
    }
  for (int i = 0; i < n; ++i) {
    out.cavities += out.depth[i] % 2;
    out.overlapping += out.overlaps[i];
  }
  return out;
}

}  // namespace acd
