#include "io/RestartFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <netcdf.h>
#include <netcdf_mem.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "common/Error.hpp"

namespace contessa::io {

namespace {

// The header of format versions 1 and 2 (a binary file): its magic and then its uint32 version.
constexpr char kOldMagic[16] = {'C', 'O', 'N', 'T', 'E', 'S', 'S', 'A', ' ', 'R', 'E', 'S', 'T', 'A', 'R', 'T'};
constexpr char kHdf5Signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
constexpr const char* kTitle = "Contessa restart file";

// A netCDF call that must succeed: the writer's failures are defects (memory only), the reader's a
// damaged file.
void check(int status, const std::string& what) {
  if (status != NC_NOERR) throw std::runtime_error(what + ": " + nc_strerror(status));
}

// The HDF5 end-of-file address of a netCDF-4 image (superblock version 0/1 at byte 40, 2/3 at byte 28;
// 8-byte offsets): the file's length. 0 when the superblock is not one of these.
std::uint64_t hdf5EndOfFile(const char* bytes, std::size_t size) {
  if (size < 48 || std::memcmp(bytes, kHdf5Signature, sizeof kHdf5Signature) != 0) return 0;
  const int version = static_cast<unsigned char>(bytes[8]);
  const std::size_t offsetSize = static_cast<unsigned char>(bytes[version <= 1 ? 13 : 9]);
  if (offsetSize != 8) return 0;
  std::uint64_t eof = 0;
  std::memcpy(&eof, bytes + (version == 0 ? 40 : version == 1 ? 44 : 28), sizeof eof);
  return eof;
}

std::uint64_t contentChecksum(const RestartContent& c) {
  std::uint64_t h = fnv1a(c.deck.data(), c.deck.size());
  h = fnv1a(&c.nodes, sizeof c.nodes, h);
  h = fnv1a(&c.elements, sizeof c.elements, h);
  h = fnv1a(&c.meshHash, sizeof c.meshHash, h);
  return stateChecksum(c.state, h);
}

void putRecord(int group, const StateRecord& record) {
  const bool table = record.isTable();
  int rowsDim = -1;
  if (table) check(nc_def_dim(group, "rows", record.rows(), &rowsDim), "rows");
  for (const auto& [name, f] : record.fields()) {
    std::vector<int> dims;
    for (std::size_t axis = 0; axis < f.shape.size(); ++axis) {
      if (table && axis == 0) {
        dims.push_back(rowsDim);
        continue;
      }
      int dim = -1;
      // A zero length is netCDF's NC_UNLIMITED: such a dimension reads back as length 0 all the same.
      check(nc_def_dim(group, (name + "_" + std::to_string(axis)).c_str(), f.shape[axis], &dim), name);
      dims.push_back(dim);
    }
    const nc_type type = f.type == StateField::Type::Double ? NC_DOUBLE : f.type == StateField::Type::Int64 ? NC_INT64 : NC_STRING;
    int var = -1;
    check(nc_def_var(group, name.c_str(), type, static_cast<int>(dims.size()), dims.data(), &var), name);
    if (f.type == StateField::Type::Double && !f.doubles.empty()) check(nc_put_var_double(group, var, f.doubles.data()), name);
    if (f.type == StateField::Type::Int64 && !f.integers.empty()) {
      static_assert(sizeof(long long) == sizeof(std::int64_t));
      check(nc_put_var_longlong(group, var, reinterpret_cast<const long long*>(f.integers.data())), name);
    }
    if (f.type == StateField::Type::Text) {
      const char* text = f.text.c_str();
      check(nc_put_var_string(group, var, &text), name);
    }
  }
  for (const auto& [name, child] : record.children()) {
    int sub = -1;
    check(nc_def_grp(group, name.c_str(), &sub), name);
    putRecord(sub, child);
  }
}

std::string nameOf(int group, int var) {
  char name[NC_MAX_NAME + 1] = {};
  check(nc_inq_varname(group, var, name), "variable name");
  return name;
}

void getRecord(int group, StateRecord& record) {
  int count = 0;
  check(nc_inq_varids(group, &count, nullptr), "variables");
  std::vector<int> vars(static_cast<std::size_t>(count));
  check(nc_inq_varids(group, &count, vars.data()), "variables");
  for (const int var : vars) {
    const std::string name = nameOf(group, var);
    nc_type type = NC_NAT;
    int ndims = 0;
    check(nc_inq_var(group, var, nullptr, &type, &ndims, nullptr, nullptr), name);
    std::vector<int> dims(static_cast<std::size_t>(ndims));
    check(nc_inq_vardimid(group, var, dims.data()), name);
    StateField f;
    for (const int dim : dims) {
      std::size_t length = 0;
      check(nc_inq_dimlen(group, dim, &length), name);
      f.shape.push_back(length);
    }
    const std::size_t n = f.count();
    if (type == NC_DOUBLE) {
      f.doubles.resize(n);
      if (n > 0) check(nc_get_var_double(group, var, f.doubles.data()), name);
    } else if (type == NC_INT64) {
      f.type = StateField::Type::Int64;
      f.integers.resize(n);
      if (n > 0) check(nc_get_var_longlong(group, var, reinterpret_cast<long long*>(f.integers.data())), name);
    } else if (type == NC_STRING && ndims == 0) {
      f.type = StateField::Type::Text;
      char* text = nullptr;
      check(nc_get_var_string(group, var, &text), name);
      f.text = text != nullptr ? text : "";
      nc_free_string(1, &text);
    } else {
      throw std::runtime_error(record.path() + name + ": a variable of netCDF type " + std::to_string(type));
    }
    record.putField(name, std::move(f));
  }
  int groups = 0;
  check(nc_inq_grps(group, &groups, nullptr), "groups");
  std::vector<int> ids(static_cast<std::size_t>(groups));
  check(nc_inq_grps(group, &groups, ids.data()), "groups");
  for (const int sub : ids) {
    char name[NC_MAX_NAME + 1] = {};
    check(nc_inq_grpname(sub, name), "group name");
    getRecord(sub, record.child(name));
  }
}

std::string textAttribute(int nc, const char* name) {
  std::size_t length = 0;
  nc_type type = NC_NAT;
  if (nc_inq_att(nc, NC_GLOBAL, name, &type, &length) != NC_NOERR || type != NC_CHAR) return "";
  std::string text(length, '\0');
  check(nc_get_att_text(nc, NC_GLOBAL, name, text.data()), name);
  return text;
}

// Closes the file however the reading ends.
struct OpenFile {
  int id = -1;
  ~OpenFile() {
    if (id >= 0) nc_close(id);
  }
};

// "path = value" lines into a map (the deck text of restartDeckText).
std::map<std::string, std::string> deckEntries(const std::string& text, std::vector<std::string>& order) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    const std::string key = eq == std::string::npos ? line : line.substr(0, eq);
    if (out.emplace(key, eq == std::string::npos ? "" : line.substr(eq + 3)).second) order.push_back(key);
  }
  return out;
}

}  // namespace

