#include "io/sha1.h"

#include <algorithm>
#include <cstring>

namespace tracer {
namespace {

uint32_t rotl(uint32_t x, int n) { return (x << n) | (x >> (32 - n)); }

}  // namespace

Sha1::Sha1() : h_{0x67452301u, 0xEFCDAB89u, 0x98BADCFEu, 0x10325476u, 0xC3D2E1F0u} {}

// FIPS 180-4 section 6.1.2: the message schedule and 80 rounds over one 512-bit block.
void Sha1::compress(const unsigned char block[64]) {
  uint32_t w[80];
  for (int t = 0; t < 16; ++t)
    w[t] = uint32_t(block[4 * t]) << 24 | uint32_t(block[4 * t + 1]) << 16 | uint32_t(block[4 * t + 2]) << 8 |
           uint32_t(block[4 * t + 3]);
  for (int t = 16; t < 80; ++t) w[t] = rotl(w[t - 3] ^ w[t - 8] ^ w[t - 14] ^ w[t - 16], 1);
  uint32_t a = h_[0], b = h_[1], c = h_[2], d = h_[3], e = h_[4];
  for (int t = 0; t < 80; ++t) {
    uint32_t f, k;
    if (t < 20)
      f = (b & c) | (~b & d), k = 0x5A827999u;
    else if (t < 40)
      f = b ^ c ^ d, k = 0x6ED9EBA1u;
    else if (t < 60)
      f = (b & c) | (b & d) | (c & d), k = 0x8F1BBCDCu;
    else
      f = b ^ c ^ d, k = 0xCA62C1D6u;
    const uint32_t temp = rotl(a, 5) + f + e + k + w[t];
    e = d, d = c, c = rotl(b, 30), b = a, a = temp;
  }
  h_[0] += a, h_[1] += b, h_[2] += c, h_[3] += d, h_[4] += e;
}

void Sha1::append(const void* data, size_t size) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  total_bytes_ += size;
  while (size > 0) {
    const size_t take = std::min(size, 64 - block_size_);
    std::memcpy(block_ + block_size_, p, take);
    block_size_ += take, p += take, size -= take;
    if (block_size_ == 64) compress(block_), block_size_ = 0;
  }
}

// Section 5.1.1: a 1 bit, zeros to 448 mod 512 bits, then the message length in bits.
void Sha1::digest(unsigned char out[20]) {
  const uint64_t bits = total_bytes_ * 8;
  const unsigned char one = 0x80, zero = 0;
  append(&one, 1);
  while (block_size_ != 56) append(&zero, 1);
  unsigned char length[8];
  for (int i = 0; i < 8; ++i) length[i] = static_cast<unsigned char>(bits >> (56 - 8 * i));
  append(length, 8);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) out[4 * i + j] = static_cast<unsigned char>(h_[i] >> (24 - 8 * j));
}

std::string Sha1::hex_digest() {
  unsigned char d[20];
  digest(d);
  static const char* digits = "0123456789ABCDEF";
  std::string text;
  for (unsigned char c : d) text += digits[c >> 4], text += digits[c & 15];
  return text;
}

}  // namespace tracer
