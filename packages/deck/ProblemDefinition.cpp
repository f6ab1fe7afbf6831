#include "deck/ProblemDefinition.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include <Teuchos_Array.hpp>

#include "common/Error.hpp"
#include "common/ParameterTable.hpp"
#include "deck/Axisymmetry.hpp"
#include "deck/AutomaticPenalty.hpp"
#include "deck/ContactLawFactory.hpp"
#include "deck/LoadDefinitions.hpp"
#include "deck/MeshReferences.hpp"
#include "deck/ParameterValidation.hpp"
#include "contact/ContactSurface.hpp"
#include "contact/MortarQuadraticFacetPair.hpp"
#include "contact/MortarQuadraticSegment.hpp"
#include "contact/SmoothedMaster.hpp"
#include "mesh/MeshDistribution.hpp"
#include "mesh/MeshFactory.hpp"
#include "mesh/MeshMerge.hpp"

namespace contessa::deck {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;
using mesh::GlobalIndex;

const char* kOpenLists[] = {"Mesh",         "Blocks",     "Materials", "Dirichlet Conditions", "Nodal Forces",
                            "Loads",        "Regression", "Contact",   "Output/History",
                            "Load Steps"};

// A mesh list's parameters validated (defaults filled in) on every rank; returns its type.
std::string validateMeshList(ParameterList& list, const std::string& where, bool isPart) {
  std::vector<std::string> types = mesh::MeshFactory::names();  // "Parts" do not nest
  requireInput(list.isParameter("Type") && list.isType<std::string>("Type"),
               where + "/Type: required; expected one of " + joinNames(isPart ? types : meshTypes()));
  const std::string type = list.get<std::string>("Type");
  requireOneOf(where + "/Type", type, isPart ? types : meshTypes());
  auto valid = Teuchos::rcp(new ParameterList(*meshValidParameters(type)));
  if (isPart) valid->set("Offset", Teuchos::Array<double>(), "Translation of this part (x, y[, z]); empty = none");
  validateAndSetDefaults(list, *valid, where);
  return type;
}

// One part of a "Parts" mesh, whole (on rank 0, which merges and distributes them).
mesh::Mesh buildWholePart(const ParameterList& list, const std::string& type, const std::string& where,
                          const std::string& deckDirectory, MPI_Comm comm) {
  mesh::Mesh mesh = mesh::MeshFactory::create(type, list, where, deckDirectory, comm);
  const auto& offset = list.get<Teuchos::Array<double>>("Offset");
  if (!offset.empty()) {
    requireInput(static_cast<int>(offset.size()) == mesh.dimension,
                 where + "/Offset: expected " + std::to_string(mesh.dimension) + " values");
    mesh = mesh::translateMesh(std::move(mesh), std::vector<double>(offset.begin(), offset.end()));
  }
  return mesh;
}

// This rank's part of the deck's mesh. Every rank checks its part (the part's elements, sets and
// coordinates; the lowest failing rank's message on every rank), so a generated mesh that no rank
// holds whole is checked as the whole mesh was.
mesh::DistributedMesh buildMesh(ParameterList& list, const std::string& deckDirectory, MPI_Comm comm) {
  const std::string where = "Problem/Mesh";
  mesh::DistributedMesh part;
  if (list.isType<std::string>("Type") && list.get<std::string>("Type") == "Parts") {
    // Separate bodies (contact): each named sublist is a mesh of its own; blocks and sets get the
    // part's name as a prefix (mergeMeshes). Rank 0 builds and merges them and sends the parts out.
    std::vector<std::pair<std::string, std::string>> parts;  // name, type
    for (auto it = list.begin(); it != list.end(); ++it) {
      const std::string& name = list.name(it);
      if (name == "Type") continue;
      requireInput(list.isSublist(name), where + "/" + name + ": expected a sublist (one per part) besides Type");
      parts.emplace_back(name, "");
    }
    requireInput(!parts.empty(), where + ": Type Parts needs at least one part sublist");
    for (auto& [name, type] : parts) type = validateMeshList(list.sublist(name), where + "/" + name, true);
    part = mesh::distributeMesh(comm, [&] {
      std::vector<std::pair<std::string, mesh::Mesh>> meshes;
      for (const auto& [name, type] : parts)
        meshes.emplace_back(name, buildWholePart(list.sublist(name), type, where + "/" + name, deckDirectory, comm));
      return mesh::mergeMeshes(meshes);
    });
  } else {
    const std::string type = validateMeshList(list, where, false);
    part = mesh::MeshFactory::createPart(type, list, where, deckDirectory, comm);
  }
  mesh::validatePart(part, where);
  return part;
}

// The valid parameters of one child of an open list (the child and its deck path given).
using ValidFor = std::function<RCP<const ParameterList>(const ParameterList& child, const std::string& where)>;

// Each named child of an open list is validated against `validFor(child)`; returns the child names in order.
std::vector<std::string> validateChildren(ParameterList& list, const ValidFor& validFor, const std::string& where) {
  std::vector<std::string> names;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    requireInput(list.isSublist(name), where + "/" + name + ": expected a sublist (one per " +
                                           where.substr(where.rfind('/') + 1) + " entry)");
    names.push_back(name);
  }
  for (const auto& name : names) {
    auto& child = list.sublist(name);
    validateAndSetDefaults(child, *validFor(child, where + "/" + name), where + "/" + name);
  }
  return names;
}

