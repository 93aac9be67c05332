#include "bundle_file.h"

#include "io/out_of_memory.h"
#include "io/output_batch.h"
#include "io/text_file.h"
#include "io/sha1.h"

namespace tracer {
namespace {

constexpr char kMagic[8] = {'T', 'R', 'B', 'U', 'N', 'D', 'L', 'E'};
constexpr uint32_t kMaxNameBytes = 256, kMaxSections = 4096;

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void put_text(std::string& out, const std::string& text) {
  put(out, static_cast<uint32_t>(text.size()));
  out += text;
}

// Reads fields from the checked bytes; every read is bounds-checked.
struct Cursor {
  const std::string& bytes;
  size_t end;  // the checksum's offset
  const std::string& path;
  size_t at = 0;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path + ": malformed bundle at byte " + std::to_string(at) + ": " + what);
  }
  void need(uint64_t n, const char* what) const {
    if (n > end - at) fail(std::string(what) + " runs past the end");
  }
  template <class T>
  T take(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    at += sizeof value;
    return value;
  }
  std::string take_text(const char* what) {
    const uint32_t n = take<uint32_t>(what);
    if (n > kMaxNameBytes) fail(std::string(what) + " of " + std::to_string(n) + " bytes");
    need(n, what);
    std::string text = bytes.substr(at, n);
    at += n;
    return text;
  }
};

}  // namespace

bool BundleFile::has(const std::string& name) const {
  for (const BundleSection& s : sections)
    if (s.name == name) return true;
  return false;
}

const BundleSection& BundleFile::find(const std::string& name, const std::string& file) const {
  for (const BundleSection& s : sections)
    if (s.name == name) return s;
  throw InputError(file + ": the " + kind + " bundle has no section " + name);
}

std::string encode_bundle(const BundleFile& bundle) {
  std::string out(kMagic, sizeof kMagic);
  put(out, kBundleVersion);
  put_text(out, bundle.kind);
  put(out, static_cast<uint32_t>(bundle.sections.size()));
  for (const BundleSection& s : bundle.sections) {
    put_text(out, s.name);
    put(out, s.element_size);
    put(out, static_cast<uint64_t>(s.element_size ? s.bytes.size() / s.element_size : 0));
    out += s.bytes;
  }
  Sha1 sha;
  sha.append(out.data(), out.size());
  unsigned char digest[20];
  sha.digest(digest);
  out.append(reinterpret_cast<const char*>(digest), sizeof digest);
  return out;
}

void write_bundle(const std::string& path, const BundleFile& bundle) {
  write_file_atomically(path, encode_bundle(bundle));
}

BundleFile read_bundle(const std::string& path, const std::string& expected_kind) {
  return naming_file_when_out_of_memory(path, "reading the bundle", [&] {
    return decode_bundle(read_text_file(path, "bundle", kBundleMaxBytes), path, expected_kind);
  });
}

BundleFile decode_bundle(const std::string& bytes, const std::string& path, const std::string& expected_kind) {
  if (bytes.size() < sizeof kMagic + 4 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(path + ": not a tracer bundle (no TRBUNDLE magic)");
  uint32_t version = 0;
  std::memcpy(&version, bytes.data() + sizeof kMagic, sizeof version);
  if (version != kBundleVersion)
    throw InputError(path + ": bundle version " + std::to_string(version) + "; this build reads version " +
                     std::to_string(kBundleVersion));
  if (bytes.size() < sizeof kMagic + 4 + 20) throw InputError(path + ": truncated bundle");
  const size_t end = bytes.size() - 20;
  Sha1 sha;
  sha.append(bytes.data(), end);
  unsigned char digest[20];
  sha.digest(digest);
  if (std::memcmp(digest, bytes.data() + end, sizeof digest) != 0)
    throw InputError(path + ": bundle checksum does not match (truncated or corrupted)");

  Cursor c{bytes, end, path, sizeof kMagic + 4};
  BundleFile bundle;
  bundle.kind = c.take_text("kind");
  if (bundle.kind != expected_kind)
    throw InputError(path + ": a " + bundle.kind + " bundle; expected a " + expected_kind + " bundle");
  const uint32_t count = c.take<uint32_t>("section count");
  if (count > kMaxSections) c.fail(std::to_string(count) + " sections");
  for (uint32_t i = 0; i < count; ++i) {
    BundleSection s;
    s.name = c.take_text("section name");
    s.element_size = c.take<uint32_t>("element size");
    const uint64_t elements = c.take<uint64_t>("element count");
    if (s.element_size == 0 && elements != 0) c.fail("section " + s.name + " has elements of 0 bytes");
    if (s.element_size != 0 && elements > (end - c.at) / s.element_size)
      c.fail("section " + s.name + " runs past the end");
    const size_t n = static_cast<size_t>(elements * s.element_size);
    s.bytes = bytes.substr(c.at, n);
    c.at += n;
    if (bundle.has(s.name)) c.fail("section " + s.name + " appears twice");
    bundle.sections.push_back(std::move(s));
  }
  if (c.at != end) c.fail(std::to_string(end - c.at) + " bytes after the last section");
  return bundle;
}

}  // namespace tracer
