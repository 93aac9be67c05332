#include "image/declared_size_check.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/input_error.h"

namespace tracer {
namespace {

constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr uint32_t kMultipartFlag = 0x1000;  // version field bit 12
constexpr size_t kMaxNameBytes = 256;        // long names: 255 characters and the terminator
constexpr uint64_t kMaxDeflateRatio = 1032;
constexpr unsigned char kJpegStart[3] = {0xff, 0xd8, 0xff};

class HeaderReader {
 public:
  HeaderReader(std::istream& in, uint64_t size, const std::string& path, std::string what)
      : path_(path), what_(std::move(what)), in_(in), size_(size) {
    if (!in_) fail("cannot open it");
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(path_ + ": cannot read image: its " + what_ + " " + why);
  }
  uint64_t left() const { return size_ - offset_; }

  void read(void* into, size_t bytes) {
    if (bytes > left() || !in_.read(static_cast<char*>(into), static_cast<std::streamsize>(bytes)))
      fail("is cut short at byte " + std::to_string(offset_));
    offset_ += bytes;
  }
  std::string name() {
    std::string text;
    for (char c = 1; text.size() <= kMaxNameBytes;) {
      read(&c, 1);
      if (c == '\0') return text;
      text += c;
    }
    fail("holds a name longer than 255 bytes at byte " + std::to_string(offset_));
  }
  int32_t int32() {  // little-endian, as EXR stores it
    unsigned char b[4];
    read(b, 4);
    return static_cast<int32_t>(uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24);
  }
  uint32_t big_endian32() {  // as PNG stores it
    unsigned char b[4];
    read(b, 4);
    return uint32_t{b[0]} << 24 | uint32_t{b[1]} << 16 | uint32_t{b[2]} << 8 | uint32_t{b[3]};
  }
  void skip(uint64_t bytes) {
    if (bytes > left() || !in_.seekg(static_cast<std::streamoff>(bytes), std::ios::cur))
      fail("is cut short at byte " + std::to_string(offset_));
    offset_ += bytes;
  }

