#include "scene/gltf_file.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "io/input_error.h"
#include "io/json_reader.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_normalize.h"
#include "scene/gltf_reader_memory.h"
#include "scene/gltf_schema.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

// What the file-system callbacks know: the folder external files must lie in, and why the
// last one was refused (tinygltf's own message would only say "not found").
struct Confinement {
  fs::path folder;  // canonical
  std::string refusal;
  std::string refused;  // the path refused
  std::set<std::string> files_read;
  uint64_t bytes_read = 0;  // over every external file, against kMaxGltfExternalTotalBytes
};

// Whether `path`, with every symlink resolved, lies inside the folder; `why` says why not.
bool inside_folder(const std::string& path, Confinement& c, std::string& why) {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(fs::path(path), ec);
  if (ec) {
    why = path + ": cannot resolve it (" + ec.message() + ")";
    return false;
  }
  const auto [end, unused] = std::mismatch(c.folder.begin(), c.folder.end(), resolved.begin(), resolved.end());
  if (end != c.folder.end()) {
    why = path + ": lies outside " + c.folder.string() + "; a glTF file's buffers and images must be in its folder";
    return false;
  }
  const fs::file_status st = fs::status(resolved, ec);
  if (ec || !fs::exists(st)) {
    why = path + ": no such file";
    return false;
  }
  if (!fs::is_regular_file(st)) {
    why = path + ": not a regular file";
    return false;
  }
  return true;
}

bool file_exists(const std::string& path, void* user) {
  // tinygltf looks in the file's folder, then in the working directory ("./URI"): only the first.
  if (path.rfind("./", 0) == 0) return false;
  Confinement& c = *static_cast<Confinement*>(user);
  std::string why;
  if (inside_folder(path, c, why)) return true;
  c.refusal = why;
  c.refused = path;
  return false;
}

std::string expand_nothing(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  Confinement& c = *static_cast<Confinement*>(user);
  std::string why;
  std::error_code ec;
  if (!inside_folder(path, c, why)) {
    *err = c.refusal = why;
    c.refused = path;
    return false;
  }
  const uint64_t size = fs::file_size(path, ec);
  if (ec || size > kMaxGltfExternalBytes || c.bytes_read + size > kMaxGltfExternalTotalBytes) {
    *err = c.refusal =
        path + ": " +
        (ec                             ? ec.message()
         : size > kMaxGltfExternalBytes ? "larger than 1 GiB, the limit for a buffer or image"
                                        : "past 4 GiB read from the files a glTF file names, their limit");
    c.refused = path;
    return false;
  }
  c.bytes_read += size;
  std::ifstream in(path, std::ios::binary);
  out->resize(size);
  if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    *err = c.refusal = path + ": cannot read it";
    c.refused = path;
    return false;
  }
  c.files_read.insert(path);
  return true;
}

bool write_nothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "the tracer writes no glTF files";
  return false;
}

// Keeps an image's encoded bytes for decode_gltf_image. tinygltf 2.7 passes an image's buffer
// view without checking that it lies inside its buffer (a fuzzed .glb read past the buffer's
// end), so `model` (the one being loaded: its buffers and views come before its images) checks it.
bool keep_encoded_image(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                        const unsigned char* bytes, int size, void* model_being_loaded) {
  if (image->bufferView >= 0) {
    const auto& model = *static_cast<const tinygltf::Model*>(model_being_loaded);
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(image->bufferView)];
    std::string why = gltf_view_outside_its_buffer(model, view);
    if (why.empty() && size < 0)  // the view's length as tinygltf's int
      why = std::to_string(view.byteLength) + " bytes, more than the 2 GiB tinygltf passes for an image";
    if (!why.empty()) {
      *err += "images[" + std::to_string(index) + "].bufferView: " + why;
      return false;
    }
  }
  image->image.assign(bytes, bytes + size);
  image->width = image->height = image->component = -1;
  return true;
}

