#include "arap_deform.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/algo/union_find.hpp>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <thread>

namespace tetmesh {

namespace {

using Mat3 = Eigen::Matrix3d;
using Mat43 = Eigen::Matrix<double, 4, 3>;

/// Rotation closest to F in the Frobenius norm (polar decomposition); a reflection is turned
/// into a rotation by flipping the axis of the smallest singular value, which costs least.
Mat3 closestRotation(const Mat3& f) {
  Eigen::JacobiSVD<Mat3> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 u = svd.matrixU();
  const Mat3& v = svd.matrixV();
  Mat3 r = u * v.transpose();
  if (r.determinant() < 0) {
    u.col(2) *= -1;  // Eigen sorts singular values in decreasing order
    r = u * v.transpose();
  }
  return r;
}


/// The per-tet constants: F_t = [x_a x_b x_c x_d] * B_t, and the weight of the tet in E.
struct TetOperator {
  std::vector<Mat43> b;
  std::vector<double> weight;  // rest volume, at least the floor; 0 for a degenerate tet (no energy)
};

TetOperator tetOperators(const TetMesh& mesh, double minWeight) {
  TetOperator op;
  op.b.resize(mesh.tets.size(), Mat43::Zero());
  op.weight.resize(mesh.tets.size(), 0.0);
  Mat43 e;  // edge vectors from corner a: [x_b - x_a, x_c - x_a, x_d - x_a] = X * e
  e << -1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& v = mesh.tets[t];
    Mat3 dm;
    dm.col(0) = mesh.points[v[1]] - mesh.points[v[0]];
    dm.col(1) = mesh.points[v[2]] - mesh.points[v[0]];
    dm.col(2) = mesh.points[v[3]] - mesh.points[v[0]];
    const double vol = dm.determinant() / 6.0;
    if (!(vol > 0)) continue;
    op.b[t] = e * dm.inverse();
    op.weight[t] = vol;
  }
  // Slivers (dihedral angles near 0, common in the unrefined mesh) have almost no volume, hence
  // almost no stiffness, and invert at no cost; a floor on the weight keeps them in shape.
  double mean = 0.0;
  for (double w : op.weight) mean += w / static_cast<double>(op.weight.size());
  for (double& w : op.weight)
    if (w > 0) w = std::max(w, minWeight * mean);
  return op;
}

Mat3 gradient(const TetMesh& mesh, const TetOperator& op, const std::vector<Vec3>& x, std::size_t t) {
  Eigen::Matrix<double, 3, 4> xs;
  for (int k = 0; k < 4; ++k) xs.col(k) = x[mesh.tets[t][k]];
  return xs * op.b[t];
}

/// Local step: best rotations for x, and the energy with them. The tets are split among
/// `threads` threads; each writes its own slots and the energy is summed in tet order, so the
/// result does not depend on the thread count.
double localStep(const TetMesh& mesh, const TetOperator& op, const std::vector<Vec3>& x, std::vector<Mat3>& rotations,
                 std::vector<double>& tetEnergy, int threads) {
  const std::size_t n = mesh.tets.size();
  auto work = [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) {
      if (op.weight[t] == 0) continue;
      const Mat3 f = gradient(mesh, op, x, t);
      rotations[t] = closestRotation(f);
      tetEnergy[t] = op.weight[t] * (f - rotations[t]).squaredNorm();
    }
  };
  const std::size_t chunks = std::min<std::size_t>(std::max(threads, 1), std::max<std::size_t>(n / 256, 1));
  std::vector<std::thread> pool;
  for (std::size_t c = 1; c < chunks; ++c) pool.emplace_back(work, n * c / chunks, n * (c + 1) / chunks);
  work(0, n / chunks);
  for (std::thread& th : pool) th.join();
  return std::accumulate(tetEnergy.begin(), tetEnergy.end(), 0.0);
}

// Roles: kFixed vertices keep a given position (constraint, rest); others are solved for.
constexpr int kFixed = -1;

