#include "opening_frame.hpp"

#include "smallest_rectangle.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace planner {

OpeningFrame openingFrame(const Opening& opening) {
  OpeningFrame f;
  f.normal = opening.normal.normalized();
  // A basis of the plane: the coordinate axis least aligned with the normal, made orthogonal.
  int least = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(f.normal[i]) < std::abs(f.normal[least])) least = i;
  const acd::Vec3 e1 = (acd::Vec3::Unit(least) - f.normal[least] * f.normal).normalized();
  const acd::Vec3 e2 = f.normal.cross(e1);
  std::vector<Point2> points;
  for (const acd::Vec3& p : opening.triangles.vertices) {
    const acd::Vec3 d = p - opening.centroid;
    points.push_back({d.dot(e1), d.dot(e2)});
  }
  const Rectangle2 r = smallestRectangle(points);
  const Point2 bestDir = r.side, bestMid = r.middle;
  double bestHalf[2] = {r.half[0], r.half[1]};
  acd::Vec3 side = bestDir[0] * e1 + bestDir[1] * e2;
  acd::Vec3 across = f.normal.cross(side);
  if (bestHalf[1] > bestHalf[0]) std::swap(side, across), std::swap(bestHalf[0], bestHalf[1]);
  f.longSide = side.normalized();
  f.shortSide = f.normal.cross(f.longSide);
  f.halfLong = bestHalf[0];
  f.halfShort = bestHalf[1];
  f.center = opening.centroid + bestMid[0] * e1 + bestMid[1] * e2;
  return f;
}

}  // namespace planner
