#include "mesh/ExodusProbe.hpp"

#include <netcdf.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

namespace contessa::mesh {

namespace {

namespace fs = std::filesystem;

// First bytes of the formats Exodus II is stored in: netCDF classic (CDF1), 64-bit offset (CDF2),
// CDF5, and HDF5 (netCDF-4).
enum class Signature { kClassic, kHdf5, kOther };

Signature signatureOf(const std::string& bytes) {
  if (bytes.size() >= 4 && bytes.compare(0, 3, "CDF") == 0 && (bytes[3] == 1 || bytes[3] == 2 || bytes[3] == 5))
    return Signature::kClassic;
  if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89HDF\r\n\x1a\n") == 0) return Signature::kHdf5;
  return Signature::kOther;
}

// Big-endian reader over a classic netCDF header (the format specification's grammar: magic,
// numrecs, dim_list, gatt_list, var_list). NON_NEG counts are 4 bytes, 8 in CDF5; offsets 4 bytes in
// CDF1, 8 in CDF2 and CDF5. Every read is bounds-checked: a damaged header yields no conclusion.
class ClassicHeader {
 public:
  explicit ClassicHeader(std::string bytes) : bytes_(std::move(bytes)) {
    const int version = bytes_.size() > 3 ? bytes_[3] : 0;
    countSize_ = version == 5 ? 8 : 4;
    offsetSize_ = version == 1 ? 4 : 8;
    pos_ = 4;
  }

  // The byte offsets ("begin") of the variables, in variable id order; empty if unreadable.
  std::vector<double> variableOffsets() {
    std::vector<double> begins;
    skip(countSize_);  // numrecs
    // dim_list: name, length
    for (double n = list(); n > 0 && ok_; --n) {
      name();
      skip(countSize_);
    }
    attributes();
    for (double n = list(); n > 0 && ok_; --n) {
      name();
      skip(countSize_ * number(countSize_));  // dimension ids
      attributes();
      skip(4);                                // nc_type
      skip(countSize_);                       // vsize
      begins.push_back(number(offsetSize_));  // begin
    }
    if (!ok_) begins.clear();
    return begins;
  }

 private:
  double number(int size) {
    if (pos_ + size > bytes_.size()) {
      ok_ = false;
      return 0;
    }
    double value = 0;
    for (int k = 0; k < size; ++k) value = value * 256 + static_cast<unsigned char>(bytes_[pos_ + k]);
    pos_ += size;
    return value;
  }
  void skip(double bytes) {
    if (bytes < 0 || pos_ + bytes > bytes_.size()) ok_ = false;
    else pos_ += static_cast<size_t>(bytes);
  }
  static double padded(double bytes) { return std::ceil(bytes / 4) * 4; }
  // tag (4 bytes: NC_DIMENSION 0x0A, NC_VARIABLE 0x0B, NC_ATTRIBUTE 0x0C, or ABSENT 0) and count.
  double list() {
    number(4);
    return number(countSize_);
  }
  void name() { skip(padded(number(countSize_))); }
  void attributes() {
    for (double n = list(); n > 0 && ok_; --n) {
      name();
      const int type = static_cast<int>(number(4));
      const double count = number(countSize_);
      skip(padded(count * typeSize(type)));
    }
  }
  static int typeSize(int type) {
    switch (type) {
      case NC_BYTE: case NC_CHAR: case NC_UBYTE: return 1;
      case NC_SHORT: case NC_USHORT: return 2;
      case NC_INT: case NC_FLOAT: case NC_UINT: return 4;
      default: return 8;  // NC_DOUBLE, NC_INT64, NC_UINT64
    }
  }