std::vector<std::string> validateChildren(ParameterList& list, const ParameterList& valid, const std::string& where) {
  return validateChildren(list, [&valid](const ParameterList&, const std::string&) { return Teuchos::rcpFromRef(valid); },
                          where);
}

// A contact interface takes the common contact parameters and those of its Law (the default law when
// none is given).
RCP<const ParameterList> contactValidFor(const ParameterList& child, const std::string& where) {
  std::string law = ContactLawFactory::defaultLaw();
  if (child.isParameter("Law")) {
    requireInput(child.isType<std::string>("Law"),
                 where + "/Law: expected a string, one of " + joinNames(ContactLawFactory::names()));
    law = child.get<std::string>("Law");
    requireOneOf(where + "/Law", law, ContactLawFactory::names());
  }
  return contactValidParameters(law);
}

// The reference coordinates of contact-surface nodes, gathered from the parts (ProblemDefinition::contactNodes).
using SurfaceCoordinates = std::map<GlobalIndex, std::vector<double>>;

// A side set's contact surface, gathered from every rank's part (collective); its nodes' coordinates kept.
contact::ContactSurface gatheredSurface(const mesh::DistributedMesh& part, const std::string& set,
                                        const std::string& where, SurfaceCoordinates& coordinates, bool revolved,
                                        mesh::ReplicatedSurface* gathered = nullptr) {
  const mesh::ReplicatedSurface facets = mesh::gatherSurface(part, set);
  if (gathered) *gathered = facets;
  const int dim = facets.dimension;
  for (std::size_t k = 0; k < facets.nodes.size(); ++k)
    coordinates[facets.nodes[k]].assign(facets.coordinates.begin() + static_cast<std::ptrdiff_t>(k * dim),
                                        facets.coordinates.begin() + static_cast<std::ptrdiff_t>((k + 1) * dim));
  return contact::ContactSurface::fromSurface(facets, where, revolved);
}

// The parameters every contact interface takes (its Law's own are ContactLawFactory's), as the deck gives them.
struct InterfaceParameters {
  enum class Discretization { NodeToSegment, Mortar };
  enum class Smoothing { None, Hermite };
  struct Rigid {
    Teuchos::Array<double> points, motion;
    Teuchos::Array<int> facets;
  };
  std::string slaveSet, masterSet;
  Rigid rigid;
  std::string law;
  double searchReach = -1.0;
  bool twoPass = false;
  Discretization discretization = Discretization::NodeToSegment;
  Smoothing smoothing = Smoothing::None;
};

const ParameterTable<InterfaceParameters::Rigid>& rigidSurfaceTable() {
  using R = InterfaceParameters::Rigid;
  static const auto table =
      ParameterTable<R>()
          .value("Points", &R::points, Teuchos::Array<double>(),
                 "2D: x0, y0, x1, y1, ...: a polyline; the rigid body lies to the left of the direction of traversal. "
                 "3D: x0, y0, z0, x1, y1, z1, ...: the corners of the Facets")
          .value("Facets", &R::facets, Teuchos::Array<int>(),
                 "3D (required): 4 point indices (0-based) per quadrilateral, counter-clockwise seen from the slave "
                 "side, so that the normal (right-hand rule) points out of the rigid body towards the slave. "
                 "2D: empty = consecutive points; else 2 indices per segment")
          .value("Motion", &R::motion, Teuchos::Array<double>(),
                 "Displacement of the rigid surface at load factor 1 (x, y[, z])");
  return table;
}

const ParameterTable<InterfaceParameters>& interfaceTable() {
  using S = InterfaceParameters;
  static const auto table =
      ParameterTable<S>("Contact Interface")
          .text("Slave Side Set", &S::slaveSet, "",
                "Side set whose nodes may not penetrate the master (node-to-segment in 2D, node-to-face in 3D); required")
          .text("Master Side Set", &S::masterSet, "",
                "Side set of a deformable master body; leave empty for a rigid master (Rigid Surface)")
          .sublist("Rigid Surface",
                   "A rigid master moving rigidly with the load factor: a polyline (2D) or quadrilaterals (3D)",
                   rigidSurfaceTable(), &S::rigid)
          .choice("Law", &S::law, ContactLawFactory::defaultLaw(), ContactLawFactory::names(),
                  "Contact law; its parameters are listed under Contact laws below")
          .real("Search Reach", &S::searchReach, -1.0,
                "Matrix graph of the interface: a length >= 0 couples each slave node to the deformable master "
                "facets within 2 x (largest master facet) + Search Reach of it, in the reference configuration at the "
                "start and in the current one whenever a slave node meets a facet beyond its reserved ones (the graph "
                "is then rebuilt: a line in the log, graph_rebuilds in the run summary); Search Reach is the margin "
                "of sliding and relative deformation (per component) beyond one master facet between rebuilds: "
                "larger, a bigger graph and fewer rebuilds. -1 = automatic: the whole master surface when slave x "
                "master nodes <= 250000 (never rebuilt), else as 0")
          .value("Two Pass", &S::twoPass, false,
                 "Also enforce contact with slave and master swapped (deformable master only)")
          .enumChoice("Discretization", &S::discretization, S::Discretization::NodeToSegment,
                      {"Node To Segment", "Mortar"},
                      "Node To Segment: one penalty element per slave node and its closest master facet. Mortar: "
                      "weighted gaps over the slave facets against every master facet they overlap (2D on 2- and 3-node sides with Coulomb "
                      "friction; 3D on Tri3/Quad4 faces with Coulomb friction, on Tri6/Quad8/Quad9 faces frictionless; penalty or augmented Lagrangian, single pass: passes the non-matching "
                      "contact patch test)")
          .enumChoice("Master Smoothing", &S::smoothing, S::Smoothing::None, {"None", "Hermite"},
                      "None: the master surface is its facets. Hermite (2D node-to-segment, deformable 2-node "
                      "master): each master segment is the cubic Hermite curve through its ends with the tangents of "
                      "the neighbouring nodes, so the surface and its normal are continuous across the master nodes "
                      "(C1); for sliding under curved bodies (docs/theory-contact.md §16)");
  return table;
}

