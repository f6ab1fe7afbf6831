// Mesh source registry: one row per generator or file reader (name, description, parameters, build).
#include "mesh/MeshFactory.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>

#include "common/Error.hpp"
#include "common/ParameterTable.hpp"
#include "common/Registry.hpp"
#include "mesh/DecomposedExodusReader.hpp"
#include "mesh/ExodusMeshReader.hpp"
#include "mesh/GmshMeshReader.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MeshConversion.hpp"
#include "mesh/MeshDistribution.hpp"

namespace contessa::mesh {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

// Generators say which parameter is wrong; the deck path is added here.
template <class F>
auto generate(const std::string& where, F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    throw InputError(where + "/" + e.what());
  }
}

// A mesh source's parameter table (common/ParameterTable.hpp), built once.
template <class Spec>
using Table = const ParameterTable<Spec>& (*)();

template <class Spec, Table<Spec> table>
RCP<ParameterList> publishedParameters() {
  return table().publish();
}

// This rank's part of a generated mesh, built alone.
template <class Spec>
DistributedMesh generatedPart(DistributedMesh (*part)(const Spec&, int, int), const Spec& spec,
                              const std::string& where, MPI_Comm comm) {
  const Ranks ranks = ranksOf(comm);
  DistributedMesh mine = generate(where, [&] { return part(spec, ranks.rank, ranks.size); });
  mine.comm = comm;
  return mine;
}

// A generator's row builds, from the spec its deck list gives, the whole mesh or this rank's part.
template <class Spec, Table<Spec> table, Mesh (*whole)(const Spec&)>
Mesh createGenerated(const ParameterList& list, const std::string& where, const std::string&, MPI_Comm) {
  const Spec spec = table().read(list);
  return generate(where, [&] { return whole(spec); });
}

template <class Spec, Table<Spec> table, DistributedMesh (*part)(const Spec&, int, int)>
DistributedMesh createGeneratedPart(const ParameterList& list, const std::string& where, const std::string&,
                                    MPI_Comm comm) {
  return generatedPart(part, table().read(list), where, comm);
}

// ---- Cell variants of the Rectangle and the Box: triangles or tetrahedra, quadratic cells ----

// `Cell Type` (the grid's cells, or simplices made from them) and `Element Order` (1, or 2: a node at
// the middle of each edge) of a structured generator.
struct CellVariant {
  std::string cellType;
  int order = 1;
};

ParameterTable<CellVariant> cellVariantTable(const std::string& cells, const std::string& simplices) {
  return ParameterTable<CellVariant>()
      .choice("Cell Type", &CellVariant::cellType, cells, {cells, simplices},
              cells + (simplices == "Triangles" ? " (QUAD4)" : " (HEX8)") + ", or " + simplices +
                  ": each cell split into " +
                  (simplices == "Triangles" ? "2 TRI3 along its diagonal from node 1 to node 3"
                                            : "the 6 TETRA4 around its diagonal from node 1 to node 7 (faces matching)"))
      .count("Element Order", &CellVariant::order, 1,
             "1 or 2: 1 linear cells; 2 a node at the middle of every edge (QUAD8, HEX20, TRI6, TETRA10; "
             "mid-edge nodes on the straight chord)");
}

// A structured grid's spec and the cells made of it.
template <class Spec>
struct WithCells {
  Spec grid;
  CellVariant cells;
};

// The grid's table, then the cell variant's rows.
template <class Spec>
ParameterTable<WithCells<Spec>> withCellVariant(const std::string& listName, const ParameterTable<Spec>& grid,
                                                 const std::string& cells, const std::string& simplices) {
  return ParameterTable<WithCells<Spec>>(listName)
      .include(grid, &WithCells<Spec>::grid)
      .include(cellVariantTable(cells, simplices), &WithCells<Spec>::cells);
}

void requireElementOrder(const CellVariant& v) {
  requireInput(v.order <= 2, "Element Order: " + std::to_string(v.order) + " is not an element order (expected 1 or 2)");
}

// The grid's own cells (`cells`), linear: what each rank can make alone.
bool isGridItself(const CellVariant& v, const char* cells) { return v.cellType == cells && v.order == 1; }

