// The lights as plain data, every kind's record in one place. A light is one of LightKind:
// lights the scene file declares (points, spots, suns) are `Light` records in
// SceneView::lights; emissive shapes are their primitives; the environment is the scene's
// Background. The path tracer's light table lists every light it samples as a LightEntry;
// each kind's sample, density and power live in its own header (point_light.h, spot_light.h,
// directional_light.h, shape_light.h, environment_light.h) and kernel/light/light.h
// dispatches on the kind.
#pragma once
#include "kernel/base/platform.h"
#include "kernel/base/vec3.h"

namespace tracer {

enum class LightKind : uint32_t {
  Point,        // a declared point light: intensity and falloff, a delta light (point_light.h)
  Spot,         // a point light whose intensity falls off about an axis (spot_light.h)
  Directional,  // the sun: parallel light, or a disc of small angular size (directional_light.h)
  Shape,        // an emissive sphere, quad or triangle (shape_light.h)
  Environment   // the background, sampled by its cells (environment_light.h)
};

// The kinds a scene file declares (SceneView::lights; the others are made of its shapes or its
// background), as X(Kind, its scene-file type), listed once.
#define TRACER_DECLARED_LIGHT_KINDS(X) X(Point, "point") X(Spot, "spot") X(Directional, "directional")

TRACER_HD constexpr bool is_declared_kind(LightKind kind) {
  switch (kind) {
#define TRACER_DECLARED_LIGHT_CASE(Kind, type) \
  case LightKind::Kind: return true;
    TRACER_DECLARED_LIGHT_KINDS(TRACER_DECLARED_LIGHT_CASE)
#undef TRACER_DECLARED_LIGHT_CASE
    default: return false;
  }
}

// A light the scene declares (a kind for which is_declared_kind holds).
struct Light {
  LightKind kind;
  Vec3 position;             // point, spot
  Vec3 intensity;            // point, spot: I on the axis (W/sr); directional: irradiance E at normal incidence
  float kc, kl, kq;          // point, spot: attenuation, used when has_attenuation
  uint32_t has_attenuation;  // 0: physical 1/d^2 falloff
  Vec3 direction;            // spot, directional: the unit direction the light travels
  float cos_inner;           // spot: cosines of the inner and outer cone's half-angles
  float cos_outer;
  float one_minus_cos;  // directional: 1 - cos of the disc's angular radius (0: a delta light)
};

// An entry of the path integrator's light table.
struct LightEntry {
  LightKind kind;
  uint32_t index;  // Point: into SceneView::lights; Shape: the emitting primitive's id; Environment: 0
  float pmf;       // probability of choosing this light
  float cdf;       // sum of the pmfs up to and including this entry; 1 for the last
};

// One sample of a light seen from a shading point.
struct LightSample {
  Vec3 wi;           // unit direction from the shading point to the light
  float distance;    // to the sampled point (a point light: to the light; the environment: infinity)
  Vec3 radiance;     // arriving at the shading point if unoccluded (a point light: I x falloff)
  float pdf;         // solid-angle density including the selection probability; the
                     // selection probability alone for a delta light
  LightKind kind;    // the light's kind
  bool delta;        // a delta light: no BSDF sample can reach it, so no MIS weight
  uint32_t emitter;  // the emitting primitive, which the shadow ray's closest hit must be; kNoHit
                     // for lights that are not surfaces (any hit before `distance` occludes)
  bool valid;
};

// The scene file's background types, as X(Kind, its type), listed once: "environment" is an
// equirectangular image (kernel/light/equirect_map.h).
#define TRACER_BACKGROUND_KINDS(X) \
  X(Constant, "constant") X(Gradient, "gradient") X(Cubemap, "cubemap") X(Environment, "environment")

enum class BackgroundKind : uint32_t {
#define TRACER_BACKGROUND_ENUM(Kind, type) Kind,
  TRACER_BACKGROUND_KINDS(TRACER_BACKGROUND_ENUM)
#undef TRACER_BACKGROUND_ENUM
};

// What a ray that leaves the scene sees, and the environment light when it is sampled.
struct Background {
  BackgroundKind kind;
  Vec3 radiance;      // constant; the zenith colour for gradient; environment: the map's multiplier (strength)
  Vec3 horizon;       // gradient only
  uint32_t faces[6];  // cubemap: textures of the faces +x, -x, +y, -y, +z, -z
  uint32_t map;       // environment: the equirectangular image's texture
  float cos_turn;     // environment: the map turned about +y by an angle of this cosine and sine
  float sin_turn;
};

// A cell of the environment's sampling distribution (environment_light.h).
struct SkyCell {
  float pmf;  // probability of drawing the cell, a multiple of 2^-24
  float cdf;  // sum of the pmfs up to and including this cell; 1 for the last
};

}  // namespace tracer