// What Discretization = Mortar does not do yet (docs/theory-contact.md, "Mortar"): one-line InputErrors.
void requireMortarSupported(bool twoPass, bool revolved, const std::string& where) {
  const std::string what = where + "/Discretization: Mortar is implemented ";
  requireInput(!revolved, what + "for plane strain and 3D only, not for an axisymmetric problem; use Node To Segment");
  requireInput(!twoPass, what + "single-pass only (its weighted gaps need no second pass); set Two Pass = false");
}

// What Master Smoothing = Hermite takes (contact/SmoothedMaster.hpp): one-line InputErrors.
void requireSmoothingSupported(const contact::ContactInterfaceSpec& spec, const std::string& where,
                               const std::string& masterSet) {
  const std::string what = where + "/Master Smoothing: Hermite ";
  requireInput(spec.dimension == 2, what + "smooths 2D master segments; this mesh is " + std::to_string(spec.dimension) + "D (use None)");
  requireInput(!spec.mortar, what + "is for Discretization = Node To Segment (use None with Mortar)");
  requireInput(spec.nodesPerFacet() == 2, what + "takes 2-node segments; side set '" + masterSet + "' has " +
                                              std::to_string(spec.nodesPerFacet()) + "-node sides (use None)");
}

// The master's segments as C1 Hermite segments, each with its two neighbouring nodes (HermiteLine4Facet).
void smoothMaster(contact::ContactInterfaceSpec& spec) {
  spec.masterFacets = contact::hermiteMasterFacets(spec.masterFacets);
  spec.masterFacetNodes = contact::HermiteLine4Facet::kNodes;
}

// Whether a side set's facets are ones the mortar kernels integrate: 2-node segments in 2D (MortarSegment)
// and 3-node ones on their flat pieces (MortarQuadraticSegment), 3-node triangles and 4-node quadrilaterals
// in 3D (MortarFacetPair), 6-, 8- and 9-node faces on their flat pieces (MortarQuadraticFacetPair).
void requireMortarFacets(int dimension, int nodesPerFacet, const std::string& set, const std::string& where) {
  const bool supported = dimension == 2 ? (nodesPerFacet == 2 || nodesPerFacet == 3)
                                        : (nodesPerFacet == 3 || nodesPerFacet == 4 || nodesPerFacet == 6 ||
                                           nodesPerFacet == 8 || nodesPerFacet == 9);
  requireInput(supported, where + "/Discretization: Mortar takes " +
                           (dimension == 2 ? std::string("2- or 3-node segments") : std::string("3-, 4-, 6-, 8- or 9-node faces")) +
                           "; side set '" + set + "' has " + std::to_string(nodesPerFacet) +
                           "-node sides (use Node To Segment)");
}

