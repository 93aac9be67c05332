// A glTF 2.0 file (.gltf with external or data-URI buffers and images, or .glb) read with
// tinygltf (docs/gltf.md). Its JSON is first parsed by the scene reader's checked parser
// (depth and duplicate keys). External files are followed only inside the glTF file's
// folder: a URI that leaves it (.., an absolute path, a symlink out) is refused, as is
// anything but a regular file. Images are kept encoded and decoded later by OpenImageIO
// (PNG and JPEG, as glTF's core allows). Errors are InputErrors naming the file.
#pragma once
#include <tiny_gltf.h>

#include <set>
#include <string>
#include <vector>

#include "image/image_io.h"

namespace tracer {

// The largest glTF file (a .glb's length field is 32 bits).
constexpr uint64_t kMaxGltfFileBytes = 0xffffffffull;
// The largest external buffer or image the reader follows.
constexpr uint64_t kMaxGltfExternalBytes = 1ull << 30;
// The most bytes read from all the external files one glTF file names, each read once.
constexpr uint64_t kMaxGltfExternalTotalBytes = 4ull << 30;

struct GltfFile {
  std::string path;                  // as the user named it
  tinygltf::Model model;             // images[i].image holds the encoded file's bytes
  std::vector<std::string> notes;    // tinygltf's warnings
  std::set<std::string> files_read;  // external buffers and images
  // model.materials holds only those a primitive names (gltf_normalize.h): each one's index
  // in the file, and the file's count, for messages.
  std::vector<uint64_t> material_in_file;
  uint64_t materials_in_file = 0;
};

// `bytes` are the file's contents (read by the caller, which checked it is a regular file).
GltfFile read_gltf_file(const std::string& bytes, const std::string& path);

// The pixels of image `index` (its first three channels at most); errors name `use`, the
// JSON path of the texture that refers to it.
ImagePixels decode_gltf_image(const GltfFile& file, int index, const std::string& use);

bool is_gltf_path(const std::string& path);

// A JSON number as a float: an InputError naming the file and `path` unless it is finite and
// within float's range (a double beyond it has no float to become).
float gltf_float(const GltfFile& file, double value, const std::string& path);  // a .gltf or .glb extension, any case

}  // namespace tracer
