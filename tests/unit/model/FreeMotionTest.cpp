// Words for the null space of a singular stiffness matrix (model/FreeMotion): rigid translations and
// rotations of a block, combinations, several blocks, and a mechanism that is no rigid motion.
#include "model/FreeMotion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/Generators.hpp"
#include "mesh/MeshMerge.hpp"

namespace {

using contessa::mesh::Mesh;
using contessa::model::describeFreeMotion;

Mesh block(const std::string& name, double x0 = 0.0) {
  contessa::mesh::RectangleSpec spec;
  spec.x0 = x0;
  spec.lx = 2.0;
  spec.ly = 1.0;
  spec.nx = 4;
  spec.ny = 2;
  spec.blockName = name;
  return contessa::mesh::generateRectangle(spec);
}

// u = t + ω e_z × (x − p) at every node, scaled arbitrarily (null vectors have no preferred length).
std::vector<double> rigid(const Mesh& mesh, double tx, double ty, double omega, double px = 0, double py = 0,
                          double scale = 0.37) {
  std::vector<double> v(mesh.coordinates.size());
  for (std::size_t n = 0; n < v.size() / 2; ++n) {
    v[2 * n] = scale * (tx - omega * (mesh.coordinates[2 * n + 1] - py));
    v[2 * n + 1] = scale * (ty + omega * (mesh.coordinates[2 * n] - px));
  }
  return v;
}

TEST(FreeMotion, Translation) {
  const Mesh m = block("block_1");
  EXPECT_EQ(describeFreeMotion(m, {rigid(m, 0, 1, 0)}), "block 'block_1' is free to translate in y");
  EXPECT_EQ(describeFreeMotion(m, {rigid(m, -2, 0, 0)}), "block 'block_1' is free to translate in x");
}

TEST(FreeMotion, RotationAboutTheCentroidAndAboutAPoint) {
  const Mesh m = block("b");
  EXPECT_EQ(describeFreeMotion(m, {rigid(m, 0, 0, 1, 1.0, 0.5)}), "block 'b' is free to rotate about z");
  // About the corner (0, 0), e.g. a block pinned there.
  EXPECT_EQ(describeFreeMotion(m, {rigid(m, 0, 0, 1, 0.0, 0.0)}),
            "block 'b' is free to rotate about z about the point (0, 0)");
}

TEST(FreeMotion, AnyBasisOfTheSameSpaceGivesTheSameWords) {
  const Mesh m = block("b");
  // Translations in x and y, given as two diagonal combinations.
  EXPECT_EQ(describeFreeMotion(m, {rigid(m, 1, 1, 0), rigid(m, 1, -1, 0)}), "block 'b' is free to translate in x and translate in y");
  // All three rigid modes, mixed.
  EXPECT_EQ(describeFreeMotion(m, {rigid(m, 1, 1, 0.3), rigid(m, 1, -1, 0), rigid(m, 0, 2, -1)}),
            "block 'b' is free to translate in x, translate in y and rotate about z");
}

TEST(FreeMotion, OnlyTheBlocksThatMove) {
  // Two separate bodies; only the second floats.
  const Mesh m = contessa::mesh::mergeMeshes({{"held", block("b")}, {"floating", block("b", 5.0)}});
  std::vector<double> v(m.coordinates.size(), 0.0);
  const auto& floating = m.block("floating");
  for (auto n : floating.connectivity) v[2 * n + 1] = 1.0;
  EXPECT_EQ(describeFreeMotion(m, {v}), "block 'floating' is free to translate in y");
}

TEST(FreeMotion, MechanismIsNotARigidMotion) {
  const Mesh m = block("b");
  std::vector<double> v(m.coordinates.size(), 0.0);
  v[2 * 7 + 1] = 1.0;  // one node alone (node id 7, Exodus id 8)
  const std::string s = describeFreeMotion(m, {v});
  EXPECT_NE(s.find("block 'b' is free to deform without resistance"), std::string::npos) << s;
  EXPECT_NE(s.find("largest at node 8"), std::string::npos) << s;
}

}  // namespace
