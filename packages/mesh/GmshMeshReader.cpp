#include "mesh/GmshMeshReader.hpp"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "common/Error.hpp"
#include "mesh/GmshLibrary.hpp"
#include "mesh/MemoryEstimate.hpp"

namespace contessa::mesh {

namespace {

// The module beside the program (build/bin/contessa → build/lib/), or where this build made it.
std::vector<std::string> gmshModuleCandidates() {
  std::vector<std::string> paths;
  std::string exe(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1);
  if (n > 0) {
    exe.resize(static_cast<std::size_t>(n));
    const auto slash = exe.rfind('/');
    if (slash != std::string::npos) paths.push_back(exe.substr(0, slash) + "/../lib/" CONTESSA_GMSH_MODULE_NAME);
  }
  paths.push_back(CONTESSA_GMSH_MODULE_PATH);
  return paths;
}

}  // namespace

GmshLibrary& gmshLibrary() {
  static GmshLibrary* library = [] {
    std::string reasons;
    for (const std::string& path : gmshModuleCandidates()) {
      // Kept loaded for the rest of the run: Gmsh's global state lives in it.
      if (void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
        using Entry = GmshLibrary* (*)();
        if (auto entry = reinterpret_cast<Entry>(::dlsym(handle, "contessa_gmsh_library"))) return entry();
        reasons += std::string(reasons.empty() ? "" : "; ") + path + ": no entry point";
      } else {
        const char* why = ::dlerror();
        reasons += std::string(reasons.empty() ? "" : "; ") + (why ? why : path);
      }
    }
    throw InputError("cannot load Contessa's Gmsh reader module (" + reasons + "); rebuild Contessa (scripts/build.sh)");
  }();
  return *library;
}

namespace {

// A Gmsh element type (its MSH format's number) as a Contessa cell: Exodus node k is Gmsh's node
// order[k]. Gmsh's orders (the Gmsh reference manual, "Node ordering") put the corners first in the
// Exodus order, but number the edges of tetrahedra, hexahedra and prisms differently, and the face
// centres of the 27-node hexahedron.
struct GmshCell {
  int gmshType;
  CellType cell;
  std::vector<int> order;  ///< empty: the same order
};

const std::vector<GmshCell>& gmshCells() {
  static const std::vector<GmshCell> cells = [] {
    // Gmsh's hexahedron edges: 8 (0,1), 9 (0,3), 10 (0,4), 11 (1,2), 12 (1,5), 13 (2,3), 14 (2,6),
    // 15 (3,7), 16 (4,5), 17 (4,7), 18 (5,6), 19 (6,7); Exodus's: the bottom edges, the vertical
    // ones, the top ones, each in corner order.
    std::vector<int> hex20{0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 10, 12, 14, 15, 16, 18, 19, 17};
    // Gmsh's face centres: 20 (z = −1), 21 (y = −1), 22 (x = −1), 23 (x = +1), 24 (y = +1), 25 (z = +1),
    // then the centre 26; Exodus's: the centre, then the faces z = −1, z = +1, x = −1, x = +1, y = −1, y = +1.
    std::vector<int> hex27 = hex20;
    hex27.insert(hex27.end(), {26, 20, 25, 22, 23, 21, 24});
    return std::vector<GmshCell>{
        {2, CellType::Tri3, {}},
        {9, CellType::Tri6, {}},
        {3, CellType::Quad4, {}},
        {16, CellType::Quad8, {}},
        {10, CellType::Quad9, {}},
        {4, CellType::Tet4, {}},
        // Gmsh: 7 (3,0), 8 (3,2), 9 (3,1); Exodus: 7 (0,3), 8 (1,3), 9 (2,3).
        {11, CellType::Tet10, {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}},
        {5, CellType::Hex8, {}},
        {17, CellType::Hex20, hex20},
        {12, CellType::Hex27, hex27},
        {6, CellType::Wedge6, {}},
        // Gmsh: 6 (0,1), 7 (0,2), 8 (0,3), 9 (1,2), 10 (1,4), 11 (2,5), 12 (3,4), 13 (3,5), 14 (4,5);
        // Exodus: 6 (0,1), 7 (1,2), 8 (2,0), 9 (0,3), 10 (1,4), 11 (2,5), 12 (3,4), 13 (4,5), 14 (5,3).
        {18, CellType::Wedge15, {0, 1, 2, 3, 4, 5, 6, 9, 7, 8, 10, 11, 12, 14, 13}},
    };
  }();
  return cells;
}

const GmshCell* gmshCell(int gmshType) {
  for (const GmshCell& c : gmshCells())
    if (c.gmshType == gmshType) return &c;
  return nullptr;
}

// Sides of cells as Gmsh elements: lines of 2 or 3 nodes (1, 8) in 2D; triangles of 3 or 6 nodes (2, 9)
// and quadrilaterals of 4, 8 or 9 (3, 16, 10) in 3D. Their corners come first; 0 for any other type.
int gmshSideCorners(int gmshType, int dimension) {
  if (dimension == 2) return gmshType == 1 || gmshType == 8 ? 2 : 0;
  if (gmshType == 2 || gmshType == 9) return 3;
  return gmshType == 3 || gmshType == 16 || gmshType == 10 ? 4 : 0;
}

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

// The Gmsh library is one global state: initialised silently (no configuration files, nothing
// printed: General.Terminal = 0) for one read, finalised whatever happens.
class GmshSession {
 public:
  explicit GmshSession(GmshLibrary& gmsh) : gmsh_(gmsh) { gmsh_.initialize(); }
  ~GmshSession() {
    try {
      gmsh_.finalize();
    } catch (...) {  // an exception leaving a destructor would terminate the program
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  GmshLibrary& gmsh_;
};

struct Group {
  int dim = 0, tag = 0;
  std::string name;
};

// The layout of an ASCII .msh file, checked before Gmsh reads it: Gmsh's reader skips to the next
// '$' line it knows, so a file with its $EndNodes missing, a section cut short or a count that does
// not match the lines below it is read without a word, and what it made of it fails much later (the
// results file cannot be written). Every section must close before the next one begins; $PhysicalNames,
// $Nodes and $Elements must hold exactly the lines their counts announce (MSH 2.x, 4.0 and 4.1). One
// pass over the file, line by line (nothing kept). Binary files (file-type 1) are left to Gmsh: their
// sections are byte counts, not lines.
class MshLayoutCheck {
 public:
  explicit MshLayoutCheck(std::string path) : path_(std::move(path)), in_(path_, std::ios::binary) {}

  void run() {
    std::string line;
    if (!in_ || !nextNonBlank(line) || line != "$MeshFormat") return;  // not MSH 2 or 4: Gmsh decides
    Section format{"MeshFormat", number_};
    const auto v = numbers(format, 3, "the version, file type and data size");
    major_ = static_cast<int>(v[0]);
    minor_ = static_cast<int>(std::lround((v[0] - major_) * 10));
    if (v[1] != 0 || (major_ != 2 && major_ != 4)) return;  // binary, or a version not checked here
    requireEnd(format);
    while (nextNonBlank(line)) {
      if (line[0] != '$')
        fail("line " + std::to_string(number_) + ": '" + shortened(line) + "' outside any section ($Name ... $EndName)");
      Section section{line.substr(1), number_};
      if (section.name == "PhysicalNames") checkPhysicalNames(section);
      else if (section.name == "Nodes") checkNodes(section);
      else if (section.name == "Elements") checkElements(section);
      else skipToEnd(section);
    }
  }

 private:
  struct Section {
    std::string name;
    int opened;  ///< line of $Name
  };

  std::string path_;
  std::ifstream in_;
  int number_ = 0;  ///< the line last read
  int major_ = 4, minor_ = 1;
  std::string line_;             ///< the line numbers() read
  std::vector<double> values_;   ///< its numbers

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": not a readable Gmsh file (" + what + ")");
  }
  static void trim(std::string& t) {
    const auto b = t.find_first_not_of(" \t\r");
    if (b == std::string::npos) return t.clear();
    t.erase(t.find_last_not_of(" \t\r") + 1);
    t.erase(0, b);
  }
  static std::string shortened(const std::string& t) { return t.size() > 40 ? t.substr(0, 40) + "..." : t; }
  std::string where(const Section& s) const { return "$" + s.name + " (line " + std::to_string(s.opened) + ")"; }

