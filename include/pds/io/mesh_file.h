#pragma once
// Triangle meshes from OBJ, PLY (ASCII or binary) and OFF files, read with
// CGAL's polygon-soup readers (CGAL::IO::read_OBJ/read_PLY/read_OFF). In the
// pds::mesh component (CGAL, header-only); the sampler is in the core
// (pds/samplers/surface.h).
//
// Only the vertex positions and the faces are read (normals, texture
// coordinates, colours and other properties are skipped). A face of more
// than three vertices is split into a fan from its first vertex (exact for
// convex planar faces). Errors (InvalidArgument) name the file: an unknown
// extension, a file CGAL cannot parse, a face of fewer than three vertices,
// a vertex index out of range, a non-finite coordinate, no triangles, zero
// area.

#include <iosfwd>
#include <string>

#include "pds/samplers/surface.h"

namespace pds {

enum class MeshFormat { Obj, Ply, Off };

/// Reads `path`, the format chosen by its extension (.obj, .ply, .off, any
/// letter case).
TriangleMesh read_mesh(const std::string& path);

/// Stream form; `name` is used in error messages. For PLY the stream must be
/// opened in binary mode.
TriangleMesh read_mesh(std::istream& in, MeshFormat format, const std::string& name);

}  // namespace pds
