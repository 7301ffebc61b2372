// The house rule of docs/architecture.md: the library's folders are the pipeline's stages, in order,
// and no file of a stage includes a header of a later one. Read from the source tree itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "test_support.h"

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kStages = {"mesh",  "io",   "geometry",     "energy", "solve",
                                          "patch", "flow", "applications", "render"};

int stage_index(const std::string& name) {
  const auto it = std::find(kStages.begin(), kStages.end(), name);
  return it == kStages.end() ? -1 : static_cast<int>(it - kStages.begin());
}

fs::path source_root() { return fs::path(fairsurf::test::data_path("")).parent_path().parent_path(); }

// Every "stage/x.h" a file includes, as <fairsurf/stage/x.h> (public) or "stage/x.h" (private).
std::vector<std::string> included_stages(const fs::path& file) {
  static const std::regex include(R"re(^#include [<"](?:fairsurf/)?(\w+)/\w+\.h[>"])re");
  std::vector<std::string> stages;
  std::ifstream in(file);
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, include) && stage_index(m[1]) >= 0) stages.push_back(m[1]);
  return stages;
}

}  // namespace

TEST(StageOrder, EveryFolderIsAStageAndNoneIncludesALaterOne) {
  const fs::path root = source_root();
  ASSERT_TRUE(fs::exists(root / "include/fairsurf/fairsurf.h")) << root;
  int files = 0;
  for (const char* top : {"include/fairsurf", "src"})
    for (const auto& folder : fs::directory_iterator(root / top)) {
      if (!folder.is_directory()) continue;
      const std::string stage = folder.path().filename().string();
      const int own = stage_index(stage);
      EXPECT_GE(own, 0) << folder.path() << " is not a stage of the pipeline";
      for (const auto& entry : fs::recursive_directory_iterator(folder.path())) {
        if (!entry.is_regular_file()) continue;
        ++files;
        for (const std::string& included : included_stages(entry.path()))
          EXPECT_LE(stage_index(included), own) << entry.path() << " (" << stage << ") includes a header of "
                                                << included << ", a later stage";
      }
    }
  EXPECT_GT(files, 100);  // the walk saw the library, not an empty tree
}
