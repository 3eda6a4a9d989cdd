#include "pds/io/point_file.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pds/error.h"
#include "pds/samplers/random.h"

namespace pds {
namespace {

namespace fs = std::filesystem;

class PointFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pds_io_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write_text(const std::string& name, const std::string& text) const { std::ofstream(path(name)) << text; }

  fs::path dir_;
};

// A version 1.0 NPY preamble and header for the given dictionary text.
std::string npy_preamble(const std::string& dict) {
  std::string header = dict;
  header.append((10 + header.size() + 1 + 63) / 64 * 64 - 10 - header.size() - 1, ' ');
  header += '\n';
  return std::string("\x93NUMPY\x01\x00", 8) + char(header.size() & 0xff) + char(header.size() >> 8) + header;
}

PointCloud awkward_cloud(int dim) {
  // Values whose shortest decimal forms are long, tiny, huge or negative.
  PointCloud cloud = dim == 2 ? PointCloud::from<2>(white_noise<2>({500}, Domain<2>::unit(), 3))
                              : PointCloud::from<3>(white_noise<3>({500}, Domain<3>::unit(), 3));
  cloud.coords[0] = 0.1;
  cloud.coords[1] = 1.0 / 3.0;
  cloud.coords[2] = -4.9406564584124654e-324;  // smallest subnormal
  cloud.coords[3] = 1.7976931348623157e308;
  cloud.coords[4] = std::nextafter(1.0, 0.0);
  return cloud;
}

TEST_F(PointFiles, CsvRoundTripIsBitExact) {
  for (int dim : {2, 3}) {
    const PointCloud cloud = awkward_cloud(dim);
    write_points(path("p.csv"), cloud);
    const PointCloud back = read_points(path("p.csv"));
    ASSERT_EQ(back.dim, dim);
    ASSERT_EQ(back.coords.size(), cloud.coords.size());
    EXPECT_EQ(std::memcmp(back.coords.data(), cloud.coords.data(), cloud.coords.size() * sizeof(double)), 0);
  }
  std::ifstream in(path("p.csv"));
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "x,y,z");
}

TEST_F(PointFiles, NpyRoundTripIsBitExactInBothTypes) {
  for (int dim : {2, 3}) {
    const PointCloud cloud = awkward_cloud(dim);
    write_points(path("p.npy"), cloud, NpyType::Float64);
    EXPECT_EQ(read_points(path("p.npy")), cloud);
    // float32: a round trip of the rounded values is exact.
    PointCloud rounded = cloud;
    rounded.coords[3] = 1.0;  // beyond float range
    for (double& v : rounded.coords) v = static_cast<float>(v);
    write_points(path("f.npy"), rounded, NpyType::Float32);
    EXPECT_EQ(read_points(path("f.npy")), rounded);
    EXPECT_EQ(fs::file_size(path("f.npy")), 128 + rounded.coords.size() * 4);
  }
}