  std::string bytes_;
  size_t pos_ = 0;
  int countSize_ = 4, offsetSize_ = 4;
  bool ok_ = true;
};

// The size a classic-format file must have: each variable's begin offset (from the header) plus
// its data (the last record's, for record variables). A shorter file is truncated; the netCDF
// library would read the missing part as zeros without a word. 0 when unknown.
double classicFileBytes(int ncid, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string header(1 << 20, '\0');  // headers are small; a larger one simply yields no conclusion
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<size_t>(in.gcount()));
  const std::vector<double> begins = ClassicHeader(std::move(header)).variableOffsets();
  int numVariables = 0, unlimited = -1;
  nc_inq_nvars(ncid, &numVariables);
  nc_inq_unlimdim(ncid, &unlimited);
  if (static_cast<int>(begins.size()) != numVariables) return 0;
  size_t records = 0;
  if (unlimited >= 0) nc_inq_dimlen(ncid, unlimited, &records);
  // Record variables interleave: record r of a variable starts at begin + r · (sum of their record sizes).
  std::vector<double> recordBytes(static_cast<size_t>(numVariables), 0);
  double recordSize = 0;
  for (int v = 0; v < numVariables; ++v) {
    nc_type type;
    int numDims = 0;
    int dims[NC_MAX_VAR_DIMS];
    size_t typeSize = 0;
    if (nc_inq_var(ncid, v, nullptr, &type, &numDims, dims, nullptr) != NC_NOERR) return 0;
    nc_inq_type(ncid, type, nullptr, &typeSize);
    double bytes = static_cast<double>(typeSize);
    const bool isRecord = numDims > 0 && dims[0] == unlimited;
    for (int k = isRecord ? 1 : 0; k < numDims; ++k) {
      size_t length = 0;
      nc_inq_dimlen(ncid, dims[k], &length);
      bytes *= static_cast<double>(length);
    }
    recordBytes[v] = isRecord ? bytes : -bytes;  // negative: a fixed-size variable of |bytes|
    if (isRecord) recordSize += std::ceil(bytes / 4) * 4;
  }
  double end = 0;
  for (int v = 0; v < numVariables; ++v) {
    if (recordBytes[v] < 0)
      end = std::max(end, begins[v] - recordBytes[v]);
    else if (records > 0)
      end = std::max(end, begins[v] + (records - 1) * recordSize + recordBytes[v]);
  }
  return end;
}

std::string netcdfProblem(const std::string& path, Signature signature, std::uintmax_t fileSize) {
  int ncid = -1;
  const int status = nc_open(path.c_str(), NC_NOWRITE, &ncid);
  if (status != NC_NOERR) {
    const std::string library = nc_strerror(status);
    return std::string("it is ") + (signature == Signature::kHdf5 ? "an HDF5" : "a netCDF classic") +
           " file that netCDF cannot open, probably truncated or damaged: " + library;
  }
  std::string problem;
  int dimension = -1;
  int versionType = 0;
  if (nc_inq_dimid(ncid, "num_dim", &dimension) != NC_NOERR) {
    problem = "it is a netCDF file without Exodus' 'num_dim' dimension";
  } else if (nc_inq_atttype(ncid, NC_GLOBAL, "version", &versionType) != NC_NOERR) {
    problem = "it has no Exodus 'version' attribute: a truncated header, or not written by an Exodus library";
  } else if (signature == Signature::kClassic) {
    const double needed = classicFileBytes(ncid, path);
    if (static_cast<double>(fileSize) < needed)
      problem = "it is truncated: " + std::to_string(fileSize) + " bytes, but its header describes " +
                std::to_string(static_cast<unsigned long long>(needed));
  }
  nc_close(ncid);
  return problem;
}

}  // namespace

std::string exodusFileProblem(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return "it does not exist";
  if (fs::is_directory(status)) return "it is a directory";
  if (!fs::is_regular_file(status)) return "it is not a regular file";
  const std::uintmax_t size = fs::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::string("it cannot be opened for reading: ") + std::strerror(errno);
  if (size == 0) return "it is empty";
  std::string head(8, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const Signature signature = signatureOf(head);
  if (signature == Signature::kOther)
    return "it is neither netCDF nor HDF5: Exodus II files start with 'CDF' or '\\x89HDF'";
  return netcdfProblem(path, signature, size);
}

}  // namespace contessa::mesh
