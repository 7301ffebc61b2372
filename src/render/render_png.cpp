// PNG output through libpng's simplified API, which writes no time or text chunks: the bytes depend
// on the pixels alone (and the zlib build), so equal images give equal files.
#include <fairsurf/io/io.h>
#include <fairsurf/mesh/errors.h>
#include <fairsurf/render/render.h>

#include <png.h>

namespace fairsurf {
namespace {

std::vector<unsigned char> encode_png(const Image& image) {
  png_image header{};
  header.version = PNG_IMAGE_VERSION;
  header.width = static_cast<png_uint_32>(image.width);
  header.height = static_cast<png_uint_32>(image.height);
  header.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  const png_int_32 stride = 3 * image.width;
  if (png_image_write_to_memory(&header, nullptr, &size, 0, image.rgb.data(), stride, nullptr) == 0)
    throw IoError(std::string("write_png: cannot encode the image: ") + header.message);
  std::vector<unsigned char> bytes(size);
  if (png_image_write_to_memory(&header, bytes.data(), &size, 0, image.rgb.data(), stride, nullptr) == 0)
    throw IoError(std::string("write_png: cannot encode the image: ") + header.message);
  bytes.resize(size);
  return bytes;
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * image.height)
    throw InvalidArgument("write_png: image size " + std::to_string(image.width) + "x" +
                          std::to_string(image.height) + " does not match its " +
                          std::to_string(image.rgb.size()) + " bytes");
  const std::vector<unsigned char> bytes = encode_png(image);
  write_file_atomically(path, std::string(bytes.begin(), bytes.end()), "write_png");
}

}  // namespace fairsurf
