// The object that precompiles the tests' common headers (tests/CMakeLists.txt: test_headers).
