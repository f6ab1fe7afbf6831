// The module libcontessa_gmsh.so: GmshLibrary over Debian's libgmsh (the only file that includes gmsh.h).
#include <gmsh.h>

#include "mesh/GmshLibrary.hpp"

namespace {

class GmshApi final : public contessa::mesh::GmshLibrary {
 public:
  void initialize() override {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  void finalize() override { gmsh::finalize(); }
  void open(const std::string& path) override { gmsh::open(path); }
  void getPhysicalGroups(std::vector<std::pair<int, int>>& dimTags) override { gmsh::model::getPhysicalGroups(dimTags); }
  void getPhysicalName(int dim, int tag, std::string& name) override { gmsh::model::getPhysicalName(dim, tag, name); }
  void getEntitiesForPhysicalGroup(int dim, int tag, std::vector<int>& entities) override {
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
  }
  void getElements(std::vector<int>& types, std::vector<std::vector<std::size_t>>& tags,
                   std::vector<std::vector<std::size_t>>& nodes, int dim, int entity) override {
    gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
  }
  std::string elementTypeName(int type) override {
    std::string name;
    int dim = 0, order = 0, numNodes = 0, numPrimary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(type, name, dim, order, numNodes, local, numPrimary);
    return name;
  }
  void getNodes(std::vector<std::size_t>& tags, std::vector<double>& xyz) override {
    std::vector<double> parametric;
    gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
  }
};

}  // namespace

extern "C" contessa::mesh::GmshLibrary* contessa_gmsh_library() {
  static GmshApi api;
  return &api;
}
