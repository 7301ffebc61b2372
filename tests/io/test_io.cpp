#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <sstream>

#include "scratch_dir.h"
#include "test_support.h"

using namespace fairsurf;
namespace fs = std::filesystem;

namespace {

class IoTest : public test::ScratchDirTest {
 protected:

  fs::path path(const std::string& name) const { return dir_ / name; }

  fs::path write_file(const std::string& name, const std::string& bytes) const {
    const fs::path p = path(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.insert(e.path().filename().string());
    return names;
  }
};

// Expects `read_mesh(p)` to throw exactly `type` with exactly `message`.
template <typename Exception>
void expect_error(const std::function<void()>& action, const std::string& message) {
  try {
    action();
    ADD_FAILURE() << "no exception; expected: " << message;
  } catch (const Exception& e) {
    EXPECT_EQ(std::string(e.what()), message);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

bool bit_equal(const Vertices& a, const Vertices& b) {
  return a.rows() == b.rows() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

struct FormatCase {
  const char* extension;
  bool binary;
};

const FormatCase kExactFormats[] = {{".obj", false}, {".off", false}, {".ply", false}, {".ply", true}};
const FormatCase kStlFormats[] = {{".stl", false}, {".stl", true}};
const char* kRoundTripMeshes[] = {"spot.obj", "fairing_cross.off", "moebius_160_10.ply", "cgal_blobby_3cc.off"};

}  // namespace

TEST_F(IoTest, ReadsBundledFilesWithTheirDocumentedCountsAndOrder) {
  ReadReport report;
  const Mesh bunny = read_mesh(test::data_path("stanford_bunny_zipper_res2.ply"), &report);
  EXPECT_EQ(bunny.num_vertices(), 8171);
  EXPECT_EQ(bunny.num_faces(), 16301);
  ASSERT_EQ(bunny.vertex_scalars.size(), 2u);
  EXPECT_EQ(bunny.vertex_scalars.at("confidence")(0), static_cast<double>(0.850855f));
  EXPECT_EQ(bunny.vertex_scalars.at("intensity")(1), 0.5);
  EXPECT_EQ(bunny.V(1, 0), static_cast<double>(-0.0453607f));  // float32 property, read as float

  const Mesh moebius = read_mesh(test::data_path("moebius_160_10.ply"));
  EXPECT_EQ(moebius.num_vertices(), 1600);
  EXPECT_EQ(moebius.num_faces(), 2880);

  const Mesh cross = read_mesh(test::data_path("fairing_cross.off"));
  EXPECT_EQ(cross.num_vertices(), 4983);
  EXPECT_EQ(cross.num_faces(), 9762);
  EXPECT_EQ(cross.V(1, 1), 1.16601562);  // second vertex line of the file
  EXPECT_EQ(cross.V(2, 0), 0.884747684);

  ReadReport spot_report;
  const Mesh spot = read_mesh(test::data_path("spot.obj"), &spot_report);
  EXPECT_EQ(spot.num_vertices(), 2930);
  EXPECT_EQ(spot.num_faces(), 5856);
  EXPECT_EQ(spot.V(0, 0), 0.348799);
  EXPECT_EQ(spot.V(18, 2), 0.951731);
  EXPECT_EQ(spot_report.polygons_triangulated, 0);
  EXPECT_TRUE(spot_report.notes.empty());  // its vt lines and v/vt corners are read, not ignored
  EXPECT_EQ(spot.TC.rows(), 3225);
  EXPECT_EQ(spot.FTC.rows(), spot.num_faces());
  EXPECT_EQ(spot.FN.rows(), 0);
}

TEST_F(IoTest, ExactFormatsRoundTripBitExactly) {
  for (const char* name : kRoundTripMeshes) {
    const Mesh original = read_mesh(test::data_path(name));
    for (const auto& format : kExactFormats) {
      SCOPED_TRACE(std::string(name) + " -> " + format.extension + (format.binary ? " binary" : " ascii"));
      const fs::path out = path(std::string("copy") + format.extension);
      write_mesh(out, original, {format.binary});
      const Mesh back = read_mesh(out);
      EXPECT_TRUE(bit_equal(back.V, original.V));
      EXPECT_EQ(back.F, original.F);
    }
  }
}

TEST_F(IoTest, NonFiniteCoordinatesAreValuesAndRoundTrip) {
  const fs::path in = write_file("nan.obj", "v nan inf -inf\nv 1e308 -0 +2.5\nv 0 0 1\nf 1 2 3\n");
  const Mesh m = read_mesh(in);
  EXPECT_TRUE(std::isnan(m.V(0, 0)));
  EXPECT_EQ(m.V(0, 1), std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.V(0, 2), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::signbit(m.V(1, 1)));
  EXPECT_EQ(m.V(1, 2), 2.5);
  for (const auto& format : kExactFormats) {
    const fs::path out = path(std::string("nan_copy") + format.extension);
    write_mesh(out, m, {format.binary});
    EXPECT_TRUE(bit_equal(read_mesh(out).V, m.V)) << format.extension;
  }
}

TEST_F(IoTest, StlRoundTripIsExactForFloatInputAndWeldsCorners) {
  Mesh original = read_mesh(test::data_path("spot.obj"));
  original.V = original.V.cast<float>().cast<double>();
  for (const auto& format : kStlFormats) {
    SCOPED_TRACE(format.binary ? "binary" : "ascii");
    const fs::path out = path("spot.stl");
    write_mesh(out, original, {format.binary});
    ReadReport report;
    const Mesh back = read_mesh(out, &report);
    ASSERT_EQ(back.num_faces(), original.num_faces());
    EXPECT_EQ(back.num_vertices(), original.num_vertices());  // spot has no duplicate positions
    for (int f = 0; f < back.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) ASSERT_EQ(back.V.row(back.F(f, k)), original.V.row(original.F(f, k)));
    // Welded vertices are numbered in order of first occurrence.
    EXPECT_EQ(back.F(0, 0), 0);
    EXPECT_EQ(back.F(0, 1), 1);
    EXPECT_EQ(back.F(0, 2), 2);
    ASSERT_EQ(report.notes.size(), 1u);
    EXPECT_EQ(report.notes[0], "welded 17568 STL corners into 2930 vertices by exact coordinate equality");
  }
}

TEST_F(IoTest, StlWeldsExactlyEqualCornersOnly) {
  const std::string facet =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  const std::string second =
      "facet normal 0 0 1\n outer loop\n  vertex 1 0 0\n  vertex 1 1 0\n  vertex 0 1.0000001 0\n endloop\nendfacet\n";
  const Mesh m = read_mesh(write_file("two.stl", "solid t\n" + facet + second + "endsolid t\n"));
  EXPECT_EQ(m.num_vertices(), 5);  // (1,0,0) is shared; (0,1.0000001,0) is a different float
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(1, 3, 4));
}

TEST_F(IoTest, BinaryStlStartingWithSolidIsReadAsBinary) {
  const fs::path out = path("tet.stl");
  write_mesh(out, test::tetrahedron());
  std::string bytes = test::read_bytes(out);
  bytes.replace(0, 5, "solid");
  const Mesh m = read_mesh(write_file("solid_header.stl", bytes));
  EXPECT_EQ(m.num_faces(), 4);
  EXPECT_EQ(m.num_vertices(), 4);
}

TEST_F(IoTest, PlyScalarsAndColoursRoundTrip) {
  Mesh m = read_mesh(test::data_path("stanford_bunny_zipper_res2.ply"));
  m.vertex_colors.resize(m.num_vertices(), 3);
  for (int v = 0; v < m.num_vertices(); ++v)
    m.vertex_colors.row(v) << static_cast<std::uint8_t>(v % 256), static_cast<std::uint8_t>(v / 256 % 256), 7;
  m.vertex_scalars["H"] = Eigen::VectorXd::LinSpaced(m.num_vertices(), -1.0 / 3.0, 2.0 / 7.0);
  for (const bool binary : {false, true}) {
    const fs::path out = path(binary ? "b.ply" : "a.ply");
    write_mesh(out, m, {binary});
    const Mesh back = read_mesh(out);
    EXPECT_TRUE(bit_equal(back.V, m.V));
    EXPECT_EQ(back.F, m.F);
    EXPECT_EQ(back.vertex_colors, m.vertex_colors);
    ASSERT_EQ(back.vertex_scalars.size(), 3u);
    for (const auto& [name, values] : m.vertex_scalars) EXPECT_EQ(back.vertex_scalars.at(name), values) << name;
  }
}

TEST_F(IoTest, BigEndianPlyWithOtherTypesAndSkippedElements) {
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\ncomment made by hand\n"
      "element vertex 3\nproperty short x\nproperty float y\nproperty int z\nproperty list uchar int tags\n"
      "element face 1\nproperty uchar flags\nproperty list ushort uint vertex_index\n"
      "element edge 1\nproperty int a\nproperty int b\nend_header\n";
  const auto put = [&](auto value) {
    unsigned char b[sizeof(value)];
    std::memcpy(b, &value, sizeof(value));
    for (std::size_t i = sizeof(value); i-- > 0;) bytes += static_cast<char>(b[i]);  // host is little-endian
  };
  for (int v = 0; v < 3; ++v) {
    put(static_cast<std::int16_t>(-v));
    put(0.25f * static_cast<float>(v));
    put(static_cast<std::int32_t>(100 + v));
    put(static_cast<std::uint8_t>(1));
    put(static_cast<std::int32_t>(42));
  }
  put(static_cast<std::uint8_t>(9));
  put(static_cast<std::uint16_t>(3));
  for (std::uint32_t i : {2u, 1u, 0u}) put(i);
  put(static_cast<std::int32_t>(0));
  put(static_cast<std::int32_t>(1));
  ReadReport report;
  const Mesh m = read_mesh(write_file("be.ply", bytes), &report);
  ASSERT_EQ(m.num_vertices(), 3);
  EXPECT_EQ(m.V.row(2), Eigen::RowVector3d(-2, 0.5, 102));
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(2, 1, 0));
  EXPECT_TRUE(m.vertex_scalars.empty());
  EXPECT_EQ(report.notes, (std::vector<std::string>{"skipped vertex list property 'tags'",
                                                    "skipped face property 'flags'",
                                                    "skipped element 'edge' (1 records)"}));
}

TEST_F(IoTest, PolygonsAreFannedFromTheirFirstCornerAndCounted) {
  const fs::path obj = write_file("poly.obj",
                                  "# a comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 1 0\n"
                                  "vt 0 0\nvn 0 0 1\ng group\nf 1/1 2/1 3/1 4/1\nf -5//1 -2//1 -1//1\n"
                                  "f 1/1/1 3/1/1 4/1/1 5/1/1 2/1/1\n");
  ReadReport report;
  const Mesh m = read_mesh(obj, &report);
  ASSERT_EQ(m.num_faces(), 2 + 1 + 3);
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(m.F.row(2), Eigen::RowVector3i(0, 3, 4));  // negative indices count back from the last v
  EXPECT_EQ(m.F.row(5), Eigen::RowVector3i(0, 4, 1));
  EXPECT_EQ(report.polygons_triangulated, 2);
  EXPECT_EQ(report.triangles_added, 1 + 2);
  EXPECT_EQ(report.notes, (std::vector<std::string>{
                              "ignored 1 comment lines (first at line 1)",
                              "ignored 1 'g' lines (first at line 9)",
                              "triangulated 2 polygons with more than 3 corners into fans (3 extra triangles)"}));
  // Texture and normal indices follow their corners through the fans; -1 where a corner has none.
  EXPECT_EQ(m.FTC, (Faces(6, 3) << 0, 0, 0, 0, 0, 0, -1, -1, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0).finished());
  EXPECT_EQ(m.FN, (Faces(6, 3) << -1, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0).finished());
  EXPECT_EQ(m.face_polygon, (Eigen::VectorXi(6) << 0, 0, 1, 2, 2, 2).finished());

  const fs::path off = write_file("poly.off", "COFF\n# comment\n4 1 0\n0 0 0 255 0 0\n1 0 0 1 2 3\n1 1 0\n0 1 0\n"
                                              "4 0 1 2 3 0.5 0.5 0.5 1\n");
  const Mesh q = read_mesh(off);
  ASSERT_EQ(q.num_faces(), 2);
  EXPECT_EQ(q.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(q.V.row(1), Eigen::RowVector3d(1, 0, 0));
}

TEST_F(IoTest, PolygonsWithFewerThanThreeCornersAreRefused) {
  RawMesh raw;
  raw.V = test::tetrahedron().V;
  raw.polygon_indices = {0, 1, 2, 0, 1};
  raw.polygon_offsets = {0, 3, 5};
  expect_error<ParseError>([&] { triangulate(raw); }, "triangulate: polygon 1 has 2 corners (at least 3 needed)");
  const fs::path off = write_file("line.off", "OFF\n2 1 0\n0 0 0\n1 0 0\n2 0 1\n");
  EXPECT_EQ(read_raw(off).polygon_offsets, (std::vector<int>{0, 2}));  // read_raw keeps it as stored
  expect_error<ParseError>([&] { read_mesh(off); }, "triangulate: polygon 0 has 2 corners (at least 3 needed)");
}

TEST_F(IoTest, MissingFilesAndUnknownExtensionsAreIoErrors) {
  const fs::path missing = path("missing.obj");
  expect_error<IoError>([&] { read_mesh(missing); },
                        "read_raw: " + missing.string() + ": cannot open (No such file or directory)");
  const fs::path unknown = write_file("mesh.xyz", "v 0 0 0\n");
  expect_error<IoError>([&] { read_mesh(unknown); },
                        "read_raw: " + unknown.string() + ": unknown extension '.xyz' (supported: .obj, .off, .ply, .stl)");
  expect_error<IoError>([&] { write_mesh(path("out.gltf"), test::tetrahedron()); },
                        "write_mesh: " + path("out.gltf").string() +
                            ": unknown extension '.gltf' (supported: .obj, .off, .ply, .stl)");
  EXPECT_NO_THROW(read_mesh(write_file("UPPER.OBJ", "v 0 0 0\n")));  // extensions are case-insensitive
}

TEST_F(IoTest, MalformedContentNamesTheFileAndThePlace) {
  const auto at = [&](const fs::path& p) { return "read_raw: " + p.string() + ": "; };
  const fs::path obj = write_file("bad.obj", "v 0 0 0\nv 1 2 x3\n");
  expect_error<ParseError>([&] { read_mesh(obj); }, at(obj) + "line 2: malformed number 'x3'");
  const fs::path corner = write_file("corner.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2/ 3\n");
  expect_error<ParseError>([&] { read_mesh(corner); }, at(corner) + "line 5: malformed face corner '2/'");
  const fs::path zero = write_file("zero.obj", "v 0 0 0\nf 0 1 1\n");
  expect_error<ParseError>([&] { read_mesh(zero); }, at(zero) + "line 2: vertex index 0 in '0' (OBJ indices start at 1)");
  const fs::path off = write_file("short.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n");
  expect_error<ParseError>([&] { read_mesh(off); }, at(off) + "unexpected end of file after 2 of 4 vertices");
  const fs::path faces = write_file("faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_error<ParseError>([&] { read_mesh(faces); }, at(faces) + "unexpected end of file after 1 of 2 faces");
  const fs::path lying = write_file("lying.off", "OFF\n2000000000 1 0\n0 0 0\n");
  expect_error<ParseError>([&] { read_mesh(lying); }, at(lying) + "unexpected end of file after 1 of 2000000000 vertices");
  const fs::path header = write_file("header.off", "PLY\n");
  expect_error<ParseError>([&] { read_mesh(header); }, at(header) + "line 1: expected an 'OFF' header, found 'PLY'");

  const std::string ply_header = "ply\nformat binary_little_endian 1.0\nelement vertex 2147483647\n"
                                 "property double x\nproperty double y\nproperty double z\nend_header\n";
  const fs::path ply = write_file("huge.ply", ply_header + std::string(30, '\0'));
  expect_error<ParseError>([&] { read_mesh(ply); },
                           at(ply) + "unexpected end of file after 1 of 2147483647 'vertex' elements");
  const fs::path count = write_file("count.ply", "ply\nformat ascii 1.0\nelement vertex 2147483648\nend_header\n");
  expect_error<ParseError>([&] { read_mesh(count); },
                           at(count) + "line 3: malformed element line (expected 'element <name> <count>')");
  const fs::path value = write_file("value.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                                 "property float y\nproperty float z\nproperty uchar red\n"
                                                 "end_header\n0 0\n0 256\n");
  expect_error<ParseError>([&] { read_mesh(value); }, at(value) + "line 10: malformed value '256'");

  const fs::path stl = path("cut.stl");
  write_mesh(stl, test::tetrahedron());
  const std::string bytes = test::read_bytes(stl);
  const fs::path cut = write_file("cut2.stl", bytes.substr(0, 84 + 50 * 2 + 20));
  expect_error<ParseError>([&] { read_mesh(cut); }, at(cut) + "unexpected end of file after 2 of 4 triangles");
  const fs::path text = write_file("text.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\nvertex 0 1 0\n");
  expect_error<ParseError>([&] { read_mesh(text); }, at(text) + "line 6: malformed number 'vertex'");
}

TEST_F(IoTest, TruncatedRealFilesThrowParseErrorsNamingTheFile) {
  std::vector<fs::path> files = {test::data_path("fairing_cross.off"), test::data_path("moebius_160_10.ply"),
                                 test::data_path("stanford_bunny_zipper_res2.ply")};
  const Mesh spot = read_mesh(test::data_path("spot.obj"));
  for (const auto& format : {FormatCase{".stl", true}, FormatCase{".stl", false}, FormatCase{".ply", true}}) {
    files.push_back(path(std::string("spot_") + (format.binary ? "b" : "a") + format.extension));
    write_mesh(files.back(), spot, {format.binary});
  }
  for (const auto& file : files) {
    const std::string bytes = test::read_bytes(file);
    for (const double fraction : {0.0, 0.001, 0.1, 0.37, 0.5, 0.9, 0.999}) {
      const auto size = static_cast<std::size_t>(fraction * static_cast<double>(bytes.size()));
      const fs::path cut = write_file("cut" + file.extension().string(), bytes.substr(0, size));
      SCOPED_TRACE(file.string() + " cut at " + std::to_string(size));
      try {
        read_mesh(cut);
        ADD_FAILURE() << "a truncated file was read without error";
      } catch (const ParseError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("read_raw: " + cut.string() + ": ", 0), 0u) << message;
        EXPECT_TRUE(message.find("unexpected end of file") != std::string::npos ||
                    message.find("line ") != std::string::npos)
            << message;
      }
    }
  }
}

// Random byte flips and truncations of small valid files only ever throw the documented types.
TEST_F(IoTest, MutatedFilesOnlyThrowIoOrParseErrors) {
  Mesh m = test::regular_grid(2, 2, 0.5);
  m.vertex_scalars["k"] = Eigen::VectorXd::LinSpaced(m.num_vertices(), 0, 1);
  m.vertex_colors = Colors::Constant(m.num_vertices(), 3, 200);
  std::vector<std::pair<std::string, std::string>> seeds;  // extension, bytes
  for (const auto& format : {FormatCase{".obj", false}, FormatCase{".off", false}, FormatCase{".ply", false},
                             FormatCase{".ply", true}, FormatCase{".stl", false}, FormatCase{".stl", true}}) {
    const fs::path p = path(std::string("seed") + format.extension);
    write_mesh(p, m, {format.binary});
    seeds.emplace_back(format.extension, test::read_bytes(p));
  }
  std::mt19937 random(12345);
  int parse_errors = 0, successes = 0;
  const int kCases = 420;
  for (int c = 0; c < kCases; ++c) {
    const auto& [extension, original] = seeds[c % seeds.size()];
    std::string bytes = original;
    if (c % 3 == 0) {
      bytes.resize(std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random));
    } else {
      const int flips = 1 + c % 4;
      for (int i = 0; i < flips; ++i) {
        const auto at = std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random);
        bytes[at] = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(random));
      }
    }
    const fs::path p = write_file("mutant" + extension, bytes);
    try {
      const Mesh read = read_mesh(p);
      EXPECT_EQ(read.V.cols(), 3);
      ++successes;
    } catch (const ParseError&) {
      ++parse_errors;
    } catch (const IoError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << c << " (" << extension << "): unexpected exception " << e.what();
    }
  }
  EXPECT_GT(parse_errors, kCases / 4);  // the mutations do reach the parsers' error paths
  EXPECT_GT(successes, 0);
}

