// emissive: an emitter (Material::radiance) that reflects as Lambert with its optional albedo
// (0 by default: black); in Whitted's model too. Its albedo view shows the emission.
#pragma once
#include "kernel/material/lambert.h"

namespace tracer {

struct EmissiveMaterial : LambertMaterial {
  TRACER_HD static Vec3 albedo(const Material& m) { return m.radiance; }
};

}  // namespace tracer