Mesh converted(Mesh mesh, const CellVariant& v, const char* cells, const std::string& where) {
  if (isGridItself(v, cells)) return mesh;
  if (v.cellType != cells) mesh = splitIntoSimplices(mesh);
  if (v.order == 2) mesh = withMidEdgeNodes(mesh);
  mesh.validate(where);
  return mesh;
}

// A generator row with the cell variants: the grid made, then converted (the whole mesh; its parts are
// sent out from rank 0 unless the variant is the grid's own cells, which each rank makes alone).
template <class Spec, Table<WithCells<Spec>> table, Mesh (*whole)(const Spec&), const char* cells>
Mesh createVariant(const ParameterList& list, const std::string& where, const std::string&, MPI_Comm) {
  const WithCells<Spec> spec = table().read(list);
  return generate(where, [&] {
    requireElementOrder(spec.cells);
    return converted(whole(spec.grid), spec.cells, cells, where);
  });
}

template <class Spec, Table<WithCells<Spec>> table, Mesh (*whole)(const Spec&),
          DistributedMesh (*part)(const Spec&, int, int), const char* cells>
DistributedMesh createVariantPart(const ParameterList& list, const std::string& where, const std::string& directory,
                                  MPI_Comm comm) {
  const WithCells<Spec> spec = table().read(list);
  generate(where, [&] { return requireElementOrder(spec.cells); });
  if (isGridItself(spec.cells, cells)) return generatedPart(part, spec.grid, where, comm);
  return distributeMesh(comm, [&] { return createVariant<Spec, table, whole, cells>(list, where, directory, comm); });
}

constexpr char kQuadrilaterals[] = "Quadrilaterals";
constexpr char kHexahedra[] = "Hexahedra";

// "Block Name", with the sets the generator defines.
std::string blockNameDoc(const std::string& setNames) {
  return "Element block name; node/side sets: " + setNames + " (node set 'all' too)";
}

// ---- Rectangle (Quad4) ----

const ParameterTable<WithCells<RectangleSpec>>& rectangleTable() {
  using S = RectangleSpec;
  static const auto table = withCellVariant(
      "Rectangle",
      ParameterTable<S>()
          .real("X Origin", &S::x0, 0.0, "x of the lower-left corner")
          .real("Y Origin", &S::y0, 0.0, "y of the lower-left corner")
          .positive("Length X", &S::lx, 1.0, "Width")
          .positive("Length Y", &S::ly, 1.0, "Height")
          .count("Elements X", &S::nx, 1, "Elements along x")
          .count("Elements Y", &S::ny, 1, "Elements along y")
          .positive("Bias X", &S::biasX, 1.0, "Last over first element width along x (geometric grading; 1 = uniform)")
          .positive("Bias Y", &S::biasY, 1.0, "Last over first element height along y (geometric grading; 1 = uniform)")
          .text("Block Name", &S::blockName, "block_1", blockNameDoc("left, right, bottom, top")),
      kQuadrilaterals, "Triangles");
  return table;
}

// ---- Annulus Sector (Quad4) and its extrusion, Hollow Cylinder Sector (Hex8) ----

// The ring segment's parameters, which both generators take.
const ParameterTable<AnnulusSectorSpec>& annulusWall() {
  using S = AnnulusSectorSpec;
  static const auto table =
      ParameterTable<S>()
          .positive("Inner Radius", &S::innerRadius, 100.0, "Inner radius, centre at the origin")
          .positive("Thickness", &S::thickness, 20.0, "Wall thickness (outer radius = inner radius + thickness)")
          .real("Start Angle", &S::startAngleDeg, 0.0, "Start angle in degrees, counter-clockwise from +x")
          .real("End Angle", &S::endAngleDeg, 90.0, "End angle in degrees (> Start Angle)")
          .count("Elements Through Thickness", &S::elementsThroughThickness, 13, "Elements across the wall")
          .count("Elements Around Arc", &S::elementsAroundArc, 101, "Elements along the arc")
          .positive("Radial Bias", &S::radialBias, 1.0,
                    "Outermost over innermost element thickness (geometric grading; 1 = uniform)")
          .positive("Arc Bias", &S::arcBias, 1.0,
                    "Last over first element angle along the arc (geometric grading; 1 = uniform)");
  return table;
}

const ParameterTable<AnnulusSectorSpec>& annulusSectorTable() {
  static const auto table = ParameterTable<AnnulusSectorSpec>("Annulus Sector")
                                .include(annulusWall())
                                .text("Block Name", &AnnulusSectorSpec::blockName, "block_1",
                                      blockNameDoc("inner, outer, start, end"));
  return table;
}