TEST_F(IoTest, WritingOntoADirectoryFailsAndLeavesNoTemporaryFile) {
  fs::create_directory(path("target.obj"));
  const auto before = entries();
  try {
    write_mesh(path("target.obj"), test::tetrahedron());
    ADD_FAILURE() << "writing onto a directory succeeded";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("write_mesh: " + path("target.obj").string() + ": rename failed (", 0), 0u)
        << e.what();
  }
  EXPECT_EQ(entries(), before);
  EXPECT_TRUE(fs::is_empty(path("target.obj")));
}

TEST_F(IoTest, AFailedWriteLeavesTheExistingTargetByteIdentical) {
  const fs::path target = path("target.ply");
  write_mesh(target, test::tetrahedron());
  const std::string before = test::read_bytes(target);
  const auto entries_before = entries();

  // Make the write itself fail part-way: a file-size limit smaller than the new file.
  const Mesh big = read_mesh(test::data_path("spot.obj"));
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = saved;
  limited.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  bool threw = false;
  try {
    write_mesh(target, big, {false});
  } catch (const IoError& e) {
    threw = std::string(e.what()).rfind("write_mesh: " + target.string() + ": write failed (", 0) == 0;
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);

  EXPECT_TRUE(threw);
  EXPECT_EQ(test::read_bytes(target), before);
  EXPECT_EQ(entries(), entries_before);
}

TEST_F(IoTest, InvalidMeshesAreRefusedBeforeWriting) {
  Mesh m = test::tetrahedron();
  m.F(3, 2) = 4;
  expect_error<InvalidArgument>([&] { write_mesh(path("t.stl"), m); },
                                "write_mesh: face 3 has vertex index 4 outside [0, 4)");
  m = test::tetrahedron();
  m.vertex_scalars["x"] = Eigen::VectorXd::Zero(4);
  expect_error<InvalidArgument>([&] { write_mesh(path("t.ply"), m); },
                                "write_mesh: vertex scalar name 'x' cannot be a PLY property name");
  EXPECT_TRUE(entries().empty());
}