namespace {

// The content into an open netCDF-4 file (tables sorted by id first).
void putContent(int nc, RestartContent& content) {
  content.state.sortTables();
  check(nc_put_att_text(nc, NC_GLOBAL, "title", std::strlen(kTitle), kTitle), "title");
  const int version = static_cast<int>(kRestartFormatVersion);
  check(nc_put_att_int(nc, NC_GLOBAL, "format_version", NC_INT, 1, &version), "format_version");
  check(nc_put_att_text(nc, NC_GLOBAL, "deck", content.deck.size(), content.deck.data()), "deck");
  const long long counts[2] = {content.nodes, content.elements};
  check(nc_put_att_longlong(nc, NC_GLOBAL, "nodes", NC_INT64, 1, &counts[0]), "nodes");
  check(nc_put_att_longlong(nc, NC_GLOBAL, "elements", NC_INT64, 1, &counts[1]), "elements");
  const unsigned long long hashes[2] = {content.meshHash, contentChecksum(content)};
  check(nc_put_att_ulonglong(nc, NC_GLOBAL, "mesh_hash", NC_UINT64, 1, &hashes[0]), "mesh_hash");
  check(nc_put_att_ulonglong(nc, NC_GLOBAL, "checksum", NC_UINT64, 1, &hashes[1]), "checksum");
  putRecord(nc, content.state);
}

// `temporary` becomes `path` by a rename that is on disk once this returns (the directory synced): a
// crash leaves the old file or the new one. "" or the reason.
std::string renameDurably(const std::string& temporary, const std::string& path) {
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    return path + ": " + reason;
  }
  // Without this a power loss may bring back the old file (never a torn one). A directory that cannot
  // be opened or synced leaves that weaker guarantee.
  const std::string::size_type slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? std::string(".") : path.substr(0, slash == 0 ? 1 : slash);
  const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  return "";
}

}  // namespace