// The reference measure of each slave facet, the mortar's dΓ_0 (InterfaceSpec::slaveFacetMeasures): a
// segment's length (2D; a 3-node segment's two chords' lengths, MortarQuadraticSegment.hpp), a triangle's area, a quadrilateral's |d_1 × d_2| / 2 (its diagonals': the area
// of its projection on the plane the 3D mortar projects it to, MortarFacetPair.hpp); a quadratic face
// (6, 8 or 9 nodes) has its flat pieces' (a triangle's area, a 4-node piece's three Jacobian
// coefficients: MortarQuadraticFacetPair.hpp, eq. M20).
std::vector<double> slaveFacetMeasures(const std::vector<contact::GlobalIndex>& facets, int perFacet, int dimension,
                                       const SurfaceCoordinates& coordinates) {
  std::vector<double> out;
  const auto at = [&](std::size_t i) { return coordinates.at(facets[i]); };
  const auto diff = [](const std::vector<double>& a, const std::vector<double>& b) {
    return std::array<double, 3>{b[0] - a[0], b[1] - a[1], a.size() > 2 ? b[2] - a[2] : 0.0};
  };
  for (std::size_t f = 0; f + perFacet <= facets.size(); f += static_cast<std::size_t>(perFacet)) {
    if (perFacet >= 6) {  // a quadratic face: its flat pieces' areas (MortarQuadraticFacetPair, eq. M20)
      contact::MortarFaceNodes x{};
      for (int a = 0; a < perFacet; ++a) std::copy_n(at(f + a).begin(), 3, x[a].begin());
      const auto pieces = contact::mortarFacetPieceMeasures(x, perFacet);
      out.insert(out.end(), pieces.begin(), pieces.begin() + contact::mortarFaceMeasures(perFacet));
      continue;
    }
    if (dimension == 2 && perFacet == 3) {  // a 3-node segment: its chords' lengths (eq. M20)
      contact::MortarSegmentNodes x{};
      for (int a = 0; a < perFacet; ++a) std::copy_n(at(f + a).begin(), 2, x[a].begin());
      const auto pieces = contact::mortarSegmentPieceLengths(x, perFacet);
      out.insert(out.end(), pieces.begin(), pieces.end());
      continue;
    }
    if (perFacet == 2) {
      const auto d = diff(at(f), at(f + 1));
      out.push_back(std::hypot(d[0], d[1]));
      continue;
    }
    const auto u = diff(at(f), at(f + 2));
    const auto v = perFacet == 3 ? diff(at(f), at(f + 1)) : diff(at(f + 1), at(f + 3));
    const std::array<double, 3> c{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    out.push_back(0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
  }
  return out;
}

// The slave nodes' areas A_a of a mortar interface on quadratic faces (2D: 3-node segments, the hat
// functions' l/2 per chord end): ∫ Φ_a dA_0 with the flat pieces'
// linear or bilinear functions (MortarQuadraticFacetPair.hpp, eq. M18), integrated as the kernel does, so
// that p_a = ε_N ⟨−g̃_a⟩ / A_a is the pressure of a uniform gap to round-off (the node-to-facet areas of
// 6- and 8-node faces are the same sub-facet shares, but scaled to the curved face's area; a 9-node face's
// are its consistent loads, A/36 at a corner, not the quarters' A/16).
std::vector<double> quadraticMortarAreas(const contact::ContactInterfaceSpec& spec, const SurfaceCoordinates& coordinates) {
  std::vector<double> out(spec.slaveNodes.size(), 0.0);
  const auto& nodes = spec.slaveNodes;
  const std::size_t perFacet = static_cast<std::size_t>(spec.slaveFacetNodes);
  for (std::size_t f = 0; f + perFacet <= spec.slaveFacets.size(); f += perFacet) {
    std::array<double, contact::kMaxMortarFaceNodes> areas{};
    if (spec.dimension == 2) {  // a 3-node segment: half of each chord at each of its ends
      contact::MortarSegmentNodes s{};
      for (std::size_t a = 0; a < perFacet; ++a) std::copy_n(coordinates.at(spec.slaveFacets[f + a]).begin(), 2, s[a].begin());
      const auto lengths = contact::mortarSegmentNodeLengths(s, spec.slaveFacetNodes);
      std::copy(lengths.begin(), lengths.end(), areas.begin());
    } else {
      contact::MortarFaceNodes x{};
      for (std::size_t a = 0; a < perFacet; ++a) std::copy_n(coordinates.at(spec.slaveFacets[f + a]).begin(), 3, x[a].begin());
      areas = contact::mortarFacetNodeAreas(x, spec.slaveFacetNodes);
    }
    for (std::size_t a = 0; a < perFacet; ++a)
      out[static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), spec.slaveFacets[f + a]) - nodes.begin())] += areas[a];
  }
  return out;
}

// Node-to-face contact on TRI6 or QUAD8 slave faces cannot pass the patch test: their consistent corner weights
// are 0 or negative, the sub-facet weights that replace them are not the loads of a uniform pressure (user
// guide, "Contact surfaces"). The audit measured a pressed Hex20 block's force 3.9 % below CalculiX C3D20 and
// the Dirichlet solution; Hertz on Tet10 reads its peak 6–8 % high. Mortar does not have the defect.
std::string serendipitySlaveFaces(int nodesPerFacet, const std::string& set, const std::string& where) {
  if (nodesPerFacet != 6 && nodesPerFacet != 8) return "";
  const bool tri6 = nodesPerFacet == 6;
  return "contessa: warning: " + where + "/Slave Side Set '" + set + "' has " + (tri6 ? "TRI6" : "QUAD8") +
         " faces: node-to-face contact on them does not pass the patch test (" +
         (tri6 ? "their corner nodes carry almost no force: Hertz's peak pressure on Tet10 reads 6-8 % high"
               : "their corners open: a Hex20 block pressed by a rigid base reads its force 3.9 % low") +
         "); Discretization = Mortar does (user guide, contact surfaces)";
}

