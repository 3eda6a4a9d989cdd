#pragma once
// Point files: CSV and NumPy .npy, read and written, the format chosen by the
// file's extension. "-" is standard input/output, as CSV.
//
// CSV: a header naming the coordinates (`x,y` or `x,y,z`), then one point a
// line, each number written in the shortest form that reads back to the same
// double (so a round trip is bit-exact). Reading accepts any header names,
// `#` comment lines (as numpy.savetxt writes) and a file without a header.
//
// NPY: format 1.0 (2.0/3.0 read too), a C-ordered (N, D) array of
// little-endian float64 ('<f8', the default) or float32 ('<f4'); Fortran
// order and big-endian arrays are read too. Writing float32 rounds each
// coordinate to the nearest float, which can move two points at the minimum
// distance a little closer; GenerateRequest::float32 (pds/float32.h) makes a
// set whose float32 values keep it.
//
// PLY (written only): binary little-endian PLY 1.0, one `vertex` element a
// point with a `double` property a coordinate (x, y, z, ...), or the named
// columns of write_table (an integer column as `int`). MeshLab, CloudCompare,
// Blender and Open3D read it as a point cloud.
//
// Errors name the file and, for CSV, the line. Writing goes to a temporary
// file beside the target that is renamed over it only when complete, so a
// failure never leaves a half-written file.

#include <iosfwd>
#include <string>
#include <vector>

#include "pds/point.h"

namespace pds {

enum class NpyType { Float64, Float32 };

/// Reads a .csv or .npy file, or CSV from standard input for "-".
PointCloud read_points(const std::string& path);

/// Writes a .csv, .npy or .ply file (atomically), or CSV to standard output
/// for "-". `npy_type` applies to .npy only.
void write_points(const std::string& path, const PointCloud& points, NpyType npy_type = NpyType::Float64);

/// A column of a table of points: its name (the CSV header, the PLY
/// property) and whether it holds integers (a PLY `int`; CSV writes them
/// without a decimal point, NPY as float64 like every column).
struct Column {
  std::string name;
  bool integer = false;
};

/// write_points with named columns, one a value of a row (`table.dim` of
/// them); integer columns must hold integers in [-2^31, 2^31).
void write_table(const std::string& path, const PointCloud& table, const std::vector<Column>& columns,
                 NpyType npy_type = NpyType::Float64);

/// The default columns of write_points: x, y, z, w, then x4, x5, ...
std::vector<Column> coordinate_columns(int dim);

/// The temporary file write_points writes `path` to before renaming it over
/// `path` (beside it, named after this process), so that a caller that stops
/// the process (the command line on Ctrl-C) can remove it.
std::string temporary_path(const std::string& path);

/// Stream forms; `name` is used in error messages.
PointCloud read_csv(std::istream& in, const std::string& name);
void write_csv(std::ostream& out, const PointCloud& points);
void write_csv(std::ostream& out, const PointCloud& table, const std::vector<Column>& columns);
void write_ply(std::ostream& out, const PointCloud& table, const std::vector<Column>& columns);
PointCloud read_npy(std::istream& in, const std::string& name);
void write_npy(std::ostream& out, const PointCloud& points, NpyType type = NpyType::Float64);

}  // namespace pds
