// The scene file's `render` and `film` keys, overridden by the command line, as the kernel's
// RenderSettings: every option of the table in kernel/scene/render_settings.h, then the
// checks that span options. Errors name the file and key, or the command-line flag.
#pragma once
#include <set>
#include <string>

#include "io/json_reader.h"
#include "options/render_options.h"
#include "options/work_limits.h"

namespace tracer {

// Also records the integrator, sampler and accel in `used_types` ("sampler:grid").
RenderSettings read_settings(const Json* render, const Json& film, const std::string& file,
                             const RenderOverrides& overrides, std::set<std::string>& used_types);

}  // namespace tracer
