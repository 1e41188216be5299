// Merging components down to a hull budget; see hull_budget.hpp.
#include <acd/algo/hull_budget.hpp>
#include <acd/algo/stopwatch.hpp>

#include <acd/algo/concavity.hpp>
#include <acd/algo/merge.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/evaluate.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/normalize.hpp>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace acd {

namespace {

struct Group {
  int uid = 0;                // fresh after every merge: keys the cache of measured pairs
  TriMesh mesh;               // input coordinates, closed (several pieces when joined)
  std::vector<int> members;   // components on entry
  Component info;             // concavity, volumes, depth, ... (hull filled in at the end)
  bool hullGap = false;
};

struct Candidate {
  bool valid = false;
  bool glued = false;
  double cost = std::numeric_limits<double>::infinity();    // concavity of the union (normalised)
  double growth = std::numeric_limits<double>::infinity();  // hull volume added (normalised)
  TriMesh mesh;                                             // the union, input coordinates
};

double hullVolume(const TriMesh& normalised) { return signedVolume(convexHull(normalised.vertices).mesh); }

TriMesh concatenated(const TriMesh& a, const TriMesh& b) {
  TriMesh out = a;
  const int base = static_cast<int>(out.vertices.size());
  out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const Face& f : b.faces) out.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  return out;
}

/// Neighbours glued along their shared faces, the union's concavity by the library's measure.
Candidate glue(const Group& a, const Group& b, const Normalization& norm, double epsilon) {
  Candidate c;
  if (!glueAlongSharedFaces(a.mesh, b.mesh, c.mesh)) return c;
  const TriMesh n = applyNormalization(c.mesh, norm);
  SurfaceGraph graph(n);
  ConcavityOptions co;
  co.epsilon = epsilon;
  c.cost = measureConcavity(n, graph, co).concavity;
  c.growth = hullVolume(n) - a.info.hullVolume - b.info.hullVolume;
  c.valid = c.glued = true;
  return c;
}

/// Pieces that share no face: the hull gap, the largest distance from the merged hull's
/// surface to the pieces, in the model's normalised units.
Candidate join(const Group& a, const Group& b, const Normalization& norm) {
  Candidate c;
  c.mesh = concatenated(a.mesh, b.mesh);
  EvaluateOptions eo;
  eo.volumeSamples = 1;  // only the surface measures are wanted
  eo.surfaceSamples = 20000;
  eo.threads = 1;
  const TriMesh hull = convexHull(c.mesh.vertices).mesh;
  const Evaluation e = evaluate(c.mesh, {hull}, eo);
  if (!e.status.ok()) return c;
  // evaluate() measures in the union's own normalised units: rescale to the model's.
  const double unionScale = minimumSphereNormalization(c.mesh).scale;
  c.cost = std::max({a.info.concavity, b.info.concavity, e.hullOutsideMax / unionScale * norm.scale});
  const TriMesh n = applyNormalization(c.mesh, norm);
  c.growth = hullVolume(n) - a.info.hullVolume - b.info.hullVolume;
  c.valid = true;
  return c;
}

/// A sphere around a mesh: the centroid of its vertices and the farthest vertex (turns with the mesh).
struct Ball {
  Vec3 centre = Vec3::Zero();
  double radius = 0.0;
};
Ball ballAround(const TriMesh& m) {
  Ball b;
  for (const Vec3& p : m.vertices) b.centre += p;
  b.centre /= static_cast<double>(std::max<std::size_t>(1, m.vertices.size()));
  for (const Vec3& p : m.vertices) b.radius = std::max(b.radius, (p - b.centre).norm());
  return b;
}

