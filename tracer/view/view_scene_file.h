// What `tracer view` reads from a request and writes when it saves: a camera as the scene
// file's `camera` block, and the scene file again with the viewer's camera and settings.
#pragma once
#include <string>

#include "io/json_reader.h"
#include "kernel/scene/render_settings.h"
#include "scene/camera_setup.h"

namespace tracer {

// The `camera` block of a scene file: from, to, up, vfov, aperture, focus_distance, each
// float written so that it reads back exactly.
Json camera_block(const CameraSpec& camera);
std::string camera_block_text(const CameraSpec& camera);

// The scene file `text` with its camera replaced, every render and film option set to the
// viewer's (`settings`), and spp the samples the image holds: `tracer render` of it, written
// beside the scene file (where its relative paths resolve), draws the viewer's image bit for bit.
std::string scene_file_with_view(const std::string& text, const RenderSettings& settings, const CameraSpec& camera,
                                 uint32_t spp);

struct SavedNames {
  std::string json, exr, png;
};
// PREFIX-N.json, .exr and .png for the first N from 1 for which none exists.
SavedNames free_save_names(const std::string& prefix);

}  // namespace tracer
