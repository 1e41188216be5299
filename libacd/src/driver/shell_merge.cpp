// Pairs of components from different shells, screened by added volume, confirmed by hull excess.
#include "shell_merge.hpp"

#include <acd/algo/canonical_frame.hpp>
#include <acd/algo/cut_choice.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/merge.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/random.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <utility>

namespace acd {

namespace {

struct Candidate {
  int i = -1, j = -1;
  TriMesh hull;  // normalised
  double cost = 0.0;
  bool screened = false;
};

bool boxesWithin(const Box3& a, const Box3& b, double gap) {
  return ((a.lo.array() - gap) <= b.hi.array()).all() && ((b.lo.array() - gap) <= a.hi.array()).all();
}

}  // namespace

int mergeAcrossShells(std::vector<Component>& components, const TriMesh& shells, const Normalization& normalization,
                      const DecomposeOptions& o) {
  const int n = static_cast<int>(components.size());
  std::vector<char> eligible(n);
  for (int i = 0; i < n; ++i) eligible[i] = !components[i].unresolved && !components[i].ofWrap;
  // With o.invariant, in the assembly's own frame, hulls in canonical form (rounded, sorted): the
  // sampled volumes, and so the order of merges, do not depend on the input's pose.
  const Normalization frame = o.invariant ? canonicalFrame({shells}) : normalization;
  auto toFrame = [&](const TriMesh& m) { return o.invariant ? canonicalMesh(m, frame).mesh : applyNormalization(m, frame); };
  const ModelExcess model(applyNormalization(shells, frame), ModelSolid::AnyClosedShell, o.threads);
  tbb::task_arena arena = workerArena(o.threads);  // the decomposition's threads, not all the machine's
  std::vector<TriMesh> hulls(n);  // in the frame
  std::vector<Box3> boxes(n);
  for (int i = 0; i < n; ++i) {
    // From the component's own vertices in the frame, not its hull moved there: on flat faces
    // the hull keeps or drops points that lie on a facet as rounding in the input's pose
    // decides, and its triangles are what the added volume is sampled over.
    hulls[i] = o.invariant ? convexHull(toFrame(components[i].mesh).vertices).mesh : toFrame(components[i].hull);
    boxes[i] = boundingBox(hulls[i]);
  }
  std::vector<char> alive(n, 1);
  std::map<std::pair<int, int>, Candidate> measured;
  int merges = 0;
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<std::pair<int, int>> fresh;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n && alive[i] && eligible[i]; ++j)
        if (alive[j] && eligible[j] && components[i].source != components[j].source &&
            boxesWithin(boxes[i], boxes[j], o.tau) && !measured.count({i, j}))
          fresh.emplace_back(i, j);
    std::vector<Candidate> screened(fresh.size());
    arena.execute([&] {
      tbb::parallel_for(std::size_t(0), fresh.size(), [&](std::size_t k) {
        Candidate& c = screened[k];
        c.i = fresh[k].first, c.j = fresh[k].second;
        std::vector<Vec3> corners = hulls[c.i].vertices;
        corners.insert(corners.end(), hulls[c.j].vertices.begin(), hulls[c.j].vertices.end());
        c.hull = convexHull(corners).mesh;
        const double volume = components[c.i].volume + components[c.j].volume;
        const std::uint64_t key = mix64(static_cast<std::uint64_t>(c.i) << 32 | static_cast<std::uint32_t>(c.j));
        c.cost = model.addedVolume(c.hull, {&hulls[c.i], &hulls[c.j]}, kModelMergeSamples, key, kModelMergeGrowth * volume);
        c.screened = c.cost <= kModelMergeGrowth * volume;
      });
    });
    for (Candidate& c : screened) measured[{c.i, c.j}] = std::move(c);
    std::vector<Candidate*> order;
    for (auto& [ij, c] : measured)
      if (c.screened && alive[ij.first] && alive[ij.second]) order.push_back(&c);
    std::stable_sort(order.begin(), order.end(), [](const Candidate* a, const Candidate* b) { return a->cost < b->cost; });
    std::vector<char> changed(n, 0);
    for (Candidate* c : order) {
      if (changed[c->i] || changed[c->j]) continue;
      const HullExcess e = model.measure(c->hull, kExcessLimit * o.tau, kExcessResolution * o.tau);
      if (e.exceeds) {
        c->screened = false;  // stays refused while both are unchanged
        continue;
      }
      Component& a = components[c->i];
      const Component& b = components[c->j];
      a.mesh = concatenate({a.mesh, b.mesh});
      // In the input's coordinates from the two hulls' own corners: it covers them exactly (the
      // frame's copy is rounded to its grid).
      std::vector<Vec3> corners = a.hull.vertices;
      corners.insert(corners.end(), b.hull.vertices.begin(), b.hull.vertices.end());
      a.hull = convexHull(corners).mesh;
      a.volume += b.volume;
      a.hullVolume = signedVolume(c->hull);
      a.hullExcess = e.distance;
      a.concavity = std::max(a.concavity, b.concavity);  // its parts' measure; the union's is not promised
      a.depth = std::min(a.depth, b.depth);
      hulls[c->i] = std::move(c->hull);
      boxes[c->i] = boundingBox(hulls[c->i]);
      alive[c->j] = 0;
      changed[c->i] = changed[c->j] = 1;
      ++merges;
      merged = true;
    }
    for (auto it = measured.begin(); it != measured.end();)
      it = changed[it->first.first] || changed[it->first.second] ? measured.erase(it) : std::next(it);
  }
  std::vector<Component> kept;
  for (int i = 0; i < n; ++i)
    if (alive[i]) kept.push_back(std::move(components[i]));
  components = std::move(kept);
  return merges;
}

}  // namespace acd