const ParameterTable<HollowCylinderSectorSpec>& hollowCylinderSectorTable() {
  using S = HollowCylinderSectorSpec;
  static const auto table =
      ParameterTable<S>("Hollow Cylinder Sector")
          .include(annulusWall(), &S::section)
          .real("Z Origin", &S::z0, 0.0, "z of the back face")
          .positive("Length Z", &S::length, 10.0, "Length along the axis (z)")
          .count("Elements Z", &S::layers, 1, "Layers of elements along the axis")
          .positive("Bias Z", &S::axialBias, 1.0,
                    "Last over first layer thickness along z (geometric grading; 1 = uniform)")
          .text("Block Name", [](S& s) -> std::string& { return s.section.blockName; }, "block_1",
                blockNameDoc("inner, outer, start, end, back (z = Z Origin), front (z = Z Origin + Length Z)"));
  return table;
}

// ---- Box (Hex8) ----

const ParameterTable<WithCells<BoxSpec>>& boxTable() {
  using S = BoxSpec;
  static const auto table = withCellVariant(
      "Box",
      ParameterTable<S>()
          .real("X Origin", &S::x0, 0.0, "x of the corner with the smallest coordinates")
          .real("Y Origin", &S::y0, 0.0, "y of that corner")
          .real("Z Origin", &S::z0, 0.0, "z of that corner")
          .positive("Length X", &S::lx, 1.0, "Size along x")
          .positive("Length Y", &S::ly, 1.0, "Size along y")
          .positive("Length Z", &S::lz, 1.0, "Size along z")
          .count("Elements X", &S::nx, 1, "Elements along x")
          .count("Elements Y", &S::ny, 1, "Elements along y")
          .count("Elements Z", &S::nz, 1, "Elements along z")
          .positive("Bias X", &S::biasX, 1.0, "Last over first element size along x (geometric grading; 1 = uniform)")
          .positive("Bias Y", &S::biasY, 1.0, "Last over first element size along y (geometric grading; 1 = uniform)")
          .positive("Bias Z", &S::biasZ, 1.0, "Last over first element size along z (geometric grading; 1 = uniform)")
          .text("Block Name", &S::blockName, "block_1",
                blockNameDoc("left, right (x), bottom, top (y), back, front (z)")),
      kHexahedra, "Tetrahedra");
  return table;
}

// ---- Sphere Octant (Hex8) ----

const ParameterTable<SphereOctantSpec>& sphereOctantTable() {
  using S = SphereOctantSpec;
  static const auto table =
      ParameterTable<S>("Sphere Octant")
          .positive("Radius", &S::radius, 50.0, "Sphere radius")
          .real("X Center", [](S& s) -> double& { return s.center[0]; }, 0.0, "x of the sphere's centre")
          .real("Y Center", [](S& s) -> double& { return s.center[1]; }, 0.0, "y of the sphere's centre")
          .real("Z Center", [](S& s) -> double& { return s.center[2]; }, 0.0, "z of the sphere's centre")
          .choice("Pole Direction", &S::poleDirection, "-z", {"-z", "+z", "-x", "+x", "-y", "+y"},
                  "Direction from the centre to the pole (the contact point): the octant lies on that side of the "
                  "equator plane and on the + side of the two symmetry planes")
          .count("Elements Along Edge", &S::elementsAlongEdge, 4,
                 "Elements along each edge of the inner cube and of each surface patch")
          .count("Elements Through Shell", &S::elementsThroughShell, 4,
                 "Element layers between the inner cube and the sphere")
          .positive("Inner Cube Fraction", &S::innerCubeFraction, 0.5, "Edge of the inner cube over the radius (< 1/sqrt(3))")
          .positive("Pole Bias", &S::poleBias, 1.0,
                    "Element size far from the pole over that at the pole, along the pole patch's edges (> 1 refines "
                    "near the pole; 1 = equiangular)")
          .positive("Radial Bias", &S::radialBias, 1.0,
                    "Outermost over innermost shell layer thickness (< 1 refines towards the surface; 1 = uniform)")
          .text("Block Name", &S::blockName, "block_1",
                "Element block name; node/side sets: surface, equator, symmetry_<axis> for the two other axes (node "
                "sets 'pole' and 'all' too)");
  return table;
}