std::string encodeRestart(RestartContent content) {
  int nc = -1;
  check(nc_create_mem("restart", NC_NETCDF4, 1 << 16, &nc), "restart file in memory");
  putContent(nc, content);
  NC_memio memory{};
  check(nc_close_memio(nc, &memory), "restart file in memory");
  const char* bytes = static_cast<const char*>(memory.memory);
  // The in-memory image is padded to its allocation; the file is HDF5's length.
  const std::uint64_t eof = hdf5EndOfFile(bytes, memory.size);
  std::string out(bytes, eof > 0 && eof <= memory.size ? eof : memory.size);
  std::free(memory.memory);
  return out;
}

RestartContent decodeRestart(const std::string& bytes, const std::string& path) {
  const std::string where = "--restart " + path + ": ";
  if (bytes.size() >= sizeof kOldMagic + sizeof(std::uint32_t) && std::memcmp(bytes.data(), kOldMagic, sizeof kOldMagic) == 0) {
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + sizeof kOldMagic, sizeof version);
    throw InputError(where + "restart file format version " + std::to_string(version) +
                     " (a binary file of positional records), this Contessa reads version " +
                     std::to_string(kRestartFormatVersion) + " (netCDF-4 with named fields); continue the run with "
                     "the Contessa that wrote it, or start it again");
  }
  requireInput(bytes.size() >= sizeof kHdf5Signature && std::memcmp(bytes.data(), kHdf5Signature, sizeof kHdf5Signature) == 0,
               where + "not a Contessa restart file");
  const std::uint64_t eof = hdf5EndOfFile(bytes.data(), bytes.size());
  requireInput(bytes.size() >= eof, where + "truncated restart file (" + std::to_string(bytes.size()) + " bytes, " +
                                        std::to_string(eof) + " expected)");
  std::vector<char> image(bytes.begin(), bytes.end());  // nc_open_mem takes non-const memory
  OpenFile file;
  const int opened = nc_open_mem(path.c_str(), NC_NOWRITE, image.size(), image.data(), &file.id);
  if (opened != NC_NOERR) {
    file.id = -1;
    throw InputError(where + "damaged restart file (" + nc_strerror(opened) + ")");
  }
  requireInput(textAttribute(file.id, "title") == kTitle, where + "not a Contessa restart file");
  int version = 0;
  requireInput(nc_get_att_int(file.id, NC_GLOBAL, "format_version", &version) == NC_NOERR,
               where + "not a Contessa restart file (no format_version)");
  requireInput(version == static_cast<int>(kRestartFormatVersion),
               where + "restart file format version " + std::to_string(version) + ", this Contessa reads version " +
                   std::to_string(kRestartFormatVersion));
  RestartContent c;
  unsigned long long hashes[2] = {0, 0};
  long long counts[2] = {0, 0};
  try {
    c.deck = textAttribute(file.id, "deck");
    check(nc_get_att_longlong(file.id, NC_GLOBAL, "nodes", &counts[0]), "nodes");
    check(nc_get_att_longlong(file.id, NC_GLOBAL, "elements", &counts[1]), "elements");
    check(nc_get_att_ulonglong(file.id, NC_GLOBAL, "mesh_hash", &hashes[0]), "mesh_hash");
    check(nc_get_att_ulonglong(file.id, NC_GLOBAL, "checksum", &hashes[1]), "checksum");
    getRecord(file.id, c.state);
  } catch (const std::runtime_error& e) {
    throw InputError(where + "damaged restart file (" + e.what() + ")");
  }
  c.nodes = counts[0];
  c.elements = counts[1];
  c.meshHash = hashes[0];
  requireInput(contentChecksum(c) == hashes[1], where + "corrupt restart file (checksum mismatch)");
  c.state.setOrigin("--restart " + path);
  return c;
}

