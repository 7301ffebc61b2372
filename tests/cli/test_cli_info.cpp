// End-to-end tests of `fairsurf info`: the built CLI is run on bundled and broken files.
#include <fairsurf/io/io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hole_meshes.h"
#include "scratch_dir.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CliInfo : public fairsurf::test::ScratchDirTest {
 protected:

  CliRun run(const std::string& args) const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    std::string command = quoted(fairsurf::test::cli_path());
    command.append(" ").append(args).append(" >").append(quoted(out.string()));
    command.append(" 2>").append(quoted(err.string()));
    const int raw = std::system(command.c_str());
    CliRun r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  static std::string quoted(const std::string& path) {
    return std::string("'").append(path).append("'");
  }
};

}  // namespace

TEST_F(CliInfo, JsonOfANonManifoldScanHasEveryKeyAndTheDocumentedCounts) {
  const CliRun r = run("info --json " + quoted(fairsurf::test::data_path("stanford_bunny_zipper_res2.ply")));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"vertices", "faces", "edges", "boundary_loops", "lone_triangles", "components", "euler_characteristic", "genus",
        "bounding_box", "mean_edge_length", "manifold", "degenerate_faces", "duplicate_faces",
        "unreferenced_vertices", "non_manifold_edges", "non_manifold_vertices",
        "inconsistent_orientation_edges", "orientable", "nan_vertices", "out_of_range_indices",
        "read_notes"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["vertices"], 8171);
  EXPECT_EQ(j["faces"], 16301);
  EXPECT_EQ(j["non_manifold_edges"], 150);
  EXPECT_EQ(j["duplicate_faces"], 87);
  EXPECT_EQ(j["unreferenced_vertices"], 25);
  EXPECT_EQ(j["manifold"], false);
  EXPECT_TRUE(j["genus"].is_null());
  EXPECT_EQ(j["examples"]["non_manifold_edges"].size(), 5u);
  EXPECT_EQ(j["examples"]["non_manifold_edges"][0].size(), 2u);
}

TEST_F(CliInfo, JsonOfAnOpenManifoldMesh) {
  const CliRun r = run("info --json " + quoted(fairsurf::test::data_path("hemisphere.off")));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"], 1861);
  EXPECT_EQ(j["faces"], 3600);
  EXPECT_EQ(j["boundary_loops"], nlohmann::json::array({120}));
  EXPECT_EQ(j["lone_triangles"], 0);
  EXPECT_EQ(j["components"], 1);
  EXPECT_EQ(j["euler_characteristic"], 1);
  EXPECT_EQ(j["genus"], 0);
  EXPECT_EQ(j["manifold"], true);
  EXPECT_EQ(j["orientable"], true);
  EXPECT_EQ(j["valid"], true);
  // V - E + F = 1 for a disk.
  EXPECT_EQ(j["vertices"].get<int>() - j["edges"].get<int>() + j["faces"].get<int>(), 1);
  const auto& box = j["bounding_box"];
  for (int k = 0; k < 3; ++k) EXPECT_LT(box["min"][k].get<double>(), box["max"][k].get<double>());
  EXPECT_GT(j["mean_edge_length"].get<double>(), 0.0);
}

TEST_F(CliInfo, TextListsEveryFindingWithExamples) {
  const CliRun r = run("info " + quoted(fairsurf::test::data_path("lagrange_prout.obj")));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("findings: 4\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  20 non-manifold edges (first: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  4 non-manifold vertices (first: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  5 duplicate faces (first: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  18 inconsistently oriented edges (first: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("genus: undefined (non-manifold)\n"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

// A ball hole in a sphere with a lone triangle hanging at a vertex of its border
// (test::sphere_hole_with_lone_triangle): text and JSON count the one triangle; a mesh without any
// prints no such line.
TEST_F(CliInfo, LoneTrianglesAreCounted) {
  const std::string debris = (dir_ / "debris.obj").string();
  fairsurf::write_mesh(debris, fairsurf::test::sphere_hole_with_lone_triangle());
  const CliRun text = run("info " + quoted(debris));
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("\nlone triangles: 1 (every edge on the border: fill takes one hanging at a hole's "
                          "border into that hole's patch where it can, and never fills one's loop alone)\n"),
            std::string::npos)
      << text.out;
  const CliRun json = run("info --json " + quoted(debris));
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["lone_triangles"], 1);
  const CliRun closed = run("info " + quoted(fairsurf::test::data_path("torus.obj")));
  ASSERT_EQ(closed.status, 0) << closed.err;
  EXPECT_EQ(closed.out.find("lone triangles"), std::string::npos) << closed.out;
}

TEST_F(CliInfo, StrictExitsWithThreeOnAnyFindingAndZeroOnACleanMesh) {
  const CliRun bad = run("info --strict " + quoted(fairsurf::test::data_path("hourglass_ico.obj")));
  EXPECT_EQ(bad.status, 3);
  EXPECT_NE(bad.out.find("1 non-manifold vertex (first: "), std::string::npos) << bad.out;
  EXPECT_EQ(bad.err, "fairsurf: error: info: " + fairsurf::test::data_path("hourglass_ico.obj") +
                         " has 1 kind of finding (--strict)\n");
  const CliRun clean = run("info --strict " + quoted(fairsurf::test::data_path("spot.obj")));
  EXPECT_EQ(clean.status, 0) << clean.err;
  EXPECT_NE(clean.out.find("findings: none\n"), std::string::npos) << clean.out;
}

TEST_F(CliInfo, MissingFileIsAnInputError) {
  const std::string missing = (dir_ / "no_such_mesh.obj").string();
  const CliRun r = run("info " + quoted(missing));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "fairsurf: error: read_raw: " + missing + ": cannot open (No such file or directory)\n");
  EXPECT_TRUE(r.out.empty());
}

TEST_F(CliInfo, TruncatedFileIsAnInputError) {
  // The first 40% of a real OFF file: the header promises more vertices than remain.
  const std::string full = slurp(fairsurf::test::data_path("hemisphere.off"));
  const fs::path truncated = dir_ / "truncated.off";
  std::ofstream(truncated) << full.substr(0, full.size() * 2 / 5);
  const CliRun r = run("info " + quoted(truncated.string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("fairsurf: error: read_raw: " + truncated.string() + ": ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_TRUE(r.out.empty());
}
