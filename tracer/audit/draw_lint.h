// A lint for kernel and test code: two draws from one input stream inside one call's argument
// list. C++ leaves the order in which a call's arguments are evaluated unspecified (gcc goes
// right to left, clang left to right, nvcc's front end is a third), so such a call is fed
// different numbers by different compilers. Braced initializer lists are evaluated in order
// and are fine; a brace also ends the search (a lambda body runs later, not as an argument).
// Draws are the test streams' stateful calls: .next(), .next_bits(), .bits(), .uniform(.
#pragma once
#include <string>
#include <vector>

namespace tracer {

struct DrawLintFinding {
  std::string file;
  int line = 0;
  int draws = 0;
};

std::vector<DrawLintFinding> lint_draws(const std::string& text, const std::string& file);

// Every .h, .cpp and .cu file under root's tracer/kernel, cuda and tests; InputError naming root
// when there is none.
std::vector<DrawLintFinding> lint_draws_in_tree(const std::string& root);

}  // namespace tracer