// ---- Mesh files ----

// What a mesh file's list says: the file, and for an Exodus file how it is laid out.
struct MeshFileSpec {
  std::string fileName;
  ExodusLayout layout = ExodusLayout::SingleFile;
};

ParameterTable<MeshFileSpec> fileTable(const std::string& name, const std::string& what) {
  return ParameterTable<MeshFileSpec>(name).text("File Name", &MeshFileSpec::fileName, "",
                                                 what + " (relative to the deck's directory); required");
}

// The path File Name gives, relative to the deck's directory.
std::string meshPath(const MeshFileSpec& spec, const std::string& where, const std::string& directory,
                     const std::string& what) {
  std::string file = spec.fileName;
  requireInput(!file.empty(), where + "/File Name: required (" + what + ")");
  if (file.front() != '/' && !directory.empty()) file = directory + "/" + file;
  return file;
}

// The file named by File Name, relative to the deck's directory, which must exist.
std::string meshFile(const MeshFileSpec& spec, const std::string& where, const std::string& directory,
                     const std::string& what) {
  const std::string file = meshPath(spec, where, directory, what);
  requireInput(std::ifstream(file).good(), where + "/File Name: mesh file '" + file + "' does not exist");
  return file;
}

const ParameterTable<MeshFileSpec>& exodusFileTable() {
  static const auto table =
      fileTable("Exodus File", "Exodus II mesh file; with Layout = Per Rank the set's name without .N.r")
          .enumChoice("Layout", &MeshFileSpec::layout, ExodusLayout::SingleFile, exodusLayoutNames(),
                      "Single File: one file holding the whole mesh, partitioned with METIS; Per Rank: the "
                      "pre-split set <File Name>.N.r for a run on N ranks (r zero-padded to the digits of N, as SEACAS "
                      "decomp or nem_slice + nem_spread write it, or Contessa's Problem/Output/Exodus Layout = Per "
                      "Rank), each rank reading only its own file, as split");
  return table;
}

bool perRank(const MeshFileSpec& spec) { return spec.layout == ExodusLayout::PerRank; }

const char* const kPerRankWhat = "the name of a per-rank Exodus II set, without .N.r";

// "1 rank", "2 ranks".
std::string ranksText(int n) { return std::to_string(n) + (n == 1 ? " rank" : " ranks"); }

// "found: the sets for 2, 4 ranks" (or "none found"), to say what the directory holds instead.
std::string setsFound(const std::string& base) {
  const std::vector<int> sets = decomposedFileSets(base);
  if (sets.empty()) return "none found";
  std::string found;
  for (std::size_t k = 0; k + 1 < sets.size(); ++k) found += std::to_string(sets[k]) + ", ";
  return (sets.size() == 1 ? "found: the set for " : "found: the sets for ") + found + ranksText(sets.back());
}

// The whole mesh from a per-rank set (for tools and tests; a run reads its part, below): the set for
// the communicator's rank count when present, otherwise the only set beside File Name; its files are
// joined on the calling rank.
Mesh joinPerRankSet(const MeshFileSpec& spec, const std::string& where, const std::string& directory, MPI_Comm comm) {
  const std::string base = meshPath(spec, where, directory, kPerRankWhat);
  const std::vector<int> sets = decomposedFileSets(base);
  const int ranks = ranksOf(comm).size;
  int numFiles = std::find(sets.begin(), sets.end(), ranks) != sets.end() ? ranks : 0;
  if (numFiles == 0 && sets.size() == 1) numFiles = sets.front();
  requireInput(numFiles > 0, where + "/File Name: Layout = Per Rank needs one set " + base + ".N.r to join into the "
                                     "whole mesh (" + setsFound(base) + ")");
  return joinDecomposedExodus(base, numFiles);
}

