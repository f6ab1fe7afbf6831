#include "model/FreeMotion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "mechanics/DenseSolve.hpp"

namespace contessa::model {

using mesh::GlobalIndex;

namespace {

// A block moves in a null vector when it carries at least this share of the largest block's motion.
constexpr double kMovingShare = 1e-2;
// A null vector is a rigid-body motion of a block when the rigid modes explain this much of its norm².
constexpr double kRigidFraction = 0.9;
// A rigid mode is free when the null space (restricted to the block) holds this much of it.
constexpr double kInSpan = 0.98;

const char* const kAxis[] = {"x", "y", "z"};

/// The rigid-body modes of one block's nodes: translations along each axis, then rotations about each
/// axis through the centroid (2D: about z; 3D: about x, y, z), as fields over the block's DOFs.
struct RigidModes {
  std::vector<GlobalIndex> nodes;
  int dim = 2;
  std::vector<double> centroid;
  std::vector<std::vector<double>> fields;  // one per mode, node-major like the DOFs
  std::vector<std::string> names;
  std::vector<double> gram;                 // fields_i · fields_j

  RigidModes(const mesh::Mesh& mesh, const mesh::ElementBlock& block) : dim(mesh.dimension), centroid(dim, 0.0) {
    nodes.assign(block.connectivity.begin(), block.connectivity.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (GlobalIndex n : nodes)
      for (int c = 0; c < dim; ++c) centroid[c] += mesh.coordinates[n * dim + c] / static_cast<double>(nodes.size());
    const std::size_t size = nodes.size() * dim;
    for (int c = 0; c < dim; ++c) {
      std::vector<double> t(size, 0.0);
      for (std::size_t k = 0; k < nodes.size(); ++k) t[k * dim + c] = 1.0;
      fields.push_back(t);
      names.push_back(std::string("translate in ") + kAxis[c]);
    }
    // Rotation in the plane (i, j) about the axis k: u_i = −(x_j − c_j), u_j = x_i − c_i.
    const std::vector<std::array<int, 3>> planes =
        dim == 2 ? std::vector<std::array<int, 3>>{{{0, 1, 2}}}
                 : std::vector<std::array<int, 3>>{{{1, 2, 0}}, {{2, 0, 1}}, {{0, 1, 2}}};
    for (const auto& [i, j, k] : planes) {
      std::vector<double> r(size, 0.0);
      for (std::size_t m = 0; m < nodes.size(); ++m) {
        r[m * dim + i] = -(mesh.coordinates[nodes[m] * dim + j] - centroid[j]);
        r[m * dim + j] = mesh.coordinates[nodes[m] * dim + i] - centroid[i];
      }
      fields.push_back(r);
      names.push_back(std::string("rotate about ") + kAxis[k]);
    }
    const int n = count();
    gram.assign(n * n, 0.0);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) gram[a * n + b] = dotFields(fields[a], fields[b]);
  }

  int count() const { return static_cast<int>(fields.size()); }

  static double dotFields(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
    return s;
  }

  /// The block's part of a global vector.
  std::vector<double> restrict(const std::vector<double>& v) const {
    std::vector<double> out(nodes.size() * dim);
    for (std::size_t m = 0; m < nodes.size(); ++m)
      for (int c = 0; c < dim; ++c) out[m * dim + c] = v[nodes[m] * dim + c];
    return out;
  }

  /// Least-squares coefficients of the rigid modes for a block field (Gram system).
  std::vector<double> fit(const std::vector<double>& field) const {
    const int n = count();
    std::vector<double> g = gram, a(n);
    for (int m = 0; m < n; ++m) a[m] = dotFields(fields[m], field);
    // n rigid modes: 3 in 2D, 6 in 3D.
    const bool solved = n == 3   ? mechanics::solveDenseInPlace<3, 1>(g.data(), a.data())
                        : n == 6 ? mechanics::solveDenseInPlace<6, 1>(g.data(), a.data())
                                 : false;
    if (!solved) a.assign(n, 0.0);  // a single node: no rotation
    return a;
  }

  double norm2(const std::vector<double>& coefficients) const {
    const int n = count();
    double s = 0.0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) s += coefficients[a] * gram[a * n + b] * coefficients[b];
    return s;
  }
  double inner(const std::vector<double>& x, const std::vector<double>& y) const {
    const int n = count();
    double s = 0.0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) s += x[a] * gram[a * n + b] * y[b];
    return s;
  }
};

std::string quoted(const std::string& name) { return "'" + name + "'"; }

std::string joinWords(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? " and " : ", ") + words[i];
  return out;
}

}  // namespace

