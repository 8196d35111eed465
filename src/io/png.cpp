#include "io/png.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <memory>
#include <string_view>

#include "base/error.h"
#include "io/echo.h"
#include "io/json.h"
#include "io/limits.h"

namespace tidepool::io {

void clearStbFailureReason();  // stb_impl.cpp, beside stb's own state

namespace {

// stb's reason for the failure of the call since the last clearStbFailureReason ("bad huffman
// code"), or ours where it gave none (a reserved deflate block type, say).
std::string failureReason() {
  const char* reason = stbi_failure_reason();
  return reason && *reason ? printable(reason) : "damaged image data; the decoder gives no reason";
}

std::uint32_t bigEndian32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// Bytes of filtered scanlines a width x height image needs (each row: a filter byte, then its
// pixels packed at `bits` per pixel); interlaced images store seven smaller passes.
std::size_t scanlineBytes(std::size_t width, std::size_t height, std::size_t bits, bool interlaced) {
  const auto rows = [&](std::size_t w, std::size_t h) { return w == 0 || h == 0 ? 0 : h * (1 + (w * bits + 7) / 8); };
  if (!interlaced) return rows(width, height);
  static const int adam7[7][4] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                  {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};  // x0, y0, dx, dy
  std::size_t total = 0;
  for (const auto& [x0, y0, dx, dy] : adam7) total += rows((width + dx - 1 - x0) / dx, (height + dy - 1 - y0) / dy);
  return total;
}

// What stb takes on trust: a chunk's length (it allocates what the length claims before reading),
// an empty first IDAT (it copies its zero bytes to a null buffer: undefined behaviour) and how far
// the image data inflates (to the end of the stream, however large). Each chunk must fit in the
// file, no IDAT may be empty, and the data must inflate to no more than the header's pixels need;
// what is otherwise malformed (checksums included) is left to stb to report.
void checkChunks(std::span<const std::uint8_t> b, const std::string& name) {
  static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() < 33 || !std::equal(signature, signature + 8, b.data())) return;
  std::vector<char> data;  // the IDAT chunks' contents: one zlib stream
  for (std::size_t at = 8; at + 8 <= b.size();) {
    const std::size_t length = bigEndian32(&b[at]), left = b.size() - at - 8;
    const std::string type = printable(std::string_view(reinterpret_cast<const char*>(&b[at + 4]), 4));
    if (length > left || left - length < 4)
      throw Error(name + ": byte " + std::to_string(at) + ": chunk '" + type + "' claims " + std::to_string(length) +
                  " bytes and its checksum, but only " + std::to_string(left) + " follow (the file is cut or damaged)");
    if (type == "IDAT" && length == 0)
      throw Error(name + ": byte " + std::to_string(at) +
                  ": chunk 'IDAT' is empty, which the decoder cannot read (re-save the image)");
    if (type == "IDAT") data.insert(data.end(), &b[at + 8], &b[at + 8] + length);
    if (type == "IEND") break;
    at += 12 + length;
  }
  const std::uint8_t* ihdr = &b[16];  // width, height, bit depth, colour type, ..., interlace
  static const int channels[7] = {1, 0, 3, 1, 2, 0, 4};
  if (ihdr[9] > 6 || channels[ihdr[9]] == 0 || ihdr[8] == 0 || ihdr[8] > 16 || data.empty()) return;
  const std::size_t needed =
      scanlineBytes(bigEndian32(ihdr), bigEndian32(ihdr + 4), std::size_t(ihdr[8]) * channels[ihdr[9]], ihdr[12] == 1);
  // Deflate expands at most 1032 times: less data cannot fill the image (stb would allocate for
  // all of it first, then find the end).
  if (needed > 1100 * data.size() + 1024)
    throw Error(name + ": " + std::to_string(data.size()) + " bytes of image data cannot fill the " +
                std::to_string(bigEndian32(ihdr)) + " x " + std::to_string(bigEndian32(ihdr + 4)) +
                " pixels its header claims (the file is cut or damaged)");
  const std::unique_ptr<char[]> out(new char[needed + 1]);  // not zeroed: only written
  clearStbFailureReason();
  if (stbi_zlib_decode_buffer(out.get(), int(needed + 1), data.data(), int(data.size())) < 0 &&
      failureReason() == "output buffer limit")
    throw Error(name + ": its image data inflates to more than the " + std::to_string(needed) + " bytes its " +
                std::to_string(bigEndian32(ihdr)) + " x " + std::to_string(bigEndian32(ihdr + 4)) +
                " pixels need (a decompression bomb?)");
}

}  // namespace

void writePng(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != std::size_t(image.width) * image.height * 4)
    throw Error("cannot write '" + shownPath(path) + "': image is empty or its size does not match its pixels");
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw Error("cannot write '" + shownPath(path) + "': check that the folder exists and is writable");
}

Image decodePng(std::span<const std::uint8_t> bytes, const std::string& name) {
  if (bytes.size() > kMaxPngFileBytes)
    throw Error(name + ": " + byteSize(bytes.size()) + ", larger than the " + byteSize(kMaxPngFileBytes) +
                " allowed for a PNG file");
  const int length = int(bytes.size());
  // The header's size first: a few bytes may claim gigapixels, and stb would try to allocate them.
  int width = 0, height = 0, channels = 0;
  clearStbFailureReason();
  // stb names an unknown chunk by its four bytes, whatever they are: quoted printable.
  if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels))
    throw Error(name + ": not a PNG image (" + failureReason() + ")");
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide ||
      std::size_t(width) * std::size_t(height) > kMaxImagePixels)
    throw Error(name + ": header: " + std::to_string(width) + " x " + std::to_string(height) +
                " pixels, larger than the " + std::to_string(kMaxImageSide) + " per side and " +
                std::to_string(kMaxImagePixels >> 20) + " Mpixel allowed");
  checkChunks(bytes, name);
  Image img;
  clearStbFailureReason();
  stbi_uc* data = stbi_load_from_memory(bytes.data(), length, &img.width, &img.height, &channels, 4);
  if (!data) throw Error(name + ": cannot decode the PNG image (" + failureReason() + ")");
  img.rgba.assign(data, data + std::size_t(img.width) * img.height * 4);
  stbi_image_free(data);
  return img;
}

Image readPng(const std::filesystem::path& path) {
  const std::string bytes = readFileLimited(path, kMaxPngFileBytes, "a PNG image");
  return decodePng({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, shownPath(path));
}

}  // namespace tidepool::io