// This rank's part of a per-rank set: its own file, base.N.r on N ranks.
DistributedMesh readPerRankSet(const MeshFileSpec& spec, const std::string& where, const std::string& directory,
                               MPI_Comm comm) {
  const std::string base = meshPath(spec, where, directory, kPerRankWhat);
  const Ranks ranks = ranksOf(comm);
  const std::string mine = decomposedFileName(base, ranks.size, ranks.rank);
  std::exception_ptr failure;
  if (!std::ifstream(mine).good())
    failure = std::make_exception_ptr(InputError(
        where + "/File Name: per-rank mesh file '" + mine + "' does not exist (Layout = Per Rank on " +
        ranksText(ranks.size) + " reads " + decomposedFileName(base, ranks.size, 0) +
        (ranks.size > 1 ? " to " + decomposedFileName(base, ranks.size, ranks.size - 1) : std::string()) + "; " +
        setsFound(base) + ")"));
  throwIfAnyRankFailed(comm, failure);  // the lowest rank missing its file speaks for all
  return readDecomposedExodus(base, comm);
}

Mesh createExodusFile(const ParameterList& list, const std::string& where, const std::string& directory, MPI_Comm comm) {
  const MeshFileSpec spec = exodusFileTable().read(list);
  if (perRank(spec)) return joinPerRankSet(spec, where, directory, comm);
  return readExodusMesh(meshFile(spec, where, directory, "an Exodus II mesh file"));
}

DistributedMesh createExodusFilePart(const ParameterList& list, const std::string& where, const std::string& directory,
                                     MPI_Comm comm) {
  const MeshFileSpec spec = exodusFileTable().read(list);
  if (perRank(spec)) return readPerRankSet(spec, where, directory, comm);
  return distributeMesh(comm, [&] { return createExodusFile(list, where, directory, comm); });
}

const ParameterTable<MeshFileSpec>& gmshFileTable() {
  static const auto table = fileTable("Gmsh File", "Gmsh mesh file (.msh)");
  return table;
}

Mesh createGmshFile(const ParameterList& list, const std::string& where, const std::string& directory, MPI_Comm) {
  return readGmshMesh(meshFile(gmshFileTable().read(list), where, directory, "a Gmsh .msh file"));
}

// "Mesh File": the reader chosen by the file's extension.
const struct {
  const char* extension;
  Mesh (*read)(const std::string&);
} kReaders[] = {{".msh", &readGmshMesh}, {".exo", &readExodusMesh}, {".e", &readExodusMesh},
                {".g", &readExodusMesh},  {".gen", &readExodusMesh}, {".ex2", &readExodusMesh}};

const ParameterTable<MeshFileSpec>& meshFileTable() {
  static const auto table = fileTable("Mesh File", "Mesh file: .msh (Gmsh) or .exo, .e, .g, .gen, .ex2 (Exodus II)");
  return table;
}

Mesh createMeshFile(const ParameterList& list, const std::string& where, const std::string& directory, MPI_Comm) {
  const std::string file = meshFile(meshFileTable().read(list), where, directory, "a .msh or Exodus II mesh file");
  std::string known;
  for (const auto& r : kReaders) {
    const std::string ext = r.extension;
    if (file.size() > ext.size() && file.compare(file.size() - ext.size(), ext.size(), ext) == 0) return r.read(file);
    known += (known.empty() ? "" : ", ") + ext;
  }
  throw InputError(where + "/File Name: '" + file + "' has none of the extensions " + known +
                   " (or choose the reader with Type = Exodus File or Gmsh File)");
}

// ---- The registry ----

// A mesh source publishes its parameters and makes the whole mesh from them, or this rank's part.
struct MeshSource {
  RCP<ParameterList> (*validParameters)();
  /// `comm`: the run's ranks (only a per-rank set's join asks how many).
  Mesh (*create)(const ParameterList&, const std::string& where, const std::string& directory, MPI_Comm comm);
  /// This rank's part built alone; null: rank 0 creates the whole mesh and sends the parts out.
  DistributedMesh (*createPart)(const ParameterList&, const std::string& where, const std::string& directory,
                                MPI_Comm comm) = nullptr;
};