std::vector<contact::ContactInterfaceSpec> buildContact(const ParameterList& list, const std::string& name,
                                                        const mesh::DistributedMesh& part,
                                                        SurfaceCoordinates& coordinates, bool revolved,
                                                        std::vector<std::string>& warnings) {
  const mesh::Mesh& mesh = part.local();
  const std::string where = "Problem/Contact/" + name;
  contact::ContactInterfaceSpec spec;
  spec.name = name;
  spec.dimension = mesh.dimension;
  const InterfaceParameters in = interfaceTable().read(list);
  spec.searchReach = in.searchReach;
  requireInput(spec.searchReach == -1.0 || spec.searchReach >= 0.0,
               where + "/Search Reach: expected a length >= 0, or -1 (automatic), got " + std::to_string(spec.searchReach));
  spec.law = ContactLawFactory::create(in.law, list, where);

  const std::string& slaveSet = in.slaveSet;
  const std::string& masterSet = in.masterSet;
  const auto& [points, motion, facets] = in.rigid;
  requireInput(!slaveSet.empty(), where + "/Slave Side Set: required");
  requireSideSet(mesh, slaveSet, where + "/Slave Side Set");
  const bool rigid = masterSet.empty();
  requireInput(rigid != points.empty(),
               where + ": give either Master Side Set (a deformable master) or Rigid Surface/Points (a rigid one), not " +
                   (rigid ? "neither" : "both"));
  spec.mortar = in.discretization == InterfaceParameters::Discretization::Mortar;
  if (spec.mortar) requireMortarSupported(in.twoPass, revolved, where);
  mesh::ReplicatedSurface slaveFacets;
  const auto slave = gatheredSurface(part, slaveSet, where + "/Slave Side Set", coordinates, revolved, &slaveFacets);
  spec.slaveFacets = slave.facets;
  spec.slaveFacetNodes = slave.nodesPerFacet;
  if (spec.mortar) {
    requireMortarFacets(mesh.dimension, slave.nodesPerFacet, slaveSet, where);
    spec.slaveFacetMeasures = slaveFacetMeasures(slave.facets, slave.nodesPerFacet, mesh.dimension, coordinates);
  }
  spec.slaveNodes = slave.nodes;
  spec.slaveAreas = slave.areas;
  if (spec.mortar && ((mesh.dimension == 3 && slave.nodesPerFacet >= 6) || (mesh.dimension == 2 && slave.nodesPerFacet == 3)))
    spec.slaveAreas = quadraticMortarAreas(spec, coordinates);
  spec.slaveFacetLengths = slave.facetLengths;
  spec.slaveAxisNodes = slave.axisNodes;
  if (!spec.mortar && mesh.dimension == 3) warnings.push_back(serendipitySlaveFaces(slave.nodesPerFacet, slaveSet, where));
  if (rigid) {
    requireInput(!in.twoPass, where + "/Two Pass: a rigid master has no slave side of its own");
    requireInput(in.smoothing == InterfaceParameters::Smoothing::None,
                 where + "/Master Smoothing: Hermite smooths a deformable master's side set; a Rigid Surface is "
                         "its own polyline (use None)");
    spec.rigidMaster = true;
    auto& surface = spec.rigidSurface;
    surface.points.assign(points.begin(), points.end());
    surface.motion.assign(motion.begin(), motion.end());
    surface.facets.assign(facets.begin(), facets.end());
    // 2D without Facets: the points are a polyline, one segment per consecutive pair.
    if (mesh.dimension == 2 && surface.facets.empty())
      for (int i = 0; i + 1 < static_cast<int>(points.size() / 2); ++i) surface.facets.insert(surface.facets.end(), {i, i + 1});
    contact::validateRigidSurface(surface, mesh.dimension, where + "/Rigid Surface");
    contact::checkRigidSurfaceFacesSlave(surface, slaveFacets, where + "/Rigid Surface");
    return {spec};
  }
  requireInput(facets.empty() && motion.empty(),
               where + "/Rigid Surface: Facets and Motion belong to a rigid master (no Master Side Set)");
  requireSideSet(mesh, masterSet, where + "/Master Side Set");
  requireInput(masterSet != slaveSet, where + "/Master Side Set: must differ from the Slave Side Set");
  const auto master = gatheredSurface(part, masterSet, where + "/Master Side Set", coordinates, revolved);
  spec.masterFacets = master.facets;
  spec.masterFacetNodes = master.nodesPerFacet;
  if (spec.mortar) requireMortarFacets(mesh.dimension, master.nodesPerFacet, masterSet, where);
  const bool smoothed = in.smoothing == InterfaceParameters::Smoothing::Hermite;
  if (smoothed) requireSmoothingSupported(spec, where, masterSet);
  if (smoothed) smoothMaster(spec);
  if (!in.twoPass) return {spec};
  // Two-pass: the same interface with slave and master swapped, each pass with its own history.
  contact::ContactInterfaceSpec swapped = spec;
  swapped.secondPass = true;
  swapped.slaveNodes = master.nodes;
  swapped.slaveAreas = master.areas;
  swapped.slaveFacetLengths = master.facetLengths;
  swapped.slaveAxisNodes = master.axisNodes;
  swapped.masterFacets = slave.facets;
  swapped.masterFacetNodes = slave.nodesPerFacet;
  if (smoothed) requireSmoothingSupported(swapped, where, slaveSet);
  if (smoothed) smoothMaster(swapped);
  return {spec, swapped};
}

}  // namespace

std::vector<std::string> meshTypes() {
  std::vector<std::string> types = mesh::MeshFactory::names();
  types.push_back("Parts");
  return types;
}

RCP<const ParameterList> meshValidParameters(const std::string& type) {
  auto p = rcp(new ParameterList("Mesh"));
  if (type == "Parts") {
    // The children are user-named sublists, each a mesh of another type plus "Offset".
    setChoice(*p, "Type", type, meshTypes(), "Separate bodies, one sublist per part");
    return p;
  }
  setChoice(*p, "Type", type, meshTypes(), mesh::MeshFactory::description(type));
  p->setParameters(*mesh::MeshFactory::validParameters(type));
  return p;
}

