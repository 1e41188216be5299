// The candidates at a notch and the choice among them. Candidates are cut and scored in parallel
// into their own slots and the best is picked in candidate order, so the choice does not depend on
// the thread count.
#include <acd/algo/cut_choice.hpp>
#include <acd/algo/stopwatch.hpp>

#include <acd/algo/cut_plane.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/knot_graph.hpp>
#include <acd/algo/hull.hpp>

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

namespace acd {

namespace {

/// Vertices this close to a cut plane are on its cap (cut vertices lie on it up to rounding).
constexpr double kCapThickness = 1e-9;

/// The plane across a pocket's floor ties with every other candidate where each plane only
/// shortens or narrows a straight pocket (a bore or slot with flat walls: every candidate lies in
/// a wall), and then it would cut the pocket into rings; across a through-slot it slices the solid
/// on both sides. It wins only when its lookahead score is below the best other candidate's by
/// this share of the piece's volume (the handle's bore: 2.1 %; a wall's through-hole: 0.34 %).
constexpr double kFloorPlaneMargin = 0.01;
}  // namespace

bool cutCleanly(const TriMesh& mesh, const Plane& plane, std::vector<TriMesh>& pieces, Plane& used, const Vec3* near) {
  // Small shifts get past degenerate sections; the larger ones past local self-intersections of the
  // input (whose sections have crossing loops), at the price of a cut slightly off the notch.
  const double nudges[] = {0.0, 1e-7, -1e-7, 1e-5, -1e-5, 1e-3, -1e-3, 4e-3, -4e-3};
  // A piece this much smaller than its parent is a sliver: the plane grazed a face and resolved nothing.
  const double minVolume = 1e-7 * signedVolume(mesh);
  for (double nudge : nudges) {
    Plane p = plane;
    p.offset += nudge * p.normal.norm();
    CutResult cut = cutByPlane(mesh, p, 1e-10, near);
    if (!cut.ok || cut.below.empty() || cut.above.empty()) continue;
    std::vector<TriMesh> out;
    bool valid = true;
    for (auto* side : {&cut.below, &cut.above})
      for (TriMesh& m : *side) {
        if (signedVolume(m) <= minVolume) valid = false;
        out.push_back(std::move(m));
      }
    if (!valid) continue;
    pieces = std::move(out);
    used = p;
    return true;
  }
  return false;
}

Plane splitCupPlane(const TriMesh& mesh, const ConcavityMap& map, int notch) {
  const int bridge = map.vertexBridge[notch];
  const Vec3 n = map.bridges[bridge].normal;
  std::vector<char> in(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (map.facePocket[f] == bridge)
      for (int v : mesh.faces[f]) in[v] = 1;
  Vec3 mean = Vec3::Zero();
  int count = 0;
  for (std::size_t v = 0; v < in.size(); ++v)
    if (in[v]) mean += mesh.vertices[v], ++count;
  const Vec3& x = mesh.vertices[notch];
  if (count < 3) return Plane::through(x, n.unitOrthogonal());
  mean /= count;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t v = 0; v < in.size(); ++v)
    if (in[v]) {
      Vec3 d = mesh.vertices[v] - mean;
      d -= d.dot(n) * n;  // projected on the bridge plane
      cov += d * d.transpose();
    }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vec3 axis = eig.eigenvectors().col(2);
  axis -= axis.dot(n) * n;
  if (axis.norm() < 1e-12) axis = n.unitOrthogonal();
  return Plane::through(x, axis.normalized());
}

std::vector<Plane> candidatePlanes(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityMap& map,
                                   const DecomposeOptions& o, const CutSite& site, double& groupingSeconds) {
  const Vec3& notch = mesh.vertices[site.notch];
  const Vec3& bridgeNormal = site.bridgeNormal;
  const int stalls = site.stalls;
  std::vector<Plane> candidates;
  if (o.featureGrouping && stalls == 0 && !site.fromExcess) {
    const auto t = Clock::now();
    // The paper's global cut: the minimum-weight cycle of the knot graph G_K through the root
    // pocket cut (Section 4.2.4). Four greedily grown cuts compete with it (they also reach
    // pockets without knots, where G_K has no edges): legs restricted to matched knots or free
    // to take the cheapest knot, with a notch on a boundary taken as an end of the root cut or
    // not. The lookahead keeps whichever plane serves better.
    const std::vector<double> curvature = slotCurvatures(mesh, graph);  // shared by the five searches
    // The five searches are independent: run in parallel, each into its own slot (search 0 is the
    // knot graph's cycle, 1-4 the grown cuts), then taken in this order.
    std::vector<std::vector<Plane>> found(5);
    tbb::parallel_for(0, 5, [&](int search) {
      if (search == 0) {
        const KnotGraph kg = buildKnotGraph(mesh, graph, map, o.delta, &curvature);
        const GlobalCut cycle = knotGraphCycle(mesh, map, kg);
        if (cycle.vertices.size() >= 3)
          found[0].push_back(Plane::through(notch, fitCutPlane(mesh, cycle, bridgeNormal, 0.5 * o.tau).normal));
        return;
      }
      const int variant = search - 1;
      FeatureOptions fo;
      fo.delta = o.delta;
      fo.matchKnots = variant < 2;
      fo.notchAsEnd = variant % 2 == 0;
      fo.slotCurvature = &curvature;
      const GlobalCut cut = findGlobalCut(mesh, graph, map, fo);
      if (cut.vertices.size() < 2) return;
      const Plane plane = fitCutPlane(mesh, cut, bridgeNormal, 0.5 * o.tau);
      // A plane (nearly) parallel to the bridge only skims the pocket: the cup-shaped case of
      // Figure 13. Split the cup through its deepest point instead, across its longest extent.
      if (variant == 0 && (cut.cupShaped || std::abs(plane.normal.normalized().dot(bridgeNormal)) > 0.9))
        found[search].push_back(splitCupPlane(mesh, map, map.notch));
      // The plane must resolve the notch it was grown from: it passes through it. (A plane a hair
      // away from the notch would only shave off a sliver and leave the notch as it was.)
      found[search].push_back(Plane::through(notch, plane.normal));
    });
    for (const std::vector<Plane>& planes : found) candidates.insert(candidates.end(), planes.begin(), planes.end());
    groupingSeconds += secondsSince(t);
  }
  if (stalls <= 1) candidates.push_back(bisectorPlane(mesh, graph, site.notch, bridgeNormal));
  // Planes through the notch that contain the bridge normal split the pocket between the bridge's
  // ends (two orthogonal ones; a different pair after each stall).
  // (unitOrthogonal follows the frame's axes: the canonical frame's, so the fan is the shape's.)
  const Vec3 u = bridgeNormal.unitOrthogonal(), w = bridgeNormal.cross(u);
  const double pi = std::acos(-1.0);
  // After repeated stalls, a wider fan competes by lookahead.
  const int fan = stalls >= 2 || site.fromExcess ? 8 : 2;
  // The plane through the notch parallel to the bridge: level with a pocket's floor, it cuts the
  // solid beside the pocket away from the part around it. A blind bore in a waisted block (the
  // handle) is best cut there first, and its axis makes the fitted planes of the grown cuts
  // arbitrary (they tilt with tau). Not for a hull standing off its piece (no pocket floor).
  if (stalls >= 2 || (stalls == 0 && !site.fromExcess)) candidates.push_back(Plane::through(notch, bridgeNormal));
  for (int k = 0; k < fan; ++k) {
    const double angle = pi * k / fan + 0.25 * pi * (stalls % 2);  // a different set on each stall
    candidates.push_back(Plane::through(notch, std::cos(angle) * u + std::sin(angle) * w));
  }
  return candidates;
}

CutChoice cutByFirstPlane(const TriMesh& mesh, const std::vector<Plane>& candidates) {
  CutChoice choice;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (cutCleanly(mesh, candidates[i], choice.pieces, choice.plane)) {
      choice.ok = true;
      choice.index = i;
      return choice;
    }
    ++choice.failed;
  }
  return choice;
}