/// Each group with its four nearest others (by the gap between the spheres around them, which
/// does not depend on the pose), as sorted index pairs without repeats.
std::vector<std::pair<int, int>> nearestPairs(const std::vector<Group>& groups) {
  std::vector<std::pair<int, int>> pairs;
  std::vector<Ball> balls;
  for (const Group& g : groups) balls.push_back(ballAround(g.mesh));
  const int m = static_cast<int>(groups.size());
  for (int i = 0; i < m; ++i) {
    std::vector<std::pair<double, int>> near;
    for (int j = 0; j < m; ++j)
      if (j != i) near.emplace_back((balls[i].centre - balls[j].centre).norm() - balls[i].radius - balls[j].radius, j);
    std::sort(near.begin(), near.end());
    for (int k = 0; k < std::min<int>(4, static_cast<int>(near.size())); ++k)
      pairs.emplace_back(std::min(i, near[k].second), std::max(i, near[k].second));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

/// Group a takes in group b, merged as `best` says.
void absorb(Group& a, const Group& b, const Candidate& best) {
  a.mesh = best.mesh;
  a.members.insert(a.members.end(), b.members.begin(), b.members.end());
  std::sort(a.members.begin(), a.members.end());
  a.info.concavity = best.cost;
  a.info.depth = std::min(a.info.depth, b.info.depth);
  a.info.source = std::min(a.info.source, b.info.source);
  a.info.volume += b.info.volume;
  a.info.hullVolume = a.info.hullVolume + b.info.hullVolume + best.growth;
  a.info.unresolved = a.info.unresolved || b.info.unresolved;
  if (b.info.unresolved && a.info.note.empty()) a.info.note = b.info.note;
  a.hullGap = a.hullGap || b.hullGap || !best.glued;
}

}  // namespace

HullBudgetReport limitHullCount(Decomposition& d, const HullBudgetOptions& options) {
  const auto start = acd::Clock::now();
  HullBudgetReport r;
  r.tau = d.options.tau;
  if (options.maxHulls < 1) {
    r.status = Status::error(StatusCode::InvalidParameter,
                             "--max-hulls must be at least 1, got " + std::to_string(options.maxHulls));
    return r;
  }
  if (!d.status.ok()) {
    r.status = d.status;
    return r;
  }
  const int n = static_cast<int>(d.components.size());
  r.before = n;
  std::vector<Group> groups(n);
  for (int i = 0; i < n; ++i) {
    groups[i].uid = i;
    groups[i].mesh = d.components[i].mesh;
    groups[i].members = {i};
    groups[i].info = d.components[i];
  }
  int nextUid = n;
  std::map<std::pair<int, int>, Candidate> measured;  // by (uid, uid): pairs untouched by a merge keep their cost
  tbb::task_arena arena = workerArena(options.threads);

  while (static_cast<int>(groups.size()) > options.maxHulls) {
    std::vector<const TriMesh*> meshes;
    for (const Group& g : groups) meshes.push_back(&g.mesh);
    std::vector<std::pair<int, int>> pairs;
    for (const SharedFaces& s : sharedFacePairs(meshes)) pairs.emplace_back(s.a, s.b);
    std::sort(pairs.begin(), pairs.end());
    bool glueable = false;
    auto measure = [&](bool joining) {
      std::vector<std::pair<int, int>> todo;
      for (const auto& [i, j] : pairs)
        if (!measured.count({groups[i].uid, groups[j].uid})) todo.emplace_back(i, j);
      std::vector<Candidate> fresh(todo.size());
      arena.execute([&] {
        tbb::parallel_for(std::size_t(0), todo.size(), [&](std::size_t k) {
          const Group& a = groups[todo[k].first];
          const Group& b = groups[todo[k].second];
          fresh[k] = joining ? join(a, b, d.normalization) : glue(a, b, d.normalization, d.options.epsilon);
        });
      });
      for (std::size_t k = 0; k < todo.size(); ++k)
        measured[{groups[todo[k].first].uid, groups[todo[k].second].uid}] = std::move(fresh[k]);
    };
    measure(false);
    for (const auto& [i, j] : pairs) glueable = glueable || measured[{groups[i].uid, groups[j].uid}].valid;
    if (!glueable) {
      // No neighbours left to glue: join each group with its nearest few (gap between the
      // spheres around them, which does not depend on the pose).
      pairs = nearestPairs(groups);
      // A pair measured by gluing (and found not glueable) is measured again by joining.
      for (const auto& [i, j] : pairs) {
        auto it = measured.find({groups[i].uid, groups[j].uid});
        if (it != measured.end() && !it->second.valid) measured.erase(it);
      }
      measure(true);
    }
    int bi = -1, bj = -1;
    const Candidate* best = nullptr;
    for (const auto& [i, j] : pairs) {  // in a fixed order: the first of equals wins
      const Candidate& c = measured[{groups[i].uid, groups[j].uid}];
      if (!c.valid) continue;
      if (best == nullptr || c.cost < best->cost || (c.cost == best->cost && c.growth < best->growth))
        best = &c, bi = i, bj = j;
    }
    if (best == nullptr) {
      r.status = Status::error(StatusCode::InternalError, "no two components could be merged");
      return r;
    }
    Group& a = groups[bi];
    const Group& b = groups[bj];
    absorb(a, b, *best);
    (best->glued ? r.gluedMerges : r.joinedMerges) += 1;
    const int oldA = a.uid, oldB = b.uid;
    a.uid = nextUid++;
    groups.erase(groups.begin() + bj);
    for (auto it = measured.begin(); it != measured.end();) {
      const bool stale = it->first.first == oldA || it->first.second == oldA || it->first.first == oldB ||
                         it->first.second == oldB;
      it = stale ? measured.erase(it) : std::next(it);
    }
  }

  // Merged components get their hull; the others keep theirs.
  const int m = static_cast<int>(groups.size());
  std::vector<Component> out(m);
  arena.execute([&] {
    tbb::parallel_for(0, m, [&](int i) {
      Component c = groups[i].info;
      if (groups[i].members.size() > 1) {
        c.mesh = groups[i].mesh;
        c.hull = convexHull(c.mesh.vertices).mesh;
        c.volume = signedVolume(applyNormalization(c.mesh, d.normalization));
        c.hullVolume = signedVolume(applyNormalization(c.hull, d.normalization));
      }
      out[i] = std::move(c);
    });
  });
  d.components = std::move(out);
  r.after = m;
  for (const Group& g : groups) {
    r.members.push_back(g.members);
    r.hullGapMeasure.push_back(g.hullGap);
    r.maxConcavity = std::max(r.maxConcavity, g.info.concavity);
  }
  r.exceedsTau = r.maxConcavity > r.tau;
  r.seconds = acd::secondsSince(start);
  return r;
}

}  // namespace acd