  // The next line that is not blank, trimmed; false at the end of the file.
  bool nextNonBlank(std::string& line) {
    while (std::getline(in_, line)) {
      ++number_;
      trim(line);
      if (!line.empty()) return true;
    }
    return false;
  }
  [[noreturn]] void failUnclosed(const Section& s) const {
    fail(where(s) + " has no $End" + s.name + ": the file ends at line " + std::to_string(number_) +
         " (a truncated file?)");
  }
  [[noreturn]] void failInterrupted(const Section& s, const std::string& line) const {
    fail("line " + std::to_string(number_) + ": " + shortened(line) + " begins before $End" + s.name + " closes " +
         where(s));
  }

  // The next line of the section as numbers (at least `fields` of them); `what()` says what it should
  // be (made only for a message: the check is one pass of strtod over the file).
  template <class What>
  const std::vector<double>& numbers(const Section& s, std::size_t fields, const What& what) {
    if (!nextNonBlank(line_)) failUnclosed(s);
    if (line_[0] == '$') {
      if (line_ == "$End" + s.name)
        fail(where(s) + " ends at line " + std::to_string(number_) + " where " + what() +
             " was expected: a count does not match the lines, or lines are missing");
      failInterrupted(s, line_);
    }
    values_.clear();
    const char* p = line_.c_str();
    while (true) {
      while (*p == ' ' || *p == '\t') ++p;
      if (*p == '\0') break;
      char* end = nullptr;
      const double v = std::strtod(p, &end);
      if (end == p || (*end != '\0' && *end != ' ' && *end != '\t')) {
        const char* stop = p;
        while (*stop != '\0' && *stop != ' ' && *stop != '\t') ++stop;
        fail("line " + std::to_string(number_) + " of " + where(s) + ": '" + shortened(std::string(p, stop)) +
             "' is not a number (" + what() + ")");
      }
      values_.push_back(v);
      p = end;
    }
    if (values_.size() < fields)
      fail("line " + std::to_string(number_) + " of " + where(s) + ": " + std::to_string(values_.size()) +
           " values where " + what() + " needs " + std::to_string(fields));
    return values_;
  }
  std::vector<double> numbers(const Section& s, std::size_t fields, const char* what) {
    return numbers(s, fields, [what] { return std::string(what); });
  }
  // A count read from the line just read: a whole number >= 0.
  long long count(double v, const Section& s) const {
    if (!(v >= 0 && v == std::floor(v) && v <= 1e15))
      fail("line " + std::to_string(number_) + " of " + where(s) + ": '" + std::to_string(v) + "' is not a count");
    return static_cast<long long>(v);
  }
  // After the lines the counts announce: $EndName.
  void requireEnd(const Section& s) {
    std::string line;
    if (!nextNonBlank(line)) failUnclosed(s);
    if (line == "$End" + s.name) return;
    if (line[0] == '$') failInterrupted(s, line);
    fail("line " + std::to_string(number_) + " of " + where(s) + ": more lines than its counts announce, or $End" +
         s.name + " missing");
  }
  void skipToEnd(const Section& s) {
    std::string line;
    while (nextNonBlank(line)) {
      if (line == "$End" + s.name) return;
      if (line[0] == '$') failInterrupted(s, line);
    }
    failUnclosed(s);
  }