TriMesh lookaheadHull(const TriMesh& child, const Plane& plane) {
  // In the plane's frame (u, w, n; right-handed, so orientation is kept) the cap's points get a
  // height of exactly 0: quickhull's tests among them are then decided without exact arithmetic
  // (cap points are coplanar only up to rounding in the model's frame, and every test of one
  // against the cap's facets would go to it). Only the cap outline's corners are kept.
  const Vec3 n = plane.normal.normalized();
  const Vec3 origin = n * (plane.offset / plane.normal.norm());
  const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
  std::vector<Vec3> framed;
  std::vector<int> vertexOf;
  std::vector<std::pair<Eigen::Vector2d, int>> cap;
  for (int v = 0; v < static_cast<int>(child.vertices.size()); ++v) {
    const Vec3 d = child.vertices[v] - origin;
    const Vec3 p(u.dot(d), w.dot(d), n.dot(d));
    if (std::abs(p.z()) > kCapThickness)
      framed.push_back(p), vertexOf.push_back(v);
    else
      cap.push_back({Eigen::Vector2d(p.x(), p.y()), v});
  }
  // Andrew's monotone chain, strict turns only; ties in position by vertex index.
  std::sort(cap.begin(), cap.end(), [](const auto& a, const auto& b) {
    if (a.first.x() != b.first.x()) return a.first.x() < b.first.x();
    if (a.first.y() != b.first.y()) return a.first.y() < b.first.y();
    return a.second < b.second;
  });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<int> outline(2 * cap.size() + 1);
  std::size_t k = 0;
  if (cap.size() < 3) {
    for (std::size_t i = 0; i < cap.size(); ++i) outline[k++] = static_cast<int>(i);
  } else {
    for (std::size_t i = 0; i < cap.size(); ++i) {  // lower chain
      while (k >= 2 && cross(cap[outline[k - 2]].first, cap[outline[k - 1]].first, cap[i].first) <= 0) --k;
      outline[k++] = static_cast<int>(i);
    }
    for (std::size_t i = cap.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
      while (k >= lower && cross(cap[outline[k - 2]].first, cap[outline[k - 1]].first, cap[i].first) <= 0) --k;
      outline[k++] = static_cast<int>(i);
    }
    --k;  // the chain ends where it began
  }
  for (std::size_t i = 0; i < k; ++i) {
    const auto& [xy, v] = cap[outline[i]];
    framed.emplace_back(xy.x(), xy.y(), 0.0);
    vertexOf.push_back(v);
  }
  ConvexHull hull = convexHull(framed);
  for (std::size_t i = 0; i < hull.mesh.vertices.size(); ++i) hull.mesh.vertices[i] = child.vertices[vertexOf[hull.source[i]]];
  return std::move(hull.mesh);
}

