// A partial render: `tracer render SCENE --samples A:B -o NAME.partial` stores the
// fixed-point film sums of samples [A, B) of every pixel, and `tracer merge` adds the parts
// of one render into the image of all its samples, identical bit for bit to rendering them
// at once (kernel/base/film.h). The file: the line "tracer-partial/2", one line of JSON (the
// render's identity, the range and the SHA-1 of the film sums), then width x height film
// sums, each three int64 and two uint32, little-endian. Reading checks every header
// number's range, the size before allocating, the checksum and each sum's range.
#pragma once
#include <nlohmann/json.hpp>  // PartialHeader holds a Json
#include <string>

#include "io/json_reader.h"
#include "render/film_buffer.h"

namespace tracer {

struct PartialHeader {
  Json render;             // resolved options and effects; parts merge only when equal
  std::string scene;       // the scene path as given to render
  std::string scene_sha1;  // of the scene file's text; parts merge only when equal
  uint32_t spp = 0;        // the whole render's samples per pixel
  uint64_t nonfinite = 0;  // samples the film rejected in this part for NaN or inf
  uint64_t overflow = 0;   // and for values beyond its range (2^30)
};

struct Partial {
  PartialHeader header;
  FilmBuffer film;  // film.range: the part's samples
};

std::string encode_partial(const Partial& partial);  // the file's bytes
Partial read_partial(const std::string& path);       // InputError naming the file

// Adds part's film sums into total's (the same size), pixel by pixel, as `tracer merge` adds
// parts and the viewer its passes. Returns the first pixel whose sum would leave the film's
// range (kFilmSumLimit), stopping there, or total.pixels.size() when every pixel fits.
size_t add_film_sums(FilmBuffer& total, const FilmBuffer& part);

// "A:B" with 0 <= A < B <= spp.
SampleRange parse_sample_range(const std::string& text, uint32_t spp);

}  // namespace tracer
