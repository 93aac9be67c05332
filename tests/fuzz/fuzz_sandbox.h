// What the fuzz targets share (docs/fuzzing.md): a private directory holding copies of the
// scene assets (scenes/models, scenes/textures) where each input is written as a file, and the
// rule that a parser may only answer bad input with an InputError; any other exception is a
// finding and aborts, so libFuzzer and the replay test report it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <string>

namespace tracer::fuzz {

// The sandbox directory, created on first use (the process id in its name) and removed at exit.
const std::filesystem::path& sandbox();

// Writes bytes to sandbox()/name and returns its path.
std::string write_input(const std::string& name, const uint8_t* data, size_t size);

// Runs one parse: InputError is the expected answer to bad input; anything else aborts.
void expect_clean_error(const std::function<void()>& parse);

}  // namespace tracer::fuzz

// The libFuzzer entry point each fuzz_*.cpp defines; replay_main.cpp calls it without libFuzzer.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