  void checkPhysicalNames(const Section& s) {
    const long long n = count(numbers(s, 1, "the number of names")[0], s);
    for (long long k = 0; k < n; ++k) {
      std::string line;
      if (!nextNonBlank(line)) failUnclosed(s);
      if (line[0] == '$')
        fail(where(s) + " ends at line " + std::to_string(number_) + " where name " + std::to_string(k + 1) + " of " +
             std::to_string(n) + " was expected: a count does not match the lines, or lines are missing");
    }
    requireEnd(s);
  }

  void checkNodes(const Section& s) {
    if (major_ == 2) return checkCountedRecords(s, "node", "(tag x y z)");
    checkBlocks(s, "node", [&](const auto& block) {
      const auto h = numbers(s, 4, [&] { return "the header of " + block(); });
      const bool parametric = h[2] != 0;
      const long long n = count(h[3], s);
      if (minor_ == 0) {
        for (long long k = 0; k < n; ++k) numbers(s, 4, [&] { return "node " + std::to_string(k + 1) + " of " + block() + " (tag x y z)"; });
      } else {
        for (long long k = 0; k < n; ++k) numbers(s, 1, [&] { return "node tag " + std::to_string(k + 1) + " of " + block(); });
        for (long long k = 0; k < n; ++k)
          numbers(s, parametric ? 4 : 3, [&] { return "the coordinates of node " + std::to_string(k + 1) + " of " + block(); });
      }
      return n;
    });
  }

  void checkElements(const Section& s) {
    if (major_ == 2) return checkCountedRecords(s, "element", "(tag type tags nodes)");
    checkBlocks(s, "element", [&](const auto& block) {
      const long long n = count(numbers(s, 4, [&] { return "the header of " + block(); })[3], s);
      for (long long k = 0; k < n; ++k)
        numbers(s, 2, [&] { return "element " + std::to_string(k + 1) + " of " + block() + " (tag nodes)"; });
      return n;
    });
  }

