#include "fuzz_sandbox.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "io/input_error.h"

namespace tracer::fuzz {
namespace {

struct Sandbox {
  std::filesystem::path dir;
  Sandbox() {
    dir = std::filesystem::temp_directory_path() / ("tracer-fuzz-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path scenes = std::filesystem::path(TRACER_SOURCE_DIR) / "scenes";
    for (const char* assets : {"models", "textures"})
      std::filesystem::copy(scenes / assets, dir / assets, std::filesystem::copy_options::recursive);
  }
  ~Sandbox() {
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
};

}  // namespace

const std::filesystem::path& sandbox() {
  static const Sandbox box;
  return box.dir;
}

std::string write_input(const std::string& name, const uint8_t* data, size_t size) {
  const std::string path = (sandbox() / name).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "fuzz sandbox: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

void expect_clean_error(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const InputError&) {
    // the answer bad input must get: a message naming the file and key
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: an error other than InputError escaped: %s\n", e.what());
    std::abort();
  }
}

}  // namespace tracer::fuzz