// The first buffer or image whose uri `stop(uri)` is true for, as its JSON path
// ("images[2].uri"); "" when none is.
template <class Stop>
std::string first_uri(const Json& root, Stop stop) {
  for (const char* array : {"buffers", "images"}) {
    const auto list = root.find(array);
    if (list == root.end()) continue;
    for (size_t i = 0; i < list->size(); ++i) {
      const auto uri = (*list)[i].find("uri");
      if (uri != (*list)[i].end() && stop(uri->get<std::string>()))
        return std::string(array) + "[" + std::to_string(i) + "].uri";
    }
  }
  return "";
}

// A buffer's or image's URI is data, or a path relative to the file's folder: an absolute
// path or another scheme (http:, file:) is refused by its JSON path before anything is read.
void check_external_uris(const Json& root, const std::string& path) {
  const auto external = [](const std::string& text) { return text.rfind("data:", 0) != 0; };
  const std::string absolute =
      first_uri(root, [&](const std::string& text) { return external(text) && !text.empty() && text[0] == '/'; });
  if (!absolute.empty())
    fail_at(path, absolute,
            "an absolute path; buffers and images must be in the glTF file's folder, named relative to it");
  const std::string scheme =
      first_uri(root, [&](const std::string& text) { return external(text) && text.find(':') != std::string::npos; });
  if (!scheme.empty())
    fail_at(path, scheme, "names a URI scheme; the reader reads data URIs and files in the glTF file's folder");
}

// The JSON path of the buffer or image whose uri names `refused` (a file the reader would
// not read), with ": " after it; "" when none does.
std::string uri_path_of(const Json& root, const std::string& refused) {
  const std::string at = first_uri(root, [&](const std::string& name) {
    return !name.empty() && refused.size() >= name.size() &&
           refused.compare(refused.size() - name.size(), name.size(), name) == 0;
  });
  return at.empty() ? "" : at + ": ";
}

constexpr unsigned char kGlbMagic[4] = {'g', 'l', 'T', 'F'};

// The JSON text of a .gltf file, or of a .glb's first chunk (glTF 2.0, 4.4), for the checked
// parse; a .glb's header is checked here.
std::string json_text(const std::string& bytes, bool binary, const std::string& path) {
  if (!binary) return bytes;
  uint32_t header[5];
  if (bytes.size() < sizeof header)
    throw InputError(path + ": a binary glTF file of " + std::to_string(bytes.size()) +
                     " bytes, shorter than the 20 bytes of its header and first chunk's header");
  std::memcpy(header, bytes.data(), sizeof header);
  if (header[2] != bytes.size())
    throw InputError(path + ": a binary glTF file whose header gives its length as " + std::to_string(header[2]) +
                     " bytes; it has " + std::to_string(bytes.size()));
  if (header[1] != 2)
    throw InputError(path + ": a binary glTF file of version " + std::to_string(header[1]) +
                     "; the reader reads version 2");
  if (header[3] > bytes.size() - 20 || header[4] != 0x4E4F534Au)
    throw InputError(path + ": a binary glTF file whose first chunk is not JSON of at most the " +
                     std::to_string(bytes.size() - 20) + " bytes that follow the header");
  return bytes.substr(20, header[3]);
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return ext == ".gltf" || ext == ".glb";
}

