#include "scratch_dir.h"

#include <unistd.h>

#include <algorithm>

namespace fairsurf::test {

void ScratchDirTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string("fairsurf_") + info->test_suite_name() + "_" + info->name() + "_" +
                     std::to_string(::getpid());
  std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests: "Prefix/Suite", "Test/0"
  dir_ = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
}

void ScratchDirTest::TearDown() { std::filesystem::remove_all(dir_); }

}  // namespace fairsurf::test
