// End-to-end tests of the flags' names (issue #15): a flag is named after the option field it sets,
// and docs/cli.md's table says which field each flag of smooth, fill, fair and blend sets. The former
// names --f, --fixed and --mumps-icntl stay as aliases: they must set the same field.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "scratch_dir.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace fairsurf;

namespace {

class CliFlagNames : public test::ScratchDirTest {
 protected:
  static std::string quoted(const std::string& s) { return "'" + s + "'"; }
  static std::string hand() { return quoted(test::data_path("hand_lowres.obj")); }

  // One step of `fairsurf smooth` on the hand with `flags`, written to NAME.obj with its log
  // NAME.json; returns the output's bytes.
  std::string smooth(const std::string& name, const std::string& flags) {
    const auto run = test::run_cli("smooth " + hand() + " -o " + quoted(file(name + ".obj")) + " --log " +
                                   quoted(file(name + ".json")) + " --steps 1 --quiet " + flags);
    EXPECT_EQ(run.exit_code, 0) << flags << ": " << run.out;
    return test::read_bytes(file(name + ".obj"));
  }
  nlohmann::json log_of(const std::string& name) const {
    std::ifstream in(file(name + ".json"));
    return nlohmann::json::parse(in);
  }
};

// The section of docs/cli.md that maps flags to fields.
std::string flag_table() {
  const fs::path docs = fs::path(test::data_path("")).parent_path().parent_path() / "docs" / "cli.md";
  const std::string text = test::read_bytes(docs);
  const auto start = text.find("## Flags and the fields they set");
  EXPECT_NE(start, std::string::npos) << docs;
  return start == std::string::npos ? "" : text.substr(start, text.find("\n## ", start + 1) - start);
}

}  // namespace

TEST_F(CliFlagNames, FunctionsAndItsAliasFSetTheSameFunctions) {
  const std::string named = smooth("named", "--functions H --functions K");
  EXPECT_EQ(smooth("alias", "--f H --f K"), named);
  EXPECT_NE(smooth("default", ""), named);  // the functions reached the flow
  EXPECT_EQ(log_of("named")["functions"], nlohmann::json({"H", "K"}));
  EXPECT_EQ(log_of("alias")["functions"], nlohmann::json({"H", "K"}));

  for (const std::string flag : {"--functions", "--f"}) {
    const auto run = test::run_cli("fill " + hand() + " -o " + quoted(file("fill" + flag + ".obj")) + " --log " +
                                   quoted(file("fill" + flag + ".json")) + " --max-steps 2 --quiet " + flag + " K");
    EXPECT_EQ(run.exit_code, 0) << flag << ": " << run.out;
    EXPECT_EQ(log_of("fill" + flag)["functions"], nlohmann::json({"K"})) << flag;
  }
  EXPECT_EQ(test::read_bytes(file("fill--functions.obj")), test::read_bytes(file("fill--f.obj")));
}

TEST_F(CliFlagNames, FixedVerticesAndItsAliasFixedHoldTheSameVertices) {
  std::ofstream(file("held.txt")) << "100 200 300\n";
  const std::string named = smooth("named", "--fixed-vertices " + quoted(file("held.txt")));
  EXPECT_EQ(smooth("alias", "--fixed " + quoted(file("held.txt"))), named);
  EXPECT_NE(smooth("free", ""), named);  // the vertices were held
}

// A control the library owns is refused by LinearSolverOptions::mumps_controls' check: under either
// name, the flag reached that field.
TEST_F(CliFlagNames, MumpsControlsAndItsAliasMumpsIcntlSetTheSameControls) {
  for (const std::string flag : {"--mumps-controls", "--mumps-icntl"}) {
    const auto refused = test::run_cli("smooth " + hand() + " -o " + quoted(file("r.obj")) + " --steps 1 --quiet " +
                                       flag + " 4=2");
    EXPECT_EQ(refused.exit_code, 1) << flag << ": " << refused.out;
    EXPECT_NE(refused.out.find("ICNTL(4) = 2: not a MUMPS control to pass through"), std::string::npos)
        << flag << ": " << refused.out;
    const auto malformed = test::run_cli("smooth " + hand() + " -o " + quoted(file("m.obj")) + " " + flag + " 7");
    EXPECT_EQ(malformed.exit_code, 1) << flag << ": " << malformed.out;
    EXPECT_NE(malformed.out.find("--mumps-controls: expected K=V"), std::string::npos)
        << flag << ": " << malformed.out;
  }
  EXPECT_EQ(smooth("alias", "--mumps-icntl 7=0"), smooth("named", "--mumps-controls 7=0"));
}

// Every flag that `fairsurf COMMAND --help` lists is in the table, so the table cannot fall behind.
TEST_F(CliFlagNames, EveryFlagOfTheFlowCommandsIsInTheDocumentedTable) {
  const std::string table = flag_table();
  const std::regex flag("(^|[\\s,])(--[a-z][a-z-]*)");
  for (const std::string command : {"smooth", "fill", "fair", "blend"}) {
    const auto help = test::run_cli(command + " --help");
    ASSERT_EQ(help.exit_code, 0) << help.out;
    std::set<std::string> flags;
    const std::sregex_iterator end;
    for (auto it = std::sregex_iterator(help.out.begin(), help.out.end(), flag); it != end; ++it)
      flags.insert((*it)[2]);
    EXPECT_TRUE(flags.count("--functions") && flags.count("--f")) << command << ": " << help.out;
    for (const std::string& name : flags)  // `--name` or `--name VALUE`
      EXPECT_TRUE(table.find("`" + name + "`") != std::string::npos || table.find("`" + name + " ") != std::string::npos)
          << command << " " << name << " is not in docs/cli.md's table";
  }
}
