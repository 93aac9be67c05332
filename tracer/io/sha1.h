// SHA-1 (FIPS 180-4), standard library only, so that the self-contained GPU runner hashes
// images and bundles exactly as the tracer does. Used for integrity and identity, not
// for security.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace tracer {

class Sha1 {
 public:
  Sha1();
  void append(const void* data, size_t size);
  void digest(unsigned char out[20]);  // finishes the hash; append no more afterwards
  std::string hex_digest();            // 40 upper-case hex digits

 private:
  void compress(const unsigned char block[64]);
  uint32_t h_[5];
  unsigned char block_[64];
  size_t block_size_ = 0;
  uint64_t total_bytes_ = 0;
};

}  // namespace tracer