RestartContent readRestartFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  requireInput(static_cast<bool>(in), "--restart " + path + ": cannot open the restart file (" +
                                          std::string(std::strerror(errno)) + ")");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return decodeRestart(bytes.str(), path);
}

std::string writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string temporary = path + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return temporary + ": " + std::strerror(errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      // write() returning 0 sets no errno.
      const std::string reason = n == 0 ? std::string("short write (the disk accepted no more bytes)") : std::strerror(errno);
      ::close(fd);
      ::unlink(temporary.c_str());
      return temporary + ": " + reason;
    }
    done += static_cast<std::size_t>(n);
  }
  // On disk before the rename makes it the restart file: a crash leaves the old file or the new one.
  const bool synced = ::fsync(fd) == 0;
  const int syncError = errno;
  const bool closed = ::close(fd) == 0;  // always closed, even when fsync failed
  if (!synced || !closed) {
    const std::string reason = std::strerror(synced ? errno : syncError);
    ::unlink(temporary.c_str());
    return temporary + ": " + reason;
  }
  return renameDurably(temporary, path);
}

std::string writeRestartFile(const std::string& path, RestartContent content) {
  // Written by the netCDF library to a file (an in-memory image written out would be one that netCDF
  // cannot open for writing: tools that edit a restart file could not), synced, renamed.
  const std::string temporary = path + ".tmp";
  int nc = -1;
  int status = nc_create(temporary.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc);
  if (status != NC_NOERR) return temporary + ": " + nc_strerror(status);
  try {
    putContent(nc, content);
  } catch (const std::runtime_error& e) {
    nc_close(nc);
    ::unlink(temporary.c_str());
    return temporary + ": " + e.what();
  }
  status = nc_close(nc);
  if (status != NC_NOERR) {
    ::unlink(temporary.c_str());
    return temporary + ": " + nc_strerror(status);
  }
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  const std::string reason = synced ? std::string() : std::string(std::strerror(errno));
  if (fd >= 0) ::close(fd);
  if (!synced) {
    ::unlink(temporary.c_str());
    return temporary + ": " + reason;
  }
  return renameDurably(temporary, path);
}

std::string deckDifference(const std::string& saved, const std::string& current) {
  if (saved == current) return "";
  std::vector<std::string> savedOrder, currentOrder;
  const auto a = deckEntries(saved, savedOrder), b = deckEntries(current, currentOrder);
  for (const auto& key : currentOrder) {
    const auto it = a.find(key);
    if (it == a.end()) return key + " is not in the restart file's deck (" + b.at(key) + " here)";
    if (it->second != b.at(key)) return key + " is " + it->second + " in the restart file, " + b.at(key) + " here";
  }
  for (const auto& key : savedOrder)
    if (b.find(key) == b.end()) return key + " (" + a.at(key) + ") is in the restart file's deck, not here";
  return "the order of the deck's parameters differs";
}

}  // namespace contessa::io