CutChoice cutByLookahead(const TriMesh& mesh, const std::vector<Plane>& candidates, const CutSite& site,
                         const ConcavityOptions& co, double tau) {
  std::vector<std::vector<TriMesh>> children(candidates.size());
  std::vector<Plane> used(candidates.size());
  std::vector<char> cutOk(candidates.size(), 0);
  std::vector<double> score(candidates.size(), 0.0);
  std::vector<int> exceeding(candidates.size(), 0);
  // Different notches' cuts often fit the same plane: an exact repeat is scored once (it could
  // not win anyway, the earlier candidate wins ties).
  std::vector<int> repeatOf(candidates.size(), -1);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    for (std::size_t j = 0; j < i && repeatOf[i] < 0; ++j)
      if (candidates[i].normal == candidates[j].normal && candidates[i].offset == candidates[j].offset)
        repeatOf[i] = static_cast<int>(j);
  // The plane across the pocket's floor (candidatePlanes) only wins by a clear margin over the
  // others: it is decided after them, and cut only when it still can win.
  const double pieceVolume = signedVolume(mesh);
  const auto acrossFloor = [&](std::size_t i) { return site.stalls == 0 && candidates[i].normal == site.bridgeNormal; };
  const auto evaluate = [&](std::size_t i) {
    // Only the section through the notch is cut: a plane across a hand would otherwise cut
    // every finger it meets, into tips too small to matter and too far apart to merge again.
    cutOk[i] = cutCleanly(mesh, candidates[i], children[i], used[i], site.atNotchOnly ? &mesh.vertices[site.notch] : nullptr);
    if (!cutOk[i]) return;
    for (const TriMesh& child : children[i]) {
      if (site.stalls > 0) {
        SurfaceGraph childGraph(child);
        score[i] = std::max(score[i], measureConcavity(child, childGraph, co).concavity);
      } else {
        const TriMesh hull = lookaheadHull(child, used[i]);
        score[i] += signedVolume(hull) - signedVolume(child);
        // A cut for a hull standing off its piece is judged first by how many children still do.
        if (site.fromExcess)
          exceeding[i] += measureHullExcess(child, hull, kExcessLimit * tau, kExcessResolution * tau).exceeds;
      }
    }
  };
  const auto evaluateAll = [&](const std::vector<std::size_t>& which) {
    tbb::parallel_for(std::size_t(0), which.size(), [&](std::size_t k) { evaluate(which[k]); });
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (repeatOf[i] >= 0) cutOk[i] = cutOk[repeatOf[i]], score[i] = score[repeatOf[i]], exceeding[i] = exceeding[repeatOf[i]];
  };
  std::vector<std::size_t> others, floors;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (repeatOf[i] < 0) (acrossFloor(i) ? floors : others).push_back(i);
  evaluateAll(others);
  // The lowest score wins, ties to the earlier candidate. (Treating scores within 1e-9 of the
  // piece's volume as ties was tried: the same on the corpus, but on a symmetric torus, where
  // rounding alone tells candidates apart, it took 56-59 parts instead of 45: docs/ALGORITHM.md.)
  CutChoice choice;
  double bestScore = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (acrossFloor(i)) continue;
    if (!cutOk[i]) {
      ++choice.failed;
      continue;
    }
    if (!choice.ok || exceeding[i] < exceeding[choice.index] ||
        (exceeding[i] == exceeding[choice.index] && score[i] < bestScore)) {
      bestScore = score[i];
      choice.index = i;
      choice.ok = true;
    }
  }
  // A score is a volume, at least 0: when the best is within the margin, nothing can beat it by
  // the margin, and the floor plane is not cut at all.
  const bool floorCanWin = !floors.empty() && (!choice.ok || bestScore > kFloorPlaneMargin * pieceVolume);
  if (floorCanWin) evaluateAll(floors);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const bool evaluated = floorCanWin || repeatOf[i] >= 0;  // a repeat has its original's values
    if (!acrossFloor(i) || !evaluated) continue;
    if (!cutOk[i]) {
      ++choice.failed;
      continue;
    }
    if (!choice.ok || score[i] < bestScore - kFloorPlaneMargin * pieceVolume) {
      bestScore = score[i];
      choice.index = i;
      choice.ok = true;
    }
  }
  if (choice.ok) {
    choice.pieces = std::move(children[choice.index]);
    choice.plane = used[choice.index];
  }
  return choice;
}

}  // namespace acd