std::string describeFreeMotion(const mesh::Mesh& mesh, const std::vector<std::vector<double>>& nullSpace) {
  const int dim = mesh.dimension;
  std::vector<RigidModes> modes;
  for (const auto& block : mesh.blocks) modes.emplace_back(mesh, block);

  // Per block: the rigid coefficients of each null vector in which it moves, and whether all were rigid.
  std::vector<std::vector<std::vector<double>>> coefficients(mesh.blocks.size());
  std::vector<char> mechanism(mesh.blocks.size(), 0);
  std::vector<GlobalIndex> mechanismNode(mesh.blocks.size(), -1);
  for (const auto& v : nullSpace) {
    std::vector<double> share(mesh.blocks.size(), 0.0);
    std::vector<std::vector<double>> parts;
    for (std::size_t b = 0; b < modes.size(); ++b) {
      parts.push_back(modes[b].restrict(v));
      share[b] = RigidModes::dotFields(parts.back(), parts.back());
    }
    const double largest = *std::max_element(share.begin(), share.end());
    if (!(largest > 0.0)) continue;
    for (std::size_t b = 0; b < modes.size(); ++b) {
      if (share[b] < kMovingShare * largest) continue;
      const auto a = modes[b].fit(parts[b]);
      if (modes[b].norm2(a) >= kRigidFraction * share[b]) {
        coefficients[b].push_back(a);
        continue;
      }
      mechanism[b] = 1;
      // Where the non-rigid motion is largest.
      double biggest = -1.0;
      for (std::size_t m = 0; m < modes[b].nodes.size(); ++m) {
        double s = 0.0;
        for (int c = 0; c < dim; ++c) s += parts[b][m * dim + c] * parts[b][m * dim + c];
        if (s > biggest) {
          biggest = s;
          mechanismNode[b] = modes[b].nodes[m];
        }
      }
    }
  }

  // Per block: an orthonormal basis of its rigid null space (Gram–Schmidt in the field inner product),
  // then the named modes that lie in it; what is left is described as a rotation about a point (2D).
  std::map<std::string, std::vector<std::string>> blocksBySentence;
  std::vector<std::string> order;
  const auto add = [&](const std::string& what, const std::string& block) {
    if (!blocksBySentence.count(what)) order.push_back(what);
    blocksBySentence[what].push_back(quoted(block));
  };
  for (std::size_t b = 0; b < modes.size(); ++b) {
    const RigidModes& rm = modes[b];
    std::vector<std::vector<double>> basis;
    for (auto a : coefficients[b]) {
      const double before = rm.norm2(a);
      for (const auto& q : basis) {
        const double p = rm.inner(a, q);
        for (int m = 0; m < rm.count(); ++m) a[m] -= p * q[m];
      }
      const double after = rm.norm2(a);
      if (!(after > 1e-6 * before) || !(after > 0.0)) continue;
      for (auto& x : a) x /= std::sqrt(after);
      basis.push_back(a);
    }
    std::vector<std::string> free;
    for (int m = 0; m < rm.count() && !basis.empty(); ++m) {
      std::vector<double> e(rm.count(), 0.0);
      e[m] = 1.0;
      double inSpan = 0.0;
      for (const auto& q : basis) inSpan += std::pow(rm.inner(e, q), 2);
      if (inSpan >= kInSpan * rm.norm2(e)) free.push_back(rm.names[m]);
    }
    if (free.size() < basis.size()) {
      if (dim == 2 && basis.size() == 1 && std::abs(basis[0][2]) > 0.0) {
        // u = t + ω e_z × (x − c) is a rotation about p = c + (−t_y, t_x)/ω.
        const auto& q = basis[0];
        const double size = std::sqrt(rm.gram[2 * rm.count() + 2] / static_cast<double>(rm.nodes.size()));
        const auto rounded = [&](double x) { return std::abs(x) <= 1e-9 * size ? 0.0 : x; };  // round-off of 0
        char point[96];
        std::snprintf(point, sizeof point, "rotate about z about the point (%.6g, %.6g)",
                      rounded(rm.centroid[0] - q[1] / q[2]), rounded(rm.centroid[1] + q[0] / q[2]));
        free.push_back(point);
      } else {
        free.push_back("move rigidly in " + std::to_string(basis.size() - free.size()) +
                       " further combination(s) of translation and rotation");
      }
    }
    if (!free.empty()) add("free to " + joinWords(free), mesh.blocks[b].name);
    if (mechanism[b])
      add("free to deform without resistance (a mechanism, not a rigid-body motion, largest at node " +
              std::to_string(mechanismNode[b] + 1) + ")",
          mesh.blocks[b].name);
  }

  std::string out;
  for (const auto& what : order) {
    const auto& blocks = blocksBySentence[what];
    out += (out.empty() ? "" : "; ") + std::string(blocks.size() == 1 ? "block " : "blocks ") + joinWords(blocks) +
           (blocks.size() == 1 ? " is " : " are ") + what;
  }
  return out.empty() ? "the free direction could not be identified" : out;
}

}  // namespace contessa::model