/// Moves the constrained vertices of `x` to their targets; returns why it cannot, or "".
std::string applyConstraints(int n, const std::vector<int>& constrained, const std::vector<Vec3>& targets,
                             std::vector<Vec3>& x, std::vector<bool>& isConstrained) {
  for (std::size_t i = 0; i < constrained.size(); ++i) {
    const int v = constrained[i];
    if (v < 0 || v >= n) return "deformation: constrained vertex " + std::to_string(v) + " does not exist";
    if (!targets[i].allFinite()) return "deformation: target of vertex " + std::to_string(v) + " is not finite";
    if (isConstrained[v] && x[v] != targets[i])
      return "deformation: vertex " + std::to_string(v) + " has two different targets";
    isConstrained[v] = true;
    x[v] = targets[i];
  }
  return {};
}

/// The unknown's number of each free vertex (kFixed for the others). Parts of the mesh (tets
/// joined at vertices) that no constraint reaches stay at rest: their vertices are pinned.
std::vector<int> numberUnknowns(const TetMesh& mesh, const std::vector<bool>& isConstrained, ArapResult& r) {
  const int n = static_cast<int>(mesh.points.size());
  std::vector<bool> used(n, false);
  acd::UnionFind sets(n);
  for (const auto& t : mesh.tets)
    for (int k = 0; k < 4; ++k) {
      used[t[k]] = true;
      sets.join(t[k], t[0]);
    }
  std::vector<bool> reached(n, false);
  for (int v = 0; v < n; ++v)
    if (isConstrained[v]) reached[sets.find(v)] = true;
  std::vector<int> unknown(n, kFixed);
  for (int v = 0; v < n; ++v) {
    if (!used[v] || isConstrained[v]) continue;
    if (!reached[sets.find(v)]) {
      ++r.pinnedVertices;
      continue;
    }
    unknown[v] = r.freeVertices++;
  }
  return unknown;
}

/// The global step's linear system: stiffness over the free vertices (factored once), and the
/// constant right-hand side from the fixed ones.
struct GlobalSystem {
  const TetMesh& mesh;
  const TetOperator& op;
  const std::vector<int>& unknown;
  int free = 0;
  Eigen::MatrixXd fixedRhs;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;

  /// false when the matrix cannot be factored.
  bool factor(const std::vector<Vec3>& x) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(mesh.tets.size() * 16);
    fixedRhs = Eigen::MatrixXd::Zero(free, 3);
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      if (op.weight[t] == 0) continue;
      const Eigen::Matrix4d k = op.weight[t] * op.b[t] * op.b[t].transpose();
      for (int i = 0; i < 4; ++i) {
        const int row = unknown[mesh.tets[t][i]];
        if (row == kFixed) continue;
        for (int j = 0; j < 4; ++j) {
          const int vj = mesh.tets[t][j];
          if (unknown[vj] != kFixed)
            entries.emplace_back(row, unknown[vj], k(i, j));
          else
            fixedRhs.row(row) -= k(i, j) * x[vj].transpose();
        }
      }
    }
    Eigen::SparseMatrix<double> stiffness(free, free);
    stiffness.setFromTriplets(entries.begin(), entries.end());
    if (free > 0) {
      solver.compute(stiffness);
      if (solver.info() != Eigen::Success) return false;
    }
    return true;
  }

  /// Global step: positions minimising E for fixed rotations; false when the solve fails.
  bool solve(const std::vector<Mat3>& rotations, std::vector<Vec3>& x) {
    if (free == 0) return true;
    Eigen::MatrixXd rhs = fixedRhs;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      if (op.weight[t] == 0) continue;
      const Eigen::Matrix<double, 3, 4> g = op.weight[t] * rotations[t] * op.b[t].transpose();
      for (int i = 0; i < 4; ++i) {
        const int row = unknown[mesh.tets[t][i]];
        if (row != kFixed) rhs.row(row) += g.col(i).transpose();
      }
    }
    const Eigen::MatrixXd solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite()) return false;
    for (int v = 0; v < static_cast<int>(x.size()); ++v)
      if (unknown[v] != kFixed) x[v] = solution.row(unknown[v]).transpose();
    return true;
  }
};

/// Volumes, inverted tets and the constraint error of the result.
void measureResult(const TetMesh& mesh, const std::vector<int>& constrained, const std::vector<Vec3>& targets,
                   ArapResult& r) {
  r.volume = meshVolume(mesh, r.positions);
  r.linearVolume = meshVolume(mesh, r.linearPositions);
  r.invertedTets = countInverted(mesh, r.positions);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& v = mesh.tets[t];
    const Vec3& a = r.positions[v[0]];
    if ((r.positions[v[1]] - a).cross(r.positions[v[2]] - a).dot(r.positions[v[3]] - a) <= 0) r.invertedRestVolume += tetVolume(mesh, static_cast<int>(t));
  }
  r.linearInvertedTets = countInverted(mesh, r.linearPositions);
  for (std::size_t i = 0; i < constrained.size(); ++i)
    r.maxConstraintError = std::max(r.maxConstraintError, (r.positions[constrained[i]] - targets[i]).norm());
}

}  // namespace