RCP<const ParameterList> blockValidParameters() {
  auto p = rcp(new ParameterList("Block"));
  setChoice(*p, "Element", "Q4", mechanics::ElementFactory::names(), "Element formulation");
  p->set("Material", std::string(""), "Name of a sublist of Problem/Materials; required");
  return p;
}

RCP<const ParameterList> dirichletValidParameters() {
  auto p = rcp(new ParameterList("Dirichlet Condition"));
  p->set("Node Set", std::string(""), "Node set the displacement is prescribed on; required");
  setChoice(*p, "Component", "x", {"x", "y", "z"}, "Displacement component");
  p->set("Value", 0.0, "Displacement at load factor 1 (applied as load factor × value)");
  return p;
}

RCP<const ParameterList> nodalForceValidParameters() {
  auto p = rcp(new ParameterList("Nodal Force"));
  p->set("Node Set", std::string(""), "Node set the force is applied on; required");
  setChoice(*p, "Component", "x", {"x", "y", "z"}, "Force direction");
  p->set("Total Force", 0.0, "Total force at load factor 1, shared equally by the node set's nodes (per unit thickness in 2D)");
  return p;
}

RCP<const ParameterList> regressionValidParameters() {
  auto p = rcp(new ParameterList("Regression Check"));
  p->set("Quantity", std::string(""), "History column to check, e.g. reaction_top_y or newton_iterations; required");
  p->set("Step", -1, "History step to check; -1 = the last converged increment");
  p->set("Load Step", 0,
         "With Problem/Load Steps: check the value at the end of this load step (1 for the first; its last "
         "history row) instead of Step; 0 = not used");
  p->set("Expected", 0.0, "Expected value");
  setNonNegative(*p, "Relative Tolerance", 1e-6, "Relative tolerance on |value - expected| / |expected|");
  setNonNegative(*p, "Absolute Tolerance", 0.0, "Absolute tolerance; the check passes if either tolerance holds");
  return p;
}

RCP<const ParameterList> contactValidParameters() { return interfaceTable().publish(); }

RCP<const ParameterList> contactValidParameters(const std::string& law) {
  auto p = rcp(new ParameterList(*contactValidParameters()));
  const auto lawParameters = ContactLawFactory::validParameters(law);
  for (auto it = lawParameters->begin(); it != lawParameters->end(); ++it)
    p->setEntry(lawParameters->name(it), lawParameters->entry(it));
  return p;
}

RCP<const ParameterList> problemValidParameters() {
  auto p = rcp(new ParameterList("Problem"));
  p->set("Title", std::string(""), "Free text written into the Exodus file");
  p->sublist("Mesh", false, "Mesh source: 'Type' selects the generator or file; see the Mesh types below");
  p->sublist("Blocks", false, "One sublist per element block (named as in the mesh): Element, Material");
  p->sublist("Materials", false, "One sublist per material (any name): Model and its parameters");
  p->sublist("Dirichlet Conditions", false, "One sublist per condition (any name): Node Set, Component, Value");
  p->sublist("Nodal Forces", false, "One sublist per force (any name): Node Set, Component, Total Force");
  p->sublist("Loads", false,
             "One sublist per load (any name): Type (Pressure, Traction, Body Force, Spring) and its parameters; see "
             "the Load types below");
  auto& out = p->sublist("Output", false, "Results files");
  out.set("Reaction Node Sets", Teuchos::Array<std::string>(),
          "Node sets whose reaction forces are summed into the history (reaction_<set>_<x|y|z>)");
  const auto& layouts = mesh::exodusLayoutNames();
  setChoice(out, "Exodus Layout", layouts[static_cast<int>(mesh::ExodusLayout::SingleFile)], layouts,
            "Single File: <name>.exo, gathered to rank 0 and written there; Per Rank: each of the N ranks writes "
            "its own piece, <name>.exo.N.r (a spatially decomposed set: ParaView opens it as one data set, "
            "SEACAS epu joins it), nothing gathered");
  out.sublist("History", false,
              "Point histories: one sublist per request (any name), written every increment as history columns and "
              "Exodus globals")
      .setParameters(*historyListValidParameters());
  auto& checkpoint = out.sublist("Checkpoint", false,
                                 "Restart files: <name>.restart in the output directory, continued with --restart FILE "
                                 "(also written on SIGTERM, SIGUSR1 and SIGINT, which stop the run with exit status 4)");
  checkpoint.set("Every N Increments", 0,
                 "Write the restart file after every N-th converged increment and go on (0: only when the run is "
                 "stopped by a signal or Max Wall Time)");
  checkpoint.set("Max Wall Time", 0.0,
                 "Seconds the run may take (0: no limit): it writes the restart file and stops (exit status 4) "
                 "after the increment at which the elapsed time plus 1.5 times the longest increment so far plus "
                 "the time of the last restart-file write would pass it");
  p->sublist("Regression", false, "Expected answers (one sublist per check): Quantity, Step, Expected, tolerances");
  p->sublist("Contact", false, "One sublist per contact interface (any name): slave, master, penalties, friction");
  p->sublist("Load Steps", false,
             "Optional ordered steps (one sublist per step, any name), each naming the end values of what changes in "
             "it; see Load Steps below");
  return p;
}

