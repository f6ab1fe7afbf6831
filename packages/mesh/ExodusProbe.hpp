#pragma once
// Why a file cannot be read as Exodus II, found before the Exodus library opens it: on a damaged
// HDF5 file ex_open prints a misleading "does not support netcdf-4" to stderr, and its own error
// says only "failed to open". Usable by any Exodus reader (mesh, results).
#include <string>

namespace contessa::mesh {

/// "" when `path` opens as netCDF and has Exodus' dimensions; otherwise the reason, for a message
/// "<path>: not a readable Exodus file (<reason>)": "it does not exist", "it is a directory", "it is
/// empty", "it is neither netCDF nor HDF5 ...", "it is truncated ...", "it is a netCDF file without
/// Exodus' 'num_dim' dimension", or the netCDF library's error. Prints nothing.
std::string exodusFileProblem(const std::string& path);

}  // namespace contessa::mesh