double meshVolume(const TetMesh& mesh, const std::vector<Vec3>& positions) {
  double sum = 0.0;
  for (const auto& v : mesh.tets)
    sum += (positions[v[1]] - positions[v[0]]).cross(positions[v[2]] - positions[v[0]]).dot(positions[v[3]] - positions[v[0]]);
  return sum / 6.0;
}

int countInverted(const TetMesh& mesh, const std::vector<Vec3>& positions) {
  int n = 0;
  for (const auto& v : mesh.tets)
    n += (positions[v[1]] - positions[v[0]]).cross(positions[v[2]] - positions[v[0]]).dot(positions[v[3]] - positions[v[0]]) <= 0 ? 1 : 0;
  return n;
}

ArapResult arapDeform(const TetMesh& mesh, const std::vector<int>& constrained, const std::vector<Vec3>& targets,
                      const ArapOptions& options) {
  ArapResult r;
  const int n = static_cast<int>(mesh.points.size());
  auto fail = [&](acd::StatusCode code, const std::string& message) {
    r.status = acd::Status::error(code, message);
    return r;
  };
  if (constrained.size() != targets.size())
    return fail(acd::StatusCode::InvalidParameter, "deformation: one target per constrained vertex is needed");
  if (options.maxIterations < 0 || !(options.tolerance >= 0) || !(options.minWeight >= 0) || !std::isfinite(options.minWeight))
    return fail(acd::StatusCode::InvalidParameter, "deformation: iterations, tolerance and weight floor must not be negative");

  std::vector<Vec3> x = mesh.points;
  std::vector<bool> isConstrained(n, false);
  if (const std::string why = applyConstraints(n, constrained, targets, x, isConstrained); !why.empty())
    return fail(acd::StatusCode::InvalidParameter, why);
  const std::vector<int> unknown = numberUnknowns(mesh, isConstrained, r);

  const TetOperator op = tetOperators(mesh, options.minWeight);
  r.restVolume = meshVolume(mesh, mesh.points);

  const auto factorStart = acd::Clock::now();
  GlobalSystem system{mesh, op, unknown, r.freeVertices, {}, {}};
  if (!system.factor(x))
    return fail(acd::StatusCode::InternalError, "deformation: the stiffness matrix could not be factored (degenerate tets?)");
  r.factorSeconds = acd::secondsSince(factorStart);

  const auto solveStart = acd::Clock::now();
  std::vector<Mat3> rotations(mesh.tets.size(), Mat3::Identity());
  std::vector<double> tetEnergy(mesh.tets.size(), 0.0);
  const int threads = options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<Vec3> restStart = x;
  if (!system.solve(rotations, x)) return fail(acd::StatusCode::InternalError, "deformation: the linear solve failed");
  r.linearPositions = x;
  if (!options.linearStart) x = restStart;
  const double weights = std::accumulate(op.weight.begin(), op.weight.end(), 0.0);
  const double scale = weights > 0 ? 1.0 / weights : 1.0;
  r.energy.push_back(scale * localStep(mesh, op, x, rotations, tetEnergy, threads));
  while (r.iterations < options.maxIterations) {
    const double previous = r.energy.back();
    if (previous <= 1e-28) {  // already a rigid motion up to rounding
      r.converged = true;
      break;
    }
    if (!system.solve(rotations, x)) return fail(acd::StatusCode::InternalError, "deformation: a solve failed");
    ++r.iterations;
    r.energy.push_back(scale * localStep(mesh, op, x, rotations, tetEnergy, threads));
    if (options.progress) options.progress(r.iterations, r.energy.back());
    if (previous - r.energy.back() <= options.tolerance * previous) {
      r.converged = true;
      break;
    }
  }
  r.solveSeconds = acd::secondsSince(solveStart);

  r.positions = std::move(x);
  measureResult(mesh, constrained, targets, r);
  return r;
}

}  // namespace tetmesh