GltfFile read_gltf_file(const std::string& bytes, const std::string& path) {
  if (bytes.size() > kMaxGltfFileBytes) throw InputError(path + ": larger than 4 GiB, the limit of a glTF file");
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), kGlbMagic, 4) == 0;
  Json root = parse_json_text(json_text(bytes, binary, path), path);  // syntax, depth and duplicate keys first
  check_gltf_schema(root, path);
  check_external_uris(root, path);
  const NormalizedGltf normalized_json = normalize_gltf_json(root, binary, path);
  static const MemoryLimit limit = memory_limit();
  check_gltf_reader_memory(root, limit, path);
  const std::string normalized = binary ? glb_with_json(bytes, root.dump(), path) : root.dump();
  std::error_code ec;
  Confinement confinement;
  const fs::path dir = fs::absolute(fs::path(path), ec).parent_path();
  confinement.folder = fs::weakly_canonical(dir, ec);
  if (ec) throw InputError(path + ": cannot resolve its folder: " + ec.message());
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({file_exists, expand_nothing, read_whole_file, write_nothing, &confinement});
  GltfFile file;
  file.path = path;
  loader.SetImageLoader(keep_encoded_image, &file.model);
  std::string err, warn;
  const bool ok = binary ? loader.LoadBinaryFromMemory(&file.model, &err, &warn,
                                                       reinterpret_cast<const unsigned char*>(normalized.data()),
                                                       static_cast<unsigned int>(normalized.size()), dir.string())
                         : loader.LoadASCIIFromString(&file.model, &err, &warn, normalized.data(),
                                                      static_cast<unsigned int>(normalized.size()), dir.string());
  const auto trimmed = [](std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
  };
  if (!ok && !confinement.refusal.empty())
    throw InputError(path + ": " + uri_path_of(root, confinement.refused) + confinement.refusal);
  if (!ok) {  // past every check above: what the library itself says, marked as its words
    std::string why = trimmed(err.empty() ? warn : err);
    // tinygltf quotes a data URI it cannot decode whole (a 4 MB file, a 4 MB line): name it by
    // its JSON path instead, and keep any other message to a line.
    const std::string undecoded = first_uri(
        root, [&](const std::string& uri) { return uri.rfind("data:", 0) == 0 && why.find(uri) != std::string::npos; });
    if (!undecoded.empty())
      throw InputError(path + ": " + undecoded + ": a data URI whose data does not decode (base64, RFC 4648)");
    constexpr size_t kMaxQuoted = 400;
    if (why.size() > kMaxQuoted) why = why.substr(0, kMaxQuoted) + "... (" + std::to_string(why.size()) + " bytes)";
    throw InputError(
        path + ": not a glTF 2.0 file the reader accepts (tinygltf: " + (why.empty() ? "no reason given" : why) + ")");
  }
  for (const int a : normalized_json.viewless_index_accessors)
    file.model.accessors[static_cast<size_t>(a)].bufferView = -1;
  file.material_in_file = normalized_json.material_in_file;
  file.materials_in_file = normalized_json.materials_in_file;
  if (!warn.empty()) file.notes.push_back(trimmed(warn));
  file.files_read = std::move(confinement.files_read);
  return file;
}

float gltf_float(const GltfFile& file, double value, const std::string& path) {
  if (!(std::abs(value) <= static_cast<double>(std::numeric_limits<float>::max())))
    throw InputError(file.path + ": " + path + ": " + std::to_string(value) + " is not a finite float");
  return static_cast<float>(value);
}

ImagePixels decode_gltf_image(const GltfFile& file, int index, const std::string& use) {
  const std::string where = file.path + ": " + use;
  if (index < 0 || static_cast<size_t>(index) >= file.model.images.size())
    throw InputError(where + ": names image " + std::to_string(index) + "; the file has " +
                     std::to_string(file.model.images.size()));
  const std::vector<unsigned char>& bytes = file.model.images[index].image;
  const std::string name = where + ": images[" + std::to_string(index) + "]";
  static const unsigned char png[4] = {0x89, 'P', 'N', 'G'}, jpeg[3] = {0xff, 0xd8, 0xff};
  std::string format;
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), png, 4) == 0) format = "png";
  if (bytes.size() >= 3 && std::memcmp(bytes.data(), jpeg, 3) == 0) format = "jpg";
  if (format.empty()) throw InputError(name + ": not a PNG or JPEG image (the formats of glTF's core)");
  return read_image_pixels_from_memory(bytes, format, name, 4);  // the 4th: a base colour's alpha
}

}  // namespace tracer