TEST_F(PointFiles, NpyHeaderIsWhatNumpyWrites) {
  write_points(path("p.npy"), PointCloud{2, {0.25, 0.5, 0.75, 1.0}});
  std::ifstream in(path("p.npy"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header_len = static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8;
  EXPECT_EQ((10 + header_len) % 64, 0u);
  EXPECT_NE(bytes.find("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }"), std::string::npos);
  EXPECT_EQ(bytes.size(), 10 + header_len + 4 * 8);
}

TEST_F(PointFiles, NpyReadsFortranOrderAndBigEndian) {
  auto npy = [&](const std::string& descr, bool fortran, const std::string& payload) {
    std::istringstream is(npy_preamble("{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                                       ", 'shape': (2, 2), }") +
                          payload);
    return read_npy(is, "test.npy");
  };
  const double c_order[] = {1, 2, 3, 4};  // rows (1,2), (3,4)
  const double f_order[] = {1, 3, 2, 4};
  EXPECT_EQ(npy("<f8", false, std::string(reinterpret_cast<const char*>(c_order), 32)).coords,
            (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(npy("<f8", true, std::string(reinterpret_cast<const char*>(f_order), 32)).coords,
            (std::vector<double>{1, 2, 3, 4}));
  std::string big(reinterpret_cast<const char*>(c_order), 32);
  for (int i = 0; i < 4; ++i) std::reverse(big.begin() + 8 * i, big.begin() + 8 * i + 8);
  EXPECT_EQ(npy(">f8", false, big).coords, (std::vector<double>{1, 2, 3, 4}));
}

void expect_error(const std::string& file, const std::string& fragment) {
  try {
    read_points(file);
    ADD_FAILURE() << file << ": no error, expected one mentioning '" << fragment << "'";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
}

TEST_F(PointFiles, MalformedCsvNamesTheFileAndLine) {
  write_text("bad_number.csv", "x,y\n0.1,0.2\n0.3,zebra\n");
  expect_error(path("bad_number.csv"), "bad_number.csv:3");
  write_text("ragged.csv", "x,y\n0.1,0.2\n0.3,0.4,0.5\n");
  expect_error(path("ragged.csv"), "ragged.csv:3: expected 2 values, found 3");
  write_text("nan.csv", "x,y\n0.1,nan\n");
  expect_error(path("nan.csv"), "nan.csv:2: non-finite");
  write_text("empty.csv", "");
  expect_error(path("empty.csv"), "empty file");
  write_text("trailing.csv", "x,y\n0.1,0.2x\n");
  expect_error(path("trailing.csv"), "trailing.csv:2");
  expect_error(path("missing.csv"), "cannot open");
  expect_error(path("points.txt"), "unknown point file extension");
}

TEST_F(PointFiles, AnyWidthFromOneColumnToThousands) {
  write_text("dim1.csv", "x\n0.5\n0.25\n");
  const PointCloud line = read_points(path("dim1.csv"));
  EXPECT_EQ(line.dim, 1);
  EXPECT_EQ(line.coords, (std::vector<double>{0.5, 0.25}));
  PointCloud wide{3000, std::vector<double>(2 * 3000)};
  for (std::size_t i = 0; i < wide.coords.size(); ++i) wide.coords[i] = static_cast<double>(i % 997) / 997.0;
  for (const char* name : {"wide.csv", "wide.npy"}) {
    write_points(path(name), wide);
    EXPECT_EQ(read_points(path(name)), wide) << name;
  }
}

TEST_F(PointFiles, CsvAcceptsCommentsNoHeaderAndCrlf) {
  write_text("loose.csv", "# written by numpy.savetxt\r\n0.5, 0.25\r\n\r\n+1e-3,7\r\n");
  EXPECT_EQ(read_points(path("loose.csv")), (PointCloud{2, {0.5, 0.25, 1e-3, 7}}));
  write_text("header_only.csv", "x,y,z\n");
  EXPECT_EQ(read_points(path("header_only.csv")), (PointCloud{3, {}}));
}

TEST_F(PointFiles, MalformedNpyIsRejected) {
  write_text("magic.npy", "not numpy at all");
  expect_error(path("magic.npy"), "bad magic");
  write_points(path("short.npy"), PointCloud{2, {0.25, 0.5, 0.75, 1.0}});
  fs::resize_file(path("short.npy"), fs::file_size(path("short.npy")) - 3);
  expect_error(path("short.npy"), "truncated");
  // An int array and a huge shape.
  write_text("int.npy", npy_preamble("{'descr': '<i8', 'fortran_order': False, 'shape': (2, 2), }"));
  expect_error(path("int.npy"), "dtype '<i8' is not supported");
  write_text("huge.npy", npy_preamble("{'descr': '<f8', 'fortran_order': False, 'shape': (999999999999, 2), }"));
  expect_error(path("huge.npy"), "is too large");
  // More digits than 64 bits hold (found by the read_npy fuzz target: stoull threw out_of_range).
  write_text("overflow.npy",
             npy_preamble("{'descr': '<f8', 'fortran_order': False, 'shape': (3333333333333333333333333333334, 2), }"));
  expect_error(path("overflow.npy"), "is too large");
  // A plausible shape with no data behind it is caught before allocating.
  write_text("empty.npy", npy_preamble("{'descr': '<f8', 'fortran_order': False, 'shape': (100000000, 3), }"));
  expect_error(path("empty.npy"), "truncated NPY data");
  write_text("flat.npy", npy_preamble("{'descr': '<f8', 'fortran_order': False, 'shape': (4,), }"));
  expect_error(path("flat.npy"), "is not (N, D)");
}

TEST_F(PointFiles, FailedWriteLeavesNothingBehind) {
  EXPECT_THROW(write_points(path("no_such_dir/p.csv"), PointCloud{2, {0.1, 0.2}}), Failure);
  EXPECT_FALSE(fs::exists(path("no_such_dir")));
  // An existing file is replaced whole, and no temporary remains.
  write_points(path("p.csv"), PointCloud{2, {0.1, 0.2}});
  write_points(path("p.csv"), PointCloud{2, {0.3, 0.4}});
  EXPECT_EQ(read_points(path("p.csv")), (PointCloud{2, {0.3, 0.4}}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace pds