  // MSH 2: the number of records ("node", "element"), then one line each of at least 4 numbers (`layout`).
  void checkCountedRecords(const Section& s, const std::string& record, const char* layout) {
    const long long n = count(numbers(s, 1, [&] { return "the number of " + record + "s"; })[0], s);
    for (long long k = 0; k < n; ++k)
      numbers(s, 4, [&] { return record + " " + std::to_string(k + 1) + " of " + std::to_string(n) + " " + layout; });
    requireEnd(s);
  }

  // MSH 4: the section's counts (blocks, total records), then its blocks: `checkBlock(block)` reads one,
  // `block()` naming it ("node block 2 of 3"), and returns how many records it held; they must add up.
  template <class CheckBlock>
  void checkBlocks(const Section& s, const std::string& record, const CheckBlock& checkBlock) {
    const auto header = numbers(s, minor_ == 0 ? 2 : 4, [&] { return "the " + record + " section's counts"; });
    const long long blocks = count(header[0], s), total = count(header[1], s);
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b)
      seen += checkBlock([&] { return record + " block " + std::to_string(b + 1) + " of " + std::to_string(blocks); });
    requireEnd(s);
    if (seen != total)
      fail(where(s) + " announces " + std::to_string(total) + " " + record + "s, its blocks hold " + std::to_string(seen));
  }
};

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  Mesh read() {
    requireReadableMshFile();
    MshLayoutCheck(path_).run();
    GmshSession session(gmsh_);
    try {
      gmsh_.open(path_);
      return build();
    } catch (const std::string& gmshError) {  // how the Gmsh 4.8 API reports an error
      throw InputError(path_ + ": not a readable Gmsh file (" + oneLine(gmshError) + ")");
    }
  }

 private:
  // Gmsh chooses its reader by the extension (and would run a .geo script): only .msh is read.
  void requireReadableMshFile() const {
    struct stat info {};
    requireInput(::stat(path_.c_str(), &info) == 0, path_ + ": the mesh file does not exist");
    requireInput(S_ISREG(info.st_mode), path_ + ": not a readable Gmsh file (it is not a regular file)");
    requireInput(info.st_size > 0, path_ + ": not a readable Gmsh file (it is empty)");
    const bool msh = path_.size() > 4 && path_.compare(path_.size() - 4, 4, ".msh") == 0;
    requireInput(msh, path_ + ": not a Gmsh mesh file (expected the extension .msh)");
  }

  Mesh build() {
    std::vector<std::pair<int, int>> dimTags;
    gmsh_.getPhysicalGroups(dimTags);
    int d = 0;
    for (const auto& [dim, tag] : dimTags) d = std::max(d, dim);
    requireInput(d >= 2, path_ + ": no physical surface or volume (Contessa makes its element blocks from the " +
                             "physical groups of the mesh's dimension: add e.g. Physical Volume(\"body\") = {1}; to the .geo)");
    std::vector<Group> groups;
    for (const auto& [dim, tag] : dimTags) {
      Group g{dim, tag, ""};
      gmsh_.getPhysicalName(dim, tag, g.name);
      if (g.name.empty()) {
        static const char* kWords[] = {"point", "curve", "surface", "volume"};
        g.name = std::string(kWords[dim]) + "_" + std::to_string(tag);
      }
      groups.push_back(g);
    }

    Mesh mesh;
    mesh.dimension = d;
    readBlocks(mesh, groups);
    readNodes(mesh);
    for (const Group& g : groups)
      if (g.dim == d - 1) readSideSet(mesh, g);
    for (const Group& g : groups)
      if (g.dim < d) readNodeSet(mesh, g);
    mesh.validate(path_);
    return mesh;
  }

  // Elements (type, tags, node tags) of every entity of group g.
  template <class F>
  void forElements(const Group& g, F&& f) const {
    std::vector<int> entities;
    gmsh_.getEntitiesForPhysicalGroup(g.dim, g.tag, entities);
    for (int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh_.getElements(types, tags, nodes, g.dim, entity);
      for (size_t t = 0; t < types.size(); ++t) f(types[t], tags[t], nodes[t]);
    }
  }

  std::string typeName(int type) const {
    std::string name = gmsh_.elementTypeName(type);
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    return name;
  }

