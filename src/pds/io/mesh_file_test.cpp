#include "pds/io/mesh_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pds/error.h"

namespace pds {
namespace {

TriangleMesh read_text(const std::string& text, MeshFormat format) {
  std::istringstream in(text, std::ios::binary);
  return read_mesh(in, format, "test");
}

// A unit square as a quad (split into a fan) plus a triangle above it.
const TriangleMesh kExpected{{{{0, 0, 0}}, {{1, 0, 0}}, {{1, 1, 0}}, {{0, 1, 0}}, {{0.5, 0.5, 2}}},
                             {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}};

void expect_mesh(const TriangleMesh& mesh) {
  EXPECT_EQ(mesh.vertices, kExpected.vertices);
  EXPECT_EQ(mesh.triangles, kExpected.triangles);
}

TEST(MeshFile, ReadsObjPlyOff) {
  // OBJ with the v/vt/vn form of faces, a comment, a group and normals.
  expect_mesh(
      read_text("# square\no square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 2\nvn 0 0 1\n"
                "f 1//1 2//1 3//1 4//1\nf 1 2 5\n",
                MeshFormat::Obj));
  expect_mesh(read_text("OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 2\n4 0 1 2 3\n3 0 1 4\n", MeshFormat::Off));
  const std::string ply_header =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  expect_mesh(read_text(ply_header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 2\n4 0 1 2 3\n3 0 1 4\n", MeshFormat::Ply));
  // Binary little-endian PLY with double coordinates.
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
      "property double z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& v : kExpected.vertices)
    for (double x : v) binary.append(reinterpret_cast<const char*>(&x), sizeof x);
  for (const std::vector<std::int32_t>& face :
       {std::vector<std::int32_t>{0, 1, 2, 3}, std::vector<std::int32_t>{0, 1, 4}}) {
    binary.push_back(static_cast<char>(face.size()));
    for (std::int32_t i : face) binary.append(reinterpret_cast<const char*>(&i), sizeof i);
  }
  expect_mesh(read_text(binary, MeshFormat::Ply));
}

TEST(MeshFile, ReadsByExtension) {
  const std::string path = (std::filesystem::temp_directory_path() / "pds_mesh_file_test.OBJ").string();
  {
    std::ofstream out(path);
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 2\nf 1 2 3 4\nf 1 2 5\n";
  }
  expect_mesh(read_mesh(path));
  std::remove(path.c_str());
  EXPECT_THROW(read_mesh(path), InvalidArgument);  // gone
  EXPECT_THROW(read_mesh("mesh.stl"), InvalidArgument);
}

TEST(MeshFile, BadFilesNameTheProblem) {
  auto message = [](const std::string& text, MeshFormat format) {
    try {
      read_text(text, format);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", MeshFormat::Obj), "no error");
  EXPECT_NE(message("", MeshFormat::Obj), "no error");
  EXPECT_NE(message("garbage\x01\x02", MeshFormat::Ply), "no error");
  EXPECT_NE(message("OFF\n3 1 0\n0 0 0\n1 0 0\n", MeshFormat::Off), "no error");
  EXPECT_NE(message("OFF\n4000000000 1 0\n", MeshFormat::Off), "no error");
  // CGAL's PLY header parser would read a property into an element that is
  // not there, or loop over a count the file cannot hold: refused first.
  EXPECT_EQ(message("ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n", MeshFormat::Ply),
            "test: a PLY property is declared before any element");
  // CGAL takes the second line for the format line whatever it says.
  EXPECT_EQ(message("ply\nend_header ascii 0\nproperty float x\nelement vertex 4\nend_header\n", MeshFormat::Ply),
            "test: a PLY property is declared before any element");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement thing 1000000000000\nend_header\n", MeshFormat::Ply),
            "test: the PLY header declares 1000000000000 thing elements in a file of 60 bytes");
  EXPECT_EQ(message(std::string("OFF BINARY\n") + std::string(12, '\xff'), MeshFormat::Off),
            "test: binary OFF is not read (use ASCII OFF, PLY or OBJ)");
  // CGAL drops the character after the keyword, so "OFF#..." is not a
  // comment to it: these made it read 20 faces (of 300,000,000 vertices
  // each) and a binary header (both found by the fuzz target).
  EXPECT_EQ(message("OFF#0 20 0\n0 0 2\n300000000 1\n", MeshFormat::Off),
            "test: the OFF keyword OFF is followed by '#'; put a space between them");
  EXPECT_EQ(message("  COFF#BINARY\n0 0 0\n", MeshFormat::Off),
            "test: the OFF keyword COFF is followed by '#'; put a space between them");
  // CGAL reads texture and colour entries past a short line and casts
  // colours to bytes unchecked: pds hands it positions and faces only.
  EXPECT_EQ(message("STOFF\n# te\xad\n8 4 3\n", MeshFormat::Off), "test: the OFF file ends after 0 of its 8 vertices");
  EXPECT_EQ(message("COFF\n3 1 0\n0 0 0 1e300 0 0\n1 0 0 2.5 9 9\n0 1 0 1 1 1\n3 0 1 2 7.5 -3 0\n", MeshFormat::Off),
            "no error");
  EXPECT_EQ(message("OFF # a comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Off), "no error");
  EXPECT_EQ(message("ply\nformat ascii 1.0\nelement vertex 1\nproperty uint32 x\nend_header\n0\n", MeshFormat::Ply),
            "test: the PLY vertex coordinate x has type uint32 (float or double are read)");
  EXPECT_EQ(
      message("ply\nformat ascii 1.0\nelement halfedge 1\nproperty float source\nend_header\n0\n", MeshFormat::Ply),
      "test: PLY halfedge elements are not read");
  // CGAL would reserve memory for the declared counts: refused first.
  EXPECT_EQ(message("OFF\n300000000 300000000 0\n", MeshFormat::Off),
            "test: the OFF header declares 300000000 vertices in a file of 26 bytes");
  EXPECT_EQ(message("# a comment\nOFF 3 90000 0\n0 0 0\n1 0 0\n0 1 0\n", MeshFormat::Off),
            "test: the OFF header declares 90000 faces in a file of 44 bytes");
  EXPECT_NE(message("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty "
                    "float y\nproperty float z\nend_header\n",
                    MeshFormat::Ply),
            "no error");
  EXPECT_NE(message("v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::Obj), "no error");
  EXPECT_EQ(message("v 0 0 0\nv 1 0 0\nf 1 2\n", MeshFormat::Obj), "test: face 0 has 2 vertices (at least 3)");
  EXPECT_EQ(message("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", MeshFormat::Obj),
            "test: mesh: the surface has area 0; it must be positive and finite");
  // CGAL's readers refuse indices out of range themselves (read_mesh checks
  // again).
  EXPECT_NE(message("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", MeshFormat::Off), "no error");
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n", MeshFormat::Obj), "no error");
}

}  // namespace
}  // namespace pds
