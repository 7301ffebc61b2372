// A test fixture with a fresh directory of its own, for tests that write files (the CLI's).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fairsurf::test {

/// Each test gets temp/fairsurf_<suite>_<test>_<pid>, created empty in SetUp and removed in
/// TearDown. Fixtures that write inputs there override SetUp and call this one first.
class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  /// The path of `name` inside the directory.
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace fairsurf::test