  [[noreturn]] void failType(int type, const Group& g, const char* supported) const {
    throw InputError(path_ + ": element type '" + typeName(type) + "' in physical group '" + g.name +
                     "' is not supported (Contessa reads " + supported + ")");
  }

  // One block per physical group of the mesh's dimension and cell type: a group of one type is the
  // block of its name; a group of several (hexahedra and prisms) is split into blocks named
  // <group>_<type> ("body_hex20", "body_wedge15"), each of one cell type.
  void readBlocks(Mesh& mesh, const std::vector<Group>& groups) {
    const int d = mesh.dimension;
    std::map<std::size_t, std::string> blockOf;  // Gmsh element tag → group, to find one in two groups
    for (const Group& g : groups) {
      if (g.dim != d) continue;
      std::vector<ElementBlock> byType;
      forElements(g, [&](int type, const std::vector<std::size_t>& tags, const std::vector<std::size_t>& nodes) {
        const GmshCell* cell = gmshCell(type);
        if (cell == nullptr || cellDimension(cell->cell) != d)
          failType(type, g, d == 2 ? "triangles of 3 and 6 nodes and quadrilaterals of 4, 8 and 9 nodes"
                                   : "tetrahedra of 4 and 10 nodes, hexahedra of 8, 20 and 27 and prisms of 6 and 15");
        auto block = std::find_if(byType.begin(), byType.end(), [&](const ElementBlock& b) { return b.cellType == cell->cell; });
        if (block == byType.end()) {
          byType.push_back(ElementBlock{g.name, cell->cell, {}, {}});
          block = byType.end() - 1;
        }
        const int nn = nodesPerCell(cell->cell);
        for (size_t e = 0; e < tags.size(); ++e) {
          auto [it, inserted] = blockOf.emplace(tags[e], g.name);
          requireInput(inserted, path_ + ": element " + std::to_string(tags[e]) + " is in physical groups '" +
                                     it->second + "' and '" + g.name + "'; an element belongs to one block");
          block->elements.push_back(0);  // numbered below
          for (int a = 0; a < nn; ++a)
            block->connectivity.push_back(static_cast<GlobalIndex>(nodes[nn * e + (cell->order.empty() ? a : cell->order[a])]));
        }
      });
      for (ElementBlock& block : byType) {
        if (byType.size() > 1) {
          std::string type = exodusCellName(block.cellType);
          std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return std::tolower(c); });
          block.name += "_" + type;
        }
        mesh.blocks.push_back(std::move(block));
      }
    }
    // Element ids run over the blocks in order, each block's contiguous (Mesh::locate's fast path).
    GlobalIndex next = 0;
    for (ElementBlock& block : mesh.blocks)
      for (GlobalIndex& id : block.elements) id = next++;
  }

  // Keeps the nodes of block elements, numbered by ascending Gmsh tag; connectivity still holds tags.
  void readNodes(Mesh& mesh) {
    for (const auto& b : mesh.blocks)
      for (GlobalIndex tag : b.connectivity) used_.push_back(static_cast<std::size_t>(tag));
    std::sort(used_.begin(), used_.end());
    used_.erase(std::unique(used_.begin(), used_.end()), used_.end());
    MeshSize size(static_cast<double>(used_.size()), static_cast<double>(mesh.numElements()), mesh.dimension);
    for (const auto& b : mesh.blocks) size.nodesPerElement = std::max(size.nodesPerElement, nodesPerCell(b.cellType));
    requireRunFits(size, path_, "use a coarser mesh or a machine with more memory");

    std::vector<std::size_t> tags;
    std::vector<double> xyz;
    gmsh_.getNodes(tags, xyz);
    const int d = mesh.dimension;
    mesh.coordinates.assign(d * used_.size(), 0.0);
    double extent = 0;
    for (size_t k = 0; k < tags.size(); ++k) {
      const GlobalIndex n = index(tags[k]);
      if (n < 0) continue;
      for (int i = 0; i < d; ++i) mesh.coordinates[d * n + i] = xyz[3 * k + i];
      for (int i = 0; i < 3; ++i) extent = std::max(extent, std::abs(xyz[3 * k + i]));
    }
    if (d == 2)
      for (size_t k = 0; k < tags.size(); ++k)
        requireInput(index(tags[k]) < 0 || std::abs(xyz[3 * k + 2]) <= 1e-12 * extent,
                     path_ + ": node " + std::to_string(tags[k]) + " has z = " + std::to_string(xyz[3 * k + 2]) +
                         "; a 2D mesh must lie in the plane z = 0");
    for (auto& b : mesh.blocks)
      for (GlobalIndex& n : b.connectivity) n = index(static_cast<std::size_t>(n));
  }

  // Contessa's node number of a Gmsh node tag, −1 for a node of no block element.
  GlobalIndex index(std::size_t tag) const {
    auto it = std::lower_bound(used_.begin(), used_.end(), tag);
    return it != used_.end() && *it == tag ? static_cast<GlobalIndex>(it - used_.begin()) : -1;
  }

  GlobalIndex requireNode(std::size_t tag, const Group& g) const {
    const GlobalIndex n = index(tag);
    requireInput(n >= 0, path_ + ": physical group '" + g.name + "' holds node " + std::to_string(tag) +
                             ", which is in no element of the blocks (the physical groups of the mesh's dimension)");
    return n;
  }

  using FaceKey = std::array<GlobalIndex, 4>;  // sorted corner node numbers; −1 pads 2- and 3-corner sides

  static FaceKey key(std::vector<GlobalIndex> corners) {
    std::sort(corners.begin(), corners.end());
    FaceKey k{-1, -1, -1, -1};
    std::copy(corners.begin(), corners.end(), k.begin());
    return k;
  }

  // Every side of every block element by its corners (built once, when a side set needs it).
  void buildFaces(const Mesh& mesh) {
    if (sidesBuilt_) return;
    sidesBuilt_ = true;
    for (const auto& b : mesh.blocks) {
      const int nn = nodesPerCell(b.cellType);
      for (size_t e = 0; e < b.elements.size(); ++e)
        for (int s = 0; s < numSides(b.cellType); ++s) {
          const auto local = sideNodes(b.cellType, s);
          std::vector<GlobalIndex> corners;
          for (int i = 0; i < numSideCorners(b.cellType, s); ++i) corners.push_back(b.connectivity[nn * e + local[i]]);
          faces_.emplace(key(corners), std::make_pair(b.elements[e], s));
        }
    }
  }

  // A side set from the lines (2D) or faces (3D) of a physical group, each matched to the element
  // side with the same corners; its mid-side nodes are the element's.
  void readSideSet(Mesh& mesh, const Group& g) {
    buildFaces(mesh);
    SideSet set;
    set.name = g.name;
    forElements(g, [&](int type, const std::vector<std::size_t>& tags, const std::vector<std::size_t>& nodes) {
      const int corners = gmshSideCorners(type, mesh.dimension);
      if (corners == 0)
        failType(type, g, mesh.dimension == 2 ? "lines of 2 and 3 nodes as sides of 2D cells"
                                              : "triangles of 3 and 6 nodes and quadrilaterals of 4, 8 and 9 as faces");
      const size_t nn = tags.empty() ? 0 : nodes.size() / tags.size();
      for (size_t f = 0; f < tags.size(); ++f) {
        std::vector<GlobalIndex> face;
        for (int a = 0; a < corners; ++a) face.push_back(requireNode(nodes[nn * f + a], g));
        // A boundary face bounds one element; a face shared by two is inside the mesh, which
        // Mesh::validate reports (naming the set and both elements) when the first is listed.
        auto it = faces_.find(key(face));
        requireInput(it != faces_.end(), path_ + ": physical group '" + g.name + "' holds a " +
                                             (mesh.dimension == 3 ? "face" : "line") + " (nodes " +
                                             std::to_string(nodes[nn * f]) +
                                             ", ...) that is not a side of any element of the blocks");
        set.elements.push_back(it->second.first);
        set.sides.push_back(it->second.second);
      }
    });
    mesh.sideSets.push_back(std::move(set));
  }

  void readNodeSet(Mesh& mesh, const Group& g) {
    NodeSet set;
    set.name = g.name;
    forElements(g, [&](int, const std::vector<std::size_t>&, const std::vector<std::size_t>& nodes) {
      for (std::size_t tag : nodes) set.nodes.push_back(requireNode(tag, g));
    });
    std::sort(set.nodes.begin(), set.nodes.end());
    set.nodes.erase(std::unique(set.nodes.begin(), set.nodes.end()), set.nodes.end());
    mesh.nodeSets.push_back(std::move(set));
  }

  GmshLibrary& gmsh_ = gmshLibrary();
  std::string path_;
  std::vector<std::size_t> used_;
  std::multimap<FaceKey, std::pair<GlobalIndex, int>> faces_;
  bool sidesBuilt_ = false;
};

}  // namespace

Mesh readGmshMesh(const std::string& path) { return Reader(path).read(); }

}  // namespace contessa::mesh
