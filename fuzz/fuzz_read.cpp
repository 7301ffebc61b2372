// libFuzzer harness for one reader (FAIRSURF_FUZZ_FORMAT: read_obj, read_off, read_ply, read_stl):
// any bytes must either parse or throw a fairsurf::Error, and whatever parses must triangulate and
// validate without a fault. The sanitizers turn every out-of-bounds access or overflow into a crash.
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/mesh/validate.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/io_formats.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fairsurf;
  const io_detail::Source source{"fuzz", std::string_view(reinterpret_cast<const char*>(data), size)};
  try {
    ReadReport report;
    RawMesh raw = io_detail::FAIRSURF_FUZZ_FORMAT(source, report);
    const Mesh mesh = triangulate(std::move(raw), &report);
    validate(mesh);
  } catch (const Error&) {
    // A precise refusal is the expected outcome for most mutations.
  }
  return 0;
}