int componentIndex(const std::string& name, int dimension, const std::string& where) {
  const int c = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
  requireInput(c >= 0 && c < dimension,
               where + ": component '" + name + "' is not valid in " + std::to_string(dimension) + "D");
  return c;
}

namespace {

// Materials: the valid list depends on the model name.
std::map<std::string, std::shared_ptr<const mechanics::Material>> buildMaterials(ParameterList& materialList) {
  std::map<std::string, std::shared_ptr<const mechanics::Material>> materials;
  for (auto it = materialList.begin(); it != materialList.end(); ++it) {
    const std::string& name = materialList.name(it);
    const std::string where = "Problem/Materials/" + name;
    requireInput(materialList.isSublist(name), where + ": expected a sublist (Model and its parameters)");
    auto& m = materialList.sublist(name);
    requireInput(m.isType<std::string>("Model"),
                 where + "/Model: required; expected one of " + joinNames(mechanics::MaterialFactory::names()));
    requireOneOf(where + "/Model", m.get<std::string>("Model"), mechanics::MaterialFactory::names());
    validateAndSetDefaults(m, *mechanics::MaterialFactory::validParameters(m.get<std::string>("Model")), where);
    materials[name] = mechanics::MaterialFactory::create(m, where);
  }
  return materials;
}

// One block's element and material, checked against the mesh block's dimension and cell type.
BlockPhysics blockPhysics(const ParameterList& bl, const mesh::ElementBlock& b, int dimension,
                          const std::map<std::string, std::shared_ptr<const mechanics::Material>>& materials) {
  const std::string where = "Problem/Blocks/" + b.name;
  BlockPhysics phys;
  phys.block = b.name;
  phys.elementName = bl.get<std::string>("Element");
  phys.materialName = bl.get<std::string>("Material");
  std::vector<std::string> knownMaterials;
  for (const auto& [n, _] : materials) knownMaterials.push_back(n);
  requireInput(materials.count(phys.materialName) == 1,
               where + "/Material: '" + phys.materialName + "' is not a sublist of Problem/Materials (known: " +
                   joinNames(knownMaterials) + ")");
  phys.material = materials.at(phys.materialName);
  phys.element = mechanics::ElementFactory::create(phys.elementName, where + "/Element");
  requireInput(phys.element->dimension() == dimension,
               where + "/Element: '" + phys.elementName + "' is a " + std::to_string(phys.element->dimension()) +
                   "D element but the mesh is " + std::to_string(dimension) + "D");
  requireInput(phys.element->numNodes() == mesh::nodesPerCell(b.cellType),
               where + "/Element: '" + phys.elementName + "' does not match the block's cell type " +
                   mesh::exodusCellName(b.cellType));
  return phys;
}

// Blocks: every mesh block needs physics, and every named block must exist.
std::vector<BlockPhysics> buildBlocks(ParameterList& blockList, ParameterList& materialList, const mesh::Mesh& mesh) {
  const auto materials = buildMaterials(materialList);
  for (const auto& name : validateChildren(blockList, *blockValidParameters(), "Problem/Blocks"))
    requireBlock(mesh, name, "Problem/Blocks/" + name);
  std::vector<BlockPhysics> blocks;
  for (const auto& b : mesh.blocks) {
    requireInput(blockList.isSublist(b.name),
                 "Problem/Blocks/" + b.name + ": missing; every element block needs an Element and a Material");
    blocks.push_back(blockPhysics(blockList.sublist(b.name), b, mesh.dimension, materials));
  }
  return blocks;
}

std::vector<DirichletCondition> buildDirichlet(ParameterList& dirichletList, const mesh::Mesh& mesh) {
  std::vector<DirichletCondition> conditions;
  for (const auto& name : validateChildren(dirichletList, *dirichletValidParameters(), "Problem/Dirichlet Conditions")) {
    const std::string where = "Problem/Dirichlet Conditions/" + name;
    const auto& d = dirichletList.sublist(name);
    DirichletCondition bc;
    bc.name = name;
    bc.nodeSet = d.get<std::string>("Node Set");
    requireNodeSet(mesh, bc.nodeSet, where + "/Node Set");
    bc.component = componentIndex(d.get<std::string>("Component"), mesh.dimension, where + "/Component");
    bc.value = d.get<double>("Value");
    conditions.push_back(bc);
  }
  return conditions;
}

std::vector<NodalForce> buildNodalForces(ParameterList& forceList, const mesh::Mesh& mesh) {
  std::vector<NodalForce> forces;
  for (const auto& name : validateChildren(forceList, *nodalForceValidParameters(), "Problem/Nodal Forces")) {
    const std::string where = "Problem/Nodal Forces/" + name;
    const auto& f = forceList.sublist(name);
    NodalForce force;
    force.name = name;
    force.nodeSet = f.get<std::string>("Node Set");
    requireNodeSet(mesh, force.nodeSet, where + "/Node Set");
    force.component = componentIndex(f.get<std::string>("Component"), mesh.dimension, where + "/Component");
    force.totalForce = f.get<double>("Total Force");
    forces.push_back(force);
  }
  return forces;
}

// Problem/Output: reaction node sets, the Exodus layout, checkpoints.
void readOutput(const ParameterList& output, const mesh::Mesh& mesh, ProblemDefinition& def) {
  for (const auto& s : output.get<Teuchos::Array<std::string>>("Reaction Node Sets")) {
    requireNodeSet(mesh, s, "Problem/Output/Reaction Node Sets");
    def.reactionNodeSets.push_back(s);
  }
  def.exodusPerRank = output.get<std::string>("Exodus Layout") ==
                      mesh::exodusLayoutNames()[static_cast<int>(mesh::ExodusLayout::PerRank)];
  const auto& checkpoint = output.sublist("Checkpoint");
  def.checkpointEvery = checkpoint.get<int>("Every N Increments");
  requireInput(def.checkpointEvery >= 0, "Problem/Output/Checkpoint/Every N Increments: expected an integer >= 0 (0: "
                                         "only on signals and Max Wall Time), got " +
                                             std::to_string(def.checkpointEvery));
  def.maxWallSeconds = checkpoint.get<double>("Max Wall Time");
  requireInput(std::isfinite(def.maxWallSeconds) && def.maxWallSeconds >= 0,
               "Problem/Output/Checkpoint/Max Wall Time: expected seconds >= 0 (0: no limit), got " +
                   std::to_string(def.maxWallSeconds));
}

// Contact interfaces and the reference coordinates of their surface nodes (collective: the surfaces are
// gathered from every rank's part).
void buildContacts(ParameterList& contactList, ProblemDefinition& def, std::vector<std::string>& warnings) {
  SurfaceCoordinates surfaceCoordinates;
  for (const auto& name : validateChildren(contactList, contactValidFor, "Problem/Contact")) {
    auto passes = buildContact(contactList.sublist(name), name, def.mesh, surfaceCoordinates, def.axisymmetric, warnings);
    setAutomaticPenalties(passes, contactList.sublist(name), def.mesh, def.blocks);  // no Normal Penalty given
    for (auto& spec : passes) def.contacts.push_back(std::move(spec));
  }
  for (const auto& [node, x] : surfaceCoordinates) {
    def.contactNodes.push_back(node);
    def.contactNodeCoordinates.insert(def.contactNodeCoordinates.end(), x.begin(), x.end());
  }
}

std::vector<RegressionCheck> buildRegression(ParameterList& regressionList) {
  std::vector<RegressionCheck> checks;
  for (const auto& name : validateChildren(regressionList, *regressionValidParameters(), "Problem/Regression")) {
    const auto& r = regressionList.sublist(name);
    RegressionCheck check;
    check.name = name;
    check.quantity = r.get<std::string>("Quantity");
    requireInput(!check.quantity.empty(), "Problem/Regression/" + name + "/Quantity: required (a history column)");
    check.step = r.get<int>("Step");
    check.loadStep = r.get<int>("Load Step");
    check.expected = r.get<double>("Expected");
    check.relativeTolerance = r.get<double>("Relative Tolerance");
    check.absoluteTolerance = r.get<double>("Absolute Tolerance");
    checks.push_back(check);
  }
  return checks;
}

}  // namespace