 private:
  std::string path_, what_;
  std::istream& in_;
  uint64_t size_ = 0, offset_ = 0;
};

void check_exr(std::istream& stream, uint64_t size, const std::string& path) {
  HeaderReader in(stream, size, path, "EXR header");
  in.skip(4);
  const uint32_t version = static_cast<uint32_t>(in.int32());
  const bool multipart = (version & kMultipartFlag) != 0;
  for (bool first_header = true;; first_header = false) {
    std::string name = in.name();
    if (name.empty() && (!multipart || !first_header)) return;  // the end of the (last) header
    for (; !name.empty(); name = in.name()) {
      const std::string type = in.name();
      const int32_t size = in.int32();
      if (size < 0 || static_cast<uint64_t>(size) > in.left())
        in.fail("attribute " + name + " (" + type + ") declares " + std::to_string(size) + " bytes; " +
                std::to_string(in.left()) + " are left in the file");
      in.skip(static_cast<uint64_t>(size));
    }
    if (!multipart) return;
  }
}

// The bits of a PNG pixel by its IHDR colour type (ISO/IEC 15948, 11.2.2), 0 for none.
uint64_t png_pixel_bits(unsigned colour_type, unsigned bit_depth) {
  static const unsigned samples[7] = {1, 0, 3, 1, 2, 0, 4};  // grey, -, RGB, palette, grey+alpha, -, RGBA
  return colour_type < 7 ? uint64_t{samples[colour_type]} * bit_depth : 0;
}

void check_png(std::istream& stream, uint64_t size, const std::string& path) {
  HeaderReader in(stream, size, path, "PNG chunk");
  in.skip(sizeof kPngSignature);
  uint64_t width = 0, height = 0, pixel_bits = 0, compressed = 0;
  for (;;) {
    const uint32_t length = in.big_endian32();
    char type[5] = {};
    in.read(type, 4);
    if (uint64_t{length} + 4 > in.left())  // the data and its CRC
      in.fail(std::string(type) + " declares " + std::to_string(length) + " bytes; " + std::to_string(in.left()) +
              " are left in the file");
    if (std::string(type) == "IHDR" && length == 13) {
      width = in.big_endian32();
      height = in.big_endian32();
      unsigned char depth_and_type[2];
      in.read(depth_and_type, 2);
      pixel_bits = png_pixel_bits(depth_and_type[1], depth_and_type[0]);
      in.skip(uint64_t{length} - 10 + 4);
    } else {
      if (std::string(type) == "IDAT") compressed += length;
      in.skip(uint64_t{length} + 4);
    }
    if (std::string(type) == "IEND" || in.left() == 0) break;
  }
  // Deflate expands a byte into at most 1032 (RFC 1951: a 258-byte match in at least two
  // bits): a 69-byte PNG declaring 8192 x 8192 pixels had libpng allocate 760 MB first.
  const uint64_t raw_bytes = (width * pixel_bits + 7) / 8 * height;
  if (raw_bytes > kMaxDeflateRatio * compressed + kMaxDeflateRatio)
    in.fail("IDAT holds " + std::to_string(compressed) + " bytes; the " + std::to_string(width) + "x" +
            std::to_string(height) + " pixels its header declares need " + std::to_string(raw_bytes) +
            ", more than deflate's 1032:1 gives");
}

// A JPEG (ITU T.81, B.1): the frame header (an SOF marker) declares the size; the entropy-coded
// data codes every 8x8 block of the first component in at least one bit, and an EOI marker
// (FF D9) ends it. A JPEG cut short was decoded as grey and accepted; one declaring 16000 x
// 16000 pixels in a few bytes took minutes and gigabytes.
void check_jpeg(const std::string& bytes, const std::string& path) {
  const auto fail = [&](const std::string& why) {
    throw InputError(path + ": cannot read image: its JPEG data " + why);
  };
  uint64_t width = 0, height = 0;
  size_t at = 2, scan = std::string::npos;
  while (at + 4 <= bytes.size() && scan == std::string::npos) {
    if (static_cast<unsigned char>(bytes[at]) != 0xff) fail("has no marker at byte " + std::to_string(at));
    const unsigned marker = static_cast<unsigned char>(bytes[at + 1]);
    if (marker == 0xff) {  // fill bytes before a marker
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd9)) {  // TEM, RSTn, SOI, EOI: no length
      at += 2;
      continue;
    }
    const size_t length =
        size_t{static_cast<unsigned char>(bytes[at + 2])} << 8 | static_cast<unsigned char>(bytes[at + 3]);
    const bool frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (frame && length >= 7 && at + 9 <= bytes.size()) {
      height = size_t{static_cast<unsigned char>(bytes[at + 5])} << 8 | static_cast<unsigned char>(bytes[at + 6]);
      width = size_t{static_cast<unsigned char>(bytes[at + 7])} << 8 | static_cast<unsigned char>(bytes[at + 8]);
    }
    if (marker == 0xda) scan = at + 2 + length;
    at += 2 + length;
  }
  if (scan == std::string::npos || scan > bytes.size()) fail("is cut short before its scan");
  if (bytes.find("\xff\xd9", scan) == std::string::npos) fail("is cut short: no end-of-image marker after its scan");
  const uint64_t blocks = (width + 7) / 8 * ((height + 7) / 8);
  if (blocks > 8 * uint64_t{bytes.size() - scan})
    fail("holds " + std::to_string(bytes.size() - scan) + " bytes of scan for the " + std::to_string(width) + "x" +
         std::to_string(height) + " pixels its header declares, fewer than one bit per 8x8 block");
}

// Checks the stream's image when its first bytes name EXR or PNG; `name` goes in errors.
void check_stream(std::istream& stream, uint64_t size, const std::string& name) {
  unsigned char magic[8] = {};
  stream.read(reinterpret_cast<char*>(magic), sizeof magic);
  const std::streamsize got = stream.gcount();
  stream.clear();
  stream.seekg(0);
  if (got >= 4 && std::memcmp(magic, kExrMagic, 4) == 0) check_exr(stream, size, name);
  if (got == 8 && std::memcmp(magic, kPngSignature, 8) == 0) check_png(stream, size, name);
  if (got >= 3 && std::memcmp(magic, kJpegStart, 3) == 0) {
    std::string bytes(size, '\0');
    stream.read(bytes.data(), static_cast<std::streamsize>(size));
    stream.clear();
    stream.seekg(0);
    check_jpeg(bytes, name);
  }
}

}  // namespace

void check_declared_sizes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (ec || !file) throw InputError(path + ": cannot read image: cannot open it");
  check_stream(file, size, path);
}

void check_declared_sizes(const std::vector<unsigned char>& bytes, const std::string& name) {
  std::istringstream stream(std::string(bytes.begin(), bytes.end()));
  check_stream(stream, bytes.size(), name);
}

}  // namespace tracer
