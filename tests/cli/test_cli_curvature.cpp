// `fairsurf curvature`: PLY output with H, K, k1, k2 and sphere values, --flip-sign, --json
// statistics, ill-posed vertices counted, and the refusal to overwrite the input.
#include <fairsurf/io/io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "analytic_meshes.h"
#include "scratch_dir.h"
#include "test_support.h"

using namespace fairsurf;
namespace fs = std::filesystem;
using test::run_cli;

namespace {

class CliCurvature : public test::ScratchDirTest {
 protected:
  // Writes an icosphere of radius R (outward normals) and returns its path.
  fs::path sphere(double R) {
    const fs::path path = dir_ / "sphere.off";
    write_mesh(path, test::icosphere(4, R));
    return path;
  }
};

}  // namespace

TEST_F(CliCurvature, WritesSphereCurvaturesAsPlyProperties) {
  const double R = 2.0;
  const fs::path in = sphere(R), out = dir_ / "curv.ply";
  const auto run = run_cli("curvature '" + in.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("2562 vertices, 2562 with a well-posed fit, 0 ill-posed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("sign: H < 0 on a sphere with outward normals"), std::string::npos) << run.out;
  const Mesh m = read_mesh(out);
  ASSERT_EQ(m.num_vertices(), 2562);
  for (const char* q : {"H", "K", "k1", "k2", "fit_status"}) ASSERT_TRUE(m.vertex_scalars.count(q)) << q;
  for (int i = 0; i < m.num_vertices(); ++i) {
    ASSERT_NEAR(m.vertex_scalars.at("H")[i], -1.0 / R, 2e-3);
    ASSERT_NEAR(m.vertex_scalars.at("K")[i], 1.0 / (R * R), 2e-3);
    ASSERT_GE(m.vertex_scalars.at("k1")[i], m.vertex_scalars.at("k2")[i]);
    ASSERT_EQ(m.vertex_scalars.at("fit_status")[i], 0.0);
  }
}

TEST_F(CliCurvature, FlipSignFlipsHAndThePrincipalCurvaturesAndSaysSo) {
  const fs::path in = sphere(1.0), plain = dir_ / "plain.ply", flipped = dir_ / "flipped.ply";
  ASSERT_EQ(run_cli("curvature '" + in.string() + "' -o '" + plain.string() + "'").exit_code, 0);
  const auto run = run_cli("curvature '" + in.string() + "' -o '" + flipped.string() + "' --flip-sign");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("sign: flipped (--flip-sign): H > 0"), std::string::npos) << run.out;
  const Mesh a = read_mesh(plain), b = read_mesh(flipped);
  const auto& s = a.vertex_scalars;
  const auto& t = b.vertex_scalars;
  EXPECT_EQ((s.at("H") + t.at("H")).norm(), 0.0);
  EXPECT_EQ((s.at("K") - t.at("K")).norm(), 0.0);
  EXPECT_EQ((s.at("k1") + t.at("k2")).norm(), 0.0);  // k1 stays the larger one
  EXPECT_EQ((s.at("k2") + t.at("k1")).norm(), 0.0);
  EXPECT_GT(t.at("H").minCoeff(), 0.99);
}

TEST_F(CliCurvature, JsonStatisticsAndIllPosedCounts) {
  // A tetrahedron joined to a sphere's file: its four vertices have too few neighbours.
  Mesh m = test::icosphere(3, 1.0);
  const int base = m.num_vertices();
  m.V.conservativeResize(base + 4, 3);
  m.V.bottomRows(4) << 5, 0, 0, 6, 0, 0, 5, 1, 0, 5, 0, 1;
  m.F.conservativeResize(m.num_faces() + 4, 3);
  m.F.bottomRows(4) << base, base + 2, base + 1, base, base + 1, base + 3, base, base + 3, base + 2,
      base + 1, base + 2, base + 3;
  const fs::path in = dir_ / "two.obj", out = dir_ / "two.ply";
  write_mesh(in, m);
  const auto run = run_cli("curvature '" + in.string() + "' -o '" + out.string() + "' --json");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const auto j = nlohmann::json::parse(run.out);
  EXPECT_EQ(j["vertices"], base + 4);
  EXPECT_EQ(j["ill_posed"], 4);
  EXPECT_EQ(j["fit_status"]["too_few_neighbours"], 4);
  EXPECT_EQ(j["flip_sign"], false);
  // Statistics cover the well-posed (sphere) vertices only (k1 − k2 = 2√(H² − K) amplifies the
  // fit error, so the principal curvatures are only checked loosely).
  EXPECT_NEAR(j["statistics"]["H"]["min"].get<double>(), -1.0, 1e-2);
  EXPECT_NEAR(j["statistics"]["H"]["max"].get<double>(), -1.0, 1e-2);
  EXPECT_NEAR(j["statistics"]["k1"]["max"].get<double>(), -1.0, 0.1);
  EXPECT_NEAR(j["statistics"]["k2"]["min"].get<double>(), -1.0, 0.1);
  EXPECT_NEAR(j["statistics"]["K"]["p50"].get<double>(), 1.0, 2e-2);  // 642 vertices: K error ≈ 1.3e-2
  EXPECT_LE(j["statistics"]["H"]["p5"].get<double>(), j["statistics"]["H"]["p50"].get<double>());
  EXPECT_LE(j["statistics"]["H"]["p50"].get<double>(), j["statistics"]["H"]["p95"].get<double>());
}

TEST_F(CliCurvature, RefusesToOverwriteTheInputWithoutForce) {
  const fs::path in = dir_ / "in.ply";
  write_mesh(in, test::icosphere(2, 1.0));
  const auto refused = run_cli("curvature '" + in.string() + "' -o '" + in.string() + "'");
  EXPECT_EQ(refused.exit_code, 5);
  EXPECT_EQ(refused.out, "fairsurf: error: curvature: -o would overwrite the input '" + in.string() +
                             "' (pass --force to allow it)\n");
  EXPECT_FALSE(read_mesh(in).vertex_scalars.count("H"));
  const auto forced = run_cli("curvature '" + in.string() + "' -o '" + in.string() + "' --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.out;
  EXPECT_TRUE(read_mesh(in).vertex_scalars.count("H"));
}

TEST_F(CliCurvature, NonPlyOutputAndMissingInputAreRefused) {
  const auto wrong = run_cli("curvature '" + sphere(1.0).string() + "' -o '" + (dir_ / "x.obj").string() + "'");
  EXPECT_EQ(wrong.exit_code, 1);
  EXPECT_NE(wrong.out.find("fairsurf: error: curvature: the output must be a .ply file"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "x.obj"));
  const auto missing = run_cli("curvature '" + (dir_ / "none.obj").string() + "' -o '" + (dir_ / "y.ply").string() + "'");
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
}

TEST_F(CliCurvature, AMeshWithoutWellPosedFitsIsReportedWithoutStatistics) {
  // cube_soup.obj: 12 unwelded triangles, every vertex has two neighbours.
  const fs::path out = dir_ / "soup.ply";
  const auto run = run_cli("curvature '" + test::data_path("cube_soup.obj") + "' -o '" + out.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("24 vertices, 0 with a well-posed fit, 24 ill-posed (24 too few neighbours)"),
            std::string::npos) << run.out;
  EXPECT_NE(run.out.find("no vertex has a well-posed fit: no statistics"), std::string::npos) << run.out;
  const auto json = run_cli("curvature '" + test::data_path("cube_soup.obj") + "' -o '" + out.string() + "' --json");
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_TRUE(j["statistics"].empty());
  EXPECT_EQ(read_mesh(out).vertex_scalars.at("fit_status").minCoeff(), 2.0);  // kTooFewNeighbours
}