ProblemDefinition buildProblem(ParameterList& problem, const std::string& deckDirectory, MPI_Comm comm) {
  ProblemDefinition def;
  validateAndSetDefaults(problem, *problemValidParameters(), "Problem",
                         std::set<std::string>(std::begin(kOpenLists), std::end(kOpenLists)));
  def.title = problem.get<std::string>("Title");
  def.mesh = buildMesh(problem.sublist("Mesh"), deckDirectory, comm);
  const mesh::Mesh& mesh = def.mesh.local();
  def.blocks = buildBlocks(problem.sublist("Blocks"), problem.sublist("Materials"), mesh);
  def.axisymmetric = axisymmetricProblem(def.blocks, def.mesh);
  def.dirichlet = buildDirichlet(problem.sublist("Dirichlet Conditions"), mesh);
  def.nodalForces = buildNodalForces(problem.sublist("Nodal Forces"), mesh);
  def.loads = buildLoads(problem.sublist("Loads"), mesh);
  readOutput(problem.sublist("Output"), mesh, def);
  std::vector<std::string> warnings;  // said once the whole problem is valid: a bad deck gets its one error line
  buildContacts(problem.sublist("Contact"), def, warnings);
  def.history = buildHistoryRequests(problem.sublist("Output").sublist("History"), def);
  def.regression = buildRegression(problem.sublist("Regression"));
  def.loadSteps = buildLoadSteps(problem.sublist("Load Steps"), def);
  requireLoadStepsChange(def);
  for (const auto& check : def.regression)
    requireInput(check.loadStep >= 0 && check.loadStep <= static_cast<int>(def.loadSteps.size()) &&
                     (check.loadStep == 0 || check.step == -1),
                 "Problem/Regression/" + check.name + "/Load Step: expected 0 or a load step of Problem/Load Steps (1 to " +
                     std::to_string(def.loadSteps.size()) + "), without Step, got " + std::to_string(check.loadStep));
  for (const auto& warning : warnings)
    if (!warning.empty() && def.mesh.rank == 0) std::fprintf(stderr, "%s\n", warning.c_str());
  std::fflush(stderr);
  return def;
}

}  // namespace contessa::deck
