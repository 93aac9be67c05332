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

void check_png(std::istream& stream, uint64_t size, const std::string& path) {
  HeaderReader in(stream, size, path, "PNG chunk");
  in.skip(sizeof kPngSignature);
  for (;;) {
    const uint32_t length = in.big_endian32();
    char type[5] = {};
    in.read(type, 4);
    if (uint64_t{length} + 4 > in.left())  // the data and its CRC
      in.fail(std::string(type) + " declares " + std::to_string(length) + " bytes; " + std::to_string(in.left()) +
              " are left in the file");
    in.skip(uint64_t{length} + 4);
    if (std::string(type) == "IEND" || in.left() == 0) return;
  }
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