const Registry<RegistryRow<MeshSource>>& registry() {
  static const Registry<RegistryRow<MeshSource>> rows("mesh type", {
    {"Rectangle", "A structured rectangle of QUAD4 (2D), graded along x and y",
     &publishedParameters<WithCells<RectangleSpec>, &rectangleTable>,
     &createVariant<RectangleSpec, &rectangleTable, &generateRectangle, kQuadrilaterals>,
     &createVariantPart<RectangleSpec, &rectangleTable, &generateRectangle, &generateRectanglePart, kQuadrilaterals>},
    {"Annulus Sector",
     "A ring segment of QUAD4 (2D) centred at the origin, graded through the wall and along the arc",
     &publishedParameters<AnnulusSectorSpec, &annulusSectorTable>,
     &createGenerated<AnnulusSectorSpec, &annulusSectorTable, &generateAnnulusSector>,
     &createGeneratedPart<AnnulusSectorSpec, &annulusSectorTable, &generateAnnulusSectorPart>},
    {"Box", "A structured box of HEX8 (3D), graded along x, y and z", &publishedParameters<WithCells<BoxSpec>, &boxTable>,
     &createVariant<BoxSpec, &boxTable, &generateBox, kHexahedra>,
     &createVariantPart<BoxSpec, &boxTable, &generateBox, &generateBoxPart, kHexahedra>},
    {"Hollow Cylinder Sector",
     "The Annulus Sector extruded along z into layers of HEX8 (3D); its first layer of nodes is the Annulus "
     "Sector's (same numbers, same x and y), so one layer with u_z = 0 reproduces a plane-strain 2D run",
     &publishedParameters<HollowCylinderSectorSpec, &hollowCylinderSectorTable>,
     &createGenerated<HollowCylinderSectorSpec, &hollowCylinderSectorTable, &generateHollowCylinderSector>,
     &createGeneratedPart<HollowCylinderSectorSpec, &hollowCylinderSectorTable, &generateHollowCylinderSectorPart>},
    {"Sphere Octant",
     "One eighth of a ball on HEX8 (3D) without degenerate elements (an inner cube and three shells reaching "
     "the sphere, as a cube-sphere), for Hertz contact at its pole",
     &publishedParameters<SphereOctantSpec, &sphereOctantTable>,
     &createGenerated<SphereOctantSpec, &sphereOctantTable, &generateSphereOctant>,
     &createGeneratedPart<SphereOctantSpec, &sphereOctantTable, &generateSphereOctantPart>},
    {"Exodus File",
     "An Exodus II mesh: element blocks of TRI3, TRI6, QUAD4, QUAD8, QUAD9 (2D) or TETRA4, TETRA10, HEX8, "
     "HEX20, HEX27, WEDGE6, WEDGE15 (3D), node sets and side sets with their names",
     &publishedParameters<MeshFileSpec, &exodusFileTable>, &createExodusFile, &createExodusFilePart},
    {"Gmsh File",
     "A Gmsh mesh (.msh) of order 1 or 2: physical volumes (2D: surfaces) become element blocks (one per "
     "cell type: a group of several is split into <group>_<type> blocks), their nodes put in the Exodus order; "
     "physical groups one dimension lower side sets and node sets, physical points and curves node sets",
     &publishedParameters<MeshFileSpec, &gmshFileTable>, &createGmshFile},
    {"Mesh File", "A Gmsh or Exodus II mesh, the reader chosen by the file's extension",
     &publishedParameters<MeshFileSpec, &meshFileTable>, &createMeshFile},
  });
  return rows;
}

// The parameter that names the mesh source: "<where>/Type", or "Type" without a path.
std::string typeParameter(const std::string& where) { return (where.empty() ? "" : where + "/") + "Type"; }

}  // namespace

const std::vector<std::string>& exodusLayoutNames() {
  static const std::vector<std::string> names = {"Single File", "Per Rank"};  // the order of ExodusLayout
  return names;
}

std::vector<std::string> MeshFactory::names() { return registry().names(); }

std::string MeshFactory::description(const std::string& type) { return registry().lookup(type, typeParameter("")).doc; }

RCP<const ParameterList> MeshFactory::validParameters(const std::string& type) {
  return registry().lookup(type, typeParameter("")).factory.validParameters();
}

Mesh MeshFactory::create(const std::string& type, const ParameterList& params, const std::string& where,
                         const std::string& directory, MPI_Comm comm) {
  return registry().lookup(type, typeParameter(where)).factory.create(params, where, directory, comm);
}

DistributedMesh MeshFactory::createPart(const std::string& type, const ParameterList& params, const std::string& where,
                                        const std::string& directory, MPI_Comm comm) {
  const MeshSource& source = registry().lookup(type, typeParameter(where)).factory;
  if (source.createPart) return source.createPart(params, where, directory, comm);
  return distributeMesh(comm, [&] { return source.create(params, where, directory, comm); });
}

}  // namespace contessa::mesh
