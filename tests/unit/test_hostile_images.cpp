// Hostile input through the CLI, images: headers that declare more pixels or bytes than the
// film's limit or the file holds are refused before anything is allocated, running out of
// memory names the file, and library errors are worded as the tracer's.
#include <gtest/gtest.h>

#include "hostile_input.h"
#include "image/image_io.h"
#include "sanitizer.h"
#include "test_util.h"

namespace tracer {
namespace {

// An EXR whose header declares 100000 x 100000 pixels (a real 2 x 2 render with its data and
// display windows and line-offset table rewritten): every command that reads images allocated
// its pixels first (120 GB) and stopped with OpenImageIO's raw allocation error, or was killed
// where the allocation succeeded. The header is now checked against the film's limit first.
TEST_F(HostileInput, AnImageHeaderIsCheckedBeforeItsPixelsAreAllocated) {
  write(dir_ / "huge.exr", exr_declaring(small_exr(), 100000));
  std::string output;
  for (const std::string& args : {"compare " + (dir_ / "huge.exr").string() + " " + (dir_ / "small.exr").string(),
                                  "compare " + (dir_ / "small.exr").string() + " " + (dir_ / "huge.exr").string()}) {
    EXPECT_EQ(run_limited(args, output), 2) << output;
    EXPECT_NE(output.find("huge.exr: cannot read image: its header declares 100000x100000 pixels"), std::string::npos)
        << output;
    EXPECT_EQ(output.find("OIIO"), std::string::npos) << "a library message reached the user raw: " << output;
  }
}

// With less memory than an input needs (ulimit -v), compare of an image within the size
// limit was killed by SIGSEGV (OpenImageIO's failed allocation went unnoticed), and a render
// named only its command line. Every allocation failure is now reported with the file, exit 2.
TEST_F(HostileInput, RunningOutOfMemoryNamesTheFileAndIsNeverASignal) {
#if TRACER_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "ulimit -v cannot hold an AddressSanitizer build (its shadow memory reserves terabytes)";
#endif
  // 16384 x 16384 is within the limits; its 3.2 GB of floats are not within 1.5 GB.
  write(dir_ / "big.exr", exr_declaring(small_exr(), 16384));
  std::string output;
  const std::string limited = "ulimit -v 1500000 && timeout 60 " + std::string(TRACER_BINARY) + " ";
  const auto expect_out_of_memory = [&](const std::string& args, const std::string& expected) {
    EXPECT_EQ(test::run_command(limited + args, &output), 2) << args << "\n" << output;
    EXPECT_NE(output.find(expected), std::string::npos) << args << "\n" << output;
  };
  expect_out_of_memory("compare " + (dir_ / "big.exr").string() + " " + (dir_ / "small.exr").string(),
                       "big.exr: cannot read image: out of memory for its 16384x16384x3 floats");
  std::string text = scene_text("", R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "t"})");
  text.replace(text.find(R"("materials": {)"), 14,
               R"("materials": {"t": {"type": "lambert", "albedo": {"texture": "big.exr"}}, )");
  write(dir_ / "textured.json", text);
  expect_out_of_memory(
      "render " + (dir_ / "textured.json").string() + out(),
      "materials.t.albedo.texture: " + (dir_ / "big.exr").string() + ": cannot read image: out of memory");
  expect_out_of_memory("render " + (dir_ / "s.json").string() + " --width 16384 --height 16384" + out(),
                       "s.json: out of memory while allocating its 16384x16384 film");
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// A filesystem error reached the user as libstdc++ words it ("filesystem error: cannot create
// directories: Not a directory [r/rows]"), and golden check rendered (or failed on its scene)
// before it found that --report could not be made.
TEST_F(HostileInput, LibraryErrorsAreWordedAsTheTracersAndChecksComeFirst) {
  write(dir_ / "afile", "a file, not a directory");
  fs::create_directories(dir_ / "root" / "golden");
  write(dir_ / "root" / "golden" / "manifest.json",
        R"({"format": "tracer-golden/1", "goldens": {"a": {"scene": "missing.json"}}})");
  const std::string report = (dir_ / "afile" / "sub").string();
  std::string output;
  EXPECT_EQ(run_limited("golden check a --root " + (dir_ / "root").string() + " --report " + report, output), 2);
  EXPECT_NE(output.find(report + ": --report: cannot make the report directory: Not a directory"), std::string::npos)
      << output;
  EXPECT_EQ(output.find("missing.json"), std::string::npos) << "the check ran before --report was checked: " << output;
  EXPECT_EQ(run_limited("golden report --report " + report, output), 2);
  EXPECT_NE(output.find(report + "/rows: cannot create directories: Not a directory"), std::string::npos) << output;
  EXPECT_EQ(output.find("filesystem error"), std::string::npos) << output;
}

// Image libraries allocate what a header declares before reading it: an EXR attribute
// (OpenEXR) or a PNG chunk (libpng) of a few hundred bytes declaring 1 GiB made every
// image-reading command allocate 1 GiB (fuzz.image found both). Every declared size must now
// fit in the file before OpenImageIO opens it.
TEST_F(HostileInput, AHeaderDeclaringMoreThanItsFileIsRefusedUnread) {
  std::string exr = small_exr();
  exr.insert(8, std::string("comments\0string\0", 16) + std::string("\0\0\0\x40", 4) + "tiny");  // after the version
  write(dir_ / "bomb.exr", exr);
  ASSERT_EQ(test::run_tracer("render " + (dir_ / "s.json").string() + " --quiet --width 2 --height 2 -o " +
                             (dir_ / "small.png").string()),
            0);
  std::string png = test::read_file(dir_ / "small.png");
  png.insert(8 + 25, std::string("\x40\0\0\0tEXt", 8) + "tiny");  // after the signature and IHDR
  write(dir_ / "bomb.png", png);
  std::string output;
  for (const auto& [file, expected] :
       {std::pair{"bomb.exr", "its EXR header attribute comments (string) declares 1073741824 bytes"},
        std::pair{"bomb.png", "its PNG chunk tEXt declares 1073741824 bytes"}}) {
    EXPECT_EQ(run_limited("compare " + (dir_ / file).string() + " " + (dir_ / "small.exr").string(), output), 2)
        << output;
    EXPECT_NE(output.find(std::string(file) + ": cannot read image: " + expected), std::string::npos) << output;
  }
}

}  // namespace
}  // namespace tracer
